#!/usr/bin/env bash
# granpen gap --write-prior --prior-seeds "1 2 41 42": a prior of four beds from the cache's
# own signature sweeps (seeds 1 2) and sweeps of its own (41 42), pooled (issue 37: a prior of
# more beds halves its noise W, and with it the margin the adaptive plan's bound adds).
#   1. with both groups' runs in the cache nothing is simulated (a LAMMPS that refuses to run);
#      the prior says seeds 1 2 41 42 and 4 beds;
#   2. two routes to one signature: the pooled prior's against the mean of the two 2-bed
#      priors written from the same runs (1 2, then 41 42). Pooling takes every run's onset to
#      the pooled baseline's mean onset, not each group's, so the binned features move by a
#      part of a bin: on the synthetic world's cache every feature agrees within 1.5 of the
#      pooled signature's own standard deviation (measured 2026-11-30: at most 1.14, median
#      0.05) and the median within 0.2; a pooling that dropped a group or summed instead of
#      averaging is off by a whole signature (tens of standard deviations);
#   3. the seeds refused by name, exit 2, nothing written: half of the signature pair (1 41),
#      a reference bed's seed (12), a seed twice (41 41).
#   prior_pooled.sh CLI INPUTS SIGNATURE_CACHE PRIOR_CACHE WORK
#   (SIGNATURE_CACHE: a diagnosis's cache with the signature sweeps; PRIOR_CACHE: one with
#   the prior41-42_ sweeps: bench/gap_selftest.sh --prior-seeds "41 42" leaves both)
set -u
CLI=$1 INPUTS=$2 SIG=$(realpath "$3") PRI=$(realpath "$4") W=$5
rm -rf "$W"; mkdir -p "$W/cache/tiny" || exit 1
fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }
for d in "$SIG"/tiny/* "$PRI"/tiny/prior41-42_*; do ln -s "$d" "$W/cache/tiny/"; done
printf '#!/bin/sh\necho "prior_pooled: a run was asked for ($*)" >&2\nexit 1\n' > "$W/refuse_lmp"; chmod +x "$W/refuse_lmp"
write() {    # SEEDS FILE
  "$CLI" gap --write-prior "$2" --scenario tiny --v0 "50 100 200" --prior-seeds "$1" --cache "$W/cache" \
    --inputs "$INPUTS" --lmp "$W/refuse_lmp" --jobs 1 > "$2.log" 2>&1
}

# 1.
write "1 2 41 42" "$W/pooled.json" || { fail "the pooled prior: $(tail -n 2 "$W/pooled.json.log")"; }
[ "$("$CLI" get "$W/pooled.json" seeds beds 2>&1)" = "$(printf '["1","2","41","42"]\t4')" ] ||
  fail "the pooled prior's seeds and beds: $("$CLI" get "$W/pooled.json" seeds beds 2>&1)"

# 2.
write "1 2" "$W/own.json" || fail "the prior of 1 2: $(tail -n 2 "$W/own.json.log")"
write "41 42" "$W/other.json" || fail "the prior of 41 42: $(tail -n 2 "$W/other.json.log")"
numbers() { "$CLI" get "$1" "grids[*].effects[*].knots[*].$2" | tr -d '[]' | tr ',' '\n'; }
if [ -f "$W/pooled.json" ] && [ -f "$W/own.json" ] && [ -f "$W/other.json" ]; then
  paste <(numbers "$W/pooled.json" signature) <(numbers "$W/pooled.json" variance) \
        <(numbers "$W/own.json" signature) <(numbers "$W/other.json" signature) > "$W/columns"
  read -r n zmax zmed < <(awk '$2 > 0 {z = ($1 - ($3 + $4) / 2) / sqrt($2); print (z < 0 ? -z : z)}' "$W/columns" | sort -g |
    awk '{v[NR] = $1} END {printf "%d %.3f %.3f\n", NR, v[NR], (NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2)}')
  echo "prior_pooled: $n features of every knot and grid: |pooled - mean of the groups| / sd at most $zmax, median $zmed"
  [ "${n:-0}" -gt 100 ] && awk -v m="$zmax" -v d="$zmed" 'BEGIN {exit !(m <= 1.5 && d <= 0.2)}' ||
    fail "the pooled signature is not the two groups' mean (n $n, max $zmax, median $zmed)"
fi

# 3.
for bad in "1 41:both or neither" "12 41:is a reference bed" "41 41:given twice"; do
  seeds=${bad%%:*} why=${bad#*:}
  "$CLI" gap --write-prior "$W/bad.json" --scenario tiny --v0 "50 100 200" --prior-seeds "$seeds" --cache "$W/cache" \
    --inputs "$INPUTS" --lmp "$W/refuse_lmp" > "$W/bad.log" 2>&1
  rc=$?
  [ "$rc" = 2 ] && grep -q -- "--prior-seeds: .*$why" "$W/bad.log" && [ ! -e "$W/bad.json" ] ||
    fail "--prior-seeds '$seeds': exit $rc, $(head -n 1 "$W/bad.log")"
done

[ "$fails" = 0 ] && echo "prior_pooled: all checks passed" || { echo "prior_pooled: $fails check(s) failed"; exit 1; }
