#!/usr/bin/env bash
# The sweep runner under faults with the real lmp_granpen (tiny preset): kill -9 of the
# runner during the pour and again during the push (at random points drawn from SEED),
# then a rerun. No LAMMPS outlives its runner; the bed poured again equals, byte for byte,
# the tiny bed of the same seed poured uninterrupted (tests/inputs fixture); the push,
# resumed from its checkpoint, has exactly the rows of an uninterrupted push of that bed
# (t column identical: none lost, none repeated) and agrees with it to 1e-6 of max F: both
# pushes run in chunks ending at their checkpoints (in.push), so the resumed one starts with
# the run set-up the uninterrupted one had at that step, and only round-off differs (its
# atoms come from the restart file in another order), grown over the steps after it;
# another bed or push differs by O(1).
#   fault_lammps.sh CLI TRACE_AGREE INPUTS BED OUT SEED    (BED: the fixture's bed_tiny, no extension)
set -euo pipefail
CLI=$1 AGREE=$2 INPUTS=$3 BED=$4 OUT=$5 SEED=$6
rm -rf "$OUT"
mkdir -p "$OUT"
fail() { echo "fault_lammps: FAILED: $*"; exit 1; }
seed=$(sed -n 's/^seed = //p' "$BED.info")
spec=$OUT/lfault.sweep
printf 'name = lfault\npreset = tiny\nmu = 0.3\nseeds = %s\nv0 = 100\ndepth = 1.0\n' "$seed" > "$spec"
args() { echo sweep "$spec" --out "$1" --inputs "$INPUTS" --checkpoint 500; }
run_bg() { ( exec "$CLI" $(args "$1") ) > "$2" 2>&1 & }
id=tiny_mu0.3_s${seed}_v100 bed=bed_tiny_mu0.3_s$seed
wait_gone() {
  for _ in $(seq 1 10); do pgrep -f -- "$1/lfault/" > /dev/null || return 0; sleep 0.1; done
  fail "lmp_granpen outlived its runner killed with -9 ($2)"
}
# alive and not a zombie (an exited runner stays one until waited for)
running() { ps -o stat= -p "$1" 2>/dev/null | grep -q '^[^Z]'; }
# kill_when DIR OUTPUT WHAT FILE PATTERN N: starts the runner on DIR, kills it with -9 once
# FILE holds N lines matching PATTERN (no time limit of its own: a loaded machine can make
# the pour minutes long), and checks that its lmp_granpen is gone; WHAT names the stage
kill_when() {
  run_bg "$1" "$2"
  local runner=$!
  until [ "$(cat "$4" 2>/dev/null | grep -c "$5" || true)" -ge "$6" ]; do
    running "$runner" || fail "the runner ended before the $3 was killed"
    sleep 0.05
  done
  kill -9 "$runner" || fail "the runner ended before the $3 was killed"
  wait "$runner" 2>/dev/null || true
  wait_gone "$1" "$3"
}
RANDOM=$SEED

# the reference: an uninterrupted push from the fixture's bed
mkdir -p "$OUT/ref/lfault/beds"
cp "$BED.restart" "$OUT/ref/lfault/beds/$bed.restart"
cp "$BED.info" "$OUT/ref/lfault/beds/$bed.info"
"$CLI" $(args "$OUT/ref") > "$OUT/ref.txt" 2>&1 || { cat "$OUT/ref.txt"; fail "the uninterrupted push failed"; }
ref=$OUT/ref/lfault/traces/$id.csv

# killed during the pour, after a random one of its first 8 progress lines (the tiny pour
# prints 7 chunks and 3 relaxations: it is still running after the 8th)
d=$OUT/killed
chunk=$((1 + RANDOM % 8))
kill_when "$d" "$OUT/pour_killed.txt" pour "$d/lfault/logs/$bed.log" '^granpen pour: \(chunk\|relaxation\)' "$chunk"
[ ! -e "$d/lfault/beds/$bed.info" ] || fail "the pour had finished when it was killed"
# killed during the push, at a random row between a fifth and four fifths of the trace
# (the first checkpoint, 500 of about 7500 steps, is written by then)
rows=$(grep -c '^[0-9-]' "$ref")
target=$((rows / 5 + RANDOM % (rows * 3 / 5)))
trace=$d/lfault/traces/$id.csv
kill_when "$d" "$OUT/push_killed.txt" push "$trace" '^[0-9-]' "$target"
[ ! -e "$trace.done" ] || fail "the push had finished when it was killed"
"$CLI" $(args "$d") > "$OUT/rerun.txt" 2>&1 || { cat "$OUT/rerun.txt"; fail "the rerun failed"; }
grep -q "start $id (resumed from $id.csv.[ab].restart" "$OUT/rerun.txt" ||
  { cat "$OUT/rerun.txt"; fail "the push was not resumed from a checkpoint"; }

cmp "$BED.restart" "$d/lfault/beds/$bed.restart" || fail "the bed poured after the kill differs from the uninterrupted pour's"
diff <(grep '^[0-9-]' "$ref" | cut -d, -f1) <(grep '^[0-9-]' "$d/lfault/traces/$id.csv" | cut -d, -f1) > "$OUT/t.diff" ||
  { head "$OUT/t.diff"; fail "the resumed trace's rows differ from the uninterrupted one's (lost or repeated rows)"; }
"$AGREE" "$ref" "$d/lfault/traces/$id.csv" --rtol 1e-6 --min-rows 100
echo "fault_lammps: 2 runners killed with -9 (pour after progress line $chunk, push at row $target of $rows), push resumed from its checkpoint, bed equal byte" \
     "for byte, $rows trace rows compared, 0 lost or repeated"
