#!/usr/bin/env bash
# Voronoi time per frame of 1e5 grains (issue 5): analysis/core/voronoi_volumes, what
# `granpen flow` does per frame of a dump without a Voronoi column, against LAMMPS's
# compute voronoi/atom on the same frame, in one run.
#   bench/voronoi_frame.sh [BUILD_DIR] [REPEAT] [GRAINS]      (./granpen build first)
# The frame (once, runs/bench/voronoi/): a jittered FCC packing at phi 0.58 of grains of
# 0.4 cm, about GRAINS of them (98304 for 1e5) in a 19.6 x 19.6 cm box periodic in x and
# y, floor at z = 0, box top at 34 cm (the paper preset's box), as a LAMMPS data file
# (bench/voronoi_frame_bench.cpp make). Each round times, alternately:
#   (a) voronoi_frame_bench time: one voronoi_volumes call on the frame (reading the file
#       not included), wall clock;
#   (b) bench/in.voronoi_frame: compute voronoi/atom (radius keyword: the same radical
#       tessellation) evaluated once in a 1-step run, LAMMPS's "Modify" time (reading the
#       data file and the set-up not included), with the ghost cutoff of a granular run
#       (0.48 cm = d_g + skin);
#   (b2) the same with a 2 cm ghost cutoff, the smallest here with which compute
#       voronoi/atom's cells fill the box exactly (see the check).
# Ratios (a)/(b) and (a)/(b2) per round, then the median. Before the rounds, a check:
# both tessellations' per-grain volumes and totals (voronoi_frame_bench check).
set -euo pipefail
BUILD=$(realpath "${1:-$(dirname "${BASH_SOURCE[0]}")/../build}")
REPEAT=${2:-5}
GRAINS=${3:-100000}
LMP=$BUILD/lmp_granpen
. "$(dirname "${BASH_SOURCE[0]}")/common.sh"
[ -x "$LMP" ] || { echo "no $LMP: ./granpen build first" >&2; exit 1; }
cmake --build "$BUILD" -j1 --target voronoi_frame_bench >/dev/null
BENCH="$BUILD/tests/analysis/io/voronoi_frame_bench"    # target of tests/analysis/io/CMakeLists.txt
DECK="$HERE/in.voronoi_frame"
DIR="$WORK/voronoi"
mkdir -p "$DIR"
DATA="$DIR/frame_$GRAINS.data"
if [ ! -f "$DATA" ]; then
  "$BENCH" make "$DATA.part" "$GRAINS" 0.58 0.4 34 1
  mv "$DATA.part" "$DATA"
fi
echo "frame: $DATA, $(awk '/ atoms$/ {print $1; exit}' "$DATA") grains; load average $(cut -d' ' -f1-3 /proc/loadavg)"

run_a() {    # seconds of one voronoi_volumes call
  local out
  out=$("$BENCH" time "$DATA")
  case "$out" in "grains "*" missing 0") ;; *) echo "voronoi_frame_bench: unexpected output: $out" >&2; exit 1 ;; esac
  awk '{print $4}' <<< "$out"
}
run_b() {    # run_b GHOST [CHECK]: compute voronoi/atom's seconds (LAMMPS's Modify row)
  local log="$DIR/lmp_ghost$1.log"
  (cd "$DIR" && "$LMP" -in "$DECK" -var data "$DATA" -var ghost "$1" -var check "${2:-no}" \
    -var dump "$DIR/voronoi_atom_ghost$1.dump" -log "$log" -screen none)
  grep -q "^voronoi/atom total volume" "$log" || { echo "$log: the compute did not run in the loop" >&2; exit 1; }
  awk -F'|' '$1 ~ /^Modify/ {printf "%.4f\n", $3}' "$log"
}

echo "check: per-grain volumes, voronoi_volumes against compute voronoi/atom"
for g in 0.48 2.0; do
  run_b "$g" yes > /dev/null
  tol=1e-9
  [ "$g" = 0.48 ] && tol=1e-3    # surface cells cut by the container at the ghost cutoff (see docs)
  echo "  ghost cutoff $g cm (total volume tolerance $tol):"
  ok=yes
  "$BENCH" check "$DATA" "$DIR/voronoi_atom_ghost$g.dump" "$tol" > "$DIR/check_ghost$g.txt" || ok=no
  sed 's/^/    /' "$DIR/check_ghost$g.txt"
  [ $ok = yes ] || { echo "check failed" >&2; exit 1; }
done

t_a=() t_b=() t_b2=() r_b=() r_b2=()
for r in $(seq 1 "$REPEAT"); do
  a=$(run_a)
  b=$(run_b 0.48)
  b2=$(run_b 2.0)
  t_a+=("$a") t_b+=("$b") t_b2+=("$b2")
  r_b+=("$(ratio "$a" "$b")")
  r_b2+=("$(ratio "$a" "$b2")")
  echo "round $r/$REPEAT: (a) voronoi_volumes $a s, (b) compute voronoi/atom ghost 0.48 cm $b s, ratio ${r_b[-1]};" \
    "(b2) ghost 2 cm $b2 s, ratio ${r_b2[-1]}"
done
echo "seconds per frame (median): (a) $(median "${t_a[@]}"), (b) $(median "${t_b[@]}"), (b2) $(median "${t_b2[@]}")"
echo "(a)/(b), ghost 0.48 cm: ratios $(printf '%s\n' "${r_b[@]}" | sort -g | tr '\n' ' ')median $(median "${r_b[@]}")"
echo "(a)/(b2), ghost 2 cm: ratios $(printf '%s\n' "${r_b2[@]}" | sort -g | tr '\n' ' ')median $(median "${r_b2[@]}")"
echo "load average $(cut -d' ' -f1-3 /proc/loadavg); $(date -I)"
