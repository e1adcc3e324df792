#!/usr/bin/env bash
# The depth-term checks (depth_term_D.sh) fail where F_z ~ D^2: on stand-ins made of the
# committed rods of the 20 cm bench box.
#  - the rods as committed pass;
#  - every rod of 2, 3 and 4 cm made of its bed's 1 cm push with F times D^2 (F_z ~ D^2 at
#    every D, exactly) fails check 1: p = 2;
#  - the 1 cm rods as committed, the 3 and 4 cm rods made of their bed's 2 cm push with F
#    times (D / 2)^2 (the excess the thin rod's alone) fail check 2: p over 2 to 4 cm = 2.
#   depth_term_D_can_fail.sh CLI SOURCE_DIR WORK_DIR
set -euo pipefail
CLI=$1 SRC=$2 WORK=$3
HERE=$SRC/tests/validation B=$SRC/data/sims/box_bench
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$WORK" && mkdir -p "$WORK"
. "$HERE/can_fail_lib.sh"
expect() { expect_exit depth_term_D.sh "$1" "$2" "$HERE/depth_term_D.sh" "$CLI" "$3" "$WORK/run"; }    # RC PATTERN ROOT
expect 0 "depth_term_D: F_z grows slower than D^2" "$SRC"

# scaled SRC D FACTOR OUT: SRC with header D and F times FACTOR
scaled() { awk -F, -v D="$2" -v k="$3" 'BEGIN { OFS = "," } /^# D = / { print "# D = " D; next } /^#/ { print; next }
  !h { for (i = 1; i <= NF; i++) col[$i] = i; h = 1; print; next } { $col["F"] = $col["F"] * k; print }' "$1" > "$4"; }
stand_in() { # FROM_D: rods of D > FROM_D made of the FROM_D push, F times (D / FROM_D)^2
  local t=$WORK/tree/data/sims/box_bench s D
  rm -rf "$WORK/tree"; mkdir -p "$t/box_bench20_D" "$t/box_bench20_D4"
  cp "$B"/box_bench20_D/*.csv "$t/box_bench20_D/"; cp "$B"/box_bench20_D4/*.csv "$t/box_bench20_D4/"
  for s in 11 12; do
    for D in 2 3 4; do
      [ "$D" -gt "$1" ] || continue
      dir=box_bench20_D; [ "$D" = 4 ] && dir=box_bench20_D4
      scaled "$B/box_bench20_D/bench_mu0.3_s${s}_v28_g981_D$1.0.csv" "$D" "$(awk -v D="$D" -v d="$1" 'BEGIN { print (D / d) ^ 2 }')" \
        "$t/$dir/bench_mu0.3_s${s}_v28_g981_D$D.0.csv"
    done
  done
}
stand_in 1
expect 1 "FAIL: 1. p over 1 to 4 cm = 2 " "$WORK/tree"
stand_in 2
expect 1 "FAIL: 2. p over 2 to 4 cm = 2 " "$WORK/tree"
echo "depth_term_D_can_fail: all checks passed"
