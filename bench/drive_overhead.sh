#!/usr/bin/env bash
# Cost per step of a bench push with fix rod/drive + compute rod/drag (and its 10 kHz
# trace) against the same push with stock fix move linear + compute reduce + fix
# ave/time, in one run: the two are run alternately REPEAT times each on the same bed,
# and the ratio of median loop times per step is reported. Target: <= 1.02.
#   bench/drive_overhead.sh [LMP_GRANPEN] [REPEAT]      (./granpen build first)
set -euo pipefail
LMP=$(realpath "${1:-$(dirname "${BASH_SOURCE[0]}")/../build/lmp_granpen}")
REPEAT=${2:-3}
. "$(dirname "${BASH_SOURCE[0]}")/common.sh"
ensure_bench_bed
cd "$WORK"
# the "Modify" row of LAMMPS's timing breakdown (fixes: integration, drive, output), per step
modify_of() { awk -F'|' '/^Loop time of/ {n=$0; sub(/.* for /,"",n); sub(/ steps.*/,"",n)} /^Modify/ {m=$3} END {printf "%.9g\n", m/n}' "$1"; }

granpen=() stock=() ratios=() mod_g=() mod_s=()
for r in $(seq 1 "$REPEAT"); do
  "$LMP" -in "$ROOT/inputs/in.push" -var inputs "$ROOT/inputs" -var preset bench -var bed bed_bench.restart \
    -var v0 100 -var trace granpen_$r.csv -log granpen_$r.log -screen none
  granpen+=("$(per_step granpen_$r.log)")
  "$LMP" -in "$HERE/in.push_stock" -var inputs "$ROOT/inputs" -var bed bed_bench.restart -var v0 100 \
    -var nsteps "$(awk '/^Loop time of/ {n=$9} END {print n}' granpen_$r.log)" \
    -var trace stock_$r.txt -log stock_$r.log -screen none
  stock+=("$(per_step stock_$r.log)")
  mod_g+=("$(modify_of granpen_$r.log)") mod_s+=("$(modify_of stock_$r.log)")
  ratios+=("$(ratio "${granpen[-1]}" "${stock[-1]}")")
  echo "round $r/$REPEAT: rod/drive ${granpen[-1]} s/step, stock ${stock[-1]} s/step, ratio ${ratios[-1]}" \
       "(Modify section: ${mod_g[-1]} vs ${mod_s[-1]} s/step)"
done
mg=$(median "${granpen[@]}") ms=$(median "${stock[@]}")
atoms=$(awk '/^Loop time of/ {print $12}' granpen_1.log | tail -1)
sorted=$(printf '%s\n' "${ratios[@]}" | sort -g | tr '\n' ' ')
echo "median s/step: rod/drive+rod/drag $mg, fix move+compute reduce $ms"
echo "ratio per round (sorted): $sorted; median $(median "${ratios[@]}") (target <= 1.02)"
echo "Modify section per step, median: rod/drive $(median "${mod_g[@]}"), stock $(median "${mod_s[@]}")"
echo "throughput: $(awk -v a="$mg" -v n="$atoms" 'BEGIN{printf "%.3g", n/a}') atom-steps/s with $atoms atoms"
