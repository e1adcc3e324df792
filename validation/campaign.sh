#!/usr/bin/env bash
# A campaign of long runs, resumable across sessions (validation/dg10.sh, validation/box.sh
# name theirs). Every session gets a new machine and only what is committed to git survives,
# so the work is cut into units that each fit a session, and each finished unit is copied
# into the campaign's data folder at once, to be committed:
#   a bed   the sweep's pour: a periodic tile (in.pour -var tile N) replicated into the bed.
#           Its tile (beds/ID.tile.data.gz, a few MB, and ID.tile.info) and the bed's ID.info
#           are copied to DATA/beds; a later session rebuilds the bed from them in seconds
#           (in.pour -var from_tile) instead of pouring it again. A committed tile may serve
#           a wider box: the sweep's `set` gives tile, box (and surface_grid), and the bed is
#           rebuilt as tile x tile copies (in.pour checks that the box is tile x the tile's side);
#           its rod_types (2: the shaft's own atom type, in.push mu_shaft) goes to the rebuild too.
#   a push  its trace goes to DATA/SWEEP/ID.csv (SWEEP: the sweep file's name); a push whose
#           trace is there is never rerun. A push of a sweep with observe = dump (dumps of
#           every atom, hundreds of MB, not committed) is followed by validation/push_flow.sh
#           on its dumps (`granpen flow` and `granpen momentum`, as for the mid push of
#           docs/results.md), whose tables (small) go to DATA/SWEEP/ID.flow/; such a push is
#           done only when they are there.
# Run it again in any session and it goes on with the first unit not committed. One run at
# a time, niced, so that the machine's other core stays free. Units in order: the beds of
# each sweep file, then its pushes, sweep file by sweep file.
#
#   validation/campaign.sh --data DIR --sweeps "FILE..." [--out DIR] [--units N] [--ranks N]
#                          [--tip "ZLO ZHI"] [--checkpoint STEPS] [--commit] [--status]
#
#   --data DIR    the committed folder of the campaign (DIR/beds, DIR/SWEEP); its name is
#                 the campaign's in messages and commits
#   --sweeps ...  the sweep files, run in this order
#   --out DIR     scratch folder of the runs (default /work/granpen-runs; lost with the
#                 machine): DIR/SWEEP/ is the sweep folder of SWEEP.sweep
#   --units N     stop after N units of work have been run (default: all); a unit is a bed
#                 poured or a push; rebuilding a bed from its committed tile is not one
#   --ranks N     run each unit on N MPI ranks (mpirun; default 1)
#   --tip "A B"   the tip's depth window of the flow analysis (push_flow.sh --tip; default 1 4)
#   --checkpoint STEPS  a push's checkpoints every STEPS steps (the sweep runner's --checkpoint,
#                 default 5000); a push is resumed with the campaign's value, and resuming one
#                 from a checkpoint written at another spacing is sound whenever that spacing
#                 is a multiple of this one (the run stops at the next multiple of STEPS)
#   --commit      git-commit DIR after every unit (on the work tree's branch)
#   --status      print what is committed and what is under way, and stop
# A push cut by the end of a session (or a kill) leaves its trace and its checkpoints
# (TRACE.a/.b.restart, every 5000 steps; about 180 MB each for the 536576 atoms of a 20 cm dg10
# bed) in OUT/SWEEP/traces, not committed: where OUT survives (this machine's /work has so far),
# the next run resumes the push from its newer complete checkpoint (the sweep runner,
# docs/sweeps.md); a checkpoint cut short in writing is never resumed from, and without a
# complete one the push starts over. A resume that LAMMPS refuses at the checkpoint (a restart
# file this build cannot read) sets its checkpoints aside (.stale) and starts the push over,
# once. --status lists such pushes under way.
# The decks are copied into OUT/inputs.CAMPAIGN at every start, so that editing inputs/ in the
# work tree never changes a run under way (LAMMPS rereads a deck at every jump), nor does
# another campaign starting in the same OUT.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
OUT=/work/granpen-runs UNITS=-1 RANKS=1 COMMIT=0 STATUS=0 DATA="" SWEEPS="" TIP="1 4" CHECKPOINT=5000
while [ $# -gt 0 ]; do
  case $1 in
    --out) OUT=$2; shift 2 ;;
    --units) UNITS=$2; shift 2 ;;
    --ranks) RANKS=$2; shift 2 ;;
    --commit) COMMIT=1; shift ;;
    --status) STATUS=1; shift ;;
    --data) DATA=$2; shift 2 ;;
    --sweeps) SWEEPS=$2; shift 2 ;;
    --tip) TIP=$2; shift 2 ;;
    --checkpoint) CHECKPOINT=$2; shift 2 ;;
    *) echo "campaign.sh: unknown argument $1 (see the header of $0)" >&2; exit 2 ;;
  esac
done
[ -n "$DATA" ] && [ -n "$SWEEPS" ] || { echo "campaign.sh: --data DIR and --sweeps \"FILE...\" are needed (see the header of $0)" >&2; exit 2; }
CAMPAIGN=$(basename "$DATA")
[[ $UNITS =~ ^(-1|[0-9]+)$ ]] || { echo "campaign.sh: --units $UNITS is not a whole number" >&2; exit 2; }
[[ $RANKS =~ ^[1-9][0-9]*$ ]] || { echo "campaign.sh: --ranks $RANKS is not a whole number >= 1" >&2; exit 2; }
[[ $CHECKPOINT =~ ^[1-9][0-9]{0,5}$ ]] || { echo "campaign.sh: --checkpoint $CHECKPOINT is not a whole number of steps >= 1" >&2; exit 2; }
LMP=${GRANPEN_LMP:-$ROOT/build/lmp_granpen} CLI=${GRANPEN_CLI:-$ROOT/build/analysis/granpen-cli}
[ -x "$CLI" ] || { echo "campaign.sh: no granpen-cli at $CLI (build first, or set GRANPEN_CLI)" >&2; exit 2; }
mkdir -p "$DATA/beds"

# the planned runs of a sweep file: lines "K pour|push ID"
plan() { "$CLI" sweep "$1" --plan --inputs "$ROOT/inputs" --out "$OUT" | awk '{print $1, $2, $3}'; }
sweep_name() { awk -F= '$1 ~ /^name *$/ {gsub(/[ \t]/, "", $2); sub(/#.*/, "", $2); print $2}' "$1"; }
# the `set` line's values of the names given, as "-var NAME VALUE" words
set_vars() {
  local f=$1; shift
  awk -F= -v want=" $* " '$1 ~ /^set *$/ {sub(/#.*/, "", $0); sub(/^set *= */, "", $0); n = split($0, kv, /[ \t]+/)
    for (i = 1; i <= n; i++) { split(kv[i], p, "="); if (p[1] != "" && index(want, " " p[1] " ")) printf "-var %s %s ", p[1], p[2] } }
    END { print "" }' "$f"
}
# 1 when the sweep's pushes write dumps (observe = dump), else 0
dumps_of() { awk -F= '$1 ~ /^observe *$/ {sub(/#.*/, "", $2); gsub(/[ \t]/, "", $2); d = ($2 == "dump")} END {print d + 0}' "$1"; }

status() {
  local total=0 done=0 beds=0 nbeds=0
  for f in $SWEEPS; do
    local name; name=$(sweep_name "$f")
    while read -r k kind id; do
      if [ "$kind" = pour ]; then
        case " $seen " in *" $id "*) continue ;; esac
        seen="$seen $id"; nbeds=$((nbeds + 1))
        [ -f "$DATA/beds/$id.tile.data.gz" ] && beds=$((beds + 1))
      else
        # sweep files of one name share a folder: a push listed by two counts once
        case " $seen " in *" $name/$id "*) continue ;; esac
        seen="$seen $name/$id"; total=$((total + 1))
        [ -f "$DATA/$name/$id.csv" ] && { [ "$(dumps_of "$f")" = 0 ] || [ -f "$DATA/$name/$id.flow/window.txt" ]; } &&
          done=$((done + 1))
      fi
    done < <(plan "$f")
  done
  echo "$CAMPAIGN: $beds of $nbeds beds and $done of $total pushes committed ($DATA)"
  for st in "$OUT"/*/beds/*.pour.state; do
    [ -f "$st" ] || continue
    echo "  under way here: ${st%.pour.state}: $(awk '$2 == "phase" {p=$4} $2 == "ichunk0" {c=$4} $2 == "irelax0" {r=$4} END {print p, (p == "settle" ? "chunk " c : "relaxation " r)}' "$st") next"
  done
  # pushes cut here: a trace without its done marker; the next run resumes each from its newer
  # complete checkpoint, or starts it over without one
  local f name t c cps
  for f in $SWEEPS; do
    name=$(sweep_name "$f")
    for t in "$OUT/$name"/traces/*.csv; do
      [ -f "$t" ] && [ ! -f "$t.done" ] && [ ! -f "$DATA/$name/$(basename "$t")" ] || continue
      case " $listed " in *" $t "*) continue ;; esac
      listed="$listed $t" cps=""
      for c in "$t".a.restart "$t".b.restart; do
        complete_checkpoint "$c" && cps="$cps $(basename "$c") (written $(date -r "$c" '+%F %R'))"
      done
      echo "  under way here: push $name/$(basename "$t" .csv): $( [ -n "$cps" ] && echo "resumes from the newer of$cps" || echo "no complete checkpoint: starts over")"
    done
  done
  return 0
}
# a checkpoint LAMMPS finished writing: the sweep runner's own test, asked (granpen checkpoint)
complete_checkpoint() { "$CLI" checkpoint "$1" > /dev/null; }
seen="" listed=""
[ "$STATUS" = 1 ] && { status; exit 0; }
[ -x "$LMP" ] || { echo "campaign.sh: no lmp_granpen at $LMP (build first, or set GRANPEN_LMP)" >&2; exit 2; }

mkdir -p "$OUT"
INPUTS=$OUT/inputs.$CAMPAIGN
rm -rf "$INPUTS.new"; cp -r "$ROOT/inputs" "$INPUTS.new"; rm -rf "$INPUTS"; mv "$INPUTS.new" "$INPUTS"
ran=0
commit() {    # MESSAGE
  [ "$COMMIT" = 1 ] || { echo "campaign.sh: $1: to be committed (git add $DATA)"; return 0; }
  git -C "$ROOT" add "$DATA" && git -C "$ROOT" commit -q -m "$CAMPAIGN: $1" -- "$DATA" && echo "campaign.sh: committed: $1"
}
budget_left() { [ "$UNITS" -lt 0 ] || [ "$ran" -lt "$UNITS" ]; }
# SWEEP_FILE K: the sweep runner runs planned run K alone; a progress line a minute (a unit
# is hours: the push's depth and its own time left, not a line every 5 s in the log)
runner() {
  local mpi=(); [ "$RANKS" -gt 1 ] && mpi=(--mpirun mpirun --ranks "$RANKS")
  nice -n 19 "$CLI" sweep "$1" --jobs 1 --only "$2" --out "$OUT" --inputs "$INPUTS" --lmp "$LMP" --checkpoint "$CHECKPOINT" \
    --progress 60 "${mpi[@]}"
}
# a push (the runner resumes it from its checkpoint when one is there); when LAMMPS refuses
# the checkpoint it was resumed from (a restart this build cannot read: the log's first ERROR
# names a restart), the checkpoints are set aside as .stale and the push starts over, once
push_run() {    # SWEEP_FILE K DIR ID
  local said=$3/logs/$4.runner t=$3/traces/$4.csv c first
  runner "$1" "$2" | tee "$said" && return 0
  first=$(grep -m1 '^ERROR' "$3/logs/$4.log" 2>/dev/null || true)
  grep -q "start .*$4 (resumed from" "$said" && [[ $first == *[Rr]estart* ]] || return 1
  echo "campaign.sh: $4: LAMMPS refused the checkpoint it resumed from ($first): set aside as .stale; the push starts over"
  for c in "$t".a.restart "$t".b.restart; do [ ! -f "$c" ] || mv "$c" "$c.stale"; done
  runner "$1" "$2"
}

for f in $SWEEPS; do
  name=$(sweep_name "$f") dir=$OUT/$(sweep_name "$f")
  mkdir -p "$dir/beds" "$dir/logs" "$DATA/$name"
  while read -r k kind id; do
    if [ "$kind" = pour ]; then
      [ -f "$dir/beds/$id.info" ] && continue
      if [ -f "$DATA/beds/$id.tile.data.gz" ]; then
        # the committed tile: the bed in seconds (preset, mu and tile checked by in.pour)
        preset=$(awk -F' = ' '$1 == "preset" {print $2}' "$DATA/beds/$id.tile.info")
        mu=$(awk -F' = ' '$1 == "mu" {print $2}' "$DATA/beds/$id.tile.info")
        tile=$(awk -F' = ' '$1 == "tile" {print $2}' "$DATA/beds/$id.tile.info")
        # the sweep's own tile count and box (a wider box of the same tile), else the tile's
        read -r -a widen < <(set_vars "$f" tile box surface_grid)
        [ "${#widen[@]}" -gt 0 ] || widen=(-var tile "$tile")
        # and its rod types (rod_types 2: the shaft's type 3 for in.push mu_shaft)
        read -r -a rods < <(set_vars "$f" rod_types)
        "$LMP" -in "$INPUTS/in.pour" -var inputs "$INPUTS" -var preset "$preset" -var mu "$mu" "${widen[@]}" "${rods[@]}" \
          -var from_tile "$DATA/beds/$id" -var out "$dir/beds/$id" -log "$dir/beds/$id.rebuild.log" -screen none >/dev/null \
          || { echo "campaign.sh: rebuilding $id from its tile failed: $(grep -m1 '^ERROR' "$dir/beds/$id.rebuild.log") ($dir/beds/$id.rebuild.log)" >&2; exit 1; }
        echo "campaign.sh: $name: bed $id rebuilt from $DATA/beds/$id.tile.data.gz"
        # a wider box's bed has its own z_s and phi_0: its .info goes with the sweep's traces
        [ "$(set_vars "$f" box)" = "" ] || cp "$dir/beds/$id.info" "$DATA/$name/$id.info"
        continue
      fi
      budget_left || break
      echo "campaign.sh: $name: pouring bed $id (a tile: docs/presets.md)"
      runner "$f" "$k"
      [ -f "$dir/beds/$id.tile.data.gz" ] && [ -f "$dir/beds/$id.info" ] || { echo "campaign.sh: the pour of $id left no tile" >&2; exit 1; }
      cp "$dir/beds/$id.tile.data.gz" "$dir/beds/$id.tile.info" "$dir/beds/$id.info" "$DATA/beds/"
      ran=$((ran + 1)); commit "bed $id (its tile)"
    else
      # a push with dumps is done when the tables of its flow are here too: its dumps are
      # not committed, so a push whose analysis was lost is pushed again
      dumps=$(dumps_of "$f")
      if [ -f "$DATA/$name/$id.csv" ] && { [ "$dumps" = 0 ] || [ -f "$DATA/$name/$id.flow/window.txt" ]; }; then continue; fi
      if [ "$dumps" = 1 ] && [ -f "$dir/traces/$id.csv.done" ] && ls "$dir/traces/$id.csv".*.dump.gz >/dev/null 2>&1; then
        echo "campaign.sh: $name: push $id done here, its flow not committed: analysing its dumps"
      else
        budget_left || break
        echo "campaign.sh: $name: push $id"
        push_run "$f" "$k" "$dir" "$id"
        [ -f "$dir/traces/$id.csv.done" ] || { echo "campaign.sh: the push $id did not finish (see $dir/logs/$id.log)" >&2; exit 1; }
        ran=$((ran + 1))
      fi
      if [ "$dumps" = 1 ]; then
        # the same analysis as the mid push of docs/results.md (fields over the frames with
        # the tip 1 to 4 cm deep, the surface flux, the momentum classes), into a scratch
        # folder first: a failed analysis leaves nothing half-written in $DATA
        rm -rf "$dir/traces/$id.flow.new"
        GRANPEN_CLI=$CLI nice -n 19 "$ROOT/validation/push_flow.sh" "$dir/traces/$id.csv" "$dir/traces/$id.flow.new" --tip "$TIP" > /dev/null \
          || { echo "campaign.sh: the flow analysis of $id failed; its trace and dumps are in $dir/traces" >&2; exit 1; }
        rm -rf "$DATA/$name/$id.flow"; cp -r "$dir/traces/$id.flow.new" "$DATA/$name/$id.flow"
      fi
      cp "$dir/traces/$id.csv" "$DATA/$name/$id.csv"
      # what an observe file writes beside the trace for granpen to read (observe/arrival.lmp)
      for side in arrival.info arrival.txt; do
        [ ! -f "$dir/traces/$id.csv.$side" ] || cp "$dir/traces/$id.csv.$side" "$DATA/$name/$id.csv.$side"
      done
      cp "$dir/manifest.json" "$DATA/$name/manifest.json" 2>/dev/null || true
      # a finished push's checkpoints serve nothing more (its trace is in $DATA, never rerun)
      # and weigh 2 x 180 MB on a 20 cm dg10 bed
      rm -f "$dir/traces/$id.csv.a.restart" "$dir/traces/$id.csv.b.restart"
      commit "push $id ($name)"
    fi
  done < <(plan "$f")
  budget_left || break
done
status
