#!/usr/bin/env bash
# Cost of the flow diagnostics during a bench push, in one run: the push with
# compute flow/azimuthal (with stress/atom) and compute momentum/vbin sampled every 100
# steps (inputs/observe/flow.lmp), and the same plus a Voronoi flow/azimuthal every 1000
# steps (observe/flow_voronoi.lmp), each against the same push without them
# (observe/none.lmp). Rounds alternate the three; ratios are per round, then the median.
# Targets: <= 1.03 and <= 1.10.
#   bench/observe_overhead.sh [LMP_GRANPEN] [REPEAT]      (./granpen build first)
set -euo pipefail
LMP=$(realpath "${1:-$(dirname "${BASH_SOURCE[0]}")/../build/lmp_granpen}")
REPEAT=${2:-3}
. "$(dirname "${BASH_SOURCE[0]}")/common.sh"
ensure_bench_bed
cd "$WORK"
push() {    # push NAME OBSERVE-FILE
  "$LMP" -in "$ROOT/inputs/in.push" -var inputs "$ROOT/inputs" -var preset bench -var bed bed_bench.restart \
    -var v0 100 -var trace "obs_$1.csv" -var observe "$ROOT/inputs/observe/$2" -log "obs_$1.log" -screen none
  per_step "obs_$1.log"
}
r_flow=() r_vor=()
for r in $(seq 1 "$REPEAT"); do
  base=$(push "none_$r" none.lmp)
  flow=$(push "flow_$r" flow.lmp)
  vor=$(push "voronoi_$r" flow_voronoi.lmp)
  r_flow+=("$(ratio "$flow" "$base")")
  r_vor+=("$(ratio "$vor" "$base")")
  echo "round $r/$REPEAT: s/step none $base, flow+momentum $flow (${r_flow[-1]}), +voronoi $vor (${r_vor[-1]})"
done
echo "flow+momentum every 100 steps: ratios $(printf '%s\n' "${r_flow[@]}" | sort -g | tr '\n' ' ')median $(median "${r_flow[@]}") (target <= 1.03)"
echo "with Voronoi every 1000 steps: ratios $(printf '%s\n' "${r_vor[@]}" | sort -g | tr '\n' ' ')median $(median "${r_vor[@]}") (target <= 1.10)"
