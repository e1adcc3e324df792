#!/usr/bin/env bash
# The sweep runner under faults, with fault_lmp (a deterministic stand-in for lmp_granpen:
# a resumed run must give files equal byte for byte to an uninterrupted run's).
#   1. kill -9 of the runner, and of its LAMMPS child, at random points of pours and pushes
#      (several seeds, three faults each), then a rerun: no child outlives its runner, and
#      every bed and trace equals the uninterrupted run's (cmp);
#   2. two runners on one sweep: the second refuses the runs the first holds, naming its pid,
#      and starts none of them;
#   3. a full disk (ulimit -f): a named error, the checkpoint cut short is never resumed
#      from, and the rerun's traces equal the uninterrupted run's.
#   fault_kill_resume.sh CLI FAULT_LMP INPUTS OUT SEED...
set -euo pipefail
CLI=$1 FAKE=$2 INPUTS=$3 OUT=$4
shift 4
SEEDS="$*"
export FAULT_LMP_MS=${FAULT_LMP_MS:-12}
rm -rf "$OUT"
mkdir -p "$OUT"
fail() { echo "fault_kill_resume: FAILED: $*"; exit 1; }
spec=$OUT/faults.sweep
printf 'name = faults\npreset = tiny\nmu = 0.3\nseeds = 1 2\nv0 = 100 200\ndepth = 0.5\n' > "$spec"
run() { "$CLI" sweep "$spec" --out "$1" --lmp "$FAKE" --inputs "$INPUTS" --jobs 2 --checkpoint 10; }
# the same in the background, $! the runner itself (exec: no shell in between)
run_bg() { ( exec "$CLI" sweep "$spec" --out "$1" --lmp "$FAKE" --inputs "$INPUTS" --jobs 2 --checkpoint 10 ) > "$2" 2>&1 & }

# processes started for folder $1 still alive (a child that outlived its runner)
alive() { pgrep -f -- "--out $1 |$1/faults/" || true; }
# within 0.5 s: a push of fault_lmp lasts 0.6 to 1.2 s, an orphan would still be running
wait_gone() {
  for _ in $(seq 1 5); do [ -z "$(alive "$1")" ] && return 0; sleep 0.1; done
  ps -o pid,ppid,pgid,args -p "$(alive "$1" | tr '\n' ',' | sed 's/,$//')" || true
  fail "$2"
}

# files of a finished sweep equal to the reference's; counts rows compared
rows_compared=0
same_as_reference() {
  local d=$1 f n
  for f in "$OUT"/ref/faults/beds/*.restart "$OUT"/ref/faults/beds/*.info "$OUT"/ref/faults/traces/*.csv; do
    n=${f#"$OUT"/ref/}
    [ -f "$d/$n" ] || fail "$d: no $n"
    cmp -s "$f" "$d/$n" || { diff <(tail -n +1 "$f") "$d/$n" | head -5; fail "$d/$n differs from the uninterrupted run's"; }
    case $f in *.csv) rows_compared=$((rows_compared + $(grep -c '^[0-9]' "$f"))) ;; esac
  done
}

run "$OUT/ref" > "$OUT/ref.txt" || { cat "$OUT/ref.txt"; fail "the uninterrupted sweep failed"; }
ntraces=$(ls "$OUT"/ref/faults/traces/*.csv | wc -l)
[ "$ntraces" = 4 ] || fail "the reference sweep made $ntraces traces, expected 4"

# 1. kill -9 at random points, three times per seed, then finish
faults=0 resumed=0 children_killed=0
for seed in $SEEDS; do
  d=$OUT/kill_$seed
  RANDOM=$seed
  for round in 1 2 3; do
    run_bg "$d" "$d.round$round.txt"
    runner=$!
    ms=$((RANDOM % 1200 + 50))
    sleep "$((ms / 1000)).$(printf '%03d' $((ms % 1000)))"
    if [ $((RANDOM % 2)) = 0 ]; then    # the child first, sometimes
      for c in $(pgrep -f -- "$d/faults/" || true); do kill -9 "$c" 2>/dev/null && children_killed=$((children_killed + 1)); done
      sleep 0.05
    fi
    if kill -9 "$runner" 2>/dev/null; then faults=$((faults + 1)); fi
    wait "$runner" 2>/dev/null || true
    wait_gone "$d" "a LAMMPS child outlived its runner killed with -9 (seed $seed, round $round)"
  done
  run "$d" > "$d.final.txt" 2>&1 || { cat "$d.final.txt"; fail "the sweep did not finish after the faults (seed $seed)"; }
  resumed=$((resumed + $(cat "$d".round*.txt "$d.final.txt" | grep -c "(resumed from" || true)))
  same_as_reference "$d"
done
[ "$faults" -ge 1 ] || fail "no fault was injected (every run ended before its kill)"
[ "$resumed" -ge 1 ] || fail "no push was resumed from a checkpoint: the faults did not test resuming"

# 2. two runners on one sweep
d=$OUT/two
FAULT_LMP_MS=20 run_bg "$d" "$d.first.txt"
first=$!
for _ in $(seq 1 100); do grep -q "^  start tiny_mu" "$d.first.txt" 2>/dev/null && break; sleep 0.1; done
grep -q "^  start " "$d.first.txt" || fail "the first runner started nothing"
if run "$d" > "$d.second.txt" 2>&1; then fail "a second runner on a sweep in use succeeded"; fi
grep -q "refused .*locked by another process (granpen sweep pid $first)" "$d.second.txt" ||
  { cat "$d.second.txt"; fail "the second runner did not name the first ($first)"; }
if grep -q "^  start " "$d.second.txt"; then cat "$d.second.txt"; fail "the second runner started a run the first holds"; fi
wait "$first" || { cat "$d.first.txt"; fail "the first runner failed"; }
same_as_reference "$d"

# 3. a full disk: a 4 KiB file size limit cuts the second checkpoint of every push short
d=$OUT/full
mkdir -p "$d/faults/beds"
cp "$OUT"/ref/faults/beds/* "$d/faults/beds/"    # the pours would not fit either
if (ulimit -f 4 && run "$d") > "$d.limited.txt" 2>&1; then fail "a sweep past the file size limit succeeded"; fi
n=$(grep -c "FAILED tiny_mu.*killed by SIGXFSZ: a file reached the file size limit (ulimit -f)" "$d.limited.txt" || true)
[ "$n" = 4 ] || { cat "$d.limited.txt"; fail "expected 4 pushes failed with the named SIGXFSZ error, got $n"; }
run "$d" > "$d.rerun.txt" 2>&1 || { cat "$d.rerun.txt"; fail "the rerun after the full disk failed"; }
n=$(grep -c "start tiny_mu.*(resumed from .*\.a\.restart (the other checkpoint is incomplete))" "$d.rerun.txt" || true)
[ "$n" = 4 ] || { cat "$d.rerun.txt"; fail "expected 4 pushes resumed from their complete checkpoint, got $n"; }
same_as_reference "$d"

echo "fault_kill_resume: $faults runners and $children_killed children killed with -9 at random points" \
     "(seeds $SEEDS), $resumed pushes resumed from checkpoints, 4 pushes past a full disk resumed," \
     "$rows_compared rows compared with uninterrupted runs, 0 lost or duplicated"
