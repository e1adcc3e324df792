#!/usr/bin/env bash
# in.pour -var tile 2: a tiny bed poured as one 3 x 3 cm tile and replicated 2 x 2, then
# rebuilt from the tile's data file alone (-var from_tile), as a later session rebuilds the
# committed dg10 beds (docs/presets.md, "dg10"). Checks, each of which a broken tile path fails:
#  1. grains: the bed holds exactly 4 x the tile's grains, and as many as the direct tiny
#     fill (1936): the tile fill keeps the direct fill's grains per area.
#  2. replication, by an independent measure: compute bed/surface on the bed with an 8 x 8
#     grid has columns of 0.75 cm, the tile's own 4 x 4 columns, and each bed column is a
#     copy of a tile column; so its z_s must be the tile's z_s (in NAME.tile.info, measured
#     before the data file was written) and its phi_0 the tile's (4 x the volume over 4 x
#     the area). A lost, doubled or shifted tile, or diameters halved on the way, move
#     these by 1/484 or more. Tolerance 1e-12 relative: the data file holds each number in
#     its shortest exact decimal (write_data), so positions and diameters come back
#     bit-identical, and what is left is the order of the volume sum (measured: equal to the
#     15 digits printed). Also the grains' mean density, mass over volume: rho_g = 3 to 1e-12
#     (read_data turns densities back into masses; a few ulp).
#  3. the rebuild from the data file (from_tile) gives the poured bed's grains, z_s and
#     phi_0 (NAME.info of each) to 1e-12 relative, for the same reason (both are built from
#     the same file; this checks that from_tile reads the tile and its info as written).
#  4. refusals: from_tile of another mu, and of a stem with no tile, end with a named
#     ERROR and exit status 1, writing no bed.
#   tile_rebuild.sh LMP_GRANPEN INPUTS WORKDIR
set -euo pipefail
LMP=$1 INPUTS=$2 WORK=$3
mkdir -p "$WORK"; cd "$WORK"
rm -f tile.* rebuilt.* refused.* check.*
fail() { echo "FAIL: $*"; exit 1; }
info() { awk -F' = ' -v k="$2" '$1 == k {print $2}' "$1"; }
# |a - b| <= rtol * |b|
close() { awk -v a="$1" -v b="$2" -v r="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; m = (b < 0 ? -b : b); exit !(d <= r * m) }'; }

"$LMP" -in "$INPUTS/in.pour" -var inputs "$INPUTS" -var preset tiny -var tile 2 -var out tile \
  -log tile.log -screen none >/dev/null || fail "the tile pour failed (tile.log)"
for f in tile.tile.data.gz tile.tile.info tile.restart tile.info; do [ -s "$f" ] || fail "the tile pour wrote no $f"; done
tg=$(info tile.tile.info grains) bg=$(info tile.info grains)
echo "tile: $tg grains, z_s $(info tile.tile.info z_s), phi_0 $(info tile.tile.info phi_0); bed: $bg grains, z_s $(info tile.info z_s), phi_0 $(info tile.info phi_0)"
[ "$bg" = $((4 * tg)) ] || fail "the bed has $bg grains, not 4 x $tg"
[ "$bg" = 1936 ] || fail "the bed has $bg grains, not the direct tiny fill's 1936"
[ "$(info tile.info tile)" = 2 ] && [ "$(info tile.info tile_grains)" = "$tg" ] || fail "tile.info lacks tile = 2, tile_grains = $tg"

# 2. the bed measured with the tile's column size
cat > check.lmp <<'EOF'
read_restart     ${bed}
group            grains type 1
compute          surf8 grains bed/surface grid 8
variable         mass atom mass
compute          m grains reduce sum v_mass
compute          r grains property/atom radius
variable         vol atom 4.0/3.0*PI*c_r^3
compute          v grains reduce sum v_vol
thermo_style     custom step c_surf8[1] c_surf8[2] c_m c_v
run              0 post no
print            "check: z_s8 = $(c_surf8[1]:%.17g) phi_08 = $(c_surf8[2]:%.17g) rho = $(c_m/c_v:%.17g)"
EOF
"$LMP" -in check.lmp -var bed tile.restart -log check.log -screen none >/dev/null || fail "the check deck failed (check.log)"
read -r z8 p8 rho < <(awk '/^check: / {print $4, $7, $10}' check.log)
echo "bed on an 8 x 8 grid: z_s $z8, phi_0 $p8; mean density $rho"
close "$z8" "$(info tile.tile.info z_s)" 1e-12 || fail "z_s of the bed on the tile's columns $z8 is not the tile's $(info tile.tile.info z_s)"
close "$p8" "$(info tile.tile.info phi_0)" 1e-12 || fail "phi_0 of the bed on the tile's columns $p8 is not the tile's $(info tile.tile.info phi_0)"
close "$rho" 3 1e-12 || fail "the grains' mean density is $rho, not rho_g = 3"

# 3. rebuilt from the data file
"$LMP" -in "$INPUTS/in.pour" -var inputs "$INPUTS" -var preset tiny -var tile 2 -var from_tile tile \
  -var out rebuilt -log rebuilt.log -screen none >/dev/null || fail "the rebuild failed (rebuilt.log)"
echo "rebuilt: $(info rebuilt.info grains) grains, z_s $(info rebuilt.info z_s), phi_0 $(info rebuilt.info phi_0)"
[ "$(info rebuilt.info grains)" = "$bg" ] || fail "the rebuilt bed has $(info rebuilt.info grains) grains, not $bg"
for k in z_s phi_0; do
  close "$(info rebuilt.info $k)" "$(info tile.info $k)" 1e-12 || fail "the rebuilt bed's $k $(info rebuilt.info $k) is not the poured bed's $(info tile.info $k)"
done
[ "$(info rebuilt.info seed)" = "$(info tile.tile.info seed)" ] || fail "the rebuilt bed's seed is not the tile's"

# 4. refusals
set +e
out=$("$LMP" -in "$INPUTS/in.pour" -var inputs "$INPUTS" -var preset tiny -var tile 2 -var from_tile tile \
  -var mu 0.5 -var out refused -log none 2>&1); st=$?
set -e
echo "$out" | grep -q "^ERROR: from_tile tile: the tile is of preset tiny, mu 0.3, tile 2; asked for preset tiny, mu 0.5, tile 2" && [ $st = 1 ] \
  || fail "from_tile with another mu: exit status $st, not the named error"
set +e
out=$("$LMP" -in "$INPUTS/in.pour" -var inputs "$INPUTS" -var preset tiny -var tile 2 -var from_tile nothing \
  -var out refused -log none 2>&1); st=$?
set -e
echo "$out" | grep -q "^ERROR: from_tile nothing: no tile nothing.tile.data.gz" && [ $st = 1 ] \
  || fail "from_tile of a missing tile: exit status $st, not the named error"
[ ! -e refused.restart ] && [ ! -e refused.info ] || fail "a refused rebuild wrote a bed"
echo "tile rebuild holds"
