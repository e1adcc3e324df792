#!/usr/bin/env bash
# The Spack and conda-forge recipes (packaging/), checked as far as this machine can:
#   agree            the -D options of packaging/conda/build.sh are those of the Spack recipe's
#                    cmake_args (read with Python's ast, not imported: Spack is not here), but for
#                    CMAKE_BUILD_TYPE and CMAKE_INSTALL_PREFIX, which Spack sets itself; both name
#                    the same LAMMPS release and checksum for the source tree the plugin needs
#   build ...        runs build.sh itself (as conda-build would: SRC_DIR, PREFIX, CPU_COUNT) with
#                    LAMMPS_SRC = the given tree and GRANPEN_POSTPROCESSOR=OFF (the post-processor's
#                    install is install_prefix_relocatable's), moves the installed prefix, loads
#                    the installed plugin through share/granpen/plugin.lmp into a LAMMPS built
#                    with PLUGIN from that tree, and requires the tiny push's force trace of
#                    lmp_granpen
#   self-test        agree must fail on copies of the recipes with one difference planted each
#                    (an option only in build.sh, one only in package.py, another checksum)
#   recipes.sh agree|self-test PROJECT_DIR
#   recipes.sh build LAMMPS_SOURCE_TREE PROJECT_DIR LMP_GRANPEN BED TRACE_AGREE WORK
# Exit: 0 holds, 1 a difference (printed), 2 usage.
set -euo pipefail
mode=${1:-}
case $mode in
  agree|self-test) [ $# -eq 2 ] || { sed -n '2,18p' "$0"; exit 2; }; ROOT=$2 ;;
  build) [ $# -eq 7 ] || { sed -n '2,18p' "$0"; exit 2; }; SRC=$2 ROOT=$3 LMP_GRANPEN=$4 BED=$5 TRACE_AGREE=$6 WORK=$7 ;;
  *) sed -n '2,18p' "$0"; exit 2 ;;
esac
ROOT=$(cd "$ROOT" && pwd)
if [ "$mode" = self-test ]; then
  tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
  plant() {    # NAME FILE SED: copy the recipes, change FILE by SED, agree must fail
    rm -rf "$tmp/p"; mkdir -p "$tmp/p"; cp -r "$ROOT/packaging" "$tmp/p/"
    sed -i "$3" "$tmp/p/packaging/$2"
    if "$0" agree "$tmp/p" > "$tmp/out" 2>&1; then echo "FAIL: self-test: $1 not caught"; return 1; fi
    grep -q "^FAIL:" "$tmp/out" || { echo "FAIL: self-test: $1 gave no finding: $(cat "$tmp/out")"; return 1; }
    echo "caught: $1: $(head -1 "$tmp/out")"
  }
  plant "an option only in build.sh" conda/build.sh 's/-DGRANPEN_TESTS=OFF/-DGRANPEN_TESTS=OFF -DGRANPEN_EXTRA=ON/'
  plant "an option only in package.py" spack/granpen/package.py 's/self.define("GRANPEN_TESTS", False)/self.define("GRANPEN_TESTS", False), self.define("LAMMPS_SIZES", "bigbig")/'
  plant "another LAMMPS checksum" conda/meta.yaml 's/lammps_sha256 = "07/lammps_sha256 = "08/'
  echo "ok: self-test: each planted difference is caught"
  exit 0
fi
BUILD_SH=$ROOT/packaging/conda/build.sh META=$ROOT/packaging/conda/meta.yaml
SPACK=$ROOT/packaging/spack/granpen/package.py

if [ "$mode" = agree ]; then
  python3 - "$BUILD_SH" "$META" "$SPACK" <<'PY'
import ast, re, sys
build_sh, meta, spack = sys.argv[1:]
conda = set(re.findall(r'-D([A-Z_]+)=', open(build_sh).read()))
tree = ast.parse(open(spack).read())
spack_defs, sources = set(), {}
for node in ast.walk(tree):
    if isinstance(node, ast.FunctionDef) and node.name == "cmake_args":
        for call in ast.walk(node):
            if isinstance(call, ast.Call) and getattr(call.func, "attr", "") in ("define", "define_from_variant"):
                spack_defs.add(call.args[0].value)
    if isinstance(node, ast.Assign) and getattr(node.targets[0], "id", "") == "lammps_sources":
        sources = {k.value: (v.elts[0].value, v.elts[1].value) for k, v in zip(node.value.keys, node.value.values)}
bad = []
own = {"CMAKE_BUILD_TYPE", "CMAKE_INSTALL_PREFIX"}    # Spack's CMakePackage passes these itself
if conda - own != spack_defs:
    bad.append(f"cmake options differ: build.sh only {sorted(conda - own - spack_defs)}, "
               f"package.py only {sorted(spack_defs - (conda - own))}")
if not {"LAMMPS_SOURCE_DIR", "GRANPEN_TESTS", "GRANPEN_POSTPROCESSOR"} <= spack_defs:
    bad.append(f"package.py's cmake_args lack the plugin route's options: {sorted(spack_defs)}")
m = dict(re.findall(r'{%\s*set\s+(\w+)\s*=\s*"([^"]*)"\s*%}', open(meta).read()))
release, sha = m.get("lammps_release"), m.get("lammps_sha256")
known = {r: s for r, s in sources.values()}
if release not in known:
    bad.append(f"meta.yaml's LAMMPS release {release} is not among package.py's {sorted(known)}")
elif known[release] != sha:
    bad.append(f"{release}: checksum {sha} in meta.yaml, {known[release]} in package.py")
for line in bad:
    print("FAIL:", line)
if bad:
    sys.exit(1)
print(f"ok: recipes agree: {len(spack_defs)} cmake options, LAMMPS sources {sorted(known)}")
PY
  exit $?
fi

rm -rf "$WORK"; mkdir -p "$WORK"; WORK=$(cd "$WORK" && pwd)
SRC=$(realpath "$SRC") LMP_GRANPEN=$(realpath "$LMP_GRANPEN") BED=$(realpath "$BED") TRACE_AGREE=$(realpath "$TRACE_AGREE")
LBUILD=$("$ROOT/tests/launcher/plugin_lammps.sh" "$SRC" "$WORK")
( cd "$WORK" && SRC_DIR=$ROOT PREFIX=$WORK/prefix CPU_COUNT=${GRANPEN_JOBS:-$(nproc)} LAMMPS_SRC=$SRC \
    GRANPEN_POSTPROCESSOR=OFF "$BUILD_SH" ) > "$WORK/build.log" 2>&1 || { tail -30 "$WORK/build.log"; echo "FAIL: build.sh"; exit 1; }
mv "$WORK/prefix" "$WORK/moved"
P=$WORK/moved
for f in lib/granpen/granpenplugin.so share/granpen/plugin.lmp share/granpen/inputs/in.push share/doc/granpen/LICENSE; do
  [ -e "$P/$f" ] || { echo "FAIL: build.sh installed no $f"; exit 1; }
done
cat > "$WORK/in.installed_plugin_push" <<'DECK'
include ${granpen_prefix}/share/granpen/plugin.lmp
include ${inputs}/in.push
DECK
# the same styles, compiled by the recipe's Release flags, on the same LAMMPS: the trace agrees
# to round-off (1e-12 of the force), as in the plugin test (the one push-and-compare of both)
"$ROOT/tests/launcher/plugin_push_agrees.sh" "$WORK" "$LMP_GRANPEN" "$LBUILD/lmp" "$P/share/granpen/inputs" "$BED" \
  "$TRACE_AGREE" "$WORK/in.installed_plugin_push" -var granpen_prefix "$P"
echo "ok: the recipe's build.sh built and installed the plugin; loaded from the moved prefix it gives lmp_granpen's trace"
