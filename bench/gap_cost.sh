#!/usr/bin/env bash
# What a gap diagnosis costs on the bench scenario (issue: gap diagnosis, "Cost"): in one
# run, with a cache of its own,
#   1. the first diagnosis from a cold cache (baseline and every effect's signature
#      simulated, then the confirmation),
#   2. a diagnosis of another data set on the warm cache (only its confirming runs new),
#   3. the first diagnosis again, finished (nothing simulated).
# Bracketed by two probes of the machine's speed (bench/common.sh: probe_pour, bed 1 poured
# alone): each figure is also given in probe pours and at the probe's 2026-11-22 speed
# (69.9 s), so that figures of different days compare (the same work took 1.6 x longer
# on a slow day).
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
LMP=$GRANPEN_LMP
. "$ROOT/bench/common.sh"
SELF=${GRANPEN_SELFTEST_WORK:-$ROOT/runs/gap_selftest}
WORK=$ROOT/runs/gap_cost
PROBE_REF=69.9
"$ROOT/bench/gap_selftest.sh" --scenario bench --jobs "$JOBS" --cases "$FIRST,$SECOND" --measured-only
rm -rf "$WORK"; mkdir -p "$WORK"
run() {    # label data-set
  local t0; t0=$(date +%s)
  "$CLI" gap --real "$SELF/bench/real_$2" --scenario bench --out "$WORK/diag_$2" --jobs "$JOBS" \
    --cache "$WORK/cache" > "$WORK/$1.log" 2>&1
  local s=$(( $(date +%s) - t0 )) last; last=$(tail -1 "$WORK/$1.log")
  echo "$1 $s $last" >> "$WORK/figures.txt"
  echo "$1: $s s ($last)"
}
echo "gap_cost: load average at the start: $(cut -d' ' -f1-3 /proc/loadavg)"
p1=$(probe_pour "$WORK/probe1")
echo "gap_cost: probe pour before: $p1 s"
run cold "$FIRST"
run warm "$SECOND"
run rerun "$FIRST"
p2=$(probe_pour "$WORK/probe2")
echo "gap_cost: probe pour after: $p2 s"
awk -v p1="$p1" -v p2="$p2" -v ref="$PROBE_REF" '{
    p = (p1 + p2) / 2
    printf "%-6s %6d s = %5.1f min; %5.1f probe pours; at the 2026-11-22 speed (%.1f s a probe): %5.1f min\n",
      $1, $2, $2 / 60, $2 / p, ref, $2 / p * ref / 60 }' "$WORK/figures.txt"
