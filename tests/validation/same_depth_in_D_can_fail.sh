#!/usr/bin/env bash
# The same-depth-in-D check (same_depth_in_D.sh) fails where the thin rod's excess is the
# depth over D: on stand-ins made of the committed pushes.
#  - the pushes as committed pass;
#  - in each setting alone, each 1 cm push replaced by its bed's 2 cm push scaled by the law
#    the suspect stands for, F = D^3 f(z / D) (t and z halved, F divided by 8, header D = 1),
#    fails check 2 in that setting: its ratio over z = D to 2 D is 1 (the stand-in's rows are
#    the 2 cm push's, so each sum is the 2 cm rod's over four: exactly 1, to round-off).
#   same_depth_in_D_can_fail.sh CLI SOURCE_DIR WORK_DIR
set -euo pipefail
CLI=$1 SRC=$2 WORK=$3
HERE=$SRC/tests/validation S=$SRC/data/sims
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$WORK" && mkdir -p "$WORK"
. "$HERE/can_fail_lib.sh"
expect() { expect_exit same_depth_in_D.sh "$1" "$2" "$HERE/same_depth_in_D.sh" "$CLI" "$3" "$WORK/run"; }    # RC PATTERN ROOT
expect 0 "in 6 of 6 settings" "$SRC"

# the 1 cm push of F = D^3 f(z / D) made of a 2 cm push: scaled TWO OUT
scaled() { awk -F, 'BEGIN { OFS = "," } /^# D = / { print "# D = 1"; next } /^#/ { print; next }
  !h { for (i = 1; i <= NF; i++) col[$i] = i; h = 1; print; next }
  { $col["t"] = $col["t"] / 2; $col["z"] = $col["z"] / 2; $col["F"] = $col["F"] / 8; print }' "$1" > "$2"; }
# stand_in NAME REL2:REL1...: a tree holding only this setting, each REL1 (path under
# data/sims of a 1 cm push) made of REL2 (its bed's 2 cm push)
stand_in() {
  local name=$1 pair t=$WORK/tree; shift
  rm -rf "$t"
  for pair in "$@"; do
    mkdir -p "$t/data/sims/$(dirname "${pair%%:*}")" "$t/data/sims/$(dirname "${pair##*:}")"
    cp "$S/${pair%%:*}" "$t/data/sims/${pair%%:*}"
    scaled "$S/${pair%%:*}" "$t/data/sims/${pair##*:}"
  done
  expect 1 "FAIL: 2. $name: alpha(1 cm) / alpha(2 cm) over z = D to 2 D is 1.000 +-" "$t"
}
vb=validation_bench/bench_mu0.3 vm=validation_mid/mid_mu0.3
stand_in bench "${vb}_s1_v28_g981_D2.0.csv:${vb}_s1_v28_g981_D1.0.csv" "${vb}_s2_v28_g981_D2.0.csv:${vb}_s2_v28_g981_D1.0.csv"
stand_in mid "${vm}_s1_v90_g981_D2.0.csv:${vm}_s1_v90_g981_D1.0.csv" "${vm}_s2_v90_g981_D2.0.csv:${vm}_s2_v90_g981_D1.0.csv"
stand_in dg10 "dg10/dg10_flow/dg10_mu0.3_s1_v100_g981_D2.0.csv:dg10/dg10_D/dg10_mu0.3_s1_v100_g981_D1.0.csv"
stand_in "dg10, 20 cm box" "dg10_box20/dg10_box20_D/dg10_mu0.3_s1_v100_g981_D2.0.csv:dg10_box20/dg10_box20_D/dg10_mu0.3_s1_v100_g981_D1.0.csv"
for b in 8 20; do
  p=box_bench/box_bench${b}_D/bench_mu0.3
  stand_in "bench, $b cm box" "${p}_s11_v28_g981_D2.0.csv:${p}_s11_v28_g981_D1.0.csv" "${p}_s12_v28_g981_D2.0.csv:${p}_s12_v28_g981_D1.0.csv"
done
echo "same_depth_in_D_can_fail: all checks passed"
