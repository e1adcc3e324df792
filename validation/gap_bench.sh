#!/usr/bin/env bash
# The gap diagnosis's figures on real LAMMPS (issue 37, sections 0 and 3), as a campaign in
# the manner of validation/campaign.sh: hours of runs on a small machine, cut into units, each
# committed when done, so that any later session (on any machine) goes on with the first unit
# not committed. Units, in order:
#   cache      the diagnosis's cache of the scenario (granpen gap --prepare-only: the
#              baseline, every knot, the reference beds) at --v0
#   prior      with --prior-seeds "41 42": the bench signature prior of four beds (granpen gap
#              --write-prior --prior-seeds "1 2 41 42": the cache's own signature sweeps and
#              sweeps of 41 42, pooled), its runs committed as a unit's, the prior in
#              DATA/prior/prior.json and, with the default --data, inputs/priors/SCENARIO.json
#              (the file a diagnosis reads): its noise W is half a 2-bed prior's, and so is
#              the part of the adaptive plan's bound that it sets (docs/gap.md)
#   fa_NN      a false-alarm set (NN = 01 .. --sets, at least 20): the no-effect case of
#              bench/gap_selftest.sh on measured beds of seeds 1001.. (bench/gap_false_alarms.sh's
#              seeds: set k has 1000+4(k-1)+1 .. 1000+4k), its diagnosis, its verdict
#   EFFECT_half  the below-limit cases (bench/gap_selftest.sh, below_limit_cases): each
#              library effect at about half its detection limit, scored by gap-score --below-limit
#   CASE       the ten selftest cases not rerun on real LAMMPS under version 2's rules (none,
#              polydispersity, sidewalls, actuator_ramp, packing, contact_stiffness, friction,
#              cohesion, rod_friction, light_grains), measured beds of seeds 101 to 104
# What a unit commits to DATA/UNIT/ (what a later machine needs to rerun its verdict in
# minutes, nothing simulated): measured.tar.gz (its measured traces, as the diagnosis read
# them), diagnosis.json, report.md, row.md (its row of the table), and cache.tar.xz: the files
# of the cache that this unit added or changed (the simulated traces with their .done markers
# and the beds' .info; never a bed's restart: the sweep runner counts a pour done by its
# .info and a push by its .done, so a restored cache is a hit for every run it holds),
# listed with their checksums in cache_files.txt. Sizes per unit: sizes.txt.
# The false-alarm table (DATA/false_alarms.md: per set the verdict; the count of false
# alarms with its exact 95% interval, granpen rate), the figure alone
# (DATA/false_alarm_rate.txt, key = value; with the default --data also
# inputs/false_alarms/SCENARIO.txt, which granpen gap reports: gap_bench_rate.h) and the
# cases' table (DATA/cases.md) are written after every unit.
#
#   validation/gap_bench.sh [--scenario bench] [--v0 "50 100 200"] [--jobs 1] [--sets 20]
#       [--cases LIST] [--data DIR] [--run DIR] [--seed-cache DIR] [--wait-pid PID]
#       [--units N] [--commit] [--status] [--restore] [--recheck] [--prior-seeds "41 42"]
#
#   --data DIR    the committed folder (default validation/gap_bench/SCENARIO); --commit
#                 commits it (in the git repository that holds it) after every unit
#   --run DIR     scratch folder (default /work/granpen-runs/gap_bench; lost with the machine):
#                 RUN/cache (the shared cache), RUN/units/UNIT (bench/gap_selftest.sh's
#                 work, GRANPEN_SELFTEST_WORK), RUN/logs, RUN/bin and RUN/inputs (copies taken
#                 at every start: rebuilding or editing the work tree never changes a run)
#   --jobs N      simulations at once, never more (default 1)
#   --sets N      false-alarm sets (default 20)
#   --cases LIST  the cases of units (c) and (d), comma-separated (default: every EFFECT_half,
#                 then the ten)
#   --seed-cache DIR  a cache made elsewhere (granpen gap --prepare-only --cache DIR) copied
#                 into RUN/cache when that is empty (after --wait-pid), read only
#   --wait-pid PID    wait until process PID has ended before anything starts (a prepare)
#   --prior-seeds SEEDS  the prior unit on these seeds besides 1 2 (after the cache; a
#                 committed prior unit is restored and rechecked without it)
#   --units N     stop after N units (default: all)
#   --status      what is committed and under way, and stop
#   --restore     a new machine: RUN/cache and each committed unit's measured traces rebuilt
#                 from DATA (the units' cache archives in order), then stop
#   --recheck     every committed unit diagnosed again from the restored cache (run
#                 --restore first) with a stand-in for LAMMPS that refuses to run: its
#                 verdict must be the committed one, nothing simulated; writes DATA/costs.md,
#                 each unit's cold cost as this build plans it (median and mean over the
#                 false-alarm sets and over the cases: the figures the docs quote)
# A new machine: --restore (then --recheck, before any run), then run as before: the campaign
# goes on from the restored cache (beds that later units push into are poured again).
# GRANPEN_CLI and GRANPEN_LMP name the binaries (default build/analysis/granpen-cli and
# build/lmp_granpen; GRANPEN_LMP=build/tests/support/fake_lmp --scenario tiny: the
# synthetic world, tests/validation/gap_bench_campaign.sh). Runs niced (15).
set -euo pipefail
# the work tree (a campaign runs from its copy in RUN/bin: editing this file never reaches a run)
ROOT=${GAP_BENCH_ROOT:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)}
SCEN=bench V0="50 100 200" JOBS=1 SETS=20 CASES="" DATA="" RUN=/work/granpen-runs/gap_bench SEED_CACHE="" WAIT_PID=""
UNITS=-1 COMMIT=0 MODE=run PRIOR_SEEDS=""
args=("$@")
while [ $# -gt 0 ]; do
  case $1 in
    --scenario) SCEN=$2; shift 2 ;;
    --v0) V0=$2; shift 2 ;;
    --jobs) JOBS=$2; shift 2 ;;
    --sets) SETS=$2; shift 2 ;;
    --cases) CASES=$2; shift 2 ;;
    --data) DATA=$2; shift 2 ;;
    --run) RUN=$2; shift 2 ;;
    --seed-cache) SEED_CACHE=$2; shift 2 ;;
    --wait-pid) WAIT_PID=$2; shift 2 ;;
    --units) UNITS=$2; shift 2 ;;
    --commit) COMMIT=1; shift ;;
    --status) MODE=status; shift ;;
    --restore) MODE=restore; shift ;;
    --recheck) MODE=recheck; shift ;;
    --prior-seeds) PRIOR_SEEDS=$2; shift 2 ;;
    *) echo "gap_bench.sh: unknown argument $1 (see the header of $0)" >&2; exit 2 ;;
  esac
done
[[ $JOBS =~ ^[1-9][0-9]*$ ]] || { echo "gap_bench.sh: --jobs $JOBS is not a whole number >= 1" >&2; exit 2; }
[[ $SETS =~ ^[0-9]+$ ]] || { echo "gap_bench.sh: --sets $SETS is not a whole number" >&2; exit 2; }
[[ $UNITS =~ ^(-1|[0-9]+)$ ]] || { echo "gap_bench.sh: --units $UNITS is not a whole number" >&2; exit 2; }
[[ $PRIOR_SEEDS =~ ^[0-9\ ]*$ ]] || { echo "gap_bench.sh: --prior-seeds '$PRIOR_SEEDS' is not a list of seeds" >&2; exit 2; }
# a campaign runs from a copy of this script (bash reads a script as it goes)
if [ "$MODE" = run ] && [ -z "${GAP_BENCH_ROOT:-}" ]; then
  mkdir -p "$RUN/bin"
  # one run at a time per run folder: the lock (descriptor 9) is held by this shell alone,
  # every process it starts gets 9 closed, so that a killed run leaves no holder behind
  exec 9> "$RUN/lock"
  flock -n 9 || { echo "gap_bench.sh: another run of this campaign holds $RUN/lock" >&2; exit 1; }
  cp "${BASH_SOURCE[0]}" "$RUN/bin/gap_bench.sh"
  GAP_BENCH_ROOT=$ROOT exec bash "$RUN/bin/gap_bench.sh" "${args[@]}"
fi
# niced, so that the machine's other work goes first
n=$(nice); [ "$n" -ge 15 ] || exec nice -n $((15 - n)) bash "${BASH_SOURCE[0]}" "${args[@]}"
FIGURE="" PRIOR_FILE=""
[ -n "$DATA" ] || FIGURE=$ROOT/inputs/false_alarms/$SCEN.txt PRIOR_FILE=$ROOT/inputs/priors/$SCEN.json
DATA=${DATA:-$ROOT/validation/gap_bench/$SCEN}
# (--status writes nothing: a folder not there yet is read as empty)
[ "$MODE" = status ] || mkdir -p "$DATA" "$RUN/logs" "$RUN/units" "$RUN/cache"
DATA=$(realpath -m "$DATA") RUN=$(realpath -m "$RUN")
CACHE=$RUN/cache
say() { echo "gap_bench: $(date -u +%H:%M:%S) $*"; }

# the cases of units (c) and (d)
# none first: the push-only cases push into its beds (bench/gap_selftest.sh), which a shared
# work folder keeps
TEN="polydispersity,sidewalls,actuator_ramp,packing,contact_stiffness,friction,cohesion,rod_friction,light_grains"
if [ -z "$CASES" ]; then
  CASES=none,$(grep -oE '^[a-z_]+_half\|' "$ROOT/bench/gap_selftest.sh" | tr -d '|' | tr '\n' ',')$TEN
fi
# the units in order: "ID KIND ARG" (ARG: a false-alarm set's seeds, with _ for spaces)
units() {
  echo "cache cache -"
  if [ -n "$PRIOR_SEEDS" ] || [ -f "$DATA/prior/row.md" ]; then echo "prior prior ${PRIOR_SEEDS// /_}"; fi
  local k
  for k in $(seq 1 "$SETS"); do
    printf 'fa_%02d fa %s\n' "$k" "$(seq $((1000 + (k - 1) * 4 + 1)) $((1000 + k * 4)) | tr '\n' '_' | sed 's/_$//')"
  done
  local c
  for c in ${CASES//,/ }; do echo "$c case -"; done
}
committed() { [ -f "$DATA/$1/row.md" ]; }
# bench/gap_selftest.sh's work folder of a unit (GRANPEN_SELFTEST_WORK): a false-alarm set's
# own (its no-effect case has other seeds), the cases' shared one; and the case it runs
unit_work() { case $1 in fa_*) echo "$RUN/units/$1" ;; *) echo "$RUN/units/cases" ;; esac; }
unit_case() { case $1 in fa_*) echo none ;; *) echo "$1" ;; esac; }

# the tables, from what is committed
tables() {
  local fa=$DATA/false_alarms.md cs=$DATA/cases.md sets=0 alarms=0 id kind arg
  { echo "| set | seeds | verdict | G_all before | null replicates not none | false alarm |"
    echo "|---|---|---|---|---|---|"; } > "$fa.new"
  { echo "| case | truth | true magnitude | detection limit | verdict | top effect | fitted magnitude | G before | G after | held-out v0 | held-out G before | held-out G after | chi^2 excess removed | wall s | pass |"
    echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"; } > "$cs.new"
  while read -r id kind arg; do
    committed "$id" || continue
    case $kind in
      fa) sets=$((sets + 1)); cat "$DATA/$id/row.md" >> "$fa.new"
          grep -q '| yes |$' "$DATA/$id/row.md" && alarms=$((alarms + 1)) ;;
      case) cat "$DATA/$id/row.md" >> "$cs.new" ;;
    esac
  done < <(units)
  if [ "$sets" -gt 0 ]; then
    read -r _ _ rate lo hi _ < <("$CLI" rate "$alarms" "$sets")
    printf '\n%s false alarm(s) in %s data sets without an effect: rate %s, 95%% interval %s to %s (Clopper-Pearson, exact; granpen rate)\n' \
      "$alarms" "$sets" "$rate" "$lo" "$hi" >> "$fa.new"
  fi
  # the figure alone (key = value), which granpen gap reports beside its null replicates
  # (analysis/gap/gap_bench_rate.h): into DATA, and into the decks' folder when DATA is the
  # project's own
  if [ "$sets" -gt 0 ]; then
    printf '# granpen gap: false alarms on data sets without an effect at %s scale, real LAMMPS (validation/gap_bench.sh)\nscenario = %s\nsets = %s\nalarms = %s\nrate = %s\nlow95 = %s\nhigh95 = %s\nsource = validation/gap_bench/%s/false_alarms.md\n' \
      "$SCEN" "$SCEN" "$sets" "$alarms" "$rate" "$lo" "$hi" "$SCEN" > "$DATA/false_alarm_rate.txt"
    [ -z "$FIGURE" ] || { mkdir -p "$(dirname "$FIGURE")"; cp "$DATA/false_alarm_rate.txt" "$FIGURE"; }
  fi
  mv "$fa.new" "$fa"; mv "$cs.new" "$cs"
}

status() {
  local n=0 done=0 id kind arg
  while read -r id kind arg; do n=$((n + 1)); committed "$id" && done=$((done + 1)); done < <(units)
  echo "gap_bench ($SCEN): $done of $n units committed ($DATA)"
  tail -1 "$DATA/false_alarms.md" 2>/dev/null | grep -q 'false alarm' && echo "  $(tail -1 "$DATA/false_alarms.md")"
  [ "${1:-}" = self ] || [ ! -f "$RUN/lock" ] || flock -n "$RUN/lock" true || echo "  a run of it is going on ($RUN/lock held)"
  [ -f "$RUN/current" ] && echo "  under way here: $(cat "$RUN/current")"
  return 0
}

CLI_SRC=${GRANPEN_CLI:-$ROOT/build/analysis/granpen-cli} LMP_SRC=${GRANPEN_LMP:-$ROOT/build/lmp_granpen}
[ -x "$CLI_SRC" ] || { echo "gap_bench.sh: no granpen-cli at $CLI_SRC (build first, or set GRANPEN_CLI)" >&2; exit 2; }
CLI=$CLI_SRC
[ "$MODE" = status ] && { status; exit 0; }

# the cache files a unit leaves (traces with their .done, the beds' .info), "SHA PATH" sorted
cache_files() {
  (cd "$CACHE" && find . -type f \( -name '*.csv.done' -o -path '*/beds/*.info' \) | sort | while read -r f; do
     sha1sum "$f"; case $f in *.csv.done) sha1sum "${f%.done}" ;; esac
   done)
}
# what every committed unit's archive holds, in unit order (a later one's file replaces)
committed_cache_files() {
  local id kind arg
  while read -r id kind arg; do [ -f "$DATA/$id/cache_files.txt" ] && cat "$DATA/$id/cache_files.txt"; done < <(units)
  return 0
}
restore() {
  local id kind arg n=0
  while read -r id kind arg; do
    committed "$id" || continue
    [ -f "$DATA/$id/cache.tar.xz" ] && tar -C "$CACHE" -xJf "$DATA/$id/cache.tar.xz"
    if [ -f "$DATA/$id/measured.tar.gz" ]; then
      local w; w=$(unit_work "$id")/$SCEN; mkdir -p "$w"; tar -C "$w" -xzf "$DATA/$id/measured.tar.gz"
    fi
    n=$((n + 1))
  done < <(units)
  say "restored $n committed unit(s) from $DATA into $RUN (cache: $(find "$CACHE" -name '*.csv.done' | wc -l) runs)"
}
[ "$MODE" = restore ] && { restore; exit 0; }

# --recheck's cost table (DATA/costs.md): per unit the cold cost (plan.spent, probe pours of
# core time, counted as a cold cache runs it) as the rechecking build plans it and as the
# committed diagnosis did; the median and mean over the false-alarm sets (no effect) and over
# the cases. The figures docs/gap-validation.md quotes: one command makes them again.
cost_stats() {    # prints "N MEDIAN MEAN" of the numbers on stdin ("-" lines skipped)
  grep -E '^[0-9.eE+-]+$' | grep -v '^-$' | sort -g | awk '{v[NR] = $1; s += $1}
    END {if (NR == 0) {print 0, "-", "-"; exit}
         m = NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2
         printf "%d %.2f %.2f\n", NR, m, s / NR}'
}
cost_table() {    # COSTS_TSV
  local f=$1 out=$DATA/costs.md kind label n med mean
  { echo "# granpen gap: the cold cost of each committed unit (validation/gap_bench.sh --recheck)"
    echo
    echo "Rechecked $(date -u '+%F %H:%M') UTC with $CLI_SRC (sha1 $(sha1sum "$CLI_SRC" | cut -c1-12)), work tree at $(git -C "$ROOT" rev-parse --short HEAD 2>/dev/null || echo '?')."
    echo "plan.spent: probe pours of core time, counted as a cold cache would run them (docs/gap.md, \"The plan's cost\")."
    echo
    for kind in fa case; do
      label=$([ "$kind" = fa ] && echo "false-alarm sets (no effect)" || echo "cases (every committed case unit)")
      read -r n med mean < <(awk -F'\t' -v k="$kind" '$2 == k {print $4}' "$f" | cost_stats)
      echo "- $label: $n, cold cost median $med, mean $mean (this build)"
      read -r n med mean < <(awk -F'\t' -v k="$kind" '$2 == k {print $5}' "$f" | cost_stats)
      echo "  - as committed (each unit's own build): $n, median $med, mean $mean"
    done
    echo
    echo "| unit | verdict, top effect (this build) | spent, this build | spent, as committed |"
    echo "|---|---|---|---|"
    awk -F'\t' '{printf "| %s | %s | %s | %s |\n", $1, $3, $4, $5}' "$f"
  } > "$out.new" && mv "$out.new" "$out"
  grep '^- ' "$out" | while read -r l; do say "recheck cost: ${l#- }"; done
}

if [ "$MODE" = recheck ]; then
  # LAMMPS refused: a diagnosis that needs a run it has not got fails instead of simulating
  printf '#!/bin/sh\necho "gap_bench --recheck: a run was asked for ($*)" >&2\nexit 1\n' > "$RUN/refuse_lmp"; chmod +x "$RUN/refuse_lmp"
  bad=0 n=0 costs=$RUN/recheck/costs.tsv
  mkdir -p "$RUN/recheck"; : > "$costs"
  while read -r id kind arg; do
    committed "$id" || continue
    [ "$kind" = cache ] || [ "$kind" = prior ] && continue
    real=$(unit_work "$id")/$SCEN/real_$(unit_case "$id")
    [ -d "$real" ] || { echo "gap_bench --recheck: $id: no measured traces in $real (run --restore first)" >&2; bad=$((bad + 1)); continue; }
    out=$RUN/recheck/$id; rm -rf "$out"; mkdir -p "$RUN/recheck"
    if ! "$CLI" gap --real "$real" --scenario "$SCEN" --out "$out" --jobs 1 --cache "$CACHE" --lmp "$RUN/refuse_lmp" \
         --inputs "${GRANPEN_INPUTS:-$ROOT/inputs}" > "$RUN/logs/recheck_$id.log" 2>&1; then
      echo "gap_bench --recheck: $id: the diagnosis failed (a run missing from the cache?): $RUN/logs/recheck_$id.log" >&2; bad=$((bad + 1)); continue
    fi
    now=$("$CLI" get "$out/diagnosis.json" verdict top_effect) was=$("$CLI" get "$DATA/$id/diagnosis.json" verdict top_effect)
    n=$((n + 1))
    # the cold cost as this build's plan buys it, beside the committed diagnosis's
    printf '%s\t%s\t%s\t%s\t%s\n' "$id" "$kind" "$(echo "$now" | tr '\t' ' ')" \
      "$("$CLI" get "$out/diagnosis.json" plan.spent --missing -)" "$("$CLI" get "$DATA/$id/diagnosis.json" plan.spent --missing -)" >> "$costs"
    if [ "$now" = "$was" ]; then say "recheck $id: $(echo "$now" | tr '\t' ' '), as committed"
    else echo "gap_bench --recheck: $id: $(echo "$now" | tr '\t' ' ') now, $(echo "$was" | tr '\t' ' ') committed" >&2; bad=$((bad + 1)); fi
  done < <(units)
  say "recheck: $n unit(s) rediagnosed from the restored cache, $bad differ or failed"
  cost_table "$costs"
  [ "$bad" = 0 ]; exit
fi

# --- the campaign ---
[ -x "$LMP_SRC" ] || { echo "gap_bench.sh: no lmp_granpen at $LMP_SRC (build first, or set GRANPEN_LMP)" >&2; exit 2; }
# the binaries, decks and selftest script as of this start (before any wait: a rebuild of
# the work tree meanwhile does not reach this run)
mkdir -p "$RUN/bin"
for b in "$CLI_SRC:granpen-cli" "$LMP_SRC:lmp_granpen"; do
  cmp -s "${b%%:*}" "$RUN/bin/${b##*:}" 2>/dev/null || cp "${b%%:*}" "$RUN/bin/${b##*:}"
done
cp "$ROOT/bench/gap_selftest.sh" "$RUN/bin/gap_selftest.sh"
rm -rf "$RUN/inputs.new"; cp -r "${GRANPEN_INPUTS:-$ROOT/inputs}" "$RUN/inputs.new"; rm -rf "$RUN/inputs"; mv "$RUN/inputs.new" "$RUN/inputs"
CLI=$RUN/bin/granpen-cli LMP=$RUN/bin/lmp_granpen INPUTS=$RUN/inputs
# a prepare still running (another process filling --seed-cache): wait for its end
if [ -n "$WAIT_PID" ]; then
  kill -0 "$WAIT_PID" 2>/dev/null && say "waiting for process $WAIT_PID to end (checked every minute)"
  while kill -0 "$WAIT_PID" 2>/dev/null; do sleep 60 9>&-; done
fi
if [ -n "$SEED_CACHE" ] && [ -z "$(ls -A "$CACHE")" ]; then
  say "copying the cache $SEED_CACHE into $CACHE"
  cp -a "$SEED_CACHE/." "$CACHE/"
fi
# A restored cache (--restore) has the beds' .info but not their restarts. The beds that later
# units push into (a push-only confirmation's beds: the sweeps named *_beds) are poured again
# when asked for: their .info goes, so the sweep runner counts them not done (the same seed
# and binary pour the same bed). Every other restored sweep is complete for what it is used.
for info in "$CACHE"/*/*_beds/beds/*.info; do
  [ -f "$info" ] && [ ! -f "${info%.info}.restart" ] || continue
  say "restored bed without its restart, to be poured again when asked for: ${info#"$CACHE"/}"; rm -f "$info"
done
[ "$(id -u)" = 0 ] && export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

commit() {    # MESSAGE
  if [ "$COMMIT" = 1 ]; then
    local paths=("$DATA"); [ -f "$FIGURE" ] && paths+=("$FIGURE"); [ -n "$PRIOR_FILE" ] && [ -f "$PRIOR_FILE" ] && paths+=("$PRIOR_FILE")
    git -C "$DATA" add -- "${paths[@]}" && git -C "$DATA" commit -q -m "gap_bench ($SCEN): $1" -- "${paths[@]}" && say "committed: $1"
  else say "$1: to be committed (git add $DATA)"; fi
}
# a progress line every 5 minutes while a unit runs: the newest log's last line
ticker() {
  while sleep "${GRANPEN_BENCH_TICK:-300}"; do
    local f; f=$(ls -t "$RUN"/logs/*.log "$RUN"/units/*/"$SCEN"/*.log 2>/dev/null | head -1)
    [ -n "$f" ] && say "$(cat "$RUN/current" 2>/dev/null) $(basename "$f"): $(tail -c 2000 "$f" | tr '\r' '\n' | grep -v '^$' | tail -1 | cut -c1-160)"
  done
}
# the unit's new cache files into DATA/ID (a scratch copy first: nothing half-written)
pack_cache() {    # ID
  local tmp=$RUN/pack_$1; rm -rf "$tmp"; mkdir -p "$tmp"
  cache_files > "$tmp/all"
  committed_cache_files | sort -u > "$tmp/have"
  { grep -vxFf "$tmp/have" "$tmp/all" || true; } > "$tmp/cache_files.txt"
  if [ -s "$tmp/cache_files.txt" ]; then
    awk '{print $2}' "$tmp/cache_files.txt" > "$tmp/paths"
    tar -C "$CACHE" -cJf "$tmp/cache.tar.xz" -T "$tmp/paths" || { echo "gap_bench: $1: the cache's archive failed" >&2; return 1; }
  fi
}
# copy a finished unit's files from the scratch folder into DATA/ID, then commit
publish() {    # ID MESSAGE
  local tmp=$RUN/pack_$1
  rm -rf "$DATA/$1.new"; mkdir -p "$DATA/$1.new"
  cp "$tmp"/* "$DATA/$1.new/" 2>/dev/null || true
  rm -f "$DATA/$1.new/all" "$DATA/$1.new/have" "$DATA/$1.new/paths"
  (cd "$DATA/$1.new" && for f in *; do [ "$f" = sizes.txt ] || printf '%s %s\n' "$(du -k "$f" | cut -f1)K" "$f"; done > sizes.txt)
  # row.md last: it marks the unit committed
  mv "$DATA/$1.new/row.md" "$DATA/$1.row.md"
  rm -rf "$DATA/$1"; mv "$DATA/$1.new" "$DATA/$1"; mv "$DATA/$1.row.md" "$DATA/$1/row.md"
  tables
  commit "$2 ($(du -sk "$DATA/$1" | cut -f1) KB committed)"
  rm -rf "$tmp"
}

run_cache_unit() {
  echo "cache (since $(date -u +%H:%M))" > "$RUN/current"
  say "unit cache: granpen gap --prepare-only (--jobs $JOBS; resumes what is in $CACHE)"
  "$CLI" gap --prepare-only --scenario "$SCEN" --v0 "$V0" --jobs "$JOBS" --cache "$CACHE" --lmp "$LMP" --inputs "$INPUTS" \
    > "$RUN/logs/cache.log" 2>&1 9>&- || { say "the cache's prepare failed: $RUN/logs/cache.log" >&2; return 1; }
  pack_cache cache
  local n; n=$(find "$CACHE" -name '*.csv.done' | wc -l)
  echo "| cache | $SCEN | v0 $V0 | $n runs |" > "$RUN/pack_cache/row.md"
  publish cache "unit cache: $n simulated runs of the diagnosis's cache"
  rm -f "$RUN/current"
}

run_prior_unit() {    # SEEDS (besides the signature seeds 1 2)
  local seeds="1 2 $1" tmp=$RUN/pack_prior
  [ -n "$1" ] || { echo "gap_bench: the prior unit needs --prior-seeds (seeds besides 1 2)" >&2; return 1; }
  echo "prior (since $(date -u +%H:%M))" > "$RUN/current"
  say "unit prior: granpen gap --write-prior --prior-seeds \"$seeds\" (--jobs $JOBS; resumes what is in $CACHE)"
  mkdir -p "$RUN/prior"
  "$CLI" gap --write-prior "$RUN/prior/prior.json" --scenario "$SCEN" --v0 "$V0" --prior-seeds "$seeds" --jobs "$JOBS" \
    --cache "$CACHE" --lmp "$LMP" --inputs "$INPUTS" > "$RUN/logs/prior.log" 2>&1 9>&- ||
    { echo "gap_bench: the prior failed: $RUN/logs/prior.log" >&2; return 1; }
  pack_cache prior || return 1
  cp "$RUN/prior/prior.json" "$tmp/prior.json"
  local beds; beds=$("$CLI" get "$tmp/prior.json" beds) || return 1
  echo "| prior | $SCEN | seeds $seeds | $beds beds |" > "$tmp/row.md"
  # the file a diagnosis reads (with the default --data), committed with the unit
  if [ -n "$PRIOR_FILE" ]; then mkdir -p "$(dirname "$PRIOR_FILE")"; cp "$tmp/prior.json" "$PRIOR_FILE.new" && mv "$PRIOR_FILE.new" "$PRIOR_FILE"; fi
  # and the units after it in this run read it (their decks are RUN/inputs, copied at the start)
  mkdir -p "$INPUTS/priors" && cp "$tmp/prior.json" "$INPUTS/priors/$SCEN.json"
  publish prior "unit prior: the signature prior of $beds beds (seeds $seeds)"
  rm -f "$RUN/current"
}

run_selftest_unit() {    # ID SEEDS ("": the selftest's own)
  local id=$1 seeds=$2 name w; name=$(unit_case "$1") w=$(unit_work "$1")
  mkdir -p "$w/$SCEN"; ln -sfn "$CACHE" "$w/$SCEN/cache"
  echo "$id (since $(date -u +%H:%M))" > "$RUN/current"
  local sargs=(--scenario "$SCEN" --jobs "$JOBS" --v0 "$V0" --cases "$name")
  [ -n "$seeds" ] && sargs+=(--seeds "$seeds")
  GRANPEN_SELFTEST_WORK=$w GRANPEN_CLI=$CLI GRANPEN_LMP=$LMP GRANPEN_INPUTS=$INPUTS \
    bash "$RUN/bin/gap_selftest.sh" "${sargs[@]}" > "$RUN/logs/$id.log" 2>&1 9>&- || true
  local d=$w/$SCEN/diag_$name
  [ -f "$d/diagnosis.json" ] && grep -q "^| $name |" "$w/$SCEN/table.md" ||
    { echo "gap_bench: unit $id left no scored diagnosis (see $RUN/logs/$id.log)" >&2; return 1; }
  local tmp=$RUN/pack_$id; pack_cache "$id" || return 1
  cp "$d/diagnosis.json" "$d/report.md" "$tmp/"
  tar -C "$w/$SCEN" -czf "$tmp/measured.tar.gz" "real_$name"
  # (called where a failure does not stop the script: each step checked)
  [ -s "$tmp/diagnosis.json" ] && [ -s "$tmp/report.md" ] && [ -s "$tmp/measured.tar.gz" ] ||
    { echo "gap_bench: unit $id: its files could not be gathered in $tmp" >&2; return 1; }
  local row; row=$(grep "^| $name |" "$w/$SCEN/table.md" | tail -1)
  if [ -n "$seeds" ]; then
    # a false-alarm set: any verdict other than none is an alarm
    local v g nn
    IFS=$'\t' read -r v g nn < <("$CLI" get "$d/diagnosis.json" verdict gap_before false_alarms.not_none --missing -)
    [ -n "$v" ] || { echo "gap_bench: unit $id: no verdict in its diagnosis" >&2; return 1; }
    printf '| %s | %s | %s | %.3f | %s | %s |\n' "${id#fa_}" "$seeds" "$v" "$g" "$nn" "$([ "$v" = none ] && echo no || echo yes)" > "$tmp/row.md"
    echo "$row" > "$tmp/score.md"
    publish "$id" "false-alarm set ${id#fa_} (seeds $seeds): $v"
  else
    echo "$row" > "$tmp/row.md"
    publish "$id" "case $name: $(echo "$row" | awk -F'|' '{gsub(/^ +| +$/, "", $6); gsub(/^ +| +$/, "", $16); print $6 ", pass " $16}')"
  fi
  rm -f "$RUN/current"
}

ticker 9>&- & TICKER=$!
trap 'kill $TICKER 2>/dev/null || true' EXIT
ran=0 failed=""
while read -r id kind arg; do
  committed "$id" && continue
  [ "$UNITS" -lt 0 ] || [ "$ran" -lt "$UNITS" ] || break
  say "unit $id: starting"
  # the cache is every unit's ground: without it, stop; a set or a case that fails (a run
  # that crashed, say) is left for the next start, and the campaign goes on with the next
  case $kind in
    cache) run_cache_unit || exit 1 ;;
    prior) run_prior_unit "${arg//_/ }" || exit 1 ;;
    fa) run_selftest_unit "$id" "${arg//_/ }" || { say "unit $id failed: going on with the next (retried at the next start)"; failed="$failed $id"; } ;;
    case) run_selftest_unit "$id" "" || { say "unit $id failed: going on with the next (retried at the next start)"; failed="$failed $id"; } ;;
  esac
  ran=$((ran + 1))
done < <(units)
status self
[ -z "$failed" ] || { say "failed this time:$failed (see $RUN/logs)"; exit 1; }
