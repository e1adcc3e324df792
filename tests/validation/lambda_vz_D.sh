#!/usr/bin/env bash
# lambda_vz against D (issue: physics in the paper's box; docs/results.md, "lambda_vz / D"):
# the paper gives the decay length of v_z below the rod's face as lambda_vz = 0.98 D. On the
# committed flow pushes of the 20 cm bench box (bed 11, 50 cm/s, the tip 1 to 3 cm deep;
# rods of 1, 2 and 4 cm: box_bench20_flow_D and box_bench20_flow), with the exponent p of
# lambda ~ D^p from the two end rods (1 and 4 cm) and its error from their fits' errors:
#  1. lambda grows with D: each wider rod's lambda exceeds the narrower one's by more than
#     two of their fits' errors combined;
#  2. but slower than D: p lies above 0 and below 1, each by more than two of its errors, so
#     lambda / D is no constant of the flow (1 would be the paper's lambda = 0.98 D at every
#     D, 0 a length of its own).
#   lambda_vz_D.sh CLI ROOT [TABLE]   (ROOT: a tree with data/sims/box_bench as the
#   repository's; TABLE: lines "D LAMBDA SE" to check instead of the committed fits, for
#   the stand-ins of lambda_vz_D_can_fail.sh)
set -euo pipefail
CLI=$1 ROOT=$2 TABLE=${3:-}
B=$ROOT/data/sims/box_bench
fail() { echo "FAIL: $*"; exit 1; }
declare -A lam se
if [ -z "$TABLE" ]; then
  for D in 1 2 4; do
    case $D in 2) j=$B/box_bench20_flow/bench_mu0.3_s11_v50_g981_D2.0.flow/flow/flow.json ;;
               *) j=$B/box_bench20_flow_D/bench_mu0.3_s11_v50_g981_D$D.0.flow/flow/flow.json ;; esac
    [ -f "$j" ] || fail "${j#$ROOT/} missing"
    [ "$("$CLI" get "$j" profile_below.lambda_vz.ok)" = true ] || fail "D = $D cm: the fit of lambda_vz is not ok"
    lam[$D]=$("$CLI" get "$j" profile_below.lambda_vz.lambda) se[$D]=$("$CLI" get "$j" profile_below.lambda_vz.lambda_se)
  done
else
  while read -r D l e; do lam[$D]=$l se[$D]=$e; done < "$TABLE"
  for D in 1 2 4; do [ -n "${lam[$D]:-}" ] || fail "$TABLE: no line for D = $D"; done
fi
for pair in 1:2 2:4; do
  a=${pair%%:*} b=${pair##*:}
  awk -v x="${lam[$a]}" -v ex="${se[$a]}" -v y="${lam[$b]}" -v ey="${se[$b]}" 'BEGIN { exit !(y - x > 2 * sqrt(ex * ex + ey * ey)) }' ||
    fail "1. lambda at $b cm (${lam[$b]} +- ${se[$b]}) does not exceed the $a cm rod's (${lam[$a]} +- ${se[$a]}) by two errors"
done
read -r p ep < <(awk -v x="${lam[1]}" -v ex="${se[1]}" -v y="${lam[4]}" -v ey="${se[4]}" \
  'BEGIN { printf "%.4g %.4g\n", log(y / x) / log(4), sqrt((ex / x) ^ 2 + (ey / y) ^ 2) / log(4) }')
echo "lambda_vz = ${lam[1]}, ${lam[2]}, ${lam[4]} cm at D = 1, 2, 4 cm: lambda ~ D^p, p = $p +- $ep (1 and 4 cm)"
awk -v p="$p" -v e="$ep" 'BEGIN { exit !(p > 2 * e && 1 - p > 2 * e) }' || fail "2. p = $p +- $ep: not between 0 and 1 by two errors"
echo "lambda_vz_D: lambda grows with D, slower than D"
