#!/usr/bin/env bash
# validation/push_flow.sh on a real push with dumps (the tiny bed, 1.6 cm at 200 cm/s,
# a frame every 250 steps = 0.125 cm of travel): the analysis docs/results.md and
# validation/dg10.sh run on the mid and dg10 flow pushes. Checks, each of which a broken
# window or a lost option fails:
#   - the window holds exactly the frames whose tip (granpen flow's z_tip over every frame)
#     is 0.5 to 1.2 cm deep, and no other;
#   - the fields were made over those frames only (flow/flow.json lists them);
#   - window.txt records them; lambda_vz and the momentum fit are numbers;
#   - a window no frame reaches exits 1 naming the depths, without window.txt; a malformed
#     --tip exits 2 naming it.
#   push_flow_window.sh LMP CLI BED OUT
set -euo pipefail
LMP=$1 CLI=$2 BED=$3 OUT=$4
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
rm -rf "$OUT"; mkdir -p "$OUT"
fail() { echo "FAIL: $*"; exit 1; }

"$LMP" -in "$ROOT/inputs/in.push" -var inputs "$ROOT/inputs" -var preset tiny -var bed "$BED" -var v0 200 \
  -var depth 1.6 -var trace "$OUT/push.csv" -var observe "$ROOT/inputs/observe/dump.lmp" -var dump_every 250 \
  -log "$OUT/push.log" -screen none > /dev/null || fail "the push failed ($OUT/push.log)"
ls "$OUT"/push.csv.*.dump.gz > /dev/null 2>&1 || fail "the push wrote no dumps"

"$ROOT/validation/push_flow.sh" "$OUT/push.csv" "$OUT/a" --cli "$CLI" --tip "0.5 1.2" > "$OUT/a.steps" 2> "$OUT/a.err" \
  || { cat "$OUT/a.err"; fail "push_flow.sh failed"; }
steps=$(cat "$OUT/a.steps")
read -r first last <<< "${steps/:/ }"
echo "window: $steps"
# (timestep, z_tip) of every frame, from the pass over every frame
"$CLI" get "$OUT/a/surface/flow.json" 'frames[*].timestep' 'frames[*].z_tip' > "$OUT/tips.txt"
[ "$(wc -l < "$OUT/tips.txt")" -ge 10 ] || fail "fewer than 10 frames in $OUT/a/surface/flow.json"
# inside the window exactly the frames 0.5 to 1.2 cm deep (the tip moves down monotonically)
bad=$(awk -v a="$first" -v b="$last" '{ inside = ($1 >= a && $1 <= b); deep = ($2 >= 0.5 && $2 <= 1.2)
  if (inside != deep) print }' "$OUT/tips.txt")
[ -z "$bad" ] || fail "frames on the wrong side of the window $steps (timestep z_tip): $bad"
nin=$(awk -v a="$first" -v b="$last" '$1 >= a && $1 <= b' "$OUT/tips.txt" | wc -l)
[ "$nin" -ge 3 ] || fail "only $nin frames in the window"
# the fields' pass read those frames and no others
nfields=$("$CLI" get "$OUT/a/flow/flow.json" 'frames[*].timestep' | wc -l)
[ "$nfields" = "$nin" ] || fail "the fields were made over $nfields frames, the window holds $nin"
[ "$(cat "$OUT/a/window.txt")" = "$steps 0.5 1.2" ] || fail "window.txt: $(cat "$OUT/a/window.txt")"
isnum() { awk -v x="$1" 'BEGIN { exit !(x ~ /^[-+]?[0-9.]+([eE][-+]?[0-9]+)?$/) }'; }
isnum "$("$CLI" get "$OUT/a/flow/flow.json" profile_below.lambda_vz.lambda_D)" || fail "no lambda_vz in the fields"
isnum "$("$CLI" get "$OUT/a/momentum/momentum.json" drag.k)" || fail "no momentum fit"

# a window below the deepest frame: exit 1, named, no window.txt
set +e
"$ROOT/validation/push_flow.sh" "$OUT/push.csv" "$OUT/b" --cli "$CLI" --tip "5 6" > /dev/null 2> "$OUT/b.err"; rc=$?
set -e
[ "$rc" = 1 ] || fail "a window no frame reaches exited $rc"
grep -q "has its tip 5 to 6 cm deep" "$OUT/b.err" || fail "no named error: $(cat "$OUT/b.err")"
[ ! -e "$OUT/b/window.txt" ] || fail "window.txt written for an empty window"
set +e
"$ROOT/validation/push_flow.sh" "$OUT/push.csv" "$OUT/c" --cli "$CLI" --tip "deep" > /dev/null 2> "$OUT/c.err"; rc=$?
set -e
[ "$rc" = 2 ] && grep -q -- '--tip "deep"' "$OUT/c.err" || fail "a malformed --tip: exit $rc, $(cat "$OUT/c.err")"
echo "push_flow.sh: window of $nin frames, fields over them, errors named"
