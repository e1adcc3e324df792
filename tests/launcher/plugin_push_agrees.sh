#!/usr/bin/env bash
# The plugin's push against lmp_granpen's, shared by plugin_matches_lmp_granpen.sh and
# tests/install/recipes.sh build: in WORK, the tiny push at 100 cm/s to 1 cm of the decks in
# INPUTS run by lmp_granpen (in.push), then by a LAMMPS built with PLUGIN running DECK (a
# deck that loads the plugin and includes in.push); the plugin must be loaded (its log says
# so) and the two force traces must agree within 1e-12 relative over at least 100 rows (the
# same styles on the same LAMMPS: round-off apart).
#   plugin_push_agrees.sh WORK LMP_GRANPEN LMP INPUTS BED TRACE_AGREE DECK [LMP_ARG...]
# LMP_ARG...: further arguments of the plugin's run (e.g. -var granpen_prefix P).
# Exit: 0 they agree, 1 not loaded or a difference (printed), 2 usage.
set -euo pipefail
[ $# -ge 7 ] || { sed -n '2,10p' "$0"; exit 2; }
WORK=$1 LMP_GRANPEN=$2 LMP=$3 INPUTS=$4 BED=$5 TRACE_AGREE=$6 DECK=$7
shift 7
COMMON=(-var inputs "$INPUTS" -var preset tiny -var bed "$BED" -var v0 100 -var depth 1.0)
cd "$WORK"
"$LMP_GRANPEN" -in "$INPUTS/in.push" "${COMMON[@]}" -var trace lmp_granpen.csv -log lmp_granpen.log -screen none
"$LMP" "$@" -in "$DECK" "${COMMON[@]}" -var trace plugin.csv -log plugin.log -screen none
grep -qi "loading plugin" plugin.log || { echo "FAIL: the plugin was not loaded"; tail -20 plugin.log; exit 1; }
"$TRACE_AGREE" lmp_granpen.csv plugin.csv --rtol 1e-12 --min-rows 100
