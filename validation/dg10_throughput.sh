#!/usr/bin/env bash
# Throughput of the dg10 runs from their LAMMPS logs: per run segment (a `run` of the pour's
# chunks, a push's checkpoint interval), atoms x steps per CPU-second, the CPU seconds being
# LAMMPS's loop time times its "CPU use" (the process's own share: a niced run on a busy
# machine gets a fraction of a core, and its wall time says nothing).
#   validation/dg10_throughput.sh [DIR]     (DIR: the runs' root, default /work/granpen-runs;
#                                           the logs of validation/dg10.sh's runs, DIR/dg10_*/logs)
set -euo pipefail
DIR=${1:-/work/granpen-runs}
logs=("$DIR"/dg10*/logs/*.log)
[ -e "${logs[0]}" ] || { echo "dg10_throughput.sh: no logs in $DIR/dg10*/logs" >&2; exit 1; }
awk '
  /^Loop time of/ { lt = $4; steps = $9; atoms = $12 }
  /% CPU use with/ {
    cpu = lt * ($1 + 0) / 100
    if (cpu > 0 && steps > 0) {
      n = split(FILENAME, p, "/"); printf "%-44s %8d steps %7.0f CPU-s %9.3g atom-steps/CPU-s\n", p[n], steps, cpu, atoms * steps / cpu
    }
  }' "${logs[@]}"
