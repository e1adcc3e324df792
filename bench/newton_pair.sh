#!/usr/bin/env bash
# newton on against newton off for the push, in one run (issue 33: a lever on the 16-rank
# loss?). The decks run newton off: a pair across two ranks is computed on both, and no
# forces are sent back. newton on computes it once and sends the ghosts' forces and torques
# back (reverse communication). On a dg10 bed rebuilt from its committed tile (the 10 cm box,
# 135032 atoms, in a second), the same short push (400 cm/s to 0.05 cm: 1501 steps, the rod
# just reaching the bed) on NP ranks, alternately REPEAT times each; a copy of the decks with
# `newton ${newton_pair}` is made in the work folder (the shipped decks stay newton off).
# Prints per round the loop time and LAMMPS's Pair, Comm and Modify rows, then the ratio of
# the medians (off / on: above 1, newton on is faster).
#   bench/newton_pair.sh [--np 2] [--repeat 2] [--tile-count 2] [LMP_GRANPEN]
set -euo pipefail
NP=2 REPEAT=2 TILES=2 LMP_ARG=""
while [ $# -gt 0 ]; do
  case "$1" in
    --np) NP=$2; shift 2 ;;
    --repeat) REPEAT=$2; shift 2 ;;
    --tile-count) TILES=$2; shift 2 ;;
    -h|--help) sed -n '2,12p' "$0"; exit 0 ;;
    -*) echo "newton_pair: unknown option $1" >&2; exit 2 ;;
    *) LMP_ARG=$1; shift ;;
  esac
done
[[ $NP =~ ^[1-9][0-9]*$ && $REPEAT =~ ^[1-9][0-9]*$ && $TILES =~ ^[1-9][0-9]*$ ]] ||
  { echo "newton_pair: --np, --repeat and --tile-count take whole numbers >= 1" >&2; exit 2; }
LMP=$(realpath "${LMP_ARG:-$(dirname "${BASH_SOURCE[0]}")/../build/lmp_granpen}")
. "$(dirname "${BASH_SOURCE[0]}")/common.sh"
[ "$(id -u)" = 0 ] && export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
OUT=$WORK/newton_pair; rm -rf "$OUT"; mkdir -p "$OUT"
# the decks, with the push's newton setting a variable
cp -r "$ROOT/inputs" "$OUT/inputs"
grep -q '^newton           off$' "$OUT/inputs/in.push" || { echo "newton_pair: in.push has no 'newton off' line to vary" >&2; exit 1; }
sed -i 's/^newton           off$/variable         newton_pair index off\nnewton           ${newton_pair}/' "$OUT/inputs/in.push"
tile=$ROOT/data/sims/dg10/beds/bed_dg10_mu0.3_s1
"$LMP" -in "$OUT/inputs/in.pour" -var inputs "$OUT/inputs" -var preset dg10 -var mu 0.3 -var tile "$TILES" \
  -var box $((TILES * 5)) -var from_tile "$tile" -var out "$OUT/bed" -log "$OUT/rebuild.log" -screen none > /dev/null
row_of() { awk -F'|' -v k="$2" '$1 ~ "^"k" " {printf "%.2f", $3}' "$1"; }    # the row's average seconds
push() {    # NEWTON ROUND
  local log=$OUT/push_$1_$2.log
  mpirun --bind-to core -np "$NP" "$LMP" -in "$OUT/inputs/in.push" -var inputs "$OUT/inputs" -var preset dg10 -var mu 0.3 \
    -var bed "$OUT/bed.restart" -var v0 400 -var depth 0.05 -var newton_pair "$1" -var trace "$OUT/trace_$1_$2.csv" \
    -log "$log" -screen none > /dev/null
  grep -q "granpen push: done" "$log" || { echo "newton_pair: the newton $1 push did not finish ($log)" >&2; exit 1; }
  echo "$(awk '/^Loop time of/ {t = $4} END {print t}' "$log") $(row_of "$log" Pair) $(row_of "$log" Comm) $(row_of "$log" Modify)"
}
echo "newton_pair: $(date -u +%FT%TZ), $(nproc --all) cores, $NP ranks, $(awk '$1 == "grains" {print $3}' "$OUT/bed.info") grains"
echo "| round | newton | loop (s) | Pair | Comm | Modify |"
echo "| --- | --- | ---: | ---: | ---: | ---: |"
off=() on=()
for r in $(seq 1 "$REPEAT"); do
  # alternate which goes first, so that a drift of the machine's speed falls on both
  for nt in $([ $((r % 2)) = 1 ] && echo "off on" || echo "on off"); do
    read -r loop pair comm modify < <(push "$nt" "$r")
    echo "| $r | $nt | $loop | $pair | $comm | $modify |"
    if [ "$nt" = off ]; then off+=("$loop"); else on+=("$loop"); fi
  done
done
echo
echo "median loop time: newton off $(median "${off[@]}") s, on $(median "${on[@]}") s; off / on = $(ratio "$(median "${off[@]}")" "$(median "${on[@]}")") (above 1: newton on is faster)"
