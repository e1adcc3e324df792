#!/usr/bin/env bash
# Issue 21's design 2 for the gap diagnosis's cost, measured at bench (docs/gap.md, "The
# superposition design"): is friction's signature its push part, paired on the baseline's
# own beds, plus its preparation part, the packing effect's signature at the matching pour
# friction? Runs (granpen sweep, resumable) into OUT:
#   baseline       bench, mu 0.3, seeds 1 2, v0 50 100 200 (the gap's signature beds)
#   friction_015  poured and pushed with mu 0.45 (the direct knot)
#   packing_03    poured with mu 0.6, pushed with 0.3 (the packing knot)
#   friction_push  the baseline's own beds pushed with mu 0.45 (friction_push.sweep)
# then tests/support/superpose_agree per speed, with the diagnosis's kernels (onset
# alignment, G of ../shared/formats/gap-metric.md): once with packing's weight linear in the
# pour friction (w = 0.15 / 0.3 = 0.5) and once matched to the beds' phi_0 (w = (phi(0.45) -
# phi(0.3)) / (phi(0.6) - phi(0.3)), from the beds' .info). About 6 bench pours and 24 pushes:
# half an hour of one core.
#   --cohesion   also cohesion_GAMMA.sweep for gamma 50, 300, 1000, 3000 (two JKR beds each, about
#                an hour more) and each one's signature against the baseline (the docs' table
#                "Cohesion at bench")
#   bench/gap_design2/run.sh [--out DIR] [--jobs N] [--cohesion]
set -euo pipefail
HERE=$(cd "$(dirname "$0")" && pwd)
ROOT=$(cd "$HERE/../.." && pwd)
OUT=$ROOT/runs/gap_design2 JOBS=1 COHESION=no
while [ $# -gt 0 ]; do
  case $1 in
    --out) OUT=$2; shift 2 ;;
    --jobs) JOBS=$2; shift 2 ;;
    --cohesion) COHESION=yes; shift ;;
    *) echo "gap_design2/run.sh: unknown option $1 (see the header of $0)" >&2; exit 2 ;;
  esac
done
[[ $JOBS =~ ^[1-9][0-9]*$ ]] || { echo "gap_design2/run.sh: --jobs $JOBS is not a whole number >= 1" >&2; exit 2; }
CLI=${GRANPEN_CLI:-$ROOT/build/analysis/granpen-cli}
AGREE=${GRANPEN_SUPERPOSE:-$ROOT/build/tests/support/superpose_agree}
export GRANPEN_LMP=${GRANPEN_LMP:-$ROOT/build/lmp_granpen}
for x in "$CLI" "$AGREE" "$GRANPEN_LMP"; do
  [ -x "$x" ] || { echo "gap_design2/run.sh: $x is missing (./granpen build)" >&2; exit 2; }
done
mkdir -p "$OUT"

sweep() {    # NAME KEYS... : one sweep, keys as lines
  local name=$1; shift
  { echo "# granpen sweep v1"; echo "name = $name"; echo "preset = bench"; echo "seeds = 1 2"; echo "v0 = 50 100 200"
    printf '%s\n' "$@"; } > "$OUT/$name.sweep"
  echo "gap_design2: sweep $name"
  "$CLI" sweep "$OUT/$name.sweep" --jobs "$JOBS" --out "$OUT" > "$OUT/$name.log" 2>&1 \
    || { echo "gap_design2/run.sh: sweep $name failed (see $OUT/$name.log)" >&2; exit 1; }
}
# the traces of sweep $1 at v0 = $2 (run ids end in _vV, or go on with _g... where g or D vary)
traces() { ls "$OUT/$1/traces/" | grep -E "_v$2(_.*)?\.csv$" | sort | sed "s#^#$OUT/$1/traces/#" | paste -sd, -; }
phi() { awk -F' = ' '$1 == "phi_0" { s += $2; n++ } END { printf "%.6f", s / n }' "$OUT/$1/beds/"*.info; }

sweep baseline "mu = 0.3"
sweep friction_015 "mu = 0.45" "mu_push = 0.45"
sweep packing_03 "mu = 0.6" "mu_push = 0.3"
# the push part on the baseline's own beds: linked, so the runner takes them as poured
mkdir -p "$OUT/friction_push/beds"
for f in "$OUT/baseline/beds/"*.restart "$OUT/baseline/beds/"*.info; do ln -f "$f" "$OUT/friction_push/beds/"; done
cp "$HERE/friction_push.sweep" "$OUT/friction_push.sweep"
echo "gap_design2: sweep friction_push"
"$CLI" sweep "$OUT/friction_push.sweep" --jobs "$JOBS" --out "$OUT" > "$OUT/friction_push.log" 2>&1 \
  || { echo "gap_design2/run.sh: sweep friction_push failed (see $OUT/friction_push.log)" >&2; exit 1; }

p30=$(phi baseline) p45=$(phi friction_015) p60=$(phi packing_03)
wphi=$(awk -v a="$p30" -v b="$p45" -v c="$p60" 'BEGIN { printf "%.3f", (b - a) / (c - a) }')
echo "phi_0 (mean of two beds): mu 0.3 $p30, 0.45 $p45, 0.6 $p60: packing's weight matched to phi_0 w = $wphi"
for v in 50 100 200; do
  for w in 0.5 "$wphi"; do
    echo "== friction +0.15, w = $w"
    "$AGREE" --v0 "$v" --base "$(traces baseline "$v")" --direct "$(traces friction_015 "$v")" \
      --push "$(traces friction_push "$v")" --pack "$(traces packing_03 "$v")" --w "$w"
  done
done

if [ "$COHESION" = yes ]; then
  for gamma in 50 300 1000 3000; do
    sweep "cohesion_$gamma" "set = cohesion=$gamma"
    # the KE per grain the pour ended with (its last settling check): did the bed settle?
    ke=$(for l in "$OUT/cohesion_$gamma/logs/"bed_*.log; do
           grep -h "granpen pour: .*KE per grain" "$l" | tail -1 | sed 's/.*KE per grain \([^ ]*\) erg.*/\1/'
         done | paste -sd' ' -)
    echo "== cohesion $gamma erg/cm^2: phi_0 $(phi "cohesion_$gamma") (mean of two beds), KE per grain at the end of each pour: $ke erg"
    for v in 50 100 200; do
      "$AGREE" --v0 "$v" --base "$(traces baseline "$v")" --direct "$(traces "cohesion_$gamma" "$v")"
    done
  done
fi
