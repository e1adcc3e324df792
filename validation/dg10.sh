#!/usr/bin/env bash
# The D/d_g = 10 runs (docs/presets.md, issue: physics at the paper's grain size ratio),
# resumable across sessions: run it again and it goes on where it stopped. Pours checkpoint
# every settling chunk (in.pour -var checkpoint 1); pushes every 5000 steps (the sweep
# runner). One run at a time, niced, so that the machine's other core stays free.
#
#   validation/dg10.sh [--out DIR] [--jobs N] [--status]
#
#   --out DIR   where the runs live (default /work/granpen-runs: outside the work tree, so
#               that a new checkout does not lose hours of pouring); DIR/dg10/ is the
#               sweep folder of inputs/sweeps/dg10_{peak,flow,D}.sweep
#   --status    print how far it got (beds poured, pushes done) and stop
# The decks are copied into DIR/dg10/inputs at every start, so that editing inputs/ in the
# work tree never changes a run under way (LAMMPS rereads a deck at every jump); a pour
# resumed under newer decks reads the same checkpoint state.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
OUT=/work/granpen-runs JOBS=1 STATUS=0
while [ $# -gt 0 ]; do
  case $1 in
    --out) OUT=$2; shift 2 ;;
    --jobs) JOBS=$2; shift 2 ;;
    --status) STATUS=1; shift ;;
    *) echo "dg10.sh: unknown argument $1 (see the header of $0)" >&2; exit 2 ;;
  esac
done
LMP=${GRANPEN_LMP:-$ROOT/build/lmp_granpen} CLI=${GRANPEN_CLI:-$ROOT/build/analysis/granpen-cli}
D=$OUT/dg10
mkdir -p "$D/beds" "$D/logs"
if [ "$STATUS" = 0 ]; then rm -rf "$D/inputs.new"; cp -r "$ROOT/inputs" "$D/inputs.new"; rm -rf "$D/inputs"; mv "$D/inputs.new" "$D/inputs"; fi

status() {
  local beds pushes
  beds=$(find "$D/beds" -maxdepth 1 -name "*.info" | wc -l)
  pushes=$(find "$D" -maxdepth 2 -path "*/traces/*.csv.done" | wc -l)
  echo "dg10: $beds of 3 beds poured, $pushes of 20 pushes done ($D)"
  for s in 1 2 3; do
    local st="$D/beds/bed_dg10_mu0.3_s$s.pour.state"
    [ -f "$st" ] && echo "  bed $s: pouring, $(awk '$2 == "phase" {p=$4} $2 == "ichunk0" {c=$4} $2 == "irelax0" {r=$4} END {print p, (p == "settle" ? "chunk " c : "relaxation " r)}' "$st") next"
  done
  return 0
}
[ "$STATUS" = 1 ] && { status; exit 0; }

# the sweep runner pours the beds (pour_checkpoint = yes: resumed at their last chunk) and
# runs the pushes; it skips what is done and resumes the rest
for part in peak flow D; do
  nice -n 19 "$CLI" sweep "$ROOT/inputs/sweeps/dg10_$part.sweep" --jobs "$JOBS" --out "$OUT" \
    --inputs "$D/inputs" --lmp "$LMP"
done
status
