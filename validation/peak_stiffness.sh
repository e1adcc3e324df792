#!/usr/bin/env bash
# Runs inputs/sweeps/peak_stiffness.sweep (the bench peak-law sweep with grains ten times
# stiffer: does the peak exponent rise toward the paper's 2?) through the sweep runner, which
# resumes where it stopped, and copies its traces, bed .info files and manifest into
# data/sims/peak_stiffness, where validation/results.sh compares them with the bench sweep.
#
#   validation/peak_stiffness.sh [--jobs N] [--out DIR]
#
#   --jobs N   runs at a time (default 1; 2 on an otherwise idle machine)
#   --out DIR  the sweep runner's folder (default runs; DIR/peak_stiffness)
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
JOBS=1 OUT=$ROOT/runs
while [ $# -gt 0 ]; do
  case $1 in
    --jobs) JOBS=$2; shift 2 ;;
    --out) OUT=$2; shift 2 ;;
    *) echo "peak_stiffness.sh: unknown argument $1 (see the header of $0)" >&2; exit 2 ;;
  esac
done
[[ $JOBS =~ ^[1-9][0-9]*$ ]] || { echo "peak_stiffness.sh: --jobs $JOBS is not a whole number >= 1" >&2; exit 2; }
CLI=${GRANPEN_CLI:-$ROOT/build/analysis/granpen-cli} LMP=${GRANPEN_LMP:-$ROOT/build/lmp_granpen}
[ -x "$CLI" ] && [ -x "$LMP" ] || { echo "peak_stiffness.sh: build first (no $CLI or $LMP)" >&2; exit 2; }
"$CLI" sweep "$ROOT/inputs/sweeps/peak_stiffness.sweep" --jobs "$JOBS" --out "$OUT" --inputs "$ROOT/inputs" --lmp "$LMP"
DATA=$ROOT/data/sims/peak_stiffness src=$OUT/peak_stiffness
mkdir -p "$DATA.new"
cp "$src"/traces/*.csv "$src"/beds/*.info "$src/manifest.json" "$DATA.new/"
rm -rf "$DATA"; mv "$DATA.new" "$DATA"
echo "peak_stiffness.sh: $(ls "$DATA"/*.csv | wc -l) traces in $DATA (validation/results.sh compares them with the bench sweep)"
