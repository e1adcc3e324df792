#!/usr/bin/env bash
# The plugin route, for real: build LAMMPS from Debian's source package (the tree
# lmp_granpen's headers come from) with PLUGIN, GRANULAR and VORONOI; build the
# GRANPEN plugin against that tree; load it with `plugin load`, run the tiny push,
# and require the same force trace as lmp_granpen gives (within 1e-12 relative).
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
COMMON=(-var inputs "$ROOT/inputs" -var preset tiny -var bed "$BED" -var v0 100 -var depth 1.0)
cd "$WORK"
"$LMP_GRANPEN" -in "$ROOT/inputs/in.push" "${COMMON[@]}" -var trace lmp_granpen.csv -log lmp_granpen.log -screen none
"$LBUILD/lmp" -in in.plugin_push "${COMMON[@]}" -var trace plugin.csv -log plugin.log -screen none
grep -q "Loading plugin: GRANPEN fix style" plugin.log || grep -qi "loading plugin" plugin.log \
  || { echo "plugin was not loaded"; tail -20 plugin.log; exit 1; }
"$TRACE_AGREE" lmp_granpen.csv plugin.csv --rtol 1e-12 --min-rows 100
