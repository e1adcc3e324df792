#!/usr/bin/env bash
# Compile-only check of the GRANPEN styles against a LAMMPS source tree
# (see docs/compat.md): configure granpen in a scratch directory with
# LAMMPS_SOURCE_DIR pointing at the tree and build the plugin target
# granpenplugin, which compiles every style plus launcher/style_registry.cpp and
# launcher/granpen_plugin.cpp against that tree's src/ and links a module that
# does not need liblammps. Nothing is downloaded.
#
#   tests/compat/check_current_lammps.sh /path/to/lammps   [the tree, or its src/]
#
# Environment: GRANPEN_JOBS (default 1), KEEP_BUILD=1 keeps the scratch build
# directory, CMAKE (default cmake).
# Exit status: 0 when the plugin builds, non-zero otherwise.
set -euo pipefail

say() { printf 'check_current_lammps: %s\n' "$*" >&2; }

if [ $# -ne 1 ]; then
  say "usage: $0 /path/to/lammps-source-tree"
  exit 2
fi

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
CMAKE=${CMAKE:-cmake}
JOBS=${GRANPEN_JOBS:-1}

src=$1
[ -d "$src" ] || { say "no such directory: $src"; exit 2; }
src=$(cd "$src" && pwd)
# accept the tree's src/ as well as the tree itself
if [ ! -f "$src/src/version.h" ] && [ -f "$src/version.h" ]; then src=$(dirname "$src"); fi
if [ ! -f "$src/src/version.h" ] || [ ! -f "$src/src/lammpsplugin.h" ]; then
  say "$src is not a LAMMPS source tree (no src/version.h or src/lammpsplugin.h)"
  exit 2
fi

build=$(mktemp -d "${TMPDIR:-/tmp}/granpen-compat.XXXXXX")
if [ "${KEEP_BUILD:-0}" = 1 ]; then
  say "build directory kept: $build"
else
  trap 'rm -rf "$build"' EXIT
fi

version=$(sed -n 's/^#define LAMMPS_VERSION "\(.*\)"/\1/p' "$src/src/version.h")
update=$(sed -n 's/^#define LAMMPS_UPDATE "\(.*\)"/ (\1)/p' "$src/src/version.h")
say "LAMMPS ${version}${update} in $src"

# The system liblammps (if any) is left out: lmp_granpen is not what is checked,
# and its configure step would insist on LAMMPS_HEADERS_DIR.
if ! "$CMAKE" -S "$ROOT" -B "$build" -DLAMMPS_SOURCE_DIR="$src" -DGRANPEN_TESTS=OFF \
     -DCMAKE_DISABLE_FIND_PACKAGE_LAMMPS=ON >"$build/configure.log" 2>&1; then
  cat "$build/configure.log" >&2
  say "FAILED: configure"
  exit 1
fi
grep 'granpen: plugin for LAMMPS' "$build/configure.log" >&2 || true

if ! "$CMAKE" --build "$build" -j "$JOBS" --target granpenplugin; then
  say "FAILED: granpenplugin does not build against $src"
  exit 1
fi

plugin="$build/granpenplugin.so"
if [ ! -f "$plugin" ]; then
  say "FAILED: $plugin was not produced"
  exit 1
fi
if command -v nm >/dev/null 2>&1 && ! nm -D --defined-only "$plugin" | grep -qw lammpsplugin_init; then
  say "FAILED: $plugin does not export lammpsplugin_init"
  exit 1
fi
say "OK: granpenplugin builds against $src"
