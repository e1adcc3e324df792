#!/usr/bin/env bash
# GRANPEN's CMake module in a LAMMPS tree (cmake/lammps/Packages/GRANPEN.cmake): configuring
# the package route with -D PKG_GRANPEN=on but without VORONOI stops at configure time with the
# module's message; with VORONOI it configures. Configure only (about a minute for both), on the
# tree lmp_granpen is built against; the full package-route build is check_current_lammps.sh's
# step 3.
#   package_route_needs_voronoi.sh LAMMPS_SOURCE_TREE PROJECT_DIR WORK
set -uo pipefail
[ $# -eq 3 ] || { sed -n '2,8p' "$0"; exit 2; }
src=$1 ROOT=$2 WORK=$3
rm -rf "$WORK"; mkdir -p "$WORK"
"$ROOT/tests/compat/granpen_package_tree.sh" "$src" "$ROOT" "$WORK/tree" || exit 1
configure() {    # NAME VORONOI
  cmake -S "$WORK/tree/cmake" -B "$WORK/$1" -DBUILD_MPI=on -DBUILD_OMP=off -DPKG_GRANPEN=on \
    -DPKG_GRANULAR=on -DPKG_VORONOI="$2" -DDOWNLOAD_VORO=off > "$WORK/$1.log" 2>&1
}
if configure without-voronoi off; then
  echo "FAIL: PKG_GRANPEN=on without PKG_VORONOI configured"; exit 1
fi
grep -q "The GRANPEN package needs the VORONOI package" "$WORK/without-voronoi.log" \
  || { tail -20 "$WORK/without-voronoi.log"; echo "FAIL: configure failed, but not with GRANPEN's message"; exit 1; }
configure with-voronoi on || { tail -20 "$WORK/with-voronoi.log"; echo "FAIL: PKG_GRANPEN=on with PKG_VORONOI=on did not configure"; exit 1; }
grep -q "GRANPEN" "$WORK/with-voronoi/CMakeCache.txt" || { echo "FAIL: the configured tree has no GRANPEN"; exit 1; }
rm -rf "$WORK/tree"    # hard links into the cached LAMMPS tree: not left lying about
echo "ok: the package route asks for VORONOI at configure time, and configures with it"
