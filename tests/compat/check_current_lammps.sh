#!/usr/bin/env bash
# The GRANPEN package against a current LAMMPS source tree, by every route a cluster user
# has (docs/compat.md says how to get a tree and what each step costs here):
#   1. compile: the plugin target against the tree's src/ (minutes)
#   2. plugin route: LAMMPS built from the tree (shared, PLUGIN GRANULAR VORONOI), the
#      plugin loaded with `plugin load`, a tiny pour and push run through it
#   3. package route: the tree copied with src/GRANPEN added and GRANPEN in its package
#      list, built with -D PKG_GRANPEN=on (+ GRANULAR, VORONOI); `lmp -h` and the same runs
#   4. the project's LAMMPS-level tests (ctest -L lammps: decks and gtests) with lmp_granpen
#      linked to the liblammps of step 2 and compiled against the tree's headers
#   5. LAMMPS's own checks on the package: tools/coding_standard/*.py on src/ and the doc
#      pages, and doc/utils/check-styles.py and check-packages.py with the package's index
#      entries added to a scratch copy of the doc tree (tests/compat/lammps_doc_entries.py)
#   6. fix wall/gran against pair gran/hertz/history for a sphere on a flat (docs/compat.md)
#   7. LAMMPS's fix-style harness (unittest/force-styles/test_fix_timestep) on fix rod/drive,
#      from the YAML files in tests/compat/force-styles/, in step 3's tree and build directory
#   8. the integer sizes and MPI variants Modify_requirements.rst asks for: src/ compiled
#      (syntax only, C++11) with -DLAMMPS_BIGBIG and MPI and with the tree's STUBS mpi.h; then
#      step 3's package route built with -D LAMMPS_SIZES=bigbig, `lmp -h` and the same runs
# Nothing is downloaded: the tree is given, GoogleTest (Debian's googletest package, packed as
# LAMMPS's unittest/ fetches it), libyaml and Voro++ come from Debian.
#
#   tests/compat/check_current_lammps.sh [--steps "1 2 3 4 5 6 7 8"] [--only-compile] LAMMPS_TREE
#
# LAMMPS builds are cached in $GRANPEN_CACHE (default ~/.cache/granpen) by tree version and
# reused; ccache is used when installed. Environment: GRANPEN_JOBS (default: all cores).
# Exit status: 0 when every step passed, 1 when one failed, 2 for a usage error, and 77
# (skipped) without a tree: `ctest -R current_lammps` runs this with GRANPEN_CURRENT_LAMMPS,
# and CI, which cannot fetch a tree, reports the test as skipped.
set -euo pipefail

say() { printf 'check_current_lammps: %s\n' "$*" >&2; }
STEPS="1 2 3 4 5 6 7 8"
while [ $# -gt 1 ]; do
  case "$1" in
    --steps) STEPS=$2; shift 2 ;;
    --only-compile) STEPS=1; shift ;;
    *) say "unknown option $1"; exit 2 ;;
  esac
done
if [ $# -ne 1 ] || [ -z "$1" ]; then
  say "skipped: no LAMMPS source tree given (usage: $0 [--steps LIST] LAMMPS_TREE; docs/compat.md)"
  exit 77
fi

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
CACHE=${GRANPEN_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/granpen}
JOBS=${GRANPEN_JOBS:-$(nproc --all)}
export OMP_NUM_THREADS=1 OMPI_MCA_rmaps_base_oversubscribe=1
[ "$(id -u)" = 0 ] && export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
LAUNCHER=()
command -v ccache >/dev/null 2>&1 && LAUNCHER=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)

src=$1
[ -d "$src" ] || { say "no such directory: $src"; exit 2; }
src=$(cd "$src" && pwd)
if [ ! -f "$src/src/version.h" ] && [ -f "$src/version.h" ]; then src=$(dirname "$src"); fi
if [ ! -f "$src/src/version.h" ] || [ ! -f "$src/src/lammpsplugin.h" ] || [ ! -d "$src/cmake" ]; then
  say "$src is not a LAMMPS source tree (needs src/version.h, src/lammpsplugin.h, cmake/)"
  exit 2
fi
version=$(sed -n 's/^#define LAMMPS_VERSION "\(.*\)"/\1/p' "$src/src/version.h")
update=$(sed -n 's/^#define LAMMPS_UPDATE "\(.*\)"/\1/p' "$src/src/version.h")
tag=$(echo "${version}_${update}" | tr -c 'A-Za-z0-9_\n' '_')
say "LAMMPS $version${update:+ ($update)} in $src"
WORK=$(mktemp -d "${TMPDIR:-/tmp}/granpen-current.XXXXXX")
say "work directory: $WORK (kept)"
LBUILD="$CACHE/lammps-current-$tag"
mkdir -p "$LBUILD"

declare -A result
failed=0
step() {    # N TITLE FUNCTION
  local n=$1 title=$2 fn=$3
  case " $STEPS " in *" $n "*) ;; *) return 0 ;; esac
  say "step $n: $title"
  local t0=$SECONDS
  # in the background, not as the condition of the if: there bash would ignore set -e in the
  # function, and a step would fail only when its last command did
  "$fn" >"$WORK/step$n.log" 2>&1 &
  if wait $!; then
    result[$n]="PASS ($((SECONDS - t0)) s) $title"
  else
    result[$n]="FAIL ($((SECONDS - t0)) s) $title: see $WORK/step$n.log"; failed=1
    tail -20 "$WORK/step$n.log" >&2
  fi
  say "${result[$n]}"
}

tiny_runs() {    # LMP PREFIX_DECK_LINE: a tiny pour and a 1 cm push; both must finish
  local lmp=$1 pre=$2 d=$WORK/runs_$3
  mkdir -p "$d" && cd "$d"
  printf '%s\ninclude %s/inputs/in.pour\n' "$pre" "$ROOT" > in.pour
  printf '%s\ninclude %s/inputs/in.push\n' "$pre" "$ROOT" > in.push
  "$lmp" -in in.pour -var inputs "$ROOT/inputs" -var preset tiny -var out bed -log pour.log -screen none
  grep -q "granpen pour: bed bed.restart: 1936 grains" pour.log
  mpirun -np 2 "$lmp" -in in.push -var inputs "$ROOT/inputs" -var preset tiny -var bed bed.restart \
    -var v0 100 -var depth 1.0 -var trace push.csv -log push.log -screen none
  grep -q "granpen push: done, depth 1.000 cm" push.log
  [ "$(grep -vc '^#' push.csv)" -gt 100 ]
}

compile_plugin() {
  "$CMAKE" -S "$ROOT" -B "$WORK/compile" -DLAMMPS_SOURCE_DIR="$src" -DGRANPEN_TESTS=OFF \
    -DCMAKE_DISABLE_FIND_PACKAGE_LAMMPS=ON -DCMAKE_CXX_FLAGS="-Wall -Wextra" "${LAUNCHER[@]}"
  "$CMAKE" --build "$WORK/compile" -j "$JOBS" --target granpenplugin
  nm -D --defined-only "$WORK/compile/granpenplugin.so" | grep -qw lammpsplugin_init
}

plugin_route() {
  # LAMMPS with PLUGIN (shared, as plugin loading needs), installed so that step 4 finds it
  if [ ! -x "$LBUILD/prefix/bin/lmp" ]; then
    "$CMAKE" -S "$src/cmake" -B "$LBUILD/plugin" -DCMAKE_BUILD_TYPE=Release -DBUILD_SHARED_LIBS=on \
      -DBUILD_MPI=on -DBUILD_OMP=off -DPKG_PLUGIN=on -DPKG_GRANULAR=on -DPKG_VORONOI=on -DDOWNLOAD_VORO=off -DPKG_COMPRESS=on \
      -DDOWNLOAD_POTENTIALS=off -DCMAKE_INSTALL_PREFIX="$LBUILD/prefix" "${LAUNCHER[@]}"
    "$CMAKE" --build "$LBUILD/plugin" -j "$JOBS" --target lmp
    # the man page and docs are not in a src-only tree: install the targets alone
    "$CMAKE" --install "$LBUILD/plugin" --component Unspecified || true
    "$CMAKE" --install "$LBUILD/plugin" || true
    [ -x "$LBUILD/prefix/bin/lmp" ] || { mkdir -p "$LBUILD/prefix/bin"; cp "$LBUILD/plugin/lmp" "$LBUILD/prefix/bin/"; }
  fi
  local lmp=$LBUILD/plugin/lmp
  "$lmp" -h | grep -A3 "Installed packages" | grep -q PLUGIN
  "$CMAKE" -S "$ROOT" -B "$WORK/plugin" -DLAMMPS_SOURCE_DIR="$src" -DGRANPEN_TESTS=OFF \
    -DCMAKE_DISABLE_FIND_PACKAGE_LAMMPS=ON -DCMAKE_BUILD_TYPE=Release "${LAUNCHER[@]}"
  "$CMAKE" --build "$WORK/plugin" -j "$JOBS" --target granpenplugin
  tiny_runs "$lmp" "plugin load $WORK/plugin/granpenplugin.so" plugin
  grep -q "Loading plugin: GRANPEN" "$WORK/runs_plugin/pour.log" || grep -qi "loading plugin" "$WORK/runs_plugin/pour.log"
}

make_package_tree() {    # src/GRANPEN, its CMake module and list entries (granpen_package_tree.sh)
  "$ROOT/tests/compat/granpen_package_tree.sh" "$src" "$ROOT" "$LBUILD/package-tree"
}

build_package() {    # TARGET [CMAKE_OPTION...]: the package tree's LAMMPS, built in $LBUILD/package
  local target=$1; shift
  CCACHE_BASEDIR=$LBUILD "$CMAKE" -S "$LBUILD/package-tree/cmake" -B "$LBUILD/package" -DCMAKE_BUILD_TYPE=Release \
    -DBUILD_MPI=on -DBUILD_OMP=off -DPKG_GRANPEN=on -DPKG_GRANULAR=on -DPKG_VORONOI=on -DDOWNLOAD_VORO=off \
    -DDOWNLOAD_POTENTIALS=off "${LAUNCHER[@]}" "$@"
  CCACHE_BASEDIR=$LBUILD "$CMAKE" --build "$LBUILD/package" -j "$JOBS" --target "$target"
}

package_route() {
  make_package_tree
  build_package lmp
  local lmp=$LBUILD/package/lmp
  "$lmp" -h > "$WORK/package-help.txt"
  grep -A4 "Installed packages" "$WORK/package-help.txt" | grep -q GRANPEN
  for s in rod/drive rod/drag bed/surface flow/azimuthal momentum/vbin create_rod restore_contact_history; do
    grep -q "$s" "$WORK/package-help.txt" || { echo "lmp -h lacks $s"; return 1; }
  done
  tiny_runs "$lmp" "" package
}

gtest_tarball() {    # prints the path and md5 of GoogleTest 1.12.1 packed as LAMMPS's unittest/ fetches it
  # LAMMPS's unittest/CMakeLists.txt downloads googletest release-1.12.1 from GitHub; Debian's
  # googletest package (/usr/src/googletest, 1.12.1-0.2 on bookworm) is the same release.
  # GRANPEN_GTEST_TARBALL names a ready tarball instead.
  local tgz=${GRANPEN_GTEST_TARBALL:-$CACHE/googletest-release-1.12.1.tar.gz}
  if [ ! -f "$tgz" ]; then
    local deb=/usr/src/googletest
    [ -f "$deb/CMakeLists.txt" ] && [ -d "$deb/googletest" ] || {
      echo "no GoogleTest sources: apt-get install googletest (or set GRANPEN_GTEST_TARBALL)" >&2; return 1; }
    local t; t=$(mktemp -d "$WORK/gtest.XXXXXX")
    cp -r "$deb" "$t/googletest-release-1.12.1"
    tar -C "$t" -czf "$tgz" googletest-release-1.12.1
  fi
  echo "$tgz $(md5sum < "$tgz" | cut -d' ' -f1)"
}

fix_harness() {
  # LAMMPS's fix-style harness (unittest/force-styles/test_fix_timestep) on fix rod/drive:
  # the YAML files of tests/compat/force-styles (and their input decks) copied into the
  # package tree's unittest/force-styles/tests/, the tree configured with ENABLE_TESTING and
  # MOLECULE (the harness's default force field needs it), test_fix_timestep built, and each
  # file run under ctest as FixTimestep:NAME (a full run, a run from the restart file)
  # LAMMPS's unittest/ CMake adds examples/COUPLE (c-library tests): a tree without it
  # stops at configure with a bare "not an existing directory"
  [ -d "$src/examples/COUPLE/simple" ] || {
    echo "the tree lacks examples/COUPLE (LAMMPS's unittest/ builds it): take examples/COUPLE and examples/plugins too (docs/compat.md, 'How to get a tree')"; return 1; }
  make_package_tree
  local tests=$LBUILD/package-tree/unittest/force-styles/tests f names=()
  for f in "$ROOT"/tests/compat/force-styles/*; do
    cp --remove-destination "$f" "$tests/"
    case $f in *.yaml) names+=("$(basename "$f" .yaml | sed 's/^fix-timestep-//')") ;; esac
  done
  local gt; gt=$(gtest_tarball)
  build_package test_fix_timestep -DPKG_MOLECULE=on -DENABLE_TESTING=on \
    -DGTEST_URL="file://${gt% *}" -DGTEST_MD5="${gt#* }"
  local re; re=$(printf '|%s' "${names[@]}"); re="^FixTimestep:(${re#|})\$"
  (cd "$LBUILD/package" && ctest -R "$re" -V) > "$WORK/fix-harness.txt" 2>&1 || true
  grep -E "Test +#|tests passed|SKIPPED|FAILED|Failure|Expected|Which is" "$WORK/fix-harness.txt" || true
  grep -q "100% tests passed, 0 tests failed out of ${#names[@]}\$" "$WORK/fix-harness.txt"
  # each file's checks ran: FixTimestep.plain passed, not skipped (omp and kokkos_omp skip
  # without the OPENMP and KOKKOS packages)
  [ "$(grep -c '\[       OK \] FixTimestep.plain' "$WORK/fix-harness.txt")" = "${#names[@]}" ]
  ! grep -q '\[  SKIPPED \] FixTimestep.plain' "$WORK/fix-harness.txt"
  # and the check can fail: the rigid push's file with v0 0.3 -> 0.301 must fail its checks
  # (a gtest failure, not a crash); not named fix-timestep-*, so ctest does not list it
  sed 's|rod/drive 0.3 |rod/drive 0.301 |' "$tests/fix-timestep-rod_drive.yaml" > "$tests/perturbed-rod_drive.yaml"
  grep -q "rod/drive 0.301 " "$tests/perturbed-rod_drive.yaml"
  if "$LBUILD/package/test_fix_timestep" "$tests/perturbed-rod_drive.yaml" > "$WORK/fix-harness-perturbed.txt" 2>&1; then
    echo "the file with v0 = 0.301 passed against the references for 0.3: the harness does not compare"
    return 1
  fi
  grep -q '\[  FAILED  \] FixTimestep.plain' "$WORK/fix-harness-perturbed.txt"
  echo "v0 0.3 -> 0.301: FixTimestep.plain fails $(grep -c ': Failure$' "$WORK/fix-harness-perturbed.txt") checks, as it must"
}

lammps_tests() {
  [ -f "$LBUILD/prefix/lib/cmake/LAMMPS/LAMMPSConfig.cmake" ] || { echo "step 2 first (the installed LAMMPS)"; return 1; }
  "$CMAKE" -S "$ROOT" -B "$WORK/tests" -DLAMMPS_DIR="$LBUILD/prefix/lib/cmake/LAMMPS" \
    -DLAMMPS_HEADERS_DIR="$src/src" -DCMAKE_BUILD_TYPE=RelWithDebInfo "${LAUNCHER[@]}"
  "$CMAKE" --build "$WORK/tests" -j "$JOBS"
  # the plugin test rebuilds Debian's LAMMPS: it is not a test of this tree
  (cd "$WORK/tests" && LD_LIBRARY_PATH="$LBUILD/prefix/lib:${LD_LIBRARY_PATH:-}" \
     ctest -L lammps -LE plugin -j "$JOBS" --output-on-failure)
}

coding_standard() {
  # tools/coding_standard, check-styles and check-packages with the package's index entries,
  # and the pages' ASCII, markup and spelling checks: the same script as the ctest
  # docs_lammps_doc_checks runs on Debian's tree
  "$ROOT/tests/compat/lammps_doc_checks.sh" "$src"
}

wall_gran() {
  # the same oblique bounce of a 0.4 cm grain on the floor (fix wall/gran hertz/history) and
  # on a 200 cm sphere under pair gran/hertz/history (R_eff within 0.2% of the flat's)
  local lmp=$LBUILD/plugin/lmp d=$WORK/wall
  mkdir -p "$d" && cd "$d"
  "$ROOT/tests/compat/wall_vs_pair.sh" "$ROOT/build/lmp_granpen" "$lmp"
}

compile_src_only() {    # SIZES MPI|STUBS: every src/*.cpp, syntax only, as C++11
  local sizes=$1 mpi=$2 cxx=c++ inc=() f
  if [ "$mpi" = STUBS ]; then inc=(-I"$src/src/STUBS"); else cxx=mpicxx; fi
  for f in "$ROOT"/src/*.cpp; do
    # OMPI_SKIP_MPICXX, MPICH_SKIP_MPICXX: as LAMMPS compiles, without the MPI C++ bindings
    "$cxx" -std=c++11 -fsyntax-only -Wall -Wextra -DOMPI_SKIP_MPICXX=1 -DMPICH_SKIP_MPICXX -DLAMMPS_"$sizes" "${inc[@]}" -I"$ROOT/src" -I"$src/src" \
      -I/usr/include/voro++ "$f" || { echo "$(basename "$f"): does not compile with LAMMPS_$sizes and $mpi"; return 1; }
  done
  echo "src/*.cpp compile with LAMMPS_$sizes and $mpi"
}

bigbig_route() {
  compile_src_only BIGBIG MPI
  compile_src_only SMALLBIG STUBS
  # the package route with 64-bit tags and image flags, in a build directory of its own
  make_package_tree
  CCACHE_BASEDIR=$LBUILD "$CMAKE" -S "$LBUILD/package-tree/cmake" -B "$LBUILD/package-bigbig" \
    -DCMAKE_BUILD_TYPE=Release -DLAMMPS_SIZES=bigbig -DBUILD_MPI=on -DBUILD_OMP=off -DPKG_GRANPEN=on \
    -DPKG_GRANULAR=on -DPKG_VORONOI=on -DDOWNLOAD_VORO=off -DDOWNLOAD_POTENTIALS=off "${LAUNCHER[@]}"
  CCACHE_BASEDIR=$LBUILD "$CMAKE" --build "$LBUILD/package-bigbig" -j "$JOBS" --target lmp
  local lmp=$LBUILD/package-bigbig/lmp
  "$lmp" -h > "$WORK/package-bigbig-help.txt"
  grep -q "sizeof(tagint): *64-bit" "$WORK/package-bigbig-help.txt" || { echo "lmp -h does not say 64-bit tagint"; return 1; }
  grep -A4 "Installed packages" "$WORK/package-bigbig-help.txt" | grep -q GRANPEN
  tiny_runs "$lmp" "" package_bigbig
}

CMAKE=${CMAKE:-cmake}
step 1 "the plugin compiles against $version" compile_plugin
step 2 "plugin route: plugin load into lmp built from the tree" plugin_route
step 3 "package route: src/GRANPEN, -D PKG_GRANPEN=on" package_route
step 4 "LAMMPS-level tests (ctest -L lammps) with lmp_granpen on the tree's liblammps" lammps_tests
step 5 "LAMMPS's coding-standard and doc index checks" coding_standard
step 6 "fix wall/gran against pair gran/hertz/history (a sphere on a flat)" wall_gran
step 7 "LAMMPS's fix-style harness (test_fix_timestep) on fix rod/drive" fix_harness
step 8 "BIGBIG and STUBS: src/ compiled in both, the package route built with LAMMPS_SIZES=bigbig" bigbig_route
echo
echo "LAMMPS $version${update:+ ($update)}:"
for n in 1 2 3 4 5 6 7 8; do [ -n "${result[$n]:-}" ] && echo "  step ${result[$n]}"; done
exit $failed
