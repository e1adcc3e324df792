#!/usr/bin/env bash
# The box series (issue: physics in the paper's box), as campaigns of validation/campaign.sh
# (its header says how units are cut, committed and resumed):
#   bench   bench grains (D/d_g = 5) in boxes of 8, 12, 16 and 20 cm, 2 x 2 to 5 x 5 copies of
#           the committed 4 cm bench tiles (data/sims/tile_bench, seeds 11 and 12, linked from
#           data/sims/box_bench/beds): per box the peak sweep (five speeds, two beds, 1.5 cm)
#           and one flow push with dumps (50 cm/s, 4 cm); the widest and narrowest boxes
#           first, so that the trend shows before the whole series is in. About 1.5
#           core-hours in all (docs/presets.md, "The box series"). Then alpha against D in
#           the 8 and 20 cm boxes: D = 1, 2, 3 cm at 28 cm/s, 4 cm deep, two beds (about
#           2.2e10 atom-steps, 1.7 core-hours), each followed by the same pushes of D = 1
#           and 2 cm with a frictionless shaft (box_bench{8,20}_shaft: beds rebuilt with the
#           shaft's atom type, mu_shaft 0; 1.5e10 atom-steps, 1.2 core-hours).
#
#   validation/box.sh bench [--out DIR] [--units N] [--ranks N] [--commit] [--status]
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
S=$ROOT/inputs/sweeps
[ $# -ge 1 ] || { echo "box.sh: usage: validation/box.sh bench [options of campaign.sh]" >&2; exit 2; }
series=$1; shift
case $series in
  bench)
    sweeps=""
    for kind in peak flow; do for b in 8 20 12 16; do sweeps="$sweeps $S/box_bench${b}_$kind.sweep"; done; done
    for b in 8 20; do sweeps="$sweeps $S/box_bench${b}_D.sweep $S/box_bench${b}_shaft.sweep"; done
    exec "$ROOT/validation/campaign.sh" --data "$ROOT/data/sims/box_bench" --sweeps "${sweeps# }" --tip "1 3" "$@" ;;
  *) echo "box.sh: no series '$series' (bench)" >&2; exit 2 ;;
esac
