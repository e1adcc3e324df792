#!/usr/bin/env bash
# validation/campaign.sh --status on a push cut with its checkpoints: which it resumes from is
# decided by one test, the sweep runner's (complete_checkpoint, asked through granpen
# checkpoint), so a checkpoint cut short in writing is reported incomplete, and a push with no
# complete checkpoint as starting over. Fixtures: restart files ending (or not) with LAMMPS's
# magic string, as a finished (or a killed) write leaves them.
#   campaign_status.sh GRANPEN_CLI WORK
set -uo pipefail
CLI=$1 W=$2
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
SWEEP=$ROOT/inputs/sweeps/tiny_demo.sweep
fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }
rm -rf "$W" && mkdir -p "$W/runs" || exit 1
id=$("$CLI" sweep "$SWEEP" --plan --inputs "$ROOT/inputs" --out "$W/runs" | awk '$2 == "push" { print $3; exit }')
[ -n "$id" ] || { echo "FAIL: no push planned in $SWEEP"; exit 1; }
T=$W/runs/tiny_demo/traces/$id.csv
mkdir -p "$(dirname "$T")" && printf 't,z,F\n0,0,0\n' > "$T"
# a complete checkpoint: some bytes, then the magic string with its '\0' (lmprestart.h)
{ head -c 4096 /dev/zero; printf 'LammpS RestartT\0'; } > "$T.a.restart"
# the same cut short by one byte (its '\0' never written), and by half the magic
head -c -1 "$T.a.restart" > "$T.b.restart"
head -c -8 "$T.a.restart" > "$W/half.restart"

# ---- the one definition, asked directly
out=$("$CLI" checkpoint "$T.a.restart"); rc=$?
[ "$rc" = 0 ] && [ "$out" = "complete $T.a.restart" ] || fail "a complete checkpoint: exit $rc, '$out'"
for f in "$T.b.restart" "$W/half.restart" "$W/missing.restart"; do
  out=$("$CLI" checkpoint "$f"); rc=$?
  [ "$rc" = 1 ] && [ "$out" = "incomplete $f" ] || fail "$(basename "$f"): exit $rc, '$out' (not incomplete)"
done
out=$("$CLI" checkpoint "$T.a.restart" "$T.b.restart"); rc=$?
[ "$rc" = 1 ] && [ "$(echo "$out" | awk '{print $1}' | tr '\n' ' ')" = "complete incomplete " ] ||
  fail "two checkpoints, one cut: exit $rc, '$out'"

# ---- campaign.sh --status asks it: resumes from a only; with a cut too, starts over
status() { GRANPEN_CLI=$CLI "$ROOT/validation/campaign.sh" --data "$W/data/camp" --sweeps "$SWEEP" --out "$W/runs" --status; }
out=$(status) || fail "campaign.sh --status exits $?"
echo "$out"
line=$(echo "$out" | grep "under way here: push tiny_demo/$id:")
[[ $line == *"resumes from the newer of $id.csv.a.restart ("* ]] || fail "the complete checkpoint not offered: '$line'"
[[ $line != *"$id.csv.b.restart"* ]] || fail "the checkpoint cut short offered: '$line'"
cp "$T.b.restart" "$T.a.restart"
out=$(status) || fail "campaign.sh --status exits $?"
echo "$out" | grep -q "under way here: push tiny_demo/$id: no complete checkpoint: starts over" ||
  fail "two checkpoints cut short, not reported as starting over: $out"

# ---- --checkpoint: refused by name when not a whole number of steps; given, it reaches the
# sweep runner (a stand-in CLI records the runner's command line and answers the rest itself)
for bad in 0 x 1e3 1000000; do
  err=$(GRANPEN_CLI=$CLI "$ROOT/validation/campaign.sh" --data "$W/data/camp" --sweeps "$SWEEP" --out "$W/runs" --checkpoint "$bad" --status 2>&1); rc=$?
  [ "$rc" = 2 ] && [[ $err == *"--checkpoint $bad is not a whole number"* ]] || fail "--checkpoint $bad: exit $rc, '$err'"
done
cat > "$W/cli" <<EOS
#!/usr/bin/env bash
case " \$* " in *" --only "*) echo "\$*" >> "$W/runner.args"; exit 1 ;; esac
exec "$CLI" "\$@"
EOS
chmod +x "$W/cli"
GRANPEN_CLI=$W/cli GRANPEN_LMP=/bin/false "$ROOT/validation/campaign.sh" --data "$W/data/camp" --sweeps "$SWEEP" --out "$W/runs" --units 1 --checkpoint 700 > "$W/run.out" 2>&1
grep -q -- "--checkpoint 700" "$W/runner.args" 2>/dev/null || fail "--checkpoint 700 not passed to the sweep runner: $(cat "$W/runner.args" 2>/dev/null)"

[ "$fails" = 0 ] && echo "campaign_status: all checks passed" || { echo "campaign_status: $fails failed"; exit 1; }
