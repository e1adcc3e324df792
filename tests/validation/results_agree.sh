#!/usr/bin/env bash
# docs/results.md's numbers are what validation/results.sh computes from the committed
# traces: regenerate them (without the dumps, which are not committed) and compare every
# line the traces alone give with docs/results/numbers.txt.
#   results_agree.sh CLI OUT
set -euo pipefail
CLI=$1 OUT=$2
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
rm -rf "$OUT"
GRANPEN_CLI=$CLI "$ROOT/validation/results.sh" --out "$OUT" --dumps /nonexistent > "$OUT.log" 2>&1 \
  || { cat "$OUT.log"; exit 1; }
n=0 bad=0
while IFS= read -r line; do
  key=${line%% = *}
  committed=$(grep -F "$key = " "$ROOT/docs/results/numbers.txt" | head -1 || true)
  n=$((n + 1))
  if [ "${committed%%  #*}" != "${line%%  #*}" ]; then
    echo "differs: $key"; echo "  regenerated: $line"; echo "  committed:   $committed"; bad=$((bad + 1))
  fi
done < "$OUT/numbers.txt"
echo "$n numbers regenerated, $bad differ from docs/results/numbers.txt"
[ "$n" -gt 50 ] && [ "$bad" = 0 ]
