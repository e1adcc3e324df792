#!/usr/bin/env bash
# The committed bench signature prior (inputs/priors/bench.json) is the one the current code
# writes from the committed bench campaign's cache (validation/gap_bench/bench): the cache
# restored by validation/gap_bench.sh --restore, the prior written again by granpen gap
# --write-prior with a LAMMPS that refuses to run (nothing may be simulated: every run it
# reads is committed), and the two files' members compared but for "source" (where it came from, said in words). Two routes to one file: the committed one and the code's.
# A failure means the prior's code or format moved on without the prior, or the campaign's
# cache changed: write it again (docs/gap.md, "The signature prior").
#   gap_bench_prior.sh CLI SOURCE_ROOT WORK
set -euo pipefail
CLI=$1 SRC=$2 WORK=$3
rm -rf "$WORK"; mkdir -p "$WORK"
[ -f "$SRC/validation/gap_bench/bench/cache/row.md" ] || { echo "gap_bench_prior: no committed cache unit in $SRC/validation/gap_bench/bench: skipped"; exit 77; }
GRANPEN_CLI=$CLI GRANPEN_LMP=/bin/false "$SRC/validation/gap_bench.sh" --scenario bench --data "$SRC/validation/gap_bench/bench" \
  --run "$WORK/run" --restore
printf '#!/bin/sh\necho "gap_bench_prior: a run was asked for ($*)" >&2\nexit 1\n' > "$WORK/refuse_lmp"; chmod +x "$WORK/refuse_lmp"
# on the committed prior's own beds (1 2, or 1 2 and the prior unit's: gap_bench.sh --prior-seeds)
seeds=$("$CLI" get "$SRC/inputs/priors/bench.json" seeds | tr -d '[]"' | tr ',' ' ')
"$CLI" gap --write-prior "$WORK/bench.json" --scenario bench --v0 "50 100 200" --prior-seeds "$seeds" --cache "$WORK/run/cache" \
  --inputs "$SRC/inputs" --lmp "$WORK/refuse_lmp" --jobs 1 > "$WORK/prior.log" 2>&1 \
  || { echo "gap_bench_prior: writing the prior from the restored cache failed:"; tail -n 5 "$WORK/prior.log"; exit 1; }
# every member but "source", as the program reads them (granpen get: the file's layout is the
# writer's), compact JSON for the grids
KEYS=(format version scenario seeds beds speeds w window bands what grids)
"$CLI" get "$SRC/inputs/priors/bench.json" "${KEYS[@]}" > "$WORK/committed.txt"
"$CLI" get "$WORK/bench.json" "${KEYS[@]}" > "$WORK/written.txt"
if cmp -s "$WORK/committed.txt" "$WORK/written.txt"; then
  echo "gap_bench_prior: the committed prior is the one written from the committed cache ($(wc -c < "$WORK/written.txt") bytes of its members)"
else
  echo "gap_bench_prior: the committed prior differs from the one written from the committed cache (members ${KEYS[*]}):"
  cmp "$WORK/committed.txt" "$WORK/written.txt" | head -n 2; exit 1
fi
