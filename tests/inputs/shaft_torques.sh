#!/usr/bin/env bash
# The frictionless shaft, checked where friction alone acts: a rod sphere's torque comes
# from the tangential (friction) forces of its contacts only (gran/hertz/history: the normal
# force acts along the line of centres; with mu = 0 the Coulomb limit cuts the tangential
# force to exactly 0). TRACE.torques.txt (shaft_torques.lmp: per 500-step window the mean
# depth, the largest torque on a shaft sphere and on a tip sphere, the grains' vertical
# force on the shaft and on the tip, each averaged over every step of the window):
#   frictionless  the shaft's torque is exactly 0 in every window, although grains touched
#                 the shaft (its vertical force is not 0 in some window: the zero is not for
#                 want of contacts), while the tip, whose friction is unchanged, has a torque
#                 in every window once it is in the bed (mean depth >= 0)
#   friction      the control with mu_shaft = mu: the shaft has a torque in some window (the
#                 probe sees a shaft's friction when there is one)
#   shaft_torques.sh TRACE.torques.txt frictionless|friction
set -euo pipefail
f=$1 mode=$2
[ -s "$f" ] || { echo "FAIL: no $f"; exit 1; }
awk -v mode="$mode" '
  /^#/ { next }
  { rows++; if ($3 != 0) shaft_tq++; if ($5 != 0) shaft_fz++; if ($2 >= 0) { buried++; if ($4 > 0) tip_tq++ } }
  END {
    printf "%d windows: shaft torque non-zero in %d, shaft force non-zero in %d; tip torque in %d of %d buried\n", rows, shaft_tq, shaft_fz, tip_tq, buried
    if (rows < 20) { print "FAIL: fewer than 20 windows"; exit 1 }
    if (mode == "frictionless") {
      if (shaft_tq > 0) { print "FAIL: a frictionless shaft felt a torque"; exit 1 }
      if (shaft_fz == 0) { print "FAIL: no grain touched the shaft: the zero torque tells nothing"; exit 1 }
      if (buried == 0 || tip_tq < buried) { print "FAIL: the buried tip lost its friction torque"; exit 1 }
    } else if (mode == "friction") {
      if (shaft_tq == 0) { print "FAIL: the shaft with friction never felt a torque"; exit 1 }
    } else { print "FAIL: mode " mode " is neither frictionless nor friction"; exit 1 }
    print "shaft torques hold (" mode ")"
  }' "$f"
