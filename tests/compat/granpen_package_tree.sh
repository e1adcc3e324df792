#!/usr/bin/env bash
# A copy of a LAMMPS source tree with GRANPEN added as LAMMPS's own packages are (the package
# route of a pull request): src/GRANPEN with the package's files, GRANPEN in STANDARD_PACKAGES,
# its CMake module cmake/Modules/Packages/GRANPEN.cmake, and GRANPEN in the list of packages
# whose module is included. The copy is of hard links (cheap); every file changed is written
# anew, never through a link. The package's files keep their times (cp -p), so a cached build
# recompiles only what changed.
#   granpen_package_tree.sh LAMMPS_SOURCE_TREE PROJECT_DIR NEW_TREE
set -euo pipefail
[ $# -eq 3 ] || { sed -n '2,8p' "$0"; exit 2; }
src=$1 ROOT=$2 tree=$3
rm -rf "$tree"; cp -al "$src" "$tree"
rm -rf "$tree/src/GRANPEN"; mkdir "$tree/src/GRANPEN"
cp -p "$ROOT"/src/*.cpp "$ROOT"/src/*.h "$ROOT"/src/README "$tree/src/GRANPEN/"
cp "$ROOT/cmake/lammps/Packages/GRANPEN.cmake" "$tree/cmake/Modules/Packages/GRANPEN.cmake"
cp --remove-destination "$src/cmake/CMakeLists.txt" "$tree/cmake/CMakeLists.txt"
sed -i -e 's/^set(STANDARD_PACKAGES$/set(STANDARD_PACKAGES\n  GRANPEN/' \
  -e '0,/^foreach(PKG_WITH_INCL /s//foreach(PKG_WITH_INCL GRANPEN /' "$tree/cmake/CMakeLists.txt"
grep -q "^  GRANPEN$" "$tree/cmake/CMakeLists.txt" || { echo "no STANDARD_PACKAGES list in $src/cmake/CMakeLists.txt"; exit 1; }
grep -q "^foreach(PKG_WITH_INCL GRANPEN " "$tree/cmake/CMakeLists.txt" \
  || { echo "no PKG_WITH_INCL list in $src/cmake/CMakeLists.txt"; exit 1; }
