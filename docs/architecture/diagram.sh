#!/bin/sh
# Regenerates docs/architecture/targets.png, the picture of docs/architecture.md, from the
# CMake targets of a configured build (cmake --graphviz, then Graphviz's dot).
#   docs/architecture/diagram.sh [BUILD_DIR]      (default: build)
# Needs cmake and dot (apt-get install graphviz).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "${1:-build}" && pwd)
command -v dot > /dev/null || { echo "diagram.sh: needs dot (apt-get install graphviz)" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"; rm -f "$build/CMakeGraphVizOptions.cmake"' EXIT
cp "$here/graphviz_options.cmake" "$build/CMakeGraphVizOptions.cmake"
(cd "$build" && cmake --graphviz="$tmp/targets.dot" . > "$tmp/cmake.log") || { cat "$tmp/cmake.log" >&2; exit 1; }
dot -Tpng -Gdpi=72 "$tmp/targets.dot" -o "$tmp/targets.png"
mv "$tmp/targets.png" "$here/targets.png"
echo "wrote $here/targets.png"
