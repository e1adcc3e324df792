#!/usr/bin/env bash
# The paper's box at dg10 (issue: physics in the paper's box): each committed dg10 tile
# (data/sims/dg10/beds, 33462 grains, 5 cm) rebuilt 4 x 4 into the 20 cm bed that
# validation/box.sh dg10 pushes (in.pour -var tile 4 -var box 20 -var surface_grid 8, as
# inputs/sweeps/dg10_box20_*.sweep set it), against the 2 x 2 bed of the same tile, whose
# .info was written when the tile was poured (the 10 cm box's own bed):
#  1. grains: 16 x the tile's, 4 x the 10 cm bed's (535392 for every tile);
#  2. z_s and phi_0 on 2.5 cm columns (8 x 8 on the 20 cm box, 4 x 4 on the 10 cm one): the
#     same columns, each four times, so the 10 cm bed's values. z_s to 1e-12 relative (each
#     column's top is one grain's, bit-identical through write_data/read_data, and the mean
#     of 64 copies of 16 values rounds like the mean of the 16); phi_0 to 1e-10: a volume
#     summed over 4 x as many grains in another order, whose rounding grows at most as
#     N eps = 535392 x 1.1e-16 = 6e-11 (measured: 1.9e-12 on each tile). A lost, doubled or
#     shifted tile moves them by 1/16 of a tile's share or more;
#  3. the 2 x 2 bed rebuilt today from the same tile has the committed .info's z_s and phi_0
#     (1e-12, the same summation as at the pour): the decks still make the 10 cm bed.
# At tiny scale tests/inputs/tile_rebuild.sh checks the same 2 x 2 -> 4 x 4 replication; this
# one runs on the committed tiles themselves: about 30 s and 600 MB of memory per tile, and a
# 180 MB restart, removed after each (hence the label slow).
#   dg10_box20_bed.sh LMP_GRANPEN INPUTS DG10_BEDS WORKDIR [SEEDS]
set -euo pipefail
LMP=$1 INPUTS=$2 BEDS=$3 WORK=$4 SEEDS=${5:-1 2 3}
mkdir -p "$WORK"; cd "$WORK"
fail() { echo "FAIL: $*"; exit 1; }
info() { awk -F' = ' -v k="$2" '$1 == k {print $2}' "$1"; }
# |a - b| <= rtol * |b|
close() { awk -v a="$1" -v b="$2" -v r="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; m = (b < 0 ? -b : b); exit !(d <= r * m) }'; }
for s in $SEEDS; do
  stem=$BEDS/bed_dg10_mu0.3_s$s bed=$BEDS/bed_dg10_mu0.3_s$s.info
  [ -f "$stem.tile.data.gz" ] && [ -f "$bed" ] || fail "no committed tile or bed .info for seed $s in $BEDS"
  rm -f wide$s.* narrow$s.*
  "$LMP" -in "$INPUTS/in.pour" -var inputs "$INPUTS" -var preset dg10 -var tile 4 -var box 20 -var surface_grid 8 \
    -var from_tile "$stem" -var out wide$s -log wide$s.log -screen none >/dev/null || fail "the 4 x 4 rebuild of tile $s failed (wide$s.log)"
  "$LMP" -in "$INPUTS/in.pour" -var inputs "$INPUTS" -var preset dg10 -var from_tile "$stem" \
    -var out narrow$s -log narrow$s.log -screen none >/dev/null || fail "the 2 x 2 rebuild of tile $s failed (narrow$s.log)"
  rm -f wide$s.restart narrow$s.restart
  echo "tile $s: 20 cm bed $(info wide$s.info grains) grains, z_s $(info wide$s.info z_s), phi_0 $(info wide$s.info phi_0);" \
    "10 cm bed (committed) $(info "$bed" grains), z_s $(info "$bed" z_s), phi_0 $(info "$bed" phi_0)"
  [ "$(info wide$s.info grains)" = $((16 * $(info "$stem.tile.info" grains))) ] && [ "$(info wide$s.info grains)" = $((4 * $(info "$bed" grains))) ] \
    || fail "tile $s: the 20 cm bed has $(info wide$s.info grains) grains, not 16 x the tile's and 4 x the 10 cm bed's"
  [ "$(info wide$s.info box)" = 20 ] && [ "$(info wide$s.info tile)" = 4 ] || fail "tile $s: wide$s.info lacks box = 20, tile = 4"
  close "$(info wide$s.info z_s)" "$(info "$bed" z_s)" 1e-12 || fail "tile $s: z_s of the 20 cm bed $(info wide$s.info z_s) is not the 10 cm bed's $(info "$bed" z_s)"
  close "$(info wide$s.info phi_0)" "$(info "$bed" phi_0)" 1e-10 || fail "tile $s: phi_0 of the 20 cm bed $(info wide$s.info phi_0) is not the 10 cm bed's $(info "$bed" phi_0)"
  for k in z_s phi_0; do
    close "$(info narrow$s.info $k)" "$(info "$bed" $k)" 1e-12 || fail "tile $s: the 10 cm bed rebuilt today has $k $(info narrow$s.info $k), not the committed $(info "$bed" $k)"
  done
done
echo "dg10 20 cm beds hold"
