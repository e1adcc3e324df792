#!/usr/bin/env bash
# Runs one of the bench peak-law variants, inputs/sweeps/NAME.sweep (peak_stiffness: grains ten
# times stiffer; peak_damping: contact damping ten times weaker in the push), through the sweep
# runner, which resumes where it stopped, and copies its traces, bed .info files and manifest
# into data/sims/NAME, where validation/results.sh compares them with the bench sweep.
#
#   validation/peak_sweep.sh NAME [--jobs N] [--out DIR]
#
#   NAME       peak_stiffness or peak_damping (any inputs/sweeps/NAME.sweep)
#   --jobs N   runs at a time (default 1; 2 on an otherwise idle machine)
#   --out DIR  the sweep runner's folder (default runs; DIR/NAME)
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
[ $# -ge 1 ] || { echo "peak_sweep.sh: usage: validation/peak_sweep.sh NAME [--jobs N] [--out DIR]" >&2; exit 2; }
NAME=$1 JOBS=1 OUT=$ROOT/runs; shift
SPEC=$ROOT/inputs/sweeps/$NAME.sweep
[[ $NAME =~ ^[A-Za-z0-9_]+$ ]] && [ -f "$SPEC" ] || { echo "peak_sweep.sh: no sweep file $SPEC" >&2; exit 2; }
while [ $# -gt 0 ]; do
  case $1 in
    --jobs) JOBS=$2; shift 2 ;;
    --out) OUT=$2; shift 2 ;;
    *) echo "peak_sweep.sh: unknown argument $1 (see the header of $0)" >&2; exit 2 ;;
  esac
done
[[ $JOBS =~ ^[1-9][0-9]*$ ]] || { echo "peak_sweep.sh: --jobs $JOBS is not a whole number >= 1" >&2; exit 2; }
CLI=${GRANPEN_CLI:-$ROOT/build/analysis/granpen-cli} LMP=${GRANPEN_LMP:-$ROOT/build/lmp_granpen}
[ -x "$CLI" ] && [ -x "$LMP" ] || { echo "peak_sweep.sh: build first (no $CLI or $LMP)" >&2; exit 2; }
"$CLI" sweep "$SPEC" --jobs "$JOBS" --out "$OUT" --inputs "$ROOT/inputs" --lmp "$LMP"
DATA=$ROOT/data/sims/$NAME src=$OUT/$NAME
rm -rf "$DATA.new"; mkdir -p "$DATA.new"
cp "$src"/traces/*.csv "$src"/beds/*.info "$src/manifest.json" "$DATA.new/"
rm -rf "$DATA"; mv "$DATA.new" "$DATA"
echo "peak_sweep.sh: $(ls "$DATA"/*.csv | wc -l) traces in $DATA (validation/results.sh compares them with the bench sweep)"
