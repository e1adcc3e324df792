#!/usr/bin/env bash
# conda-build's build script for granpen (meta.yaml beside it). conda-build runs it in $SRC_DIR
# (granpen's sources, with LAMMPS's release tarball unpacked into lammps-src/) and installs
# into $PREFIX. The cmake commands are the route tests/install/recipes.sh runs here (with
# LAMMPS_SRC pointing at Debian's 29Sep2021 tree and GRANPEN_POSTPROCESSOR=OFF); the same
# -D options as packaging/spack/granpen/package.py's cmake_args (checked by that test).
set -euo pipefail
LAMMPS_SRC=${LAMMPS_SRC:-$SRC_DIR/lammps-src}
cmake -S "$SRC_DIR" -B _build ${CMAKE_ARGS:-} \
  -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_INSTALL_PREFIX="$PREFIX" \
  -DLAMMPS_SOURCE_DIR="$LAMMPS_SRC" \
  -DCMAKE_DISABLE_FIND_PACKAGE_LAMMPS=ON \
  -DGRANPEN_TESTS=OFF \
  -DGRANPEN_POSTPROCESSOR="${GRANPEN_POSTPROCESSOR:-ON}"
cmake --build _build --parallel "${CPU_COUNT:-1}"
cmake --install _build
