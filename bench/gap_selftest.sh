#!/usr/bin/env bash
# granpen gap, checked on data whose effect is withheld (issue: gap diagnosis).
#   bench/gap_selftest.sh [--scenario bench|tiny] [--jobs N] [--cases LIST] [--effects LIST] [--v0 "50 100 200"]
#                         (--cases may name the below-limit cases EFFECT_half and the opt-in effects' cases too:
#                          see below_limit_cases, opt_in_cases)
#                         [--seeds "101 102 103 104"] [--measured-only]   (make the measured data only)
#                         [--max-mean-cost P]   (fail when the mean cold cost per case exceeds P probe pours)
#                         [--prior-seeds "41 42"]   (a signature prior of the scenario on those beds, written
#                                                    once by `granpen gap --write-prior` in its own cache and
#                                                    given to every diagnosis: docs/gap.md, "The adaptive plan")
#                         [--no-prior]   (every diagnosis without a prior, even the scenario's committed one)
# For each case it makes "measured" data: a sweep of the scenario with one effect at a
# magnitude the diagnosis is not told (or none, or an effect outside the library: grains
# lighter than the header says), on beds no diagnosis uses (seeds 101 to 104); every trace's
# header is cut to the standard keys (units v0 D d_g rho_g g run mu), its depth origin moved
# by a random offset up to +-0.2 cm and 2% noise added to F. Then `granpen gap` runs
# blind on it, and `granpen gap-score` scores the case (analysis/gap/gap_selftest_score.h):
# the right top effect for library cases, "none" for the no-effect case, no confident wrong
# effect for the outside case (force_scale at the grains' density ratio less 1 is right for
# lighter grains: outside_as), G_all shrunk as an explained verdict requires where explained;
# a library case whose true magnitude lies below its detection limit in this data
# (diagnosis.json detection_limits) may be missed (none or unexplained), one above it may not
# (issue 21). Everything is cached in runs/gap_selftest (resumable); the table goes
# to runs/gap_selftest/SCENARIO/table.md (docs/gap-validation.md quotes it).
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
SCEN=bench JOBS=2 CASES="" EFFECTS="" V0="50 100 200" MEASURED_ONLY=no SEEDS="101 102 103 104" MAX_MEAN_COST="" PRIOR_SEEDS="" NO_PRIOR=no
while [ $# -gt 0 ]; do
  case "$1" in
    --scenario) SCEN=$2; shift 2 ;;
    --jobs) JOBS=$2; shift 2 ;;
    --cases) CASES=$2; shift 2 ;;
    --effects) EFFECTS=$2; shift 2 ;;
    --v0) V0=$2; shift 2 ;;
    --seeds) SEEDS=$2; shift 2 ;;
    --measured-only) MEASURED_ONLY=yes; shift ;;
    --max-mean-cost) MAX_MEAN_COST=$2; shift 2 ;;
    --prior-seeds) PRIOR_SEEDS=$2; shift 2 ;;
    --no-prior) NO_PRIOR=yes; shift ;;
    *) echo "gap_selftest: unknown option $1" >&2; exit 2 ;;
  esac
done
CLI=${GRANPEN_CLI:-$ROOT/build/analysis/granpen-cli}
export GRANPEN_LMP=${GRANPEN_LMP:-$ROOT/build/lmp_granpen} GRANPEN_INPUTS=${GRANPEN_INPUTS:-$ROOT/inputs}
[ "$(id -u)" = 0 ] && export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
WORK=${GRANPEN_SELFTEST_WORK:-$ROOT/runs/gap_selftest}/$SCEN
mkdir -p "$WORK"

# case: name | truth (expected top effect, or none / outside; two effects at once: A,B) | magnitude said in the table
# (A,B: X,Y) | sweep keys (; between lines). chain_ramp: the mount at 2.4 ms (natural frequency 417 Hz, its reading
# peaking near 400 Hz; k = m (2 pi / T)^2, c = 2 zeta sqrt(k m), zeta 0.2) with a 1.2 cm ramp (issue 37)
all_cases() {
  cat <<'CASES'
none|none|0|
rolling_resistance|rolling_resistance|0.2|set = mu_roll=0.2
polydispersity|polydispersity|0.22|set = poly=0.22
sidewalls|sidewalls|0.5|set = walls=1 mu_wall=0.5
measurement_chain|measurement_chain|1.0|push_set = mount_k=3.947842e9 mount_c=2.513274e5 mount_m=100
actuator_ramp|actuator_ramp|2.4|push_set = ramp=2.4
packing|packing|-0.18|mu = 0.12
contact_stiffness|contact_stiffness|-0.5|set = kn=3.16228e8 kt=3.16228e8
friction|friction|0.1|mu = 0.4;mu_push = 0.4
cohesion|cohesion|1800|set = cohesion=1800
rod_friction|rod_friction|-0.15|push_set = dmu_rod=-0.15
light_grains|outside|rho_g 2.5 (header says 3.0)|set = rho_g=2.5
chain_ramp|measurement_chain,actuator_ramp|2.4,1.2|push_set = mount_k=6.853892e8 mount_c=1.047198e5 mount_m=100 ramp=1.2
CASES
}

# Below-limit cases (issue 37, section 0): each library effect at about half its detection
# limit on bench (4 measured beds a speed; limits of docs/gap-validation.md, 2026-11-27, on
# real LAMMPS: rolling 0.041, the mount 0.071 ms, ramp 1.27 cm, packing -0.13, stiffness
# -0.20, force_scale 0.09 to 0.13; where that data had no limit within the knots, half the
# nearest knot). A miss is right, and so is the truth named (alone or in a tie); another
# effect named alone is a confident wrong answer (gap-score --below-limit). Run only when
# --cases names them (validation/gap_bench.sh): their magnitudes are bench's, not tiny's.
below_limit_cases() {
  cat <<'CASES'
rolling_resistance_half|rolling_resistance|0.02|set = mu_roll=0.02
measurement_chain_half|measurement_chain|0.035|push_set = mount_k=3.222728e12 mount_c=7.180783e6 mount_m=100
actuator_ramp_half|actuator_ramp|0.64|push_set = ramp=0.64
packing_half|packing|-0.065|mu = 0.235
contact_stiffness_half|contact_stiffness|-0.1|set = kn=7.943282e8 kt=7.943282e8
force_scale_half|force_scale|0.05|set = rho_g=3.15
cohesion_half|cohesion|500|set = cohesion=500
friction_half|friction|0.075|mu = 0.375;mu_push = 0.375
polydispersity_half|polydispersity|0.125|set = poly=0.125
sidewalls_half|sidewalls|0.3|set = walls=1 mu_wall=0.3
rod_friction_half|rod_friction|-0.1|push_set = dmu_rod=-0.1
CASES
}
# Cases of an opt-in effect (analysis/gap/effects.h, Effect::opt_in): run only when --cases
# names them, diagnosed with the default library and their effect (--effects default,EFFECT;
# unless --effects is given). cohesion_dmt at 1200, between its knots 800 and 2400.
opt_in_cases() {
  cat <<'CASES'
cohesion_dmt|cohesion_dmt|1200|set = cohesion_dmt=1200
CASES
}
# Outside cases beyond the twelve (issue 37): an effect the library lacks and the synthetic
# world can make, run only when --cases names them. hard_layer: a harder layer buried at 1.3
# cm (fake_lmp's layer: a bump of 0.15 cm at any speed, not the grains'; no key of the beds'
# field, so its beds are the seeds' own), at 9e4 dyne a gap near the omnibus limit (chi^2 70
# to 82 over tiny's 42 features on four seed sets), at 3e5 (hard_layer_big) far beyond it
# (490 to 515), which no candidate explains a quarter of: the plan skips what its prior's
# bounds rule out (ctest gap_outside_layer_skips_only_what_cannot_pass,
# gap_outside_layer_unexplained_gate; docs/gap.md, "A gap that nothing explains").
# strata: a bed of alternating strata 1 cm apart (fake_lmp's strata), 6e4 dyne: a shape no
# pour-level signature resembles, which the actuator ramp's shift explains 0.44 of.
outside_cases() {
  cat <<'CASES'
hard_layer|outside|layer 9e4 at 1.3 cm|set = layer=9e4 layer_z=1.3
hard_layer_big|outside|layer 3e5 at 1.3 cm|set = layer=3e5 layer_z=1.3
strata|outside|strata 6e4 every 1 cm|set = strata=6e4 strata_l=1
CASES
}
# the cases run: the twelve, and the below-limit, opt-in and outside ones that --cases names
run_cases() {
  all_cases
  { below_limit_cases; opt_in_cases; outside_cases; } | while IFS='|' read -r name rest; do
    [[ ",$CASES," == *",$name,"* ]] && echo "$name|$rest"
  done
  return 0
}

# An outside case the library has an effect for that does to the force exactly what it
# does: lighter grains than the header's scale the lithostatic term and the impact peak
# alike (F ~ rho_g), which is force_scale at rho_g / rho_header - 1 (its doc line names
# grain density as one of its two causes). Named with that magnitude, it is a right answer.
outside_as() {
  case "$1" in
    light_grains) echo "force_scale $(awk 'BEGIN { printf "%.6g", 2.5 / 3.0 - 1 }')" ;;
  esac
}

make_measured() {    # name keys -> $WORK/real_NAME/*.csv
  local name=$1 keys=$2 real=$WORK/real_$name
  # what made the data: a case changed since (other knots, beds or speeds) is made again
  local stamp="keys=$keys seeds=$SEEDS v0=$V0"
  [ -f "$real/.complete" ] && [ "$(cat "$real/.complete")" = "$stamp" ] && return 0
  local tdir=$WORK/truth/truth_$name
  # the truth sweep of other keys, seeds or speeds is removed: its traces would join these
  if [ -d "$tdir" ] && [ "$(cat "$tdir/.keys" 2>/dev/null)" != "$stamp" ]; then rm -rf "$tdir"; fi
  mkdir -p "$tdir"; echo "$stamp" > "$tdir/.keys"
  local spec=$WORK/truth_$name.sweep
  { echo "name = truth_$name"; echo "preset = $SCEN"; echo "seeds = $SEEDS"; echo "v0 = $V0"
    [ -n "$keys" ] && echo "$keys" | tr ';' '\n'
    # a pour friction alone is packing: the push keeps the calibrated 0.3
    case "$keys" in *mu_push*) ;; mu*) echo "mu_push = 0.3" ;; esac; } > "$spec"
  # a push-only effect pushes into the no-effect case's beds (poured once)
  case "$keys" in
    push_set*) mkdir -p "$WORK/truth/truth_$name/beds"
               for f in "$WORK/truth/truth_none/beds/"*.restart "$WORK/truth/truth_none/beds/"*.info; do
                 [ -e "$f" ] && ln -f "$f" "$WORK/truth/truth_$name/beds/" 2>/dev/null || true
               done ;;
  esac
  "$CLI" sweep "$spec" --jobs "$JOBS" --out "$WORK/truth" > "$WORK/truth_$name.log" 2>&1 \
    || { echo "gap_selftest: the measured sweep of $name failed: $WORK/truth_$name.log" >&2; return 1; }
  rm -rf "$real"; mkdir -p "$real"
  local i=0 f
  for f in "$WORK/truth/truth_$name/traces/"*.csv; do
    i=$((i + 1))
    # standard header keys only (the effect's own keys would give it away), a depth offset,
    # 2% multiplicative Gaussian noise on F (Box-Muller; seeded per file)
    awk -F, -v seed=$((i * 7919 + ${#name})) -v OFS=, '
      BEGIN { srand(seed); off = (rand() * 2 - 1) * 0.2 }
      NR == 1 { print; next }
      /^#/ { split(substr($0, 3), kv, " = ");
             if (kv[1] ~ /^(units|v0|D|d_g|g|run|mu)$/) print;
             else if (kv[1] == "rho_g") print "# rho_g = 3";
             next }
      !hdr { hdr = 1; print "# source = granpen gap selftest (effect withheld)"; print; for (c = 1; c <= NF; c++) col[$c] = c; next }
      { u1 = rand(); u2 = rand(); if (u1 < 1e-12) u1 = 1e-12;
        n = sqrt(-2 * log(u1)) * cos(6.283185307179586 * u2);
        $col["z"] = sprintf("%.6f", $col["z"] + off); $col["F"] = sprintf("%.6g", $col["F"] * (1 + 0.02 * n)); print }' \
      "$f" > "$real/$(basename "$f")"
  done
  echo "$stamp" > "$real/.complete"
}

# the table of a scored run (a --measured-only run leaves the last one in place)
TABLE=$WORK/table.md
[ "$MEASURED_ONLY" = yes ] && TABLE=/dev/null
echo "| case | truth | true magnitude | detection limit | verdict | top effect | fitted magnitude | G before | G after | held-out v0 | held-out G before | held-out G after | chi^2 excess removed | wall s | pass |" > "$TABLE"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|" >> "$TABLE"
fails=0
# the signature prior: made once (its cost is the scenario's, not a diagnosis's: not counted)
PRIOR_ARGS=()
[ "$NO_PRIOR" = yes ] && PRIOR_ARGS=(--prior none)
if [ -n "$PRIOR_SEEDS" ] && [ "$MEASURED_ONLY" != yes ]; then
  echo "gap_selftest: the signature prior on seeds $PRIOR_SEEDS"
  "$CLI" gap --write-prior "$WORK/prior.json" --scenario "$SCEN" --v0 "$V0" --prior-seeds "$PRIOR_SEEDS" \
    --cache "$WORK/prior_cache" --jobs "$JOBS" > "$WORK/prior.log" 2>&1 \
    || { echo "gap_selftest: writing the prior failed: $WORK/prior.log" >&2; exit 1; }
  PRIOR_ARGS=(--prior "$WORK/prior.json")
fi
COSTS=$WORK/costs.txt    # case, the plan's least and most, the cold cost spent (probe pours of core time)
: > "$COSTS"
while IFS='|' read -r name truth mag keys; do
  [ -n "$CASES" ] && ! [[ ",$CASES," == *",$name,"* ]] && continue
  echo "gap_selftest: case $name: making the measured data"
  make_measured "$name" "$keys"
  [ "$MEASURED_ONLY" = yes ] && continue
  out=$WORK/diag_$name
  echo "gap_selftest: case $name: diagnosing blind"
  args=(gap --real "$WORK/real_$name" --scenario "$SCEN" --out "$out" --jobs "$JOBS" --cache "$WORK/cache")
  if [ -n "$EFFECTS" ]; then args+=(--effects "$EFFECTS")
  elif opt_in_cases | cut -d'|' -f1 | grep -qx "$name"; then args+=(--effects "default,$truth"); fi
  args+=("${PRIOR_ARGS[@]}")
  t0=$(date +%s)
  "$CLI" "${args[@]}" > "$WORK/diag_$name.log" 2>&1 || { echo "gap_selftest: gap failed on $name: $WORK/diag_$name.log" >&2; fails=$((fails + 1)); continue; }
  secs=$(( $(date +%s) - t0 ))
  # the case scored by granpen gap-score (analysis/gap/gap_selftest_score.h): its row of the
  # table; exit 0 when it passes, 3 when it does not
  score=(gap-score "$out/diagnosis.json" --case "$name" --truth "$truth" --magnitude "$mag" --wall-seconds "$secs")
  read -r as_effect as_mag <<< "$(outside_as "$name")"
  [ -n "$as_effect" ] && score+=(--as-effect "$as_effect" --as-magnitude "$as_mag")
  case "$name" in *_half) score+=(--below-limit) ;; esac
  rc=0; row=$("$CLI" "${score[@]}" 2> "$WORK/score_$name.log") || rc=$?
  [ "$rc" = 0 ] || [ "$rc" = 3 ] || { echo "gap_selftest: scoring $name failed: $(cat "$WORK/score_$name.log")" >&2; fails=$((fails + 1)); continue; }
  echo "$row" | tee -a "$TABLE"
  [ "$rc" = 0 ] || fails=$((fails + 1))
  # the cost, counted as a cold cache runs it (diagnosis.json plan, in probe pours of core
  # time), and the plan's range, which must hold it
  read -r least most spent <<< "$("$CLI" get "$out/diagnosis.json" plan.least plan.most plan.spent | tr '\n' ' ')"
  echo "$name $least $most $spent" >> "$COSTS"
  if ! awk -v l="$least" -v m="$most" -v s="$spent" 'BEGIN { exit !(l <= s * 1.000001 && s <= m * 1.000001) }'; then
    echo "gap_selftest: $name: cold cost $spent probe pours outside the plan's range $least to $most" >&2; fails=$((fails + 1))
  fi
done < <(run_cases)
if [ "$MEASURED_ONLY" != yes ] && [ -s "$COSTS" ]; then
  mean=$(awk '{ s += $4; n++ } END { printf "%.2f", s / n }' "$COSTS")
  echo "gap_selftest: mean cold cost per case $mean probe pours of core time over $(wc -l < "$COSTS") case(s) (plan range per case: $COSTS)"
  if [ -n "$MAX_MEAN_COST" ] && awk -v m="$mean" -v x="$MAX_MEAN_COST" 'BEGIN { exit !(m > x) }'; then
    echo "gap_selftest: the mean cold cost $mean exceeds --max-mean-cost $MAX_MEAN_COST: a cost regression" >&2; fails=$((fails + 1))
  fi
fi
if [ "$MEASURED_ONLY" = yes ]; then echo "gap_selftest: measured data in $WORK/real_*"
else echo "gap_selftest: table in $TABLE; $fails case(s) failed"; fi
[ "$fails" = 0 ]
