#!/usr/bin/env bash
# The parting checks (box_parting.sh) fail when the boxes do not part as an echo would part
# them: on stand-ins made of the committed bench box series.
#  - the series as committed passes;
#  - the 12 and 20 cm boxes replaced by the 8 and 16 cm ones (an effect that does not scale
#    with the width) fails check 2: the 12 cm box does not part after the 8 cm box;
#  - each narrow box's push made of its wide twin with the drag 20% higher from a fixed depth
#    past contact on (0.4 cm in the 8 cm box, 0.6 cm in the 12 cm one: a front reaching the
#    boundary at a depth in proportion to the width) passes checks 1 to 3 and fails check 4:
#    its partings go as v0^-1;
#  - the narrow boxes' pushes made to part at 1 and 1.5 ms after contact whatever the speed
#    (the widths' ratio, at a time) pass checks 1 to 4 and fail check 5: sooner than the
#    rod's first front could have been to the boundary and back.
#   box_parting_can_fail.sh CLI SOURCE_DIR WORK_DIR
set -euo pipefail
CLI=$1 SRC=$2 WORK=$3
HERE=$SRC/tests/validation BOX=$SRC/data/sims/box_bench
DG10=$SRC/data/sims/dg10/dg10_peak DG10BOX=$SRC/data/sims/dg10_box20/dg10_box20_peak
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$WORK" && mkdir -p "$WORK"
. "$HERE/can_fail_lib.sh"
# expect RC PATTERN BOX_DIR: box_parting.sh on BOX_DIR exits RC and prints PATTERN
expect() { expect_exit box_parting.sh "$1" "$2" "$HERE/box_parting.sh" "$CLI" "$3" "$DG10" "$DG10BOX" "$WORK/run"; }
expect 0 "the boxes part at a time set by the narrower box's width" "$BOX"

mkdir -p "$WORK/same"
for b in 8 16; do cp -r "$BOX/box_bench${b}_peak" "$WORK/same/"; done
cp -r "$BOX/box_bench8_peak" "$WORK/same/box_bench12_peak"
cp -r "$BOX/box_bench16_peak" "$WORK/same/box_bench20_peak"
expect 1 "FAIL: v0 50, bed 11: the 12 cm box parts at" "$WORK/same"

# stepped WIDE COLUMN FROM OUT: the trace with F times 1.2 from FROM past its contact on, in
# depth (COLUMN 2, cm) or in time (COLUMN 1, s)
stepped() { awk -F, -v c="$2" -v d="$3" 'BEGIN { OFS = "," } /^#/ || $1 == "t" { print; next }
  !on && $3 > 0 { on = 1; x0 = $c } on && $c >= x0 + d - 1e-9 { $3 = $3 * 1.2 } { print }' "$1" > "$4"; }
# stand_in DIR COLUMN FROM8 FROM12: the wide boxes as committed, each narrow box's push its
# wide twin stepped from FROM8 (8 cm box) or FROM12 (12 cm box), the far rings as committed
stand_in() {
  local f
  rm -rf "$1" && mkdir -p "$1" && cp -r "$BOX/box_bench16_arrival_far" "$1/"
  for b in 8 12 16 20; do mkdir -p "$1/box_bench${b}_peak"; done
  for f in "$BOX"/box_bench16_peak/*.csv; do
    cp "$f" "$1/box_bench16_peak/" && stepped "$f" "$2" "$3" "$1/box_bench8_peak/$(basename "$f")"
  done
  for f in "$BOX"/box_bench20_peak/*.csv; do
    cp "$f" "$1/box_bench20_peak/" && stepped "$f" "$2" "$4" "$1/box_bench12_peak/$(basename "$f")"
  done
}
stand_in "$WORK/depth" 2 0.4 0.6
# (check 4 runs after checks 1 to 3: its failure says they passed)
expect 1 "FAIL: the 8 cm pair parts at a depth" "$WORK/depth"
# partings at 1 and 1.5 ms whatever the speed: the widths' ratio and a time, so checks 1 to
# 4 pass, but sooner than any front could be back from the boundary
stand_in "$WORK/early" 1 1.0e-3 1.5e-3
expect 1 "before an echo could be back" "$WORK/early"
echo "box_parting_can_fail: all checks passed"
