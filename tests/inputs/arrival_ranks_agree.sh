#!/bin/sh
# observe/arrival.lmp on 1 and 2 ranks (the same push on the tiny bed): granpen arrival reads
# a front in both, and each ring's arrival is the same sample on both (the rings' sums are
# LAMMPS's reduce/region over the ranks; the front comes in the push's first milliseconds,
# before round-off grown by the granular dynamics could move a sample across the factor).
#   arrival_ranks_agree.sh CLI TRACE_NP1 TRACE_NP2 WORK
set -u
CLI=$1 A=$2 B=$3 W=$4
mkdir -p "$W" || exit 1
for t in "$A" "$B"; do
  "$CLI" arrival "$t" --json "$W/$(basename "$t").json" || { echo "FAIL: granpen arrival on $t"; exit 1; }
  [ "$("$CLI" get "$W/$(basename "$t").json" fitted)" = true ] || { echo "FAIL: no front in $t"; exit 1; }
done
a=$("$CLI" get "$W/$(basename "$A").json" 'rings[*].t_after_ms' | tr '\n' ' ')
b=$("$CLI" get "$W/$(basename "$B").json" 'rings[*].t_after_ms' | tr '\n' ' ')
echo "arrivals (ms after contact): 1 rank: $a; 2 ranks: $b"
[ "$a" = "$b" ] || { echo "FAIL: the ranks disagree"; exit 1; }
echo "arrival: the ranks agree"
