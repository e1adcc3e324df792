#!/usr/bin/env bash
# An interrupted sweep resumes cleanly: after a full tiny sweep, one push is made to look
# interrupted (its done marker removed, its trace cut after the checkpoint and a few rows
# of a "later" run appended), and the sweep is run again. It must resume that push from its
# checkpoint, skip the rest, and leave a valid trace agreeing with the original one. Then the
# same push with its trace gone and its checkpoints left must start over, removing them.
#   resume_interrupted.sh CLI TRACE_AGREE SWEEP_FILE OUT
set -euo pipefail
CLI=$1 AGREE=$2 SPEC=$3 OUT=$4
rm -rf "$OUT"
"$CLI" sweep "$SPEC" --out "$OUT" --jobs 2 --checkpoint 4000 | tail -2
dir="$OUT/tiny_demo/traces"
t="$dir/tiny_mu0.3_s1_v100_D2.0.csv"
cp "$t" "$OUT/original.csv"
[ -f "$t.a.restart" ] || { echo "no checkpoint was written"; exit 1; }
rm "$t.done"
"$CLI" sweep "$SPEC" --out "$OUT" --jobs 2 --checkpoint 4000 | tee "$OUT/second.txt"
grep -q "(4 already done)" "$OUT/second.txt" || { echo "finished runs were not skipped"; exit 1; }
grep -q "start tiny_mu0.3_s1_v100_D2.0 (resumed from" "$OUT/second.txt" || { echo "the push was not resumed"; exit 1; }
grep -q "replacing [0-9]* rows" "$OUT/tiny_demo/logs/tiny_mu0.3_s1_v100_D2.0.log" || { echo "no rows were replaced"; exit 1; }
# to round-off: the sweep's pushes run in chunks ending at their checkpoints (in.push), so the
# resumed push starts with the run set-up the original had at that step; 1e-6 of max F is
# round-off grown over the steps after it (the resumed atoms come in another order), as for
# tests/inputs restart_agrees (measured here: 1.3e-10 on 29Sep2021, 5.7e-11 on 22Jul2025)
"$AGREE" "$OUT/original.csv" "$t" --rtol 1e-6 --min-rows 100
# A push whose trace is gone but whose checkpoints are left (an earlier attempt's) starts over
# and removes them first: kept, a cut before the new run's first checkpoint would resume from
# them onto the new trace. Rerun without checkpoints (--checkpoint beyond the push's steps), so
# that any checkpoint left after it can only be the stale one.
[ -f "$t.a.restart" ] || [ -f "$t.b.restart" ] || { echo "no checkpoint left to go stale"; exit 1; }
rm "$t" "$t.done"
"$CLI" sweep "$SPEC" --out "$OUT" --jobs 2 --checkpoint 1000000 | tee "$OUT/third.txt"
grep -q "start tiny_mu0.3_s1_v100_D2.0 (started (the checkpoints of an earlier attempt" "$OUT/third.txt" ||
  { echo "the push with stale checkpoints was not started over"; exit 1; }
[ ! -e "$t.a.restart" ] && [ ! -e "$t.b.restart" ] || { echo "the stale checkpoints were left"; exit 1; }
[ -f "$t.done" ] || { echo "the push started over did not finish"; exit 1; }
echo "resume_interrupted: all checks passed"
