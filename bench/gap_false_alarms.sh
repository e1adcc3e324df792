#!/usr/bin/env bash
# granpen gap: the false-alarm rate on data without any effect (issue 21). Two sources:
#   - the selftest's no-effect case (bench/gap_selftest.sh --cases none) on SETS seed sets of
#     measured beds each (seeds 1001.., disjoint from every bed the diagnosis simulates), one
#     verdict per set;
#   - the null replicates (the reference beds split into a no-effect measurement and its
#     reference, tested with thresholds from the other replicates: diagnosis.json
#     `false_alarms`); they depend on the cache and the measured runs per speed only, so they
#     are the same in every set and counted once.
# A false alarm is any verdict other than `none`.
#   bench/gap_false_alarms.sh [--scenario tiny|bench] [--sets 10] [--beds 4] [--jobs 2] [--v0 "50 100 200"]
# GRANPEN_LMP, GRANPEN_CLI, GRANPEN_INPUTS and GRANPEN_SELFTEST_WORK as for gap_selftest.sh
# (GRANPEN_LMP=build/tests/fake_lmp: the synthetic world). The cache is shared by the sets,
# so only the first pays for it. The table goes to WORK/SCENARIO/false_alarms.md, with the
# sets' rate and its exact 95% interval (granpen rate). At bench scale on real LAMMPS the
# same sets run as a campaign committed set by set: validation/gap_bench.sh.
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
SCEN=tiny SETS=10 BEDS=4 JOBS=2 V0="50 100 200"
while [ $# -gt 0 ]; do
  case "$1" in
    --scenario) SCEN=$2; shift 2 ;;
    --sets) SETS=$2; shift 2 ;;
    --beds) BEDS=$2; shift 2 ;;
    --jobs) JOBS=$2; shift 2 ;;
    --v0) V0=$2; shift 2 ;;
    *) echo "gap_false_alarms: unknown option $1" >&2; exit 2 ;;
  esac
done
WORK=${GRANPEN_SELFTEST_WORK:-$ROOT/runs/gap_selftest}/$SCEN
CLI=${GRANPEN_CLI:-$ROOT/build/analysis/granpen-cli}
mkdir -p "$WORK"
TABLE=$WORK/false_alarms.md
echo "| set | seeds | verdict | G_all before | null replicates | their verdicts other than none | wall s |" > "$TABLE"
echo "|---|---|---|---|---|---|---|" >> "$TABLE"
alarms=0 nulls=0 null_alarms=0
for k in $(seq 1 "$SETS"); do
  seeds=$(seq $((1000 + (k - 1) * BEDS + 1)) $((1000 + k * BEDS)) | tr '\n' ' ' | sed 's/ $//')
  t0=$(date +%s)
  # a `none` that is right passes; a false alarm is a failed case (exit 1): go on either way
  bash "$ROOT/bench/gap_selftest.sh" --scenario "$SCEN" --jobs "$JOBS" --v0 "$V0" --cases none --seeds "$seeds" \
    > "$WORK/false_alarms_$k.log" 2>&1 || true
  j=$WORK/diag_none/diagnosis.json
  [ -f "$j" ] || { echo "gap_false_alarms: set $k: no diagnosis (see $WORK/false_alarms_$k.log)" >&2; exit 1; }
  cp "$j" "$WORK/false_alarms_$k.json"
  IFS=$'\t' read -r v g n nn < <("$CLI" get "$j" verdict gap_before false_alarms.null_replicates false_alarms.not_none)
  [ "$v" = none ] || alarms=$((alarms + 1))
  [ "$k" = 1 ] && nulls=$n null_alarms=$nn
  printf '| %d | %s | %s | %.3f | %d | %d | %d |\n' "$k" "$seeds" "$v" "$g" "$n" "$nn" $(( $(date +%s) - t0 )) | tee -a "$TABLE"
done
{
  echo
  echo "data sets without an effect: $alarms false alarm(s) in $SETS ($(awk -v a=$alarms -v n=$SETS 'BEGIN{printf "%.3f", a / n}'))"
  echo "null replicates: $null_alarms false alarm(s) in $nulls ($(awk -v a=$null_alarms -v n=$nulls 'BEGIN{printf "%.3f", n ? a / n : 0}'))"
  echo "together: $((alarms + null_alarms)) in $((SETS + nulls)) ($(awk -v a=$((alarms + null_alarms)) -v n=$((SETS + nulls)) 'BEGIN{printf "%.3f", a / n}'))"
  # the sets' rate with its exact 95% interval (granpen rate: Clopper-Pearson)
  if [ "$SETS" -gt 0 ]; then
    read -r _ _ r lo hi _ < <("$CLI" rate "$alarms" "$SETS")
    echo "data sets without an effect: rate $r, 95% interval $lo to $hi (exact)"
  fi
} | tee -a "$TABLE"
