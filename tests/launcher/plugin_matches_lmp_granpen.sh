#!/usr/bin/env bash
# The plugin route, for real: build LAMMPS from Debian's source package (the tree
# lmp_granpen's headers come from) with PLUGIN, GRANULAR and VORONOI; build the
# GRANPEN plugin against that tree; load it with `plugin load`, run the tiny push,
# and require the same force trace as lmp_granpen gives (within 1e-12 relative:
# plugin_push_agrees.sh, which tests/install/recipes.sh build runs too).
# The LAMMPS build (about 10 minutes on 2 cores) is cached and reused.
#   plugin_matches_lmp_granpen.sh LAMMPS_SOURCE_TREE PROJECT_DIR LMP_GRANPEN BED TRACE_AGREE WORKDIR
set -euo pipefail
SRC=$1 ROOT=$2 LMP_GRANPEN=$3 BED=$4 TRACE_AGREE=$5 WORK=$6
JOBS=${GRANPEN_JOBS:-$(nproc)}
mkdir -p "$WORK"
LBUILD=$("$(dirname "$0")/plugin_lammps.sh" "$SRC" "$WORK")

echo "building the GRANPEN plugin against $SRC"
cmake -S "$ROOT" -B "$WORK/plugin-build" -DLAMMPS_SOURCE_DIR="$SRC" -DGRANPEN_TESTS=OFF \
  -DCMAKE_DISABLE_FIND_PACKAGE_LAMMPS=ON -DCMAKE_CXX_FLAGS="-O2" >"$WORK/plugin-configure.log" 2>&1 \
  || { tail -30 "$WORK/plugin-configure.log"; exit 1; }
cmake --build "$WORK/plugin-build" --target granpenplugin -j "$JOBS" >"$WORK/plugin-build.log" 2>&1 \
  || { tail -30 "$WORK/plugin-build.log"; exit 1; }
PLUGIN="$WORK/plugin-build/granpenplugin.so"

cat >"$WORK/in.plugin_push" <<DECK
plugin load $PLUGIN
include $ROOT/inputs/in.push
DECK
"$(dirname "$0")/plugin_push_agrees.sh" "$WORK" "$LMP_GRANPEN" "$LBUILD/lmp" "$ROOT/inputs" "$BED" "$TRACE_AGREE" \
  "$WORK/in.plugin_push"
