#!/usr/bin/env bash
# One push of the 20 cm dg10 series on many MPI ranks of a machine without Debian's packages
# (a lent many-core machine): the bundle of shared/tools/lmp-bundle.sh, the bed rebuilt from
# its committed tile as validation/campaign.sh rebuilds it, then the sweep runner's planned
# run K alone (--only K, as a SLURM array task runs it) through mpirun. The trace, its .done,
# the bed's .info and the push's log go to OUT, to be committed beside the one-rank pushes
# (data/sims/dg10_box20/dg10_box20_peak; the commit message says the rank count). No
# checkpoints: a 20 cm checkpoint (180 MB) could not come back from such a machine anyway.
# The figures of docs/cluster.md, "Checked over whole pushes", came from it (2026-11-30:
# dg10_box20_peak2.sweep K 5 and 7, beds 2 and 3, 16 ranks, 317 and 302 s).
#   here:   shared/tools/lmp-bundle.sh build inputs BUNDLE.tar.xz, and shared/tools/
#           lmp-bundle-env.sh beside it (in a folder the run tool carries)
#   there:  validation/box_push_many_ranks.sh BUNDLE.tar.xz SWEEP K SEED RANKS OUT
#           (SWEEP: inputs/sweeps/dg10_box20_peak2.sweep; K from granpen sweep SWEEP --plan)
set -uo pipefail
[ $# -eq 6 ] || { echo "box_push_many_ranks: usage: $0 BUNDLE.tar.xz SWEEP K SEED RANKS OUT" >&2; exit 2; }
BUNDLE=$1 SWEEP=$2 K=$3 SEED=$4 RANKS=$5 OUT=$6
ROOT=$(cd "$(dirname "$0")/.." && pwd)
[[ $K =~ ^[0-9]+$ && $SEED =~ ^[0-9]+$ && $RANKS =~ ^[1-9][0-9]*$ ]] ||
  { echo "box_push_many_ranks: K, SEED and RANKS are whole numbers (RANKS >= 1)" >&2; exit 2; }
[ -f "$BUNDLE" ] && [ -f "$SWEEP" ] || { echo "box_push_many_ranks: no bundle $BUNDLE or sweep $SWEEP" >&2; exit 2; }
# the bundle's set-up script: beside the bundle (a lent machine has no ../shared), else shared's
env_sh=$(dirname "$BUNDLE")/lmp-bundle-env.sh
[ -f "$env_sh" ] || env_sh=$ROOT/../shared/tools/lmp-bundle-env.sh
# shellcheck disable=SC1090
. "$env_sh" "$BUNDLE"
echo "box_push_many_ranks: $(nproc) cores; $(grep -m1 'model name' /proc/cpuinfo)"
R=/tmp/box_push_runs D=/tmp/box_push_runs/dg10_box20_peak id=bed_dg10_mu0.3_s$SEED
mkdir -p "$D/beds" "$D/logs" "$OUT"
t0=$(date +%s)
"$GP/lmp_granpen" -in "$GP/inputs/in.pour" -var inputs "$GP/inputs" -var preset dg10 -var mu 0.3 -var tile 4 -var box 20 \
  -var surface_grid 8 -var from_tile "$ROOT/data/sims/dg10/beds/$id" -var out "$D/beds/$id" -log "$D/beds/$id.rebuild.log" \
  -screen none > /dev/null || { grep -m3 ERROR "$D/beds/$id.rebuild.log" >&2; exit 1; }
echo "box_push_many_ranks: bed $id rebuilt in $(( $(date +%s) - t0 )) s"
cp "$D/beds/$id.info" "$OUT/"
"$GP/granpen-cli" sweep "$SWEEP" --jobs 1 --only "$K" --out "$R" --inputs "$GP/inputs" --lmp "$GP/lmp_granpen" \
  --checkpoint 1000000 --mpirun mpirun --ranks "$RANKS"
rc=$?
echo "box_push_many_ranks: the push's rc $rc after $(( $(date +%s) - t0 )) s"
cp "$D"/traces/*.csv "$D"/traces/*.done "$D/manifest.json" "$OUT/" 2>/dev/null
for log in "$D"/logs/dg10_*.log; do [ -f "$log" ] && grep -H "^Loop time" "$log" | tail -1 && cp "$log" "$OUT/"; done
exit $rc
