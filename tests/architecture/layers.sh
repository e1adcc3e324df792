#!/bin/sh
# layers.sh: fails when a layer includes a header of a layer above it. The layers, lowest
# first: src (the LAMMPS package and its pure kernels), analysis/core, analysis/io,
# analysis/sweep, analysis/gap, analysis/cli. A file may include headers of its own layer
# and of the layers below; src/ includes nothing of analysis/. A header is known by its
# file name (the layers' include roots are flat); names found in no layer (system,
# LAMMPS, Voro++ headers) are not checked.
#   layers.sh [--self-test] [ROOT]
# Exit: 0 clean, 1 an include goes up, 2 usage. Needs only sh, find and awk.
set -u
root=.
self_test=no
while [ $# -gt 0 ]; do
  case "$1" in
    --self-test) self_test=yes; shift ;;
    -h|--help) sed -n '2,9p' "$0"; exit 0 ;;
    -*) echo "layers.sh: unknown option $1" >&2; exit 2 ;;
    *) root=$1; shift ;;
  esac
done

LAYERS="src analysis/core analysis/io analysis/sweep analysis/gap analysis/cli"

check() {
  croot=$1
  [ -d "$croot/src" ] && [ -d "$croot/analysis" ] || { echo "layers.sh: $croot has no src/ and analysis/" >&2; return 2; }
  # "rank dir file" for every source file of every layer, then each include line
  (
    cd "$croot" || exit 2
    rank=0
    for dir in $LAYERS; do
      [ -d "$dir" ] && find "$dir" -maxdepth 1 \( -name '*.h' -o -name '*.cpp' \) | sort | sed "s|^|$rank |"
      rank=$((rank + 1))
    done
  ) > "$tmp/files"
  awk -v root="$croot" -v layers="$LAYERS" '
    BEGIN { n = split(layers, name, " ") }
    FNR == NR {
      f = $2; b = f; sub(/.*\//, "", b)
      rank[f] = $1
      if (b ~ /\.h$/) {
        if ((b in owner) && owner[b] != $1) print "note: " b " is in two layers; the lower counts"
        if (!(b in owner) || $1 < owner[b]) owner[b] = $1
      }
      files[++nf] = f
      next
    }
    END {
      for (i = 1; i <= nf; i++) {
        f = files[i]; line = 0
        while ((getline l < (root "/" f)) > 0) {
          line++
          if (l !~ /^[ \t]*#[ \t]*include[ \t]*"/) continue
          h = l; sub(/^[^"]*"/, "", h); sub(/".*/, "", h); sub(/.*\//, "", h)
          if (!(h in owner)) continue
          checked++
          if (owner[h] > rank[f]) {
            printf "%s:%d: %s (layer %s) includes %s of %s, a layer above it\n", f, line, f, name[rank[f] + 1], h, name[owner[h] + 1]
            bad++
          }
        }
        close(root "/" f)
      }
      printf "%d files, %d includes of the layers checked: %d going up\n", nf, checked, bad
      exit bad ? 1 : 0
    }' "$tmp/files" "$tmp/files"
}

tmp=$(mktemp -d) || exit 2
trap 'rm -rf "$tmp"' EXIT

if [ "$self_test" = yes ]; then
  # a fixture tree: clean, it passes; core including an io header, or src including an
  # analysis header, fails and is named
  t="$tmp/tree"
  for d in $LAYERS; do mkdir -p "$t/$d"; done
  echo '#include "kernel.h"' > "$t/src/kernel.cpp"; : > "$t/src/kernel.h"
  printf '#include "kernel.h"\n#include <vector>\n#include "lammps.h"\n' > "$t/analysis/core/fields.cpp"
  : > "$t/analysis/core/fields.h"; : > "$t/analysis/io/reader.h"
  printf '#include "fields.h"\n#include "reader.h"\n' > "$t/analysis/gap/stage.cpp"
  printf '#include "stage.h"\n#include "reader.h"\n' > "$t/analysis/cli/main.cpp"; : > "$t/analysis/gap/stage.h"
  check "$t" || { echo "SELF-TEST FAILED: a clean tree fails"; exit 1; }
  printf '#include "kernel.h"\n#include "reader.h"    // up\n' > "$t/analysis/core/fields.cpp"
  out=$(check "$t"); rc=$?
  echo "$out"
  case "$out" in *"analysis/core/fields.cpp:2: analysis/core/fields.cpp (layer analysis/core) includes reader.h of analysis/io"*) ;;
    *) echo "SELF-TEST FAILED: core including io not reported"; exit 1 ;; esac
  [ $rc -eq 1 ] || { echo "SELF-TEST FAILED: exit $rc, 1 expected"; exit 1; }
  printf '#include "kernel.h"\n' > "$t/analysis/core/fields.cpp"
  echo '#include "fields.h"' >> "$t/src/kernel.cpp"
  check "$t" > /dev/null && { echo "SELF-TEST FAILED: src including analysis/core passes"; exit 1; }
  echo "self-test passed: the check fails when a layer includes one above it"
  exit 0
fi

check "$root"
