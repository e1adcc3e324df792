#!/usr/bin/env bash
# Wall time of a 3-speed, 2-seed bench sweep run by `granpen sweep` (each bed poured once,
# pushes branching from it, 2 at once) against the naive way (a pour for every push, one
# run at a time), in one run, as a ratio. Both produce the same 6 traces.
#   bench/sweep_vs_naive.sh [JOBS]         (./granpen build first; takes about 12 minutes)
set -euo pipefail
JOBS=${1:-2}
LMP=$(realpath "$(dirname "${BASH_SOURCE[0]}")/../build/lmp_granpen")
. "$(dirname "${BASH_SOURCE[0]}")/common.sh"
WORK=$WORK/sweep_vs_naive
rm -rf "$WORK"; mkdir -p "$WORK"
export GRANPEN_LMP=$LMP GRANPEN_INPUTS=$ROOT/inputs

t0=$(date +%s.%N)
"$ROOT/build/analysis/granpen-cli" sweep "$ROOT/inputs/sweeps/v0_bench.sweep" --out "$WORK/sweep" --jobs "$JOBS" \
  | grep -E "^granpen sweep|done|FAILED"
t1=$(date +%s.%N)
echo "naive: a pour before every push, one run at a time"
for seed in 1 2; do
  for v0 in 50 100 200; do
    "$LMP" -in "$ROOT/inputs/in.pour" -var inputs "$ROOT/inputs" -var preset bench -var mu 0.3 -var seed "$seed" \
      -var out "$WORK/naive_bed_s${seed}_v$v0" -log "$WORK/naive_pour_s${seed}_v$v0.log" -screen none
    "$LMP" -in "$ROOT/inputs/in.push" -var inputs "$ROOT/inputs" -var preset bench -var mu 0.3 \
      -var bed "$WORK/naive_bed_s${seed}_v$v0.restart" -var v0 "$v0" -var run "$seed" \
      -var trace "$WORK/naive_s${seed}_v$v0.csv" -log "$WORK/naive_push_s${seed}_v$v0.log" -screen none
    echo "  seed $seed, v0 $v0 done"
  done
done
t2=$(date +%s.%N)
awk -v a="$t0" -v b="$t1" -v c="$t2" 'BEGIN {
  s = b - a; n = c - b
  printf "sweep (bed reuse, %s at once): %.0f s; naive: %.0f s; ratio naive/sweep %.2f\n", "'"$JOBS"'", s, n, n / s }'
