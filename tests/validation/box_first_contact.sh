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
# A part of the series not committed yet skips the test (exit 77).
#   box_first_contact.sh DATA
set -euo pipefail
DATA=$1
fail() { echo "FAIL: $*"; exit 1; }
# mean F over 0 < z <= 0.5 cm of a trace (granpen-trace v1: t,z,F after the header)
q() { awk -F, '/^#/ || $1 == "t" { next } $2 > 0 && $2 <= 0.5 { s += $3; n++ } END { if (n == 0) exit 1; printf "%.10g\n", s / n }' "$1"; }
for b in 8 12 16 20; do
  n=$( (ls "$DATA"/box_bench${b}_peak/bench_mu0.3_s1[12]_v*_g981_D2.0.csv 2>/dev/null || true) | wc -l)
  [ "$n" = 10 ] || { echo "box $b cm: $n of 10 peak pushes committed: skipped"; exit 77; }
done
box_sq=0 box_n=0 box_max=0 bed_sq=0 bed_n=0 bed_max=0
for v in 28 50 100 200 280; do
  for b in 8 12 16 20; do
    a=$(q "$DATA/box_bench${b}_peak/bench_mu0.3_s11_v${v}_g981_D2.0.csv") c=$(q "$DATA/box_bench${b}_peak/bench_mu0.3_s12_v${v}_g981_D2.0.csv")
    r=$(awk -v a="$a" -v c="$c" 'BEGIN { d = 2 * (a - c) / (a + c); print (d < 0 ? -d : d) }')
    bed_sq=$(awk -v s="$bed_sq" -v r="$r" 'BEGIN { print s + r * r }') bed_n=$((bed_n + 1))
    bed_max=$(awk -v m="$bed_max" -v r="$r" 'BEGIN { print (r > m ? r : m) }')
  done
  for pair in 16:8 20:12; do
    w=${pair%%:*} n=${pair##*:}
    for s in 11 12; do
      qw=$(q "$DATA/box_bench${w}_peak/bench_mu0.3_s${s}_v${v}_g981_D2.0.csv") qn=$(q "$DATA/box_bench${n}_peak/bench_mu0.3_s${s}_v${v}_g981_D2.0.csv")
      r=$(awk -v a="$qw" -v b="$qn" 'BEGIN { d = a / b - 1; print (d < 0 ? -d : d) }')
      echo "v0 $v, bed $s: $w cm / $n cm = $(awk -v a="$qw" -v b="$qn" 'BEGIN { printf "%.5f", a / b }')"
      box_sq=$(awk -v s="$box_sq" -v r="$r" 'BEGIN { print s + r * r }') box_n=$((box_n + 1))
      box_max=$(awk -v m="$box_max" -v r="$r" 'BEGIN { print (r > m ? r : m) }')
      [ "$v" != 280 ] || awk -v r="$r" 'BEGIN { exit !(r <= 1e-3) }' ||
        fail "v0 280, bed $s: the $w cm box's first 0.5 cm differs from the $n cm box's by $r (same grains, same first steps)"
    done
  done
done
box_rms=$(awk -v s="$box_sq" -v n="$box_n" 'BEGIN { printf "%.4f", sqrt(s / n) }')
bed_rms=$(awk -v s="$bed_sq" -v n="$bed_n" 'BEGIN { printf "%.4f", sqrt(s / n) }')
echo "first 0.5 cm: the box changes the mean drag by $box_rms RMS (largest $box_max) over $box_n pairs; the bed by $bed_rms RMS (largest $bed_max) over $bed_n"
awk -v a="$box_rms" -v b="$bed_rms" 'BEGIN { exit !(a < 0.5 * b) }' || fail "the box moves the first contact by $box_rms RMS, not below half the beds' $bed_rms"
awk -v a="$box_max" -v b="$bed_max" 'BEGIN { exit !(a <= b) }' || fail "one pair differs by $box_max, more than the largest bed difference $bed_max"
echo "the first contact does not depend on the box (within the spread over beds)"
