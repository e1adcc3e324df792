# The first-contact checks' shared bookkeeping, sourced by box_first_contact.sh and
# dg10_box20_first_contact.sh (one definition of the mean, the two spreads and the verdict):
# each script pairs its own traces (which boxes, beds and speeds), then records
#   fc_bed A C          the bed-to-bed relative difference |2 (A - C) / (A + C)| of two means;
#   fc_box QW QN LABEL  the box's |QW / QN - 1|, printing "LABEL = QW / QN" (fc_r: the difference);
# and ends with fc_verdict WHAT: the RMS and the largest of each, one line, and the two checks:
#  1. the box's RMS below half the beds' (half: "within the spread over beds", and a box effect
#     half of it would already show in a few pairs);
#  2. no single pair beyond the largest bed-to-bed difference.
# (sourced, not run: no shebang, no set -e of its own; the callers set -euo pipefail)

fail() { echo "FAIL: $*"; exit 1; }

# mean F over 0 < z <= 0.5 cm of a trace (granpen-trace v1: t,z,F after the header)
fc_mean() { awk -F, '/^#/ || $1 == "t" { next } $2 > 0 && $2 <= 0.5 { s += $3; n++ } END { if (n == 0) exit 1; printf "%.10g\n", s / n }' "$1"; }

# mean F over ZLO <= z < ZHI of a trace (fc_window_mean ZLO ZHI FILE): the deeper windows
# the dg10 check prints beside its verdict
fc_window_mean() { awk -F, -v lo="$1" -v hi="$2" '/^#/ || $1 == "t" { next } $2 >= lo && $2 < hi { s += $3; n++ } END { if (n == 0) exit 1; printf "%.3g\n", s / n }' "$3"; }

# the largest F of a trace and its depth: "F at z"
fc_peak() { awk -F, '/^#/ || $1 == "t" { next } n == 0 || $3 > m { m = $3; z = $2; n = 1 } END { if (n == 0) exit 1; printf "%.3g at %.2f\n", m, z }' "$1"; }

fc_box_sq=0 fc_box_n=0 fc_box_max=0 fc_bed_sq=0 fc_bed_n=0 fc_bed_max=0 fc_r=0

fc_bed() {
  local r
  r=$(awk -v a="$1" -v c="$2" 'BEGIN { d = 2 * (a - c) / (a + c); print (d < 0 ? -d : d) }')
  fc_bed_sq=$(awk -v s="$fc_bed_sq" -v r="$r" 'BEGIN { print s + r * r }') fc_bed_n=$((fc_bed_n + 1))
  fc_bed_max=$(awk -v m="$fc_bed_max" -v r="$r" 'BEGIN { print (r > m ? r : m) }')
}

fc_box() {
  fc_r=$(awk -v a="$1" -v b="$2" 'BEGIN { d = a / b - 1; print (d < 0 ? -d : d) }')
  echo "$3 = $(awk -v a="$1" -v b="$2" 'BEGIN { printf "%.5f", a / b }')"
  fc_box_sq=$(awk -v s="$fc_box_sq" -v r="$fc_r" 'BEGIN { print s + r * r }') fc_box_n=$((fc_box_n + 1))
  fc_box_max=$(awk -v m="$fc_box_max" -v r="$fc_r" 'BEGIN { print (r > m ? r : m) }')
}

# fc_verdict WHAT: WHAT names the box in the summary line ("the box", "the 20 cm box")
fc_verdict() {
  local box_rms bed_rms
  box_rms=$(awk -v s="$fc_box_sq" -v n="$fc_box_n" 'BEGIN { printf "%.4f", sqrt(s / n) }')
  bed_rms=$(awk -v s="$fc_bed_sq" -v n="$fc_bed_n" 'BEGIN { printf "%.4f", sqrt(s / n) }')
  echo "first 0.5 cm: $1 changes the mean drag by $box_rms RMS (largest $fc_box_max) over $fc_box_n pairs; the bed by $bed_rms RMS (largest $fc_bed_max) over $fc_bed_n"
  awk -v a="$box_rms" -v b="$bed_rms" 'BEGIN { exit !(a < 0.5 * b) }' || fail "the box moves the first contact by $box_rms RMS, not below half the beds' $bed_rms"
  awk -v a="$fc_box_max" -v b="$fc_bed_max" 'BEGIN { exit !(a <= b) }' || fail "one pair differs by $fc_box_max, more than the largest bed difference $fc_bed_max"
  echo "the first contact does not depend on the box (within the spread over beds)"
}
