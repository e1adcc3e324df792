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
#     the same file; this checks that from_tile reads the tile and its info as written);
#     so does the rebuild with the rod shaft's atom type (-var rod_types 2).
#  4. refusals: from_tile of another mu or preset, of a stem with no tile, into a box that is
#     not a whole number of tiles, and with a tile count that does not make the box, end with
#     a named ERROR and exit status 1, writing no bed.
#  5. a wider box from the same tile (-var tile 4 -var box 12, issue: the paper's box): 16 x
#     the tile's grains; on a 16 x 16 grid (the tile's columns again) z_s and phi_0 are the
#     tile's, so the 4 x 4 bed and the 2 x 2 bed agree column for column (1e-12 relative, as
#     in 2.); and its NAME.info, measured with -var surface_grid 8 (the 2 x 2 bed's column
#     width, 1.5 cm, on the twice wider box), has the 2 x 2 bed's z_s and phi_0 (1e-12: the
#     same columns, each four times). With the default grid (4, columns twice as wide) z_s
#     comes out higher (the highest top of a wider column), which is why a wider box keeps
#     the column width: checked too (it must differ by more than 1e-3 cm).
#   tile_rebuild.sh LMP_GRANPEN INPUTS WORKDIR
set -euo pipefail
LMP=$1 INPUTS=$2 WORK=$3
mkdir -p "$WORK"; cd "$WORK"
rm -f tile.* rebuilt.* rebuilt3.* types.* refused.* check.*
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
# ... and with the shaft's atom type (-var rod_types 2: read_data extra/atom/types 1): the same
# grains in the same places (an empty type adds nothing), so the same z_s and phi_0 (1e-12, as
# above), the third type in the box, and rod_types = 2 in its info
"$LMP" -in "$INPUTS/in.pour" -var inputs "$INPUTS" -var preset tiny -var tile 2 -var from_tile tile -var rod_types 2 \
  -var out rebuilt3 -log rebuilt3.log -screen none >/dev/null || fail "the rebuild with rod_types 2 failed (rebuilt3.log)"
for k in z_s phi_0; do
  close "$(info rebuilt3.info $k)" "$(info tile.info $k)" 1e-12 || fail "the rebuilt bed with rod_types 2 has $k $(info rebuilt3.info $k), not the poured bed's $(info tile.info $k)"
done
[ "$(info rebuilt3.info rod_types)" = 2 ] && [ "$(info rebuilt.info rod_types)" = 1 ] || fail "rod_types in the infos: $(info rebuilt3.info rod_types) and $(info rebuilt.info rod_types), not 2 and 1"
printf 'read_restart ${bed}\ninfo system out log\n' > types.lmp
"$LMP" -in types.lmp -var bed rebuilt3.restart -log types.log -screen none >/dev/null || fail "reading rebuilt3.restart failed (types.log)"
grep -Eq "^Atoms += +1936, +types = +3," types.log || fail "the bed rebuilt with rod_types 2 is not 1936 atoms of 3 types: $(grep '^Atoms' types.log)"

# 4. refusals
set +e
out=$("$LMP" -in "$INPUTS/in.pour" -var inputs "$INPUTS" -var preset tiny -var tile 2 -var from_tile tile \
  -var mu 0.5 -var out refused -log none 2>&1); st=$?
set -e
echo "$out" | grep -q "^ERROR: from_tile tile: the tile is of preset tiny, mu 0.3; asked for preset tiny, mu 0.5" && [ $st = 1 ] \
  || fail "from_tile with another mu: exit status $st, not the named error"
# refused: ARGS... then the message's pattern as the last argument
refused() {
  local pat=${*: -1} args=("${@:1:$#-1}") out st
  set +e; out=$("$LMP" -in "$INPUTS/in.pour" -var inputs "$INPUTS" -var from_tile tile "${args[@]}" \
    -var out refused -log none 2>&1); st=$?; set -e
  echo "$out" | grep -q "$pat" && [ $st = 1 ] || fail "from_tile ${args[*]}: exit status $st, not the named error /$pat/"
}
refused -var preset bench -var tile 2 "^ERROR: from_tile tile: the tile is of preset tiny, mu 0.3; asked for preset bench, mu 0.3"
refused -var preset tiny -var tile 3 -var box 10 "^ERROR: from_tile tile: box = 10 cm is not a whole number of its tiles of 3 cm"
refused -var preset tiny -var tile 3 -var box 12 "^ERROR: from_tile tile: tile = 3 tiles of 3 cm do not make box = 12 cm (4 do)"
refused -var preset tiny -var tile 4 "^ERROR: from_tile tile: tile = 4 tiles of 3 cm do not make box = 6.0 cm (2 do)"
set +e
out=$("$LMP" -in "$INPUTS/in.pour" -var inputs "$INPUTS" -var preset tiny -var tile 2 -var from_tile nothing \
  -var out refused -log none 2>&1); st=$?
set -e
echo "$out" | grep -q "^ERROR: from_tile nothing: no tile nothing.tile.data.gz" && [ $st = 1 ] \
  || fail "from_tile of a missing tile: exit status $st, not the named error"
[ ! -e refused.restart ] && [ ! -e refused.info ] || fail "a refused rebuild wrote a bed"

# 5. a 4 x 4 bed of the same tile
"$LMP" -in "$INPUTS/in.pour" -var inputs "$INPUTS" -var preset tiny -var tile 4 -var box 12 -var from_tile tile \
  -var surface_grid 8 -var out wide -log wide.log -screen none >/dev/null || fail "the 4 x 4 rebuild failed (wide.log)"
"$LMP" -in "$INPUTS/in.pour" -var inputs "$INPUTS" -var preset tiny -var tile 4 -var box 12 -var from_tile tile \
  -var out wide4 -log wide4.log -screen none >/dev/null || fail "the 4 x 4 rebuild on the default grid failed (wide4.log)"
echo "4 x 4: $(info wide.info grains) grains, z_s $(info wide.info z_s), phi_0 $(info wide.info phi_0), box $(info wide.info box)"
[ "$(info wide.info grains)" = $((16 * tg)) ] || fail "the 4 x 4 bed has $(info wide.info grains) grains, not 16 x $tg"
[ "$(info wide.info box)" = 12 ] && [ "$(info wide.info tile)" = 4 ] && [ "$(info wide.info tile_side)" = 3 ] \
  || fail "wide.info lacks box = 12, tile = 4, tile_side = 3"
sed 's/grid 8/grid 16/' check.lmp > check16.lmp
"$LMP" -in check16.lmp -var bed wide.restart -log check16.log -screen none >/dev/null || fail "the check deck failed (check16.log)"
read -r z16 p16 rho16 < <(awk '/^check: / {print $4, $7, $10}' check16.log)
echo "4 x 4 bed on a 16 x 16 grid: z_s $z16, phi_0 $p16 (2 x 2 bed on 8 x 8: $z8, $p8)"
close "$z16" "$z8" 1e-12 || fail "z_s of the 4 x 4 bed on the tile's columns $z16 is not the 2 x 2 bed's $z8"
close "$p16" "$p8" 1e-12 || fail "phi_0 of the 4 x 4 bed on the tile's columns $p16 is not the 2 x 2 bed's $p8"
close "$rho16" 3 1e-12 || fail "the 4 x 4 bed's mean density is $rho16, not rho_g = 3"
for k in z_s phi_0; do
  close "$(info wide.info $k)" "$(info tile.info $k)" 1e-12 || fail "the 4 x 4 bed's $k $(info wide.info $k) (surface_grid 8) is not the 2 x 2 bed's $(info tile.info $k)"
done
echo "4 x 4 bed on the default grid (3 cm columns): z_s $(info wide4.info z_s) against $(info wide.info z_s) on 1.5 cm columns"
awk -v a="$(info wide4.info z_s)" -v b="$(info wide.info z_s)" 'BEGIN { exit !(a - b > 1e-3) }' \
  || fail "z_s on 3 cm columns $(info wide4.info z_s) is not above z_s on 1.5 cm columns $(info wide.info z_s): surface_grid did not reach the measurement"
echo "tile rebuild holds"
