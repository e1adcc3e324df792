#!/usr/bin/env bash
# The flow of one push from its dumps, as docs/results.md reports it: the same commands for
# the mid push (validation/results.sh, from the dumps of the mid g sweep) and for the dg10
# flow pushes (validation/dg10.sh, while their dumps exist: they are not committed).
#
#   validation/push_flow.sh TRACE OUT [--cli PATH] [--tip "ZLO ZHI"]
#
#   TRACE       the push's trace; its dumps are TRACE.*.dump.gz (inputs/observe/dump.lmp)
#   OUT         OUT/surface: `granpen flow --voronoi none` over every frame (the tip's depth
#               per frame, and the surface flux of the near-shaft strip against t~);
#               OUT/flow: `granpen flow --rod-cells` over the frames with the tip ZLO to ZHI
#               cm deep (the fields, the profile below the rod, phi against I at the edge);
#               OUT/momentum: `granpen momentum` over every frame; OUT/surface.txt,
#               OUT/flow/flow.txt, OUT/momentum.txt: what they printed; OUT/window.txt:
#               the window's steps FIRST:LAST and its depths
#   --tip       the depth window of the tip, cm (default "1 4": past the impact, and for
#               the mid and dg10 beds at least 4 cm, 13 and 20 grains, above the floor,
#               which would stop the flow below the rod and shorten its decay)
# Prints the window's steps (FIRST:LAST) on stdout; exits non-zero, naming the step, when a
# command fails or no frame has its tip in the window.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
CLI=${GRANPEN_CLI:-$ROOT/build/analysis/granpen-cli} TIP="1 4"
[ $# -ge 2 ] || { echo "push_flow.sh: usage: push_flow.sh TRACE OUT [--cli PATH] [--tip \"ZLO ZHI\"]" >&2; exit 2; }
TRACE=$1 OUT=$2; shift 2
while [ $# -gt 0 ]; do
  case $1 in
    --cli) CLI=$2; shift 2 ;;
    --tip) TIP=$2; shift 2 ;;
    *) echo "push_flow.sh: unknown argument $1 (see the header of $0)" >&2; exit 2 ;;
  esac
done
read -r ZLO ZHI <<< "$TIP"
[[ $ZLO =~ ^[0-9.]+$ && $ZHI =~ ^[0-9.]+$ ]] || { echo "push_flow.sh: --tip \"$TIP\" is not two depths in cm" >&2; exit 2; }
[ -f "$TRACE" ] || { echo "push_flow.sh: no trace $TRACE" >&2; exit 2; }
shopt -s nullglob
dumps=("$TRACE".*.dump.gz)
[ ${#dumps[@]} -gt 0 ] || { echo "push_flow.sh: no dumps $TRACE.*.dump.gz" >&2; exit 2; }
mkdir -p "$OUT"
echo "push_flow.sh: ${#dumps[@]} frames of $TRACE (granpen flow, granpen momentum)" >&2

# every frame without tessellation first: the tip's depth per frame, and the surface flux
# (v_z of the top grain layer 0.5-1.5 cm from the shaft) against t~ with its sign change
"$CLI" flow "${dumps[@]}" --trace "$TRACE" --voronoi none --out "$OUT/surface" > "$OUT/surface.txt" \
  || { echo "push_flow.sh: granpen flow --voronoi none failed (see $OUT/surface.txt)" >&2; exit 1; }
steps=$("$CLI" get "$OUT/surface/flow.json" 'frames[*].timestep' 'frames[*].z_tip' |
        awk -v lo="$ZLO" -v hi="$ZHI" '$2 >= lo && $2 <= hi { if (!a) a = $1; b = $1 } END { if (a) print a ":" b }')
[ -n "$steps" ] || { echo "push_flow.sh: no frame of $TRACE has its tip $ZLO to $ZHI cm deep ($OUT/surface/flow.json)" >&2; exit 1; }
# --rod-cells: the rod's spheres bound the grains' Voronoi cells (phi at the rod edge)
mkdir -p "$OUT/flow"
"$CLI" flow "${dumps[@]}" --trace "$TRACE" --rod-cells --steps "$steps" --out "$OUT/flow" > "$OUT/flow/flow.txt" \
  || { echo "push_flow.sh: granpen flow --rod-cells --steps $steps failed (see $OUT/flow/flow.txt)" >&2; exit 1; }
"$CLI" momentum "${dumps[@]}" --trace "$TRACE" --out "$OUT/momentum" > "$OUT/momentum.txt" \
  || { echo "push_flow.sh: granpen momentum failed (see $OUT/momentum.txt)" >&2; exit 1; }
echo "$steps $ZLO $ZHI" > "$OUT/window.txt.partial" && mv "$OUT/window.txt.partial" "$OUT/window.txt"
echo "$steps"
