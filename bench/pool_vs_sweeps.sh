#!/usr/bin/env bash
# What running a diagnosis's sweeps as one pool gains over running them one after another
# (each sweep ending with a core idle behind its last push), in one run, as a ratio: the
# same cold cache of `granpen gap --prepare-only` (baseline, reference beds, every effect
# knot) made twice into empty caches, --sweep-by-sweep and pooled, with the same --jobs.
# Also the busy fraction of each: the runs' summed wall time / (jobs x wall time).
#   bench/pool_vs_sweeps.sh [--scenario tiny] [--jobs 2] [--v0 "50 100 200"] [--effects LIST]
#   (./granpen build first; tiny: about 22 minutes on 2 cores; bench with
#   --effects measurement_chain: about 35 minutes; bench, every effect: about 2 hours)
set -euo pipefail
SCENARIO=tiny JOBS=2 V0="50 100 200" EFFECTS=""
while [ $# -gt 0 ]; do
  case "$1" in
    --scenario) SCENARIO=$2; shift 2 ;;
    --jobs) JOBS=$2; shift 2 ;;
    --v0) V0=$2; shift 2 ;;
    --effects) EFFECTS=$2; shift 2 ;;
    *) echo "pool_vs_sweeps: unknown option $1" >&2; exit 2 ;;
  esac
done
LMP=$(realpath "$(dirname "${BASH_SOURCE[0]}")/../build/lmp_granpen")
. "$(dirname "${BASH_SOURCE[0]}")/common.sh"
WORK=$WORK/pool_vs_sweeps_$SCENARIO
rm -rf "$WORK"; mkdir -p "$WORK"
CLI=$ROOT/build/analysis/granpen-cli
echo "pool_vs_sweeps: $SCENARIO, v0 = $V0, effects: ${EFFECTS:-all}, --jobs $JOBS; load average at the start: $(cut -d' ' -f1-3 /proc/loadavg)"
make_cache() {    # label [--sweep-by-sweep]
  local t0 wall; t0=$(date +%s.%N)
  "$CLI" gap --prepare-only --scenario "$SCENARIO" --v0 "$V0" --jobs "$JOBS" --cache "$WORK/$1" --lmp "$LMP" \
    --inputs "$ROOT/inputs" ${EFFECTS:+--effects "$EFFECTS"} ${2:-} > "$WORK/$1.log" 2>&1 || { tail -5 "$WORK/$1.log"; exit 1; }
  wall=$(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { print b - a }')
  echo "$wall" > "$WORK/$1.wall"
  # every run's own wall time, from the manifests (linked beds count 0)
  busy=$(for m in "$WORK/$1/$SCENARIO"/*/manifest.json; do "$CLI" get "$m" 'runs[*].wall_seconds_run' --missing 0; done |
         awk '{s += $1} END {print s}')
  awk -v w="$wall" -v busy="$busy" -v j="$JOBS" -v l="$1" 'BEGIN {
    printf "%-15s wall %7.1f s; runs %8.1f s; busy %5.1f%%\n", l, w, busy, 100 * busy / (j * w) }' |
    tee -a "$WORK/summary.txt"
}
make_cache sweep_by_sweep --sweep-by-sweep
make_cache pooled
echo "ratio sweep-by-sweep / pooled: $(ratio "$(cat "$WORK/sweep_by_sweep.wall")" "$(cat "$WORK/pooled.wall")")" |
  tee -a "$WORK/summary.txt"
