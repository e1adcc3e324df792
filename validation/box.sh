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
#           shaft's atom type, mu_shaft 0; 1.5e10 atom-steps, 1.2 core-hours). Last, the
#           arrival pushes in the 16 cm box (box_bench16_arrival: 0.6 cm at the four speeds
#           above v_c, two beds, with observe/arrival.lmp; 3e9 atom-steps, minutes), and
#           the same with the rings at 2, 4 and 6 cm (box_bench16_arrival_far). Then a 4 cm
#           rod in the 20 cm box (box_bench20_D4: 28 cm/s, 4 cm, two beds; about 1 core-hour),
#           the test of a term at the tip's rim (docs/results.md, "How F_z grows with D"); and
#           the 20 cm box's flow push with rods of 1 and 4 cm (box_bench20_flow_D: lambda_vz
#           against D; two pushes with dumps, about half a core-hour).
#
#   dg10    the paper's box at the paper's grain size ratio: 20 cm beds of 4 x 4 copies of the
#           three committed 5 cm dg10 tiles (data/sims/dg10/beds, linked from
#           data/sims/dg10_box20/beds; 535392 grains, rebuilt in seconds, not a unit): peak
#           pushes 1.5 cm deep at 200 cm/s on beds 1 to 3, then 140 and 80, then 40 and 20 on
#           bed 1, then 40 on beds 2 and 3 (dg10_box20_peak{1,2,3,4}.sweep, one folder: the
#           pushes that fit one session first, since a session's machine may not outlive it);
#           D = 1, 2, 3 cm at 100 cm/s to 5 cm (dg10_box20_D); D = 1 and 2 cm with a
#           frictionless shaft (dg10_box20_shaft); the 40 cm/s flow push with dumps
#           (dg10_box20_flow: 5.5 hours at 2 ranks, after the pushes at 100 cm/s, 2.2 to 2.6
#           hours each, which a session finishes alone); last 20 cm/s on beds 2 and 3
#           (dg10_box20_peak5: the issue's "if the first show a change", which bed 1's 20 cm/s
#           push answers). 21 pushes, 9.8e11 atom-steps: about
#           76 hours of one core at 3.6e6 atom-steps/s, units of 0.7 to 11 hours (docs/presets.md,
#           "The paper's box"): a push cut by the end of a session resumes from its last
#           checkpoint (every 1000 steps, in the run folder, not committed) when the next run of
#           box.sh dg10 finds it there. 1000, not the sweep's 5000: a 535k-grain step is 0.15 s
#           of a core alone and up to 1 s niced beside other work, so 5000 steps lost up to 1.5
#           hours at a session's end; a 200 MB checkpoint every 1000 steps costs a few seconds.
#
#   validation/box.sh bench|dg10 [--out DIR] [--units N] [--ranks N] [--commit] [--status]
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
S=$ROOT/inputs/sweeps
[ $# -ge 1 ] || { echo "box.sh: usage: validation/box.sh bench|dg10 [options of campaign.sh]" >&2; exit 2; }
series=$1; shift
case $series in
  bench)
    sweeps=""
    for kind in peak flow; do for b in 8 20 12 16; do sweeps="$sweeps $S/box_bench${b}_$kind.sweep"; done; done
    for b in 8 20; do sweeps="$sweeps $S/box_bench${b}_D.sweep $S/box_bench${b}_shaft.sweep"; done
    sweeps="$sweeps $S/box_bench16_arrival.sweep $S/box_bench16_arrival_far.sweep $S/box_bench20_D4.sweep $S/box_bench20_flow_D.sweep"
    exec "$ROOT/validation/campaign.sh" --data "$ROOT/data/sims/box_bench" --sweeps "${sweeps# }" --tip "1 3" "$@" ;;
  dg10)
    sweeps=""
    for part in peak1 peak2 peak3 peak4 D shaft flow peak5; do sweeps="$sweeps $S/dg10_box20_$part.sweep"; done
    # the flow analysis as the 10 cm box's (validation/dg10.sh: the tip 1 to 4 cm deep)
    exec "$ROOT/validation/campaign.sh" --data "$ROOT/data/sims/dg10_box20" --sweeps "${sweeps# }" --tip "1 4" --checkpoint 1000 "$@" ;;
  *) echo "box.sh: no series '$series' (bench, dg10)" >&2; exit 2 ;;
esac
