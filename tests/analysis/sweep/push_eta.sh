#!/usr/bin/env bash
# A running push's own ETA in the sweep runner's progress lines (sweep_runner.h:
# push_seconds_left), end to end: fake_lmp writes the tiny demo's first push at an even pace
# over PACE seconds (GRANPEN_FAKE_LMP_PUSH_SECONDS), the runner reports every second
# (--progress 1). Before any run has finished, the lines must say "z=Z of 1.00 (Ns left)",
# each line's ETA must be its push's own time left (one job, nothing pending), and the
# finish they predict (the line's elapsed time + N) must come when the push did end.
#   push_eta.sh CLI FAKE_LMP INPUTS OUT
set -euo pipefail
CLI=$1 FAKE=$2 INPUTS=$3 OUT=$4 PACE=6
SWEEP=$INPUTS/sweeps/tiny_demo.sweep
fail() { echo "push_eta: $*"; exit 1; }
rm -rf "$OUT"; mkdir -p "$OUT"
run() { "$CLI" sweep "$SWEEP" --jobs 1 --out "$OUT" --lmp "$FAKE" --inputs "$INPUTS" --progress 1 "$@"; }
pour=$(run --plan | awk '$2 == "pour" { print $1; exit }') push=$(run --plan | awk '$2 == "push" { print $1; exit }')
run --only "$pour" > "$OUT/pour.txt" 2>&1 || { cat "$OUT/pour.txt"; fail "the pour failed"; }
GRANPEN_FAKE_LMP_PUSH_SECONDS=$PACE run --only "$push" > "$OUT/push.txt" 2>&1 || { cat "$OUT/push.txt"; fail "the push failed"; }
# "  [ELAPSED] ... z=Z of 1.00 (LEFTs left); ETA ETAs" -> "ELAPSED LEFT ETA"
lines=$(sed -n 's/^  \[\([0-9]*\)s\].* z=[-0-9.]* of 1\.00 (\([0-9]*\)s left); ETA \([0-9]*\)s$/\1 \2 \3/p' "$OUT/push.txt")
[ "$(echo "$lines" | grep -c .)" -ge 2 ] || { cat "$OUT/push.txt"; fail "fewer than 2 progress lines with the push's own time left"; }
echo "$lines" | awk '$2 != $3 { exit 1 }' || fail "an ETA is not the running push's own time left: $lines"
wall=$(sed -n 's/^  done .* in \([0-9]*\)s$/\1/p' "$OUT/push.txt")
[ -n "$wall" ] || { cat "$OUT/push.txt"; fail "no done line with the push's wall time"; }
# the runner starts the push within a second of its own start, each of the three figures is
# printed to the second and the first depth it reads may be a row old: 2.5 s either way
echo "$lines" | awk -v w="$wall" '{ d = $1 + $2 - w; if (d < -2.5 || d > 2.5) { print "finish predicted at " $1 + $2 " s, the push ended at " w " s"; bad = 1 } }
  END { exit bad }' || fail "a progress line's time left is off by more than 2.5 s"
[ "$wall" -ge $((PACE - 1)) ] || fail "the push took ${wall}s, less than its pace ($PACE s): the pacing did not hold"
echo "push_eta: $(echo "$lines" | wc -l) progress lines, each predicting the end within 2.5 s of ${wall}s"
