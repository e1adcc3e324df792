#!/usr/bin/env bash
# A sweep with one failing push: exit status 1, the failure named with LAMMPS's ERROR line
# (in the output and the manifest), and the other push done.
# Then a second sweep file with the same name adds a push from the same bed, and the manifest
# keeps the runs of both files.
#   expect_one_failure.sh CLI SWEEP_FILE OUT SECOND_SWEEP_FILE
set -uo pipefail
CLI=$1 SPEC=$2 OUT=$3 MORE=$4
rm -rf "$OUT/one_fails"; mkdir -p "$OUT"    # run alone, no other test has made OUT
"$CLI" sweep "$SPEC" --out "$OUT" --jobs 2 > "$OUT/one_fails.txt" 2>&1
rc=$?
cat "$OUT/one_fails.txt"
[ "$rc" = 1 ] || { echo "exit status $rc, expected 1"; exit 1; }
grep -q "FAILED tiny_s1_v200_D0.3 in .*: ERROR: Create_rod: rod diameter must exceed the sphere diameter" \
  "$OUT/one_fails.txt" || { echo "the failure was not reported"; exit 1; }
run() { "$CLI" get "$OUT/one_fails/manifest.json" "runs[id=$1].kind" "runs[id=$1].status" 2>&1; }    # "KIND<tab>STATUS"
[ "$(run tiny_s1_v200_D0.3)" = "$(printf 'push\tfailed')" ] || { echo "the manifest does not record the failure"; exit 1; }
[ "$(run tiny_s1_v200_D2.0)" = "$(printf 'push\tdone')" ] || { echo "the other push did not complete"; exit 1; }
echo "one failure reported, the rest done"
"$CLI" sweep "$MORE" --out "$OUT" --jobs 2 > "$OUT/one_more.txt" 2>&1
rc=$?
cat "$OUT/one_more.txt"
[ "$rc" = 0 ] || { echo "the second sweep file: exit status $rc, expected 0"; exit 1; }
grep -q "2 runs (1 already done)" "$OUT/one_more.txt" || { echo "the second file did not reuse the bed"; exit 1; }
for id in tiny_s1_v200_D0.3 tiny_s1_v200_D2.0 tiny_s1_v300_D2.0 bed_tiny_s1; do
  [ "$("$CLI" get "$OUT/one_fails/manifest.json" 'runs[*].id' | grep -cx "$id")" = 1 ] \
    || { echo "the merged manifest does not list $id once"; cat "$OUT/one_fails/manifest.json"; exit 1; }
done
echo "the second file's push added, the manifest keeps both files' runs"
