#!/usr/bin/env bash
# The lambda_vz checks (lambda_vz_D.sh) fail where the decay follows D or is a length of its
# own: on stand-ins of the committed fits (their lambda and error per rod, read with granpen
# get, as a table) with the 4 cm rod's lambda replaced.
#  - the fits as committed pass;
#  - the 4 cm rod's lambda 4 times the 1 cm rod's (lambda / D constant, the paper's reading)
#    fails check 2 (p = 1);
#  - the 4 cm rod's lambda the 2 cm rod's (a length of its own past 2 cm) fails check 1.
#   lambda_vz_D_can_fail.sh CLI SOURCE_DIR WORK_DIR
set -euo pipefail
CLI=$1 SRC=$2 WORK=$3
HERE=$SRC/tests/validation B=$SRC/data/sims/box_bench
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$WORK" && mkdir -p "$WORK"
. "$HERE/can_fail_lib.sh"
expect() { expect_exit lambda_vz_D.sh "$1" "$2" "$HERE/lambda_vz_D.sh" "$CLI" "$SRC" "${@:3}"; }    # RC PATTERN [TABLE]
expect 0 "lambda_vz_D: lambda grows with D, slower than D"

j=bench_mu0.3_s11_v50_g981_D
fit() { "$CLI" get "$B/$1" profile_below.lambda_vz.lambda profile_below.lambda_vz.lambda_se | tr '\t' ' '; }
one=$(fit box_bench20_flow_D/${j}1.0.flow/flow/flow.json) two=$(fit box_bench20_flow/${j}2.0.flow/flow/flow.json)
four_se=$(fit box_bench20_flow_D/${j}4.0.flow/flow/flow.json | awk '{ print $2 }')
printf '1 %s\n2 %s\n4 %s %s\n' "$one" "$two" "$(awk -v x="${one% *}" 'BEGIN { printf "%.10g", 4 * x }')" "$four_se" > "$WORK/follows_D.txt"
expect 1 "FAIL: 2. p = 1 +-" "$WORK/follows_D.txt"
printf '1 %s\n2 %s\n4 %s %s\n' "$one" "$two" "${two% *}" "$four_se" > "$WORK/stops.txt"
expect 1 "FAIL: 1. lambda at 4 cm" "$WORK/stops.txt"
echo "lambda_vz_D_can_fail: all checks passed"
