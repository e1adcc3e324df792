#!/usr/bin/env bash
# Writes the manifests the manifest test compares (SweepManifest.* in test_manifest.cpp)
# with fake_lmp (milliseconds): a sweep of 2 pours and 4 pushes, then a second sweep file
# of the same name adding a push (the manifest keeps the first file's runs), then the
# first again (every run skipped).
#   manifest_sweeps.sh CLI FAKE_LMP INPUTS OUT
set -euo pipefail
CLI=$1 FAKE=$2 INPUTS=$3 OUT=$4
rm -rf "$OUT"; mkdir -p "$OUT"
printf 'name = manifest_demo\npreset = tiny\nmu = 0.3\nseeds = 1 2\nv0 = 100 200\ndepth = 0.5\n' > "$OUT/a.sweep"
printf 'name = manifest_demo\npreset = tiny\nmu = 0.3\nseeds = 1\nv0 = 300\ndepth = 0.5\n' > "$OUT/b.sweep"
for s in a b a; do
  "$CLI" sweep "$OUT/$s.sweep" --out "$OUT/runs" --lmp "$FAKE" --inputs "$INPUTS" --jobs 2 > "$OUT/$s.txt" 2>&1 ||
    { cat "$OUT/$s.txt"; echo "manifest_sweeps: sweep $s failed"; exit 1; }
done
echo "manifest_sweeps: wrote $OUT/runs/manifest_demo/manifest.json"
