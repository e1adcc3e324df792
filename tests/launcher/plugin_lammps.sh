#!/usr/bin/env bash
# A LAMMPS with PLUGIN, GRANULAR and VORONOI built from a source tree, cached (about 10 minutes
# on 2 cores the first time), for the tests that load the GRANPEN plugin into it. Prints the
# build directory (its lmp and liblammps.so); build logs go to WORK.
#   plugin_lammps.sh LAMMPS_SOURCE_TREE WORK
set -euo pipefail
SRC=$1 WORK=$2
CACHE=${GRANPEN_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/granpen}
JOBS=${GRANPEN_JOBS:-$(nproc)}
LBUILD="$CACHE/lammps-plugin-build-$(basename "$SRC")-shared"
mkdir -p "$WORK" "$LBUILD"
if [ ! -x "$LBUILD/lmp" ] || [ ! -f "$LBUILD/liblammps.so" ]; then
  echo "building LAMMPS with PLUGIN, GRANULAR, VORONOI from $SRC into $LBUILD" >&2
  # Debian's own flags for liblammps: -O2, no -march, so floating point matches;
  # plugin loading in 29Sep2021 needs a shared liblammps
  cmake -S "$SRC/cmake" -B "$LBUILD" -DCMAKE_BUILD_TYPE=None -DCMAKE_CXX_FLAGS="-g0 -O2" \
    -DBUILD_MPI=on -DBUILD_OMP=on -DBUILD_SHARED_LIBS=on -DPKG_PLUGIN=on -DPKG_GRANULAR=on \
    -DPKG_VORONOI=on -DDOWNLOAD_VORO=off -DLAMMPS_EXCEPTIONS=off >"$WORK/lammps-configure.log" 2>&1 \
    || { tail -30 "$WORK/lammps-configure.log" >&2; exit 1; }
  cmake --build "$LBUILD" -j "$JOBS" >"$WORK/lammps-build.log" 2>&1 || { tail -30 "$WORK/lammps-build.log" >&2; exit 1; }
fi
"$LBUILD/lmp" -h >"$WORK/lmp-help.txt"
grep -q "PLUGIN" "$WORK/lmp-help.txt" || { echo "the built lmp lacks PLUGIN" >&2; exit 1; }
echo "$LBUILD"
