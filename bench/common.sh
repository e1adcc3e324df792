# Shared by the bench/ scripts (sourced): paths, the bench bed, and timing helpers.
# Sets HERE, ROOT, WORK; expects LMP to be set by the caller.
HERE=$(cd "$(dirname "${BASH_SOURCE[1]}")" && pwd)
ROOT=$(dirname "$HERE")
WORK=${GRANPEN_BENCH_WORK:-$ROOT/runs/bench}
export OMP_NUM_THREADS=1

# pour the bench bed once into $WORK/bed_bench.restart
ensure_bench_bed() {
  mkdir -p "$WORK"
  if [ ! -f "$WORK/bed_bench.restart" ]; then
    echo "pouring the bench bed (once, about a minute)"
    "$LMP" -in "$ROOT/inputs/in.pour" -var inputs "$ROOT/inputs" -var preset bench \
      -var out "$WORK/bed_bench" -log "$WORK/pour.log" -screen none
  fi
}
# seconds per step of the last run in a LAMMPS log
per_step() { awk '/^Loop time of/ {t=$4; n=$9} END {printf "%.9g\n", t/n}' "$1"; }
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print (NR%2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2)}'; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN{printf "%.4f", a/b}'; }
# The machine's speed, as one number a cost can be divided by: the wall seconds of bed 1
# of the bench scenario poured alone (110000 steps; 69.9 s on 2026-11-22,
# data/sims/validation_bench/bed_bench_mu0.3_s1.info). Prints the seconds.
probe_pour() {    # DIR
  local t0 t1; mkdir -p "$1"; t0=$(date +%s.%N)
  "$LMP" -in "$ROOT/inputs/in.pour" -var inputs "$ROOT/inputs" -var preset bench -var mu 0.3 -var seed 1 \
    -var out "$1/probe_bed" -log "$1/probe_pour.log" -screen none > /dev/null 2>&1 || true
  t1=$(date +%s.%N)
  [ -f "$1/probe_bed.info" ] || { echo "probe_pour: the pour failed (see $1/probe_pour.log)" >&2; return 1; }
  awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.1f\n", b - a }'
}
