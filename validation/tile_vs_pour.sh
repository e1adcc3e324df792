#!/usr/bin/env bash
# Is a bed poured as tiles and replicated (in.pour -var tile N) the same bed as one poured
# directly? The test of docs/presets.md, "dg10", at bench scale, where it is cheap and
# stricter than dg10's: the bench box (8 x 8 cm, 0.4 cm grains) poured as 2 x 2 tiles of
# 4 x 4 cm, 10 grain diameters (dg10's tiles are 25). Three tile beds (seeds 11, 12, 13),
# each pushed at 100 cm/s to 4 cm (in.push -var preset bench), against the five directly
# poured bench beds whose traces are committed (data/sims/v0_bench, seeds 1 and 2, and
# data/sims/v0_bench_ensemble, seeds 3 to 5; their z_s and phi_0 from the sweeps' manifests).
# Compared: phi_0, z_s, the mean drag over z = 1 to 3 cm, the peak force (largest F over
# z = 0 to 1 cm) and k_z over 1 to 3 cm (granpen fit; at 100 cm/s the bench push ends at
# t~ = 0.9, before the linear regime, so this slope is mostly the force's fluctuations of
# wavelength d_g and is the least telling of the five); each by Welch's t: the difference of the two means in standard errors of the
# difference, against t(0.995) at the Welch-Satterthwaite degrees of freedom (rounded
# down, so the test is conservative): about 1% false alarms for a true equality.
# Also, two controls:
#   * a direct bench pour (seed 11) and push with the decks as they are now, that the
#     committed direct beds (made by earlier decks) are still today's physics;
#   * the tile bed of seed 11 rebuilt with untile_relax (one pour chunk, 10000 steps of
#     5e-6 s) and pushed: the effect of the contact histories the data file does not keep
#     (the largest displacement the relaxation makes, and the drag against the unrelaxed bed).
#   validation/tile_vs_pour.sh [--work DIR] [--save DIR] [--seeds "11 12 13"] [--no-control]
#   --work DIR   where the runs go (default: a new folder under /tmp); runs already there
#                (a .info or a trace with its log's "done") are not redone
#   --save DIR   copy the tiles (.tile.data.gz, .tile.info), the beds' .info, the traces and
#                the summary there (default data/sims/tile_bench: small files, committed)
#   --seeds "S..." the tile beds' seeds (default 11 12 13; more seeds, a sharper test)
#   --no-control skip the direct pour and the relaxed rebuild (about half the CPU time)
# One run at a time, at the niceness this script is started with (start it with nice).
# Cost on a quiet core: three tile pours of about 25 s, a direct pour of 60 to 100 s,
# a relaxation of about 10 s and five pushes of about 15 s.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
WORK="" SAVE=$ROOT/data/sims/tile_bench CONTROL=1 SEEDS="11 12 13"
while [ $# -gt 0 ]; do
  case $1 in
    --work) WORK=$2; shift 2 ;;
    --save) SAVE=$2; shift 2 ;;
    --seeds) SEEDS=$2; shift 2 ;;
    --no-control) CONTROL=0; shift ;;
    *) echo "tile_vs_pour.sh: unknown argument $1 (see the header of $0)" >&2; exit 2 ;;
  esac
done
LMP=${GRANPEN_LMP:-$ROOT/build/lmp_granpen} CLI=${GRANPEN_CLI:-$ROOT/build/analysis/granpen-cli}
INPUTS=${GRANPEN_INPUTS:-$ROOT/inputs}
[ -x "$LMP" ] || { echo "tile_vs_pour.sh: no lmp_granpen at $LMP (set GRANPEN_LMP)" >&2; exit 2; }
[ -x "$CLI" ] || { echo "tile_vs_pour.sh: no granpen-cli at $CLI (set GRANPEN_CLI)" >&2; exit 2; }
[ -n "$WORK" ] || WORK=$(mktemp -d /tmp/tile_vs_pour.XXXXXX)
mkdir -p "$WORK" "$SAVE"; cd "$WORK"
[[ $SEEDS =~ ^[1-9][0-9]*( [1-9][0-9]*)+$ ]] || { echo "tile_vs_pour.sh: --seeds '$SEEDS' is not two or more positive whole numbers" >&2; exit 2; }
DIRECT_TRACES=("$ROOT"/data/sims/v0_bench/bench_mu0.3_s{1,2}_v100.csv "$ROOT"/data/sims/v0_bench_ensemble/bench_mu0.3_s{3,4,5}_v100.csv)
for f in "${DIRECT_TRACES[@]}"; do [ -f "$f" ] || { echo "tile_vs_pour.sh: missing $f" >&2; exit 1; }; done

pour() {    # NAME, in.pour arguments...
  local name=$1; shift
  [ -f "$name.info" ] && return 0
  echo "pour $name" >&2
  "$LMP" -in "$INPUTS/in.pour" -var inputs "$INPUTS" -var preset bench -var out "$name" "$@" \
    -log "$name.log" -screen none >/dev/null || { echo "FAIL: pour $name (see $WORK/$name.log)"; exit 1; }
}
push() {    # BED (NAME of NAME.restart): trace push_NAME.csv
  local bed=$1
  [ -f "push_$bed.log" ] && grep -q "granpen push: done" "push_$bed.log" && return 0
  echo "push $bed" >&2
  "$LMP" -in "$INPUTS/in.push" -var inputs "$INPUTS" -var preset bench -var bed "$bed.restart" -var v0 100 \
    -var trace "push_$bed.csv" -log "push_$bed.log" -screen none >/dev/null || { echo "FAIL: push $bed (see $WORK/push_$bed.log)"; exit 1; }
}
for s in $SEEDS; do pour "tile_s$s" -var seed "$s" -var tile 2; push "tile_s$s"; done
if [ "$CONTROL" = 1 ]; then
  pour direct_s11 -var seed 11; push direct_s11
  pour relaxed_s11 -var tile 2 -var from_tile tile_s11 -var untile_relax 10000; push relaxed_s11
fi

info() { awk -F' = ' -v k="$2" '$1 == k {print $2}' "$1"; }
manifest() {    # KEY of the direct beds, seeds 1 to 5
  for m in "$ROOT"/data/sims/v0_bench/manifest.json "$ROOT"/data/sims/v0_bench_ensemble/manifest.json; do
    "$CLI" get "$m" 'runs[*].id' "runs[*].$1" --missing '' | awk -F'\t' '$1 ~ /^bed_bench_mu0\.3_s[0-9]+$/ && $2 != "" { print $2 }'
  done
}
peakf() { awk -F, '!/^#/ && $1 != "t" && $2 >= 0.0 && $2 <= 1.0 && $3 > m {m = $3} END {printf "%.9g\n", m}' "$1"; }
meanf() { awk -F, '!/^#/ && $1 != "t" && $2 >= 1.0 && $2 <= 3.0 {s += $3; n++} END {printf "%.9g\n", s / n}' "$1"; }
kz() { "$CLI" fit "$1" --zmin 1 --zmax 3 --csv kz.csv >/dev/null 2>&1 || { echo "FAIL: granpen fit $1"; exit 1; }
       awk -F, 'NR == 1 {for (i = 1; i <= NF; i++) if ($i == "k_z") c = i; next} {print $c}' kz.csv; }

direct_q() {    # QUANTITY: values of the five direct beds
  case $1 in
    phi_0|z_s) manifest "$1" ;;
    drag) for f in "${DIRECT_TRACES[@]}"; do meanf "$f"; done ;;
    peak) for f in "${DIRECT_TRACES[@]}"; do peakf "$f"; done ;;
    k_z) for f in "${DIRECT_TRACES[@]}"; do kz "$f"; done ;;
  esac
}
bed_q() {    # QUANTITY BED
  case $1 in
    phi_0|z_s) info "$2.info" "$1" ;;
    drag) meanf "push_$2.csv" ;;
    peak) peakf "push_$2.csv" ;;
    k_z) kz "push_$2.csv" ;;
  esac
}

SUM=$WORK/summary.txt
{
echo "# validation/tile_vs_pour.sh: bench beds poured as 2 x 2 tiles of 4 x 4 cm (seeds $SEEDS) against"
echo "# the five direct bench beds of data/sims/v0_bench{,_ensemble} (seeds 1-5); pushes at 100 cm/s."
echo "# drag: mean F over z = 1-3 cm (dyne); peak: largest F over z = 0-1 cm (dyne); k_z: granpen fit"
echo "# --zmin 1 --zmax 3 (dyne/cm; mostly fluctuations at 100 cm/s on the bench, t~ < 0.9)."
echo "# mean +- sd (n); difference in standard errors of the difference (Welch), limit t(0.995, dof)."
} > "$SUM"
status=0
for q in phi_0 z_s drag peak k_z; do
  a=$(direct_q "$q" | tr '\n' ' ')
  b=$(for s in $SEEDS; do bed_q "$q" "tile_s$s"; done | tr '\n' ' ')
  awk -v a="$a" -v b="$b" -v q="$q" 'function stats(str, arr,   n, i, m, v) {
      n = split(str, arr, " "); m = 0; for (i = 1; i <= n; i++) m += arr[i]; m /= n
      v = 0; for (i = 1; i <= n; i++) v += (arr[i] - m)^2; v /= (n - 1); M = m; V = v; N = n }
    BEGIN { split("63.657 9.925 5.841 4.604 4.032 3.707 3.499 3.355 3.250 3.169", T, " ")
      stats(a, x); m1 = M; v1 = V; n1 = N; stats(b, y); m2 = M; v2 = V; n2 = N
      se2 = v1 / n1 + v2 / n2; se = sqrt(se2); d = m2 - m1
      dof = se2^2 / ((v1 / n1)^2 / (n1 - 1) + (v2 / n2)^2 / (n2 - 1)); k = int(dof); if (k < 1) k = 1; if (k > 10) k = 10
      ts = (se > 0 ? d / se : 0)
      printf "%-6s direct %.6g +- %.3g (%d)  tiles %.6g +- %.3g (%d)  difference %+.3g (%+.2f%%) = %+.2f se, limit %.2f (dof %.1f)\n",
        q, m1, sqrt(v1), n1, m2, sqrt(v2), n2, d, 100 * d / m1, ts, T[k], dof
      exit ((ts < 0 ? -ts : ts) <= T[k] ? 0 : 1) }' >> "$SUM" || { echo "$q: DIFFERS beyond the limit" >> "$SUM"; status=1; }
  echo "  direct:$(echo " $a" | sed 's/ / /g')" >> "$SUM"
  echo "  tiles: $b" >> "$SUM"
done
if [ "$CONTROL" = 1 ]; then
  {
  echo "# controls"
  echo "direct pour with today's decks, seed 11: phi_0 $(bed_q phi_0 direct_s11), z_s $(bed_q z_s direct_s11), drag $(bed_q drag direct_s11), peak $(bed_q peak direct_s11), k_z $(bed_q k_z direct_s11)"
  echo "tile bed seed 11 rebuilt with untile_relax 10000: $(grep '^granpen pour: untile_relax' relaxed_s11.log | sed 's/^granpen pour: //')"
  echo "  phi_0 $(bed_q phi_0 relaxed_s11) (unrelaxed $(bed_q phi_0 tile_s11)), z_s $(bed_q z_s relaxed_s11) (unrelaxed $(bed_q z_s tile_s11)),"
  echo "  drag $(bed_q drag relaxed_s11) (unrelaxed $(bed_q drag tile_s11)), peak $(bed_q peak relaxed_s11) (unrelaxed $(bed_q peak tile_s11)),"
  echo "  k_z $(bed_q k_z relaxed_s11) (unrelaxed $(bed_q k_z tile_s11))"
  } >> "$SUM"
fi
echo "# tile pours: $(for s in $SEEDS; do echo -n "$(info tile_s$s.tile.info wall_seconds) s, "; done)pushes: $(for s in $SEEDS; do awk '/^Loop time/ {t += $4} END {printf "%.1f s, ", t}' push_tile_s$s.log; done)(loop time, this machine)" >> "$SUM"
cat "$SUM"

# the small artefacts, to be committed
for s in $SEEDS; do cp "tile_s$s.tile.data.gz" "tile_s$s.tile.info" "tile_s$s.info" "push_tile_s$s.csv" "$SAVE/"; done
if [ "$CONTROL" = 1 ]; then cp direct_s11.info push_direct_s11.csv relaxed_s11.info push_relaxed_s11.csv "$SAVE/"; fi
cp "$SUM" "$SAVE/summary.txt"
[ $status = 0 ] && echo "tile beds agree with direct pours" || echo "FAIL: a quantity differs (summary above)"
exit $status
