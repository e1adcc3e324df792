#!/usr/bin/env bash
# What a gap diagnosis costs on the bench scenario (issue: gap diagnosis, "Cost"): in one
# run, with a cache of its own,
#   1. the first diagnosis from a cold cache (baseline and every effect's signature
#      simulated, then the confirmation),
#   2. a diagnosis of another data set on the warm cache (only its confirming runs new),
#   3. the first diagnosis again, finished (nothing simulated).
# The data sets are two of bench/gap_selftest.sh's measured cases (made first if missing).
#   bench/gap_cost.sh [--jobs 2] [--first CASE] [--second CASE]
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
JOBS=2 FIRST=rolling_resistance SECOND=measurement_chain    # both explained: each has confirming runs
while [ $# -gt 0 ]; do
  case "$1" in
    --jobs) JOBS=$2; shift 2 ;;
    --first) FIRST=$2; shift 2 ;;
    --second) SECOND=$2; shift 2 ;;
    *) echo "gap_cost: unknown option $1" >&2; exit 2 ;;
  esac
done
CLI=${GRANPEN_CLI:-$ROOT/build/analysis/granpen-cli}
export GRANPEN_LMP=${GRANPEN_LMP:-$ROOT/build/lmp_granpen} GRANPEN_INPUTS=${GRANPEN_INPUTS:-$ROOT/inputs}
SELF=${GRANPEN_SELFTEST_WORK:-$ROOT/runs/gap_selftest}
WORK=$ROOT/runs/gap_cost
"$ROOT/bench/gap_selftest.sh" --scenario bench --jobs "$JOBS" --cases "$FIRST,$SECOND" --measured-only
rm -rf "$WORK"; mkdir -p "$WORK"
run() {    # label data-set
  local t0; t0=$(date +%s)
  "$CLI" gap --real "$SELF/bench/real_$2" --scenario bench --out "$WORK/diag_$2" --jobs "$JOBS" \
    --cache "$WORK/cache" > "$WORK/$1.log" 2>&1
  echo "$1: $(( $(date +%s) - t0 )) s ($(tail -1 "$WORK/$1.log"))"
}
echo "gap_cost: load average at the start: $(cut -d' ' -f1-3 /proc/loadavg)"
run cold "$FIRST"
run warm "$SECOND"
run rerun "$FIRST"
