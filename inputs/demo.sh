#!/usr/bin/env bash
# granpen demo: pour the tiny bed, push the rod at 50, 100 and 200 cm/s, plot F(z).
# Usage: demo.sh LMP_GRANPEN [OUTDIR]   (./granpen demo calls it). Rerunning skips
# what is already complete: the bed, and each push whose trace reached full depth.
set -euo pipefail
LMP=$1
INPUTS=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
ROOT=$(dirname "$INPUTS")
OUT=${2:-${GRANPEN_DEMO_OUT:-$ROOT/runs/demo}}
SPEEDS=(50 100 200)
mkdir -p "$OUT"; cd "$OUT"

progress() { grep --line-buffered -E "$1" | sed -u "s/^/  /" || true; }

if [ -f bed_tiny.restart ] && [ -f bed_tiny.info ]; then
  echo "[1/3] bed already poured: $OUT/bed_tiny.restart"
else
  echo "[1/3] pouring the tiny bed (about 2000 grains)"
  "$LMP" -in "$INPUTS/in.pour" -var inputs "$INPUTS" -var preset tiny -log pour.log \
    | progress "^granpen pour"
  [ -f bed_tiny.info ] || { echo "pour failed: see $OUT/pour.log"; exit 1; }
fi

i=0
for v in "${SPEEDS[@]}"; do
  i=$((i + 1))
  trace=trace_tiny_v$v.csv
  if [ -f "$trace" ] && grep -q "granpen push: done" "push_v$v.log" 2>/dev/null; then
    echo "[2/3] push $i/${#SPEEDS[@]} at v0 = $v cm/s already done: $trace"
    continue
  fi
  echo "[2/3] push $i/${#SPEEDS[@]} at v0 = $v cm/s (step, time, depth, F, contacts, t~, F/F_z)"
  "$LMP" -in "$INPUTS/in.push" -var inputs "$INPUTS" -var preset tiny -var v0 "$v" \
    -var trace "$trace" -var thermo_every 5000 -log "push_v$v.log" \
    | progress "^ +[0-9]+ +[-0-9.e+]+ +[-0-9.e+]+ +[-0-9.e+]+ |^granpen push"
done

echo "[3/3] plotting F against depth"
files=""
for v in "${SPEEDS[@]}"; do files="$files trace_tiny_v$v.csv"; done
gnuplot -e "files='${files# }'; out='force_depth.png'" "$ROOT/analysis/plots/force_depth.gp"

echo
echo "granpen demo done. Outputs in $OUT:"
echo "  bed:    bed_tiny.restart, bed_tiny.info ($(grep -E '^(z_s|phi_0)' bed_tiny.info | tr '\n' ' '))"
for v in "${SPEEDS[@]}"; do echo "  trace:  trace_tiny_v$v.csv   (log push_v$v.log)"; done
echo "  plot:   force_depth.png"
