#!/usr/bin/env bash
# docs/package.md lists exactly the styles src/ registers (FixStyle, ComputeStyle,
# CommandStyle lines of src/*.h), each with its doc page, and every page exists.
#   package_doc_lists_styles.sh PROJECT_DIR
set -euo pipefail
ROOT=$1
registered=$(sed -n -E 's/^(Fix|Compute|Command)Style\(([^,]+),.*/\1 \2/p' "$ROOT"/src/*.h |
  awk '{k = tolower($1); print (k == "command" ? $2 : k " " $2)}' | sort)
documented=$(awk -F'|' '/^\| `/ {gsub(/`/, "", $2); gsub(/^ +| +$/, "", $2); print $2}' "$ROOT/docs/package.md" |
  grep -E '^(fix|compute) |^[a-z_]+$' | sort)
if [ "$registered" != "$documented" ]; then
  echo "docs/package.md and src/ differ:"; diff <(echo "$registered") <(echo "$documented") || true; exit 1
fi
n=0
while read -r style; do
  page=$(echo "$style" | tr ' /' '__').rst
  [ -f "$ROOT/docs/$page" ] || { echo "no page docs/$page for $style"; exit 1; }
  grep -q "($page)" "$ROOT/docs/package.md" || { echo "docs/package.md does not link $page"; exit 1; }
  n=$((n + 1))
done <<< "$registered"
echo "docs/package.md lists the $n registered styles"
