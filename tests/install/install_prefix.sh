#!/usr/bin/env bash
# An installed granpen is complete and relocatable: `cmake --install BUILD --prefix P`, then P
# moved elsewhere; the moved tree holds the programs, decks, examples, plugin loader and docs,
# no installed file names the build tree, the source tree or P, the installed granpen-cli
# runs, and the installed lmp_granpen reproduces the installed examples' 1-rank logs
# (tests/examples/lammps_examples.sh --current). With --demo also the installed granpen-demo.
#   install_prefix.sh [--demo] BUILD_DIR SOURCE_DIR WORK_DIR
# Exit: 0 all hold, 1 something is missing or wrong (printed), 2 usage.
set -uo pipefail
demo=no
[ "${1:-}" = --demo ] && { demo=yes; shift; }
[ $# -eq 3 ] || { sed -n '2,8p' "$0"; exit 2; }
build=$(cd "$1" && pwd) src=$(cd "$2" && pwd) work=$3
rm -rf "$work"; mkdir -p "$work"; work=$(cd "$work" && pwd)
fail() { echo "FAIL: $*"; exit 1; }

cmake --install "$build" --prefix "$work/prefix" > "$work/install.log" 2>&1 || { cat "$work/install.log"; fail "cmake --install"; }
mv "$work/prefix" "$work/moved"
P=$work/moved
for f in bin/lmp_granpen bin/granpen-cli bin/granpen-demo share/granpen/inputs/in.pour share/granpen/inputs/in.push \
    share/granpen/inputs/demo.sh share/granpen/inputs/presets/tiny.lmp share/granpen/analysis/plots/force_depth.gp \
    share/granpen/examples/in.rod_drive share/granpen/plugin.lmp share/doc/granpen/LICENSE \
    share/doc/granpen/LICENSE.data share/doc/granpen/fix_rod_drive.rst share/doc/granpen/upstream.md; do
  [ -e "$P/$f" ] || fail "$f not installed"
done
[ -x "$P/bin/granpen-demo" ] && [ -x "$P/share/granpen/inputs/demo.sh" ] || fail "the demo scripts are not executable"
# no installed text file points back at the build, the sources or the first prefix (-I: the
# binaries' debug info keeps the compile directory, which does not matter to a run; their
# RPATH, which does, is checked below); the docs may name source paths in prose
hits=$(grep -rlIF -e "$build" -e "$work/prefix" "$P" 2>/dev/null; grep -rlIF "$src/" "$P" 2>/dev/null | grep -v '\.md$\|\.rst$')
[ -z "$hits" ] || fail "installed files name the build, source or install path: $hits"
for b in "$P"/bin/lmp_granpen "$P"/bin/granpen-cli; do
  rp=$(readelf -d "$b" | grep -E 'RPATH|RUNPATH' || true)
  [ -z "$rp" ] || case $rp in *"$build"*|*"$src"*) fail "$b keeps a build RPATH: $rp" ;; esac
done
"$P/bin/granpen-cli" --help > "$work/cli-help.txt" 2>&1 || fail "installed granpen-cli --help: $(head -3 "$work/cli-help.txt")"
"$src/tests/examples/lammps_examples.sh" --current "$P/bin/lmp_granpen" "$P/share/granpen/examples" || fail "the installed examples"
if [ "$demo" = yes ]; then
  (cd "$work" && "$P/bin/granpen-demo" demo-out) > "$work/demo.log" 2>&1 || { tail -20 "$work/demo.log"; fail "granpen-demo"; }
  for f in bed_tiny.restart trace_tiny_v50.csv trace_tiny_v100.csv trace_tiny_v200.csv force_depth.png; do
    [ -s "$work/demo-out/$f" ] || fail "granpen-demo wrote no $f"
  done
  echo "ok: the installed granpen-demo ran from the moved prefix"
fi
echo "ok: installed into a prefix, moved, and run from there: programs, decks, examples, docs"
