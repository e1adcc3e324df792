#!/usr/bin/env bash
# The first-contact checks (box_first_contact.sh, dg10_box20_first_contact.sh, one bookkeeping:
# first_contact_lib.sh) fail when the box does move the first contact: on stand-ins made of the
# committed traces, with the drag over the first 0.5 cm multiplied where a box effect would be.
#  - dg10: the 10 cm series as its own 20 cm twin passes (every ratio 1); the same with every
#    push's drag 30% higher fails check 1 (RMS 0.30 against half the beds' 0.06);
#  - box: one 20 cm push at 200 cm/s (its pair's ratio 1.00000) with its drag 40% higher fails
#    check 2 only (the box's RMS 0.096, below half the beds' 0.205; that pair's 0.40 beyond the
#    largest bed difference, 0.34); one 16 cm push at 280 cm/s 1% higher fails check 3 (1e-2
#    against 1e-3).
#   first_contact_can_fail.sh SOURCE_DIR WORK_DIR
set -euo pipefail
SRC=$1 WORK=$2
HERE=$SRC/tests/validation
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$WORK" && mkdir -p "$WORK"
# scaled TRACE K OUT: the trace with its F column times K (header and t, z untouched)
scaled() { awk -F, -v k="$2" 'BEGIN { OFS = "," } /^#/ || $1 == "t" { print; next } { $3 = $3 * k; print }' "$1" > "$3"; }
. "$HERE/can_fail_lib.sh"
# expect RC PATTERN SCRIPT ARGS...: the script exits RC and prints PATTERN
expect() { expect_exit "$(basename "$3")" "$@"; }

DG10=$SRC/data/sims/dg10/dg10_peak
expect 0 "does not depend on the box" "$HERE/dg10_box20_first_contact.sh" "$DG10" "$DG10"
mkdir -p "$WORK/dg10_30"
for f in "$DG10"/*.csv; do scaled "$f" 1.3 "$WORK/dg10_30/$(basename "$f")"; done
expect 1 "FAIL: the box moves the first contact by 0.3000 RMS" "$HERE/dg10_box20_first_contact.sh" "$DG10" "$WORK/dg10_30"

# the box series: a copy of its peak sweeps, then one push changed at a time
box_copy() { rm -rf "$WORK/box" && mkdir -p "$WORK/box" && cp -r "$SRC"/data/sims/box_bench/box_bench{8,12,16,20}_peak "$WORK/box/"; }
box_copy
expect 0 "does not depend on the box" "$HERE/box_first_contact.sh" "$WORK/box"
one=$WORK/box/box_bench20_peak/bench_mu0.3_s11_v200_g981_D2.0.csv
scaled "$SRC/data/sims/box_bench/box_bench20_peak/$(basename "$one")" 1.4 "$one"
expect 1 "FAIL: one pair differs by 0.4" "$HERE/box_first_contact.sh" "$WORK/box"
box_copy
one=$WORK/box/box_bench16_peak/bench_mu0.3_s11_v280_g981_D2.0.csv
scaled "$SRC/data/sims/box_bench/box_bench16_peak/$(basename "$one")" 1.01 "$one"
expect 1 "FAIL: v0 280, bed 11" "$HERE/box_first_contact.sh" "$WORK/box"
echo "first_contact_can_fail: all checks passed"
