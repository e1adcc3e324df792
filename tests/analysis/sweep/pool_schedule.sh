#!/usr/bin/env bash
# The gap diagnosis's simulations run as one pool of sweeps (sweep_runner.h: run_sweeps),
# checked on the tiny cache of one push-only effect with fake_lmp: every pour starts before
# any push; pushes start longest first (v0 never falls); a run of a later sweep starts
# before the first sweep has finished (one pool, not sweeps one after another); the
# push-only knots' beds are the baseline's own files (hard links made in the pool, once
# poured); a second run starts nothing and finds every run done.
#   pool_schedule.sh CLI FAKE_LMP INPUTS OUT
set -euo pipefail
CLI=$1 FAKE=$2 INPUTS=$3 OUT=$4
rm -rf "$OUT"; mkdir -p "$OUT"
run() { "$CLI" gap --prepare-only --scenario tiny --v0 "200 50 100" --effects measurement_chain --jobs 2 \
          --cache "$OUT/cache" --lmp "$FAKE" --inputs "$INPUTS" > "$OUT/$1.txt" 2>&1; }
fail() { echo "pool_schedule: $*"; exit 1; }
run first || { cat "$OUT/first.txt"; fail "the pool failed"; }
starts=$(grep "^  start " "$OUT/first.txt" | awk '{ print $2 }')
# the mount's knots up to 2 ms are the baseline's traces filtered (nothing simulated); its
# two longer knots (4 and 10 ms, where the rod's motion feeds back into the grains) are 6
# pushes each on the baseline's beds, beside the baseline (6 pours, 6 pushes) and the fresh
# baseline: 6 pours and 30 pushes, as the plan line says
[ "$(echo "$starts" | wc -l)" -eq 36 ] || fail "expected 36 runs started (6 pours, 30 pushes)"
! grep -q "^  start measurement_chain_\(0\|1\|2\)[._]" "$OUT/first.txt" || fail "a filtered knot (<= 2 ms) was simulated"
last_pour=$(echo "$starts" | grep -n '/bed_' | tail -1 | cut -d: -f1)
first_push=$(echo "$starts" | grep -vn '/bed_' | head -1 | cut -d: -f1)
[ "$last_pour" -lt "$first_push" ] || fail "a push started before the last pour"
echo "$starts" | grep -v '/bed_' | sed 's/.*_v\([0-9]*\).*/\1/' | awk 'NR > 1 && $1 < prev { bad = 1 } { prev = $1 }
  END { exit bad }' || fail "pushes did not start longest (slowest) first"
closed=$(grep -n "^granpen sweep baseline: [0-9]* done, " "$OUT/first.txt" | head -1 | cut -d: -f1)
other=$(grep -n "^  start measurement_chain_" "$OUT/first.txt" | head -1 | cut -d: -f1)
[ -n "$closed" ] && [ -n "$other" ] && [ "$other" -lt "$closed" ] || fail "the mount's runs waited for the baseline sweep to end"
for knot in 4 10; do
  for f in bed_tiny_s1.restart bed_tiny_s2.info; do
    [ "$(stat -c %i "$OUT/cache/tiny/baseline/beds/$f")" = "$(stat -c %i "$OUT/cache/tiny/measurement_chain_$knot/beds/$f")" ] ||
      fail "measurement_chain_$knot/beds/$f is not the baseline's bed"
  done
done
[ "$(grep -c '0 failed' "$OUT/first.txt")" -eq 4 ] || fail "not every sweep ended without a failure"
run second || fail "the rerun failed"
! grep -q "^  start " "$OUT/second.txt" || fail "the rerun started a run"
[ "$(grep -c 'already done' "$OUT/second.txt")" -eq 4 ] || fail "the rerun did not skip every sweep"
grep -o "[0-9]* runs ([0-9]* already done)" "$OUT/second.txt" | awk '{ a = $1; b = substr($3, 2); if (a != b) exit 1 }' ||
  fail "the rerun left runs undone"
echo "pool_schedule: one pool of 4 sweeps, pours first, pushes longest first, beds linked, rerun skips all"
