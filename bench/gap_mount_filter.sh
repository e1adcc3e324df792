#!/usr/bin/env bash
# granpen gap's measurement_chain is a filter on the baseline's traces (core/sensor_response.h)
# instead of pushes with fix rod/drive's dynamic mount. This checks that route against LAMMPS's
# own mount: the tiny preset (--scenario), beds of seeds 1 to 4 (--seeds), the rigid push and
# pushes with the mount (100 g, damping ratio 0.2) at natural periods 0.2 to 20 ms on the same
# beds, at 50, 100 and 200 cm/s; then tests/support/mount_filter_agree per period and speed
# (kernel: the mount's reading against its own grain force filtered; route: against the rigid
# push filtered; signature: against the rigid push; systematic parts over the beds; bed to bed).
# docs/gap.md ("measurement_chain") quotes the table.
#   bench/gap_mount_filter.sh [--scenario tiny] [--seeds "1 2 3 4"] [--periods "0.2 ... 20"] [--v0 "50 100 200"] [--jobs N] [--how band|linear|constant]
# Needs build/lmp_granpen, build/analysis/granpen-cli, build/tests/support/mount_filter_agree
# (or GRANPEN_LMP, GRANPEN_CLI, GRANPEN_MOUNT_AGREE). Output in runs/gap_mount_filter
# (GRANPEN_BENCH_WORK/gap_mount_filter), resumable; the table in its table.md.
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
SCEN=tiny SEEDS="1 2 3 4" PERIODS="0.2 0.4 0.7 1.4 2 3 4 10 20" V0="50 100 200" JOBS=1 HOW=band
while [ $# -gt 0 ]; do
  case "$1" in
    --scenario) SCEN=$2; shift 2 ;;
    --seeds) SEEDS=$2; shift 2 ;;
    --periods) PERIODS=$2; shift 2 ;;
    --v0) V0=$2; shift 2 ;;
    --jobs) JOBS=$2; shift 2 ;;
    --how) HOW=$2; shift 2 ;;
    *) echo "gap_mount_filter: unknown option $1" >&2; exit 2 ;;
  esac
done
LMP=${GRANPEN_LMP:-$ROOT/build/lmp_granpen}
CLI=${GRANPEN_CLI:-$ROOT/build/analysis/granpen-cli}
AGREE=${GRANPEN_MOUNT_AGREE:-$ROOT/build/tests/support/mount_filter_agree}
WORK=${GRANPEN_BENCH_WORK:-$ROOT/runs}/gap_mount_filter$([ "$SCEN" = tiny ] || echo "_$SCEN")
export OMP_NUM_THREADS=1
[ "$(id -u)" = 0 ] && export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mkdir -p "$WORK"
sweep() {    # NAME [push_set line]
  { echo "name = $1"; echo "preset = $SCEN"; echo "seeds = $SEEDS"; echo "v0 = $V0"; [ -n "${2:-}" ] && echo "$2"; } > "$WORK/$1.sweep"
  "$CLI" sweep "$WORK/$1.sweep" --jobs "$JOBS" --out "$WORK/out" --lmp "$LMP" --inputs "$ROOT/inputs" > "$WORK/$1.log" 2>&1 ||
    { echo "gap_mount_filter: sweep $1 failed: $WORK/$1.log" >&2; exit 1; }
}
sweep base
for T in $PERIODS; do
  name=mount_$(echo "$T" | tr . p)
  mkdir -p "$WORK/out/$name/beds"
  ln -f "$WORK/out/base/beds/"* "$WORK/out/$name/beds/"    # the rigid push's beds, poured once
  sweep "$name" "push_set = $(awk -v T="$T" 'BEGIN { m = 100; z = 0.2; w = 2 * 3.141592653589793 / (T * 1e-3); k = m * w * w
    printf "mount_k=%.7g mount_c=%.7g mount_m=%g", k, 2 * z * sqrt(k * m), m }')"
done
table=$WORK/table.md
{
  echo "| T ms | v0 | kernel G_all (largest) | route G_all (mean) | route systematic G, G_spec | signature systematic G, G_spec | signature scatter, one bed, G_spec: simulated, filtered | bed to bed G, G_spec | rod speed - v0, largest (% of v0) |"
  echo "|---|---|---|---|---|---|---|---|---|"
} > "$table"
for T in $PERIODS; do
  name=mount_$(echo "$T" | tr . p)
  for v in $V0; do
    args=()
    for s in $SEEDS; do
      m=$(ls "$WORK/out/$name/traces/"*"_s${s}_v${v}.csv") b=$(ls "$WORK/out/base/traces/"*"_s${s}_v${v}.csv")
      args+=(--pair "$m" "$b")
    done
    out=$("$AGREE" "${args[@]}" --how "$HOW")
    echo "$out" > "$WORK/agree_${name}_v$v.txt"
    echo "$out" | awk -v T="$T" -v v="$v" '
      function after(key,   i) { for (i = 1; i < NF; i++) if ($i == key) return $(i + 1); return "" }
      / kernel / { if (after("G_all") + 0 > k) k = after("G_all") + 0 }
      / route / && !/systematic/ { r += after("G_all"); nr++ }
      /systematic.*route/ { rs = after("G") ", " after("G_spec") }
      /systematic.*signature/ { ss = after("G") ", " after("G_spec") }
      /bed to bed/ { bb = after("G") ", " after("G_spec") }
      /scatter.*simulated/ { sc = after("G_spec") }
      /scatter.*filtered/ { sf = after("G_spec") }
      /rod speed/ { p = after("cm/s"); gsub(/[(%]/, "", p); if (p + 0 > dv) dv = p + 0 }
      END { printf "| %s | %s | %.4f | %.4f | %s | %s | %s, %s | %s | %.3g |\n", T, v, k, r / nr, rs, ss, sc, sf, bb, dv }' >> "$table"
  done
done
cat "$table"
