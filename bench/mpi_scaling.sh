#!/usr/bin/env bash
# Strong scaling of the pour and the push at 1 and 2 MPI ranks (more with --ranks), in one
# run, so the speed-ups compare runs made on the same day; plus where the time of the
# package's own collectives goes, and a correctness run on more ranks than cores.
#   bench/mpi_scaling.sh [--presets "bench mid"] [--ranks "1 2"] [--check-ranks 4]
#                        [--push-depth CM] [--pour-chunks N] [--balance] [LMP_GRANPEN]
# For each preset: a bed poured once at one rank ($WORK/bed_PRESET.restart); the pour timed
# from the start for --pour-chunks settling chunks and one relaxation chunk (the same seed,
# the same steps at every rank count); the push at 100 cm/s to --push-depth from that bed.
# Speed-up = loop time at 1 rank / at N ranks; efficiency = speed-up / N. LAMMPS's decks
# cut the box in x-y columns (inputs/model/decomposition.lmp); --balance adds a run of each
# at the highest rank count with comm_style tiled + rcb balancing, and one with LAMMPS's
# default grid (cut along the tallest side, z) for comparison.
# The package's collectives: the push at the highest rank count again under an LD_PRELOAD
# PMPI counter (bench/mpi_collectives.c): calls per step and seconds by calling function.
set -euo pipefail
PRESETS="bench mid" RANKS="1 2" CHECK=4 PUSH_DEPTH="" POUR_CHUNKS=4 BALANCE=0 LMP_ARG=""
while [ $# -gt 0 ]; do
  case "$1" in
    --presets) PRESETS=$2; shift 2 ;;
    --ranks) RANKS=$2; shift 2 ;;
    --check-ranks) CHECK=$2; shift 2 ;;
    --push-depth) PUSH_DEPTH=$2; shift 2 ;;
    --pour-chunks) POUR_CHUNKS=$2; shift 2 ;;
    --balance) BALANCE=1; shift ;;
    -h|--help) sed -n '2,16p' "$0"; exit 0 ;;
    -*) echo "mpi_scaling: unknown option $1" >&2; exit 2 ;;
    *) LMP_ARG=$1; shift ;;
  esac
done
LMP=$(realpath "${LMP_ARG:-$(dirname "${BASH_SOURCE[0]}")/../build/lmp_granpen}")
. "$(dirname "${BASH_SOURCE[0]}")/common.sh"
export OMPI_MCA_rmaps_base_oversubscribe=1
[ "$(id -u)" = 0 ] && export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
OUT="$WORK/mpi_scaling"; mkdir -p "$OUT"
# Open MPI busy-polls while it waits: two ranks on two cores, nothing else, or the figures
# measure the neighbours. Bind each rank to a core.
MPIRUN=(mpirun --bind-to core)
loop_sum() { awk '/^Loop time of/ {t += $4} END {printf "%.3f\n", t}' "$1"; }
loop_last() { awk '/^Loop time of/ {t = $4} END {printf "%.3f\n", t}' "$1"; }
steps_last() { awk '/^Loop time of/ {n = $9} END {print n}' "$1"; }
atoms_last() { awk '/^Loop time of/ {n = $12} END {print n}' "$1"; }
run_np() {    # NP LOG ARGS...: one LAMMPS run on NP ranks (1: no mpirun; more than cores: unbound)
  local np=$1 log=$2; shift 2
  if [ "$np" = 1 ]; then "$LMP" "$@" -log "$log" -screen none >/dev/null
  elif [ "$np" -gt "$(nproc --all)" ]; then
    mpirun --bind-to none --oversubscribe -np "$np" "$LMP" "$@" -log "$log" -screen none >/dev/null
  else "${MPIRUN[@]}" -np "$np" "$LMP" "$@" -log "$log" -screen none >/dev/null; fi
}
grid_of() {    # "2 by 1 by 1", or "tiled (rcb)"
  if grep -q "^comm_style *tiled" "$1"; then echo "tiled (rcb)"
  else grep -m1 -E "^ *[0-9]+ by [0-9]+ by [0-9]+ MPI processor grid" "$1" | awk '{print $1, $2, $3, $4, $5}'; fi
}
row() { printf '| %s | %s | %s | %s | %s | %s | %s |\n' "$@"; }

echo "mpi_scaling: $(date -u +%FT%TZ), $(nproc --all) cores, LMP $LMP"
echo
row preset run ranks grid "loop time (s)" speed-up efficiency
row --- --- ---: --- ---: ---: ---:
for P in $PRESETS; do
  bed="$WORK/bed_$P.restart"
  if [ ! -f "$bed" ]; then
    echo "pouring the $P bed once at one rank (bench: about a minute, mid: about 13 minutes)" >&2
    "$LMP" -in "$ROOT/inputs/in.pour" -var inputs "$ROOT/inputs" -var preset "$P" \
      -var out "$WORK/bed_$P" -log "$WORK/pour_$P.log" -screen none >/dev/null
  fi
  depth=${PUSH_DEPTH:-$(awk '$1=="variable" && $2=="depth" {print $4}' "$ROOT/inputs/presets/$P.lmp")}
  for kind in pour push; do
    t1=""
    variants=()
    for np in $RANKS; do variants+=("$np:columns"); done
    if [ "$BALANCE" = 1 ]; then
      top=${RANKS##* }; variants+=("$top:rcb" "$top:zcut")
    fi
    for v in "${variants[@]}"; do
      np=${v%%:*} how=${v#*:}
      extra=()
      [ "$how" = rcb ] && extra=(-var balance rcb)
      [ "$how" = zcut ] && extra=(-var px "*" -var py "*" -var pz "*")
      log="$OUT/${P}_${kind}_np${np}_$how.log"
      if [ "$kind" = pour ]; then
        run_np "$np" "$log" -in "$ROOT/inputs/in.pour" -var inputs "$ROOT/inputs" -var preset "$P" \
          -var out "$OUT/bed_${P}_np${np}_$how" -var max_chunks "$POUR_CHUNKS" -var relax_runs 1 "${extra[@]}"
        t=$(loop_sum "$log")
      else
        run_np "$np" "$log" -in "$ROOT/inputs/in.push" -var inputs "$ROOT/inputs" -var preset "$P" \
          -var bed "$bed" -var v0 100 -var depth "$depth" -var trace "$OUT/${P}_np${np}_$how.csv" "${extra[@]}"
        t=$(loop_last "$log")
      fi
      [ -z "$t1" ] && t1=$t
      s=$(awk -v a="$t1" -v b="$t" 'BEGIN {printf "%.3f", a/b}')
      e=$(awk -v s="$s" -v n="$np" 'BEGIN {printf "%.0f%%", 100*s/n}')
      row "$P" "$kind ($how)" "$np" "$(grid_of "$log")" "$t" "$s" "$e"
    done
  done
done

# the package's own collectives, at the highest rank count, on the first preset's push
P=${PRESETS%% *} np=${RANKS##* }
if [ "$np" -gt 1 ]; then
  so="$OUT/mpi_collectives.so"
  mpicc -O2 -shared -fPIC "$HERE/mpi_collectives.c" -o "$so" -ldl
  log="$OUT/${P}_push_np${np}_collectives.log"
  MPI_COLLECTIVES_OUT="$OUT/collectives.txt" "${MPIRUN[@]}" -np "$np" -x LD_PRELOAD="$so" -x MPI_COLLECTIVES_OUT \
    "$LMP" -in "$ROOT/inputs/in.push" -var inputs "$ROOT/inputs" -var preset "$P" -var bed "$WORK/bed_$P.restart" \
    -var v0 100 -var depth "${PUSH_DEPTH:-1.0}" -var trace "$OUT/${P}_collectives.csv" -log "$log" -screen none >/dev/null
  steps=$(steps_last "$log") loop=$(loop_last "$log")
  echo
  echo "collectives of the $P push on $np ranks ($steps steps, loop $loop s on rank 0), by calling function:"
  echo
  row "object" "function" "collective" "calls" "per step" "seconds" "share of loop"
  row --- --- --- ---: ---: ---: ---:
  sort -k2,2nr "$OUT/collectives.txt" | awk '$2 >= 10' | while read -r name count secs obj off; do
    # a return address points after the call: step back one byte for the calling line
    fn=$(addr2line -f -C -e "$obj" "$(printf '0x%x' $((off - 1)))" 2>/dev/null | head -1 | sed 's/(.*//')
    row "$(basename "$obj")" "$fn" "$name" "$count" "$(awk -v c="$count" -v n="$steps" 'BEGIN {printf "%.3f", c/n}')" \
      "$secs" "$(awk -v s="$secs" -v l="$loop" 'BEGIN {printf "%.1f%%", 100*s/l}')"
  done
fi

# correctness on more ranks than cores (oversubscribed: no timing claimed)
if [ "$CHECK" -gt 0 ]; then
  P=${PRESETS%% *}
  log="$OUT/${P}_push_np${CHECK}_check.log" trace="$OUT/${P}_np${CHECK}_check.csv"
  run_np "$CHECK" "$log" -in "$ROOT/inputs/in.push" -var inputs "$ROOT/inputs" -var preset "$P" \
    -var bed "$WORK/bed_$P.restart" -var v0 100 -var depth 1.0 -var trace "$trace"
  ref="$OUT/${P}_np1_check.csv"
  run_np 1 "$OUT/${P}_push_np1_check.log" -in "$ROOT/inputs/in.push" -var inputs "$ROOT/inputs" -var preset "$P" \
    -var bed "$WORK/bed_$P.restart" -var v0 100 -var depth 1.0 -var trace "$ref"
  mean_f() { awk -F, '!/^#/ && NR > 1 && $2 >= 0.5 && $2 <= 1.0 {s += $3; n++} END {printf "%.4g %d", s/n, n}' "$1"; }
  echo
  echo "correctness on $CHECK ranks ($(grid_of "$log")), $P push to 1 cm at 100 cm/s:" \
       "atoms $(atoms_last "$OUT/${P}_push_np1_check.log") at 1 rank, $(atoms_last "$log") at $CHECK;" \
       "mean F over z = 0.5-1 cm (dyne, rows): 1 rank $(mean_f "$ref"), $CHECK ranks $(mean_f "$trace")"
  grep -q "granpen push: done" "$log" || { echo "mpi_scaling: the $CHECK-rank push did not finish" >&2; exit 1; }
fi
