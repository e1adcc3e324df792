#!/usr/bin/env bash
# validation/gap_bench.sh end to end in the synthetic world (fake_lmp, tiny), committing into
# a scratch git repository (never the project's): five units (the cache, two false-alarm sets,
# one selftest case with confirming runs, one below-limit case);
#   1. --units 2: two units run and committed, one commit each;
#   2. a run killed in the middle of a unit's measured sweep leaves nothing committed of it,
#      and the next run resumes it (the sweep reports runs already done) and finishes; a
#      second run beside a running one is refused;
#   3. a run with every unit committed runs nothing and commits nothing;
#   4. a new run folder restored from the committed files alone (--restore: no bed restarts)
#      gives every unit's committed verdict again with a LAMMPS that refuses to run (--recheck);
#   5. the false-alarm table carries the count with its exact interval; the recheck's cost table
#      (costs.md) has each unit's cold cost, the same as its commit's;
#   6. the prior unit (--prior-seeds) commits a four-bed prior whose runs a new machine restores.
# usage: gap_bench_campaign.sh GRANPEN_CLI FAKE_LMP INPUTS WORK
set -u
CLI=$1 LMP=$2 INPUTS=$3 W=$4
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
rm -rf "$W" && mkdir -p "$W/repo" || exit 1
git -C "$W/repo" init -q && git -C "$W/repo" config user.email test@example.org && git -C "$W/repo" config user.name test
DATA=$W/repo/gap_bench RUN=$W/run
export GRANPEN_CLI=$CLI GRANPEN_LMP=$LMP GRANPEN_INPUTS=$INPUTS
B=(bash "$ROOT/validation/gap_bench.sh" --scenario tiny --jobs 2 --sets 2 --cases contact_stiffness,rolling_resistance_half
   --data "$DATA" --commit)
fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }
commits() { git -C "$W/repo" rev-list --count HEAD 2>/dev/null || echo 0; }

# 1. two units, two commits
"${B[@]}" --run "$RUN" --units 2 > "$W/1.log" 2>&1 || { fail "--units 2 failed"; tail -20 "$W/1.log"; }
[ "$(commits)" = 2 ] || fail "--units 2: $(commits) commits, expected 2"
[ -f "$DATA/cache/row.md" ] && [ -f "$DATA/fa_01/row.md" ] && [ ! -e "$DATA/fa_02" ] || fail "--units 2: not cache and fa_01 alone"
grep -q '^[0-9]*K cache.tar.xz$' "$DATA/cache/sizes.txt" || fail "the cache unit's archive is not in sizes.txt"
tar -tJf "$DATA/cache/cache.tar.xz" | grep -q '\.restart$' && fail "a bed restart in the cache archive"

# 2. killed in the middle of fa_02's measured sweep (runs slowed so that it can be caught)
GRANPEN_FAKE_LMP_WORK=3e5 setsid "${B[@]}" --run "$RUN" > "$W/2.log" 2>&1 &
pid=$!
traces=$RUN/units/fa_02/tiny/truth/truth_none/traces
for i in $(seq 1 600); do
  [ "$(ls "$traces"/*.csv.done 2>/dev/null | wc -l)" -ge 2 ] && break
  sleep 0.2
done
# a second run of the same run folder meanwhile is refused
"${B[@]}" --run "$RUN" > "$W/2b.log" 2>&1 && fail "a second run beside the first was not refused"
grep -q 'another run of this campaign holds' "$W/2b.log" || fail "the second run: $(tail -1 "$W/2b.log")"
kill -TERM -- -"$pid" 2>/dev/null; wait "$pid" 2>/dev/null
ndone=$(ls "$traces"/*.csv.done 2>/dev/null | wc -l)
[ "$ndone" -ge 2 ] && [ "$ndone" -lt 12 ] || fail "the kill did not land inside fa_02's sweep ($ndone of 12 runs done)"
[ ! -e "$DATA/fa_02/row.md" ] && [ "$(commits)" = 2 ] || fail "a killed unit was committed"
"${B[@]}" --run "$RUN" > "$W/3.log" 2>&1 || { fail "the resumed run failed"; tail -20 "$W/3.log"; }
grep -Eq 'truth_none: 16 runs \(([2-9]|1[0-5]) already done\)' "$RUN/units/fa_02/tiny/truth_none.log" ||
  fail "fa_02's sweep did not resume ($(grep -m1 'already done' "$RUN/units/fa_02/tiny/truth_none.log"))"
[ "$(commits)" = 5 ] || fail "after the resume: $(commits) commits, expected 5"
grep -q 'pass' "$DATA/cases.md" && grep -q '^| rolling_resistance_half | rolling_resistance | 0.02 |' "$DATA/cases.md" ||
  fail "the cases' table lacks the below-limit case"

# 3. nothing left: nothing run, nothing committed
"${B[@]}" --run "$RUN" > "$W/4.log" 2>&1 || fail "the run with everything committed failed"
grep -q 'starting' "$W/4.log" && fail "a committed unit ran again"
[ "$(commits)" = 5 ] || fail "a run with nothing to do committed"
grep -q '5 of 5 units committed' "$W/4.log" || fail "status: $(tail -1 "$W/4.log")"

# 4. a new machine: the cache and the measured traces from the committed files alone
bash "$ROOT/validation/gap_bench.sh" --scenario tiny --sets 2 --cases contact_stiffness,rolling_resistance_half --data "$DATA" \
  --run "$W/run2" --restore > "$W/5.log" 2>&1 || fail "--restore failed"
find "$W/run2/cache" -name '*.restart' | grep -q . && fail "--restore made bed restarts"
bash "$ROOT/validation/gap_bench.sh" --scenario tiny --sets 2 --cases contact_stiffness,rolling_resistance_half --data "$DATA" \
  --run "$W/run2" --recheck > "$W/6.log" 2>&1 || { fail "--recheck: verdicts differ or a run was asked for"; cat "$W/6.log"; }
grep -q 'recheck: 4 unit(s) rediagnosed from the restored cache, 0 differ' "$W/6.log" || fail "--recheck: $(tail -1 "$W/6.log")"
# the recheck's cost table: the same build that committed the units plans the same cold cost
# for each (plan.spent is counted cold, whatever the restored cache holds), to the digit
grep -q '^- false-alarm sets (no effect): 2, cold cost median [0-9.]*, mean [0-9.]* (this build)$' "$DATA/costs.md" &&
  grep -q '^- cases (every committed case unit): 2, ' "$DATA/costs.md" || fail "costs.md: $(grep '^- ' "$DATA/costs.md" 2>/dev/null | tr '\n' ' ')"
awk -F'|' '/^[|] (fa|contact|rolling)/ {n++; if ($4 != $5 || $4 ~ /^ *-? *$/) bad++} END {exit !(n == 4 && bad == 0)}' "$DATA/costs.md" ||
  fail "costs.md: a unit's cold cost differs between the recheck and its commit: $(grep '^| [fcr]' "$DATA/costs.md" | tr '\n' ' ')"

# 5. the rate with its interval (2 sets: 0 of 2 -> 0 to 0.8419 = 1 - 0.025^(1/2))
tail -1 "$DATA/false_alarms.md" | grep -Eq '^[0-2] false alarm\(s\) in 2 data sets without an effect: rate [0-9.]+, 95% interval [0-9.]+ to [0-9.]+' ||
  fail "the false-alarm table's last line: $(tail -1 "$DATA/false_alarms.md")"
grep -q '^0 false alarm(s) in 2 .* interval 0.0000 to 0.8419' "$DATA/false_alarms.md" || echo "note: $(tail -1 "$DATA/false_alarms.md")"
# 6. the prior unit (--prior-seeds "41 42"): a prior of four beds committed with its runs; from
# the committed files alone (--restore on a new run folder) granpen gap --write-prior writes
# the same prior again with a LAMMPS that refuses to run (the route of validation_gap_bench_prior)
"${B[@]}" --run "$RUN" --prior-seeds "41 42" --units 1 > "$W/7.log" 2>&1 || { fail "the prior unit failed"; tail -5 "$W/7.log"; }
[ "$(commits)" = 6 ] && [ -f "$DATA/prior/row.md" ] || fail "the prior unit: $(commits) commits, expected 6 ($(tail -1 "$W/7.log"))"
[ "$("$CLI" get "$DATA/prior/prior.json" seeds beds 2>&1)" = "$(printf '["1","2","41","42"]\t4')" ] ||
  fail "the prior unit's prior: $("$CLI" get "$DATA/prior/prior.json" seeds beds 2>&1)"
tar -tJf "$DATA/prior/cache.tar.xz" 2>/dev/null | grep -q 'prior41-42_baseline/traces/.*\.csv\.done$' || fail "the prior unit's archive has no prior41-42_ runs"
bash "$ROOT/validation/gap_bench.sh" --scenario tiny --sets 2 --cases contact_stiffness,rolling_resistance_half --data "$DATA" \
  --run "$W/run3" --restore > "$W/8.log" 2>&1 || fail "--restore with the prior unit failed"
printf '#!/bin/sh\necho "a run was asked for ($*)" >&2\nexit 1\n' > "$W/refuse_lmp"; chmod +x "$W/refuse_lmp"
"$CLI" gap --write-prior "$W/prior_again.json" --scenario tiny --v0 "50 100 200" --prior-seeds "1 2 41 42" --cache "$W/run3/cache" \
  --inputs "$INPUTS" --lmp "$W/refuse_lmp" --jobs 1 > "$W/9.log" 2>&1 || fail "the prior from the restored cache: $(tail -1 "$W/9.log")"
KEYS=(seeds beds speeds grids)
[ "$("$CLI" get "$DATA/prior/prior.json" "${KEYS[@]}" 2>&1)" = "$("$CLI" get "$W/prior_again.json" "${KEYS[@]}" 2>&1)" ] ||
  fail "the prior written from the restored cache is not the committed one"

cat "$W/4.log" | tail -2
for u in cache fa_01 fa_02 contact_stiffness rolling_resistance_half; do echo "$u: $(du -sk "$DATA/$u" | cut -f1) KB"; done
[ "$fails" = 0 ] && echo "gap_bench_campaign: all checks passed"
[ "$fails" = 0 ]
