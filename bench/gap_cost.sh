#!/usr/bin/env bash
# What a gap diagnosis costs on the bench scenario (issue: gap diagnosis, "Cost"): in one
# run, with a cache of its own,
#   1. the first diagnosis from a cold cache (the cheap stage, the pour-level candidates the
#      adaptive plan buys, then the confirmation),
#   2. a diagnosis of another data set on the warm cache (only its new runs),
#   3. the first diagnosis again, finished (nothing simulated).
# Bracketed by two probes of the machine's speed (bench/common.sh: probe_pour, bed 1 poured
# alone): each figure is also given in probe pours and at the probe's 2026-11-22 speed
# (69.9 s), so that figures of different days compare (the same work took 1.6 x longer
# on a slow day).
# The plan's estimate checked (docs/gap.md, "The plan's cost"): for the cold diagnosis, the
# core time (CPU seconds of the diagnosis and every run it started) and the wall time, in
# probe pours, against what the plan counts for the runs it made (diagnosis.json plan.spent,
# plan.wall_spent at --jobs) within 15%, and inside the plan's range (plan.least to plan.most).
# --synthetic: the same in the synthetic world (tests/support/fake_lmp, tiny, eight measured
# beds), its runs doing the work the plan counts (GRANPEN_FAKE_LMP_WORK): a check of the
# plan's counting and of its wall-time model on this machine in a few minutes.
# The data sets are two of bench/gap_selftest.sh's measured cases (made first if missing).
#   bench/gap_cost.sh [--jobs 2] [--first CASE] [--second CASE] [--synthetic]
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
JOBS=2 FIRST=rolling_resistance SECOND=measurement_chain SYNTHETIC=no    # both explained: each has confirming runs
while [ $# -gt 0 ]; do
  case "$1" in
    --jobs) JOBS=$2; shift 2 ;;
    --first) FIRST=$2; shift 2 ;;
    --second) SECOND=$2; shift 2 ;;
    --synthetic) SYNTHETIC=yes; shift ;;
    *) echo "gap_cost: unknown option $1" >&2; exit 2 ;;
  esac
done
CLI=${GRANPEN_CLI:-$ROOT/build/analysis/granpen-cli}
export GRANPEN_LMP=${GRANPEN_LMP:-$ROOT/build/lmp_granpen} GRANPEN_INPUTS=${GRANPEN_INPUTS:-$ROOT/inputs}
SCEN=bench SELFTEST_ARGS=()
# the fake's probe pour is the bench pour as the plan counts it (0.6 s: 120000 steps), the real
# one ran 110000 (its .info): seconds per probe pour of the plan's unit = probe x 110/120
PROBE_SCALE=1
if [ "$SYNTHETIC" = yes ]; then
  export GRANPEN_LMP=${GRANPEN_FAKE_LMP:-$ROOT/build/tests/support/fake_lmp}
  export GRANPEN_SELFTEST_WORK=${GRANPEN_SELFTEST_WORK:-$ROOT/runs/gap_cost_synthetic_selftest}
  SCEN=tiny SELFTEST_ARGS=(--seeds "101 102 103 104 105 106 107 108") PROBE_SCALE=$(awk 'BEGIN { print 110000 / 120000 }')
  WORK_PER_MEGA=${GRANPEN_FAKE_LMP_WORK:-1e6}    # iterations per 1e6 atom-steps: a probe pour of a few seconds
  unset GRANPEN_FAKE_LMP_WORK                    # the measured data are made without it
fi
LMP=$GRANPEN_LMP
. "$ROOT/bench/common.sh"
SELF=${GRANPEN_SELFTEST_WORK:-$ROOT/runs/gap_selftest}
WORK=$ROOT/runs/gap_cost$([ "$SYNTHETIC" = yes ] && echo _synthetic)
PROBE_REF=69.9
"$ROOT/bench/gap_selftest.sh" --scenario "$SCEN" --jobs "$JOBS" --cases "$FIRST,$SECOND" --measured-only "${SELFTEST_ARGS[@]}"
[ "$SYNTHETIC" = yes ] && export GRANPEN_FAKE_LMP_WORK=$WORK_PER_MEGA
rm -rf "$WORK"; mkdir -p "$WORK"
# user + sys of this shell's finished children, s: `times` in this shell (in a $(...) it
# would be the subshell's), read back from a file
children_cpu() {
  times > "$WORK/times.txt"
  awk 'NR == 2 { s = 0; for (i = 1; i <= 2; i++) { split($i, t, /[ms]/); s += t[1] * 60 + t[2] } printf "%.2f", s }' "$WORK/times.txt"
}
run() {    # label data-set
  local t0 c0 c1; t0=$(date +%s.%N)
  children_cpu > "$WORK/cpu0.txt"; c0=$(cat "$WORK/cpu0.txt")
  "$CLI" gap --real "$SELF/$SCEN/real_$2" --scenario "$SCEN" --out "$WORK/diag_$2" --jobs "$JOBS" \
    --cache "$WORK/cache" > "$WORK/$1.log" 2>&1
  children_cpu > "$WORK/cpu1.txt"; c1=$(cat "$WORK/cpu1.txt")
  local s; s=$(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
  local cpu; cpu=$(awk -v a="$c0" -v b="$c1" 'BEGIN { printf "%.1f", b - a }')
  local last; last=$(tail -1 "$WORK/$1.log")
  echo "$1 $s $cpu $2 $last" >> "$WORK/figures.txt"
  echo "$1: $s s wall, $cpu s core ($last)"
}
echo "gap_cost: load average at the start: $(cut -d' ' -f1-3 /proc/loadavg)"
# the probe's wall seconds (the day's speed, load included) and its CPU seconds (the core time
# the plan's unit is: on a busy machine the wall time of a lone probe overstates it)
children_cpu > "$WORK/cpu0.txt"
p1=$(probe_pour "$WORK/probe1")
children_cpu > "$WORK/cpu1.txt"
q1=$(awk -v a="$(cat "$WORK/cpu0.txt")" -v b="$(cat "$WORK/cpu1.txt")" 'BEGIN { printf "%.2f", b - a }')
echo "gap_cost: probe pour before: $p1 s wall, $q1 s core"
run cold "$FIRST"
run warm "$SECOND"
run rerun "$FIRST"
children_cpu > "$WORK/cpu0.txt"
p2=$(probe_pour "$WORK/probe2")
children_cpu > "$WORK/cpu1.txt"
q2=$(awk -v a="$(cat "$WORK/cpu0.txt")" -v b="$(cat "$WORK/cpu1.txt")" 'BEGIN { printf "%.2f", b - a }')
echo "gap_cost: probe pour after: $p2 s wall, $q2 s core"
awk -v p1="$p1" -v p2="$p2" -v q1="$q1" -v q2="$q2" -v ref="$PROBE_REF" -v k="$PROBE_SCALE" '{
    p = (p1 + p2) / 2 * k; q = (q1 + q2) / 2 * k
    printf "%-6s %7.1f s = %5.1f min wall, %6.1f probe pours; core %7.1f s, %6.1f probe pours of core time; at the 2026-11-22 speed (%.1f s a probe): %5.1f min\n",
      $1, $2, $2 / 60, $2 / p, $3, $3 / q, ref, $2 / p * ref / 60 }' "$WORK/figures.txt"
# the plan's estimate against the cold run: counted (plan.spent, plan.wall_spent) against
# measured, within 15%, and inside the plan's range
read -r least most spent wall_spent jobs <<< "$("$CLI" get "$WORK/diag_$FIRST/diagnosis.json" plan.least plan.most plan.spent plan.wall_spent plan.jobs | tr '\n' ' ')"
read -r _ wall core _ < <(grep '^cold ' "$WORK/figures.txt")
awk -v p1="$p1" -v p2="$p2" -v q1="$q1" -v q2="$q2" -v k="$PROBE_SCALE" -v wall="$wall" -v core="$core" -v least="$least" \
    -v most="$most" -v spent="$spent" -v wspent="$wall_spent" -v jobs="$jobs" 'BEGIN {
  p = (p1 + p2) / 2 * k; q = (q1 + q2) / 2 * k; mc = core / q; mw = wall / p
  # measured core time at --jobs > 1 is the runs side by side: the plan counts them alone
  side = jobs > 1 ? 0.95 : 1
  ec = spent / side
  rc = mc / ec; rw = mw / wspent
  printf "gap_cost: the plan against the cold run: core time %.2f probe pours measured, %.2f planned (%.2f alone, run side by side at 0.95), ratio %.3f; wall time at --jobs %d %.2f measured, %.2f planned, ratio %.3f; the plan range %.2f to %.2f probe pours of core time\n",
    mc, ec, spent, rc, jobs, mw, wspent, rw, least, most
  bad = 0
  if (rc < 0.85 || rc > 1.15) { print "gap_cost: core time off the plan by more than 15%"; bad = 1 }
  if (rw < 0.85 || rw > 1.15) { print "gap_cost: wall time off the plan by more than 15%"; bad = 1 }
  if (mc * side < least * 0.85 || mc * side > most * 1.15) { print "gap_cost: the cold run outside the plan range"; bad = 1 }
  if (!bad) print "gap_cost: the plan holds within 15% in core and wall time"
  exit bad }'
