#!/usr/bin/env bash
# The box series' first contact (issue: physics in the paper's box, "checks that can fail"):
# the box should matter for the flow, not for the rod's first contact with the bed. On the
# committed peak sweeps (data/sims/box_bench), the mean drag over the first 0.5 cm of each
# push in a wide box against the push of the same bed and speed in the box 8 cm narrower:
# 16 cm against 8 cm and 20 cm against 12 cm, the pairs that put the same grains under the
# rod (it stands at the box's centre: a tile corner in the 8 and 16 cm boxes, a tile centre
# in the 12 and 20 cm ones). Must hold:
#  1. the box moves that mean by less than the bed does: the RMS over pairs, beds and speeds
#     of Q_wide / Q_narrow - 1 is below half the RMS over boxes and speeds of the relative
#     difference between the two beds (half: the issue asks "within the spread over beds",
#     and a box effect half the bed-to-bed spread would already be visible in 20 pairs);
#  2. no single pair differs by more than the largest bed-to-bed difference;
#  3. at the fastest speed (280 cm/s: 0.5 cm in 1.8 ms, 900 steps) the pairs agree to 1e-3
#     relative: the same grains and the same rod; only the far field differs, and the
#     contact sums' round-off (another neighbour order) grows through the chaotic contacts
#     (measured: 3 of 4 pairs identical to the 7 digits the traces print, one 5e-5 apart;
#     the bed-to-bed difference is 14 to 25%).
# A part of the series not committed yet skips the test (exit 77). The bookkeeping (means,
# spreads, checks 1 and 2) is first_contact_lib.sh's, shared with dg10_box20_first_contact.sh.
#   box_first_contact.sh DATA
set -euo pipefail
DATA=$1
. "$(dirname "$0")/first_contact_lib.sh"
for b in 8 12 16 20; do
  n=$( (ls "$DATA"/box_bench${b}_peak/bench_mu0.3_s1[12]_v*_g981_D2.0.csv 2>/dev/null || true) | wc -l)
  [ "$n" = 10 ] || { echo "box $b cm: $n of 10 peak pushes committed: skipped"; exit 77; }
done
for v in 28 50 100 200 280; do
  for b in 8 12 16 20; do
    a=$(fc_mean "$DATA/box_bench${b}_peak/bench_mu0.3_s11_v${v}_g981_D2.0.csv") c=$(fc_mean "$DATA/box_bench${b}_peak/bench_mu0.3_s12_v${v}_g981_D2.0.csv")
    fc_bed "$a" "$c"
  done
  for pair in 16:8 20:12; do
    w=${pair%%:*} n=${pair##*:}
    for s in 11 12; do
      qw=$(fc_mean "$DATA/box_bench${w}_peak/bench_mu0.3_s${s}_v${v}_g981_D2.0.csv") qn=$(fc_mean "$DATA/box_bench${n}_peak/bench_mu0.3_s${s}_v${v}_g981_D2.0.csv")
      fc_box "$qw" "$qn" "v0 $v, bed $s: $w cm / $n cm"
      [ "$v" != 280 ] || awk -v r="$fc_r" 'BEGIN { exit !(r <= 1e-3) }' ||
        fail "v0 280, bed $s: the $w cm box's first 0.5 cm differs from the $n cm box's by $fc_r (same grains, same first steps)"
    done
  done
done
fc_verdict "the box"
