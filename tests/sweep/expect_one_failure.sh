#!/usr/bin/env bash
# A sweep with one failing push: exit status 1, the failure named with LAMMPS's ERROR line
# (in the output and the manifest), and the other push done.
#   expect_one_failure.sh CLI SWEEP_FILE OUT
set -uo pipefail
CLI=$1 SPEC=$2 OUT=$3
rm -rf "$OUT/one_fails"
"$CLI" sweep "$SPEC" --out "$OUT" --jobs 2 > "$OUT/one_fails.txt" 2>&1
rc=$?
cat "$OUT/one_fails.txt"
[ "$rc" = 1 ] || { echo "exit status $rc, expected 1"; exit 1; }
grep -q "FAILED tiny_s1_v200_D0.3 in .*: ERROR: Create_rod: rod diameter must exceed the sphere diameter" \
  "$OUT/one_fails.txt" || { echo "the failure was not reported"; exit 1; }
grep -q '"id": "tiny_s1_v200_D0.3", "kind": "push", "status": "failed"' "$OUT/one_fails/manifest.json" \
  || { echo "the manifest does not record the failure"; exit 1; }
grep -q '"id": "tiny_s1_v200_D2.0", "kind": "push", "status": "done"' "$OUT/one_fails/manifest.json" \
  || { echo "the other push did not complete"; exit 1; }
echo "one failure reported, the rest done"
