#!/usr/bin/env bash
# The measurement chain's example (inputs/examples/in.push_mount: a 50 g rod behind a
# spring-damper sensor) obeys the rod's equation of motion, m dV/dt = F - F_grain: over the
# push after the actuator's ramp, the impulse of the sensor force minus the grains' force
# equals m times the rod's change of speed, and the rod then moves at v0 on average.
#   Impulse: within 1% of max(|impulse|, m v0). The trace's F and F_grain are averages over
#   each 1e-4 s window and v_rod the speed at the window's end, so the sum over windows is
#   the integral up to velocity Verlet's half-step offsets: measured 1.4e-4 (np 1).
#   Speed: the mean of v_rod over z >= 1 cm within 2% of v0 (measured 0.01%; the spring,
#   k = 1e8 dyne/cm against drag swings of 1e5 dyne, lets the rod lag by about 1e-3 cm).
#   mount_momentum_balance.sh TRACE
set -euo pipefail
trace=$1
m=$(awk -F' = ' '$1 == "# mount" {split($2, a, " "); print a[3]}' "$trace")
v0=$(awk -F' = ' '$1 == "# v0" {print $2}' "$trace")
[ -n "$m" ] && [ -n "$v0" ] || { echo "FAIL: $trace has no mount or v0 header"; exit 1; }
grep -v '^#' "$trace" | awk -F, -v m="$m" -v v0="$v0" '
  NR == 1 { if ($3 != "F" || $4 != "F_grain" || $5 != "v_rod") { print "FAIL: columns " $0; bad = 1; exit 1 } next }
  { t[++n] = $1; z[n] = $2; F[n] = $3; G[n] = $4; V[n] = $5 }
  END {
    if (bad) exit 1
    for (a = 1; a <= n && z[a] < 0.0; a++) {}       # after the ramp and the gap: from contact
    I = 0; for (i = a + 1; i <= n; i++) I += (F[i] - G[i]) * (t[i] - t[i - 1])
    dp = m * (V[n] - V[a]); scale = (I < 0 ? -I : I); if (m * v0 > scale) scale = m * v0
    vs = 0; nv = 0; for (i = 1; i <= n; i++) if (z[i] >= 1.0) { vs += V[i]; nv++ }
    d = I - dp; if (d < 0) d = -d
    printf "impulse %.6g, m dV %.6g: %.2g of %.4g; mean v_rod over z >= 1 cm %.6g (v0 %g, %d rows)\n", I, dp, d / scale, scale, vs / nv, v0, nv
    ok = (d <= 0.01 * scale) && nv > 10 && ((vs / nv - v0) < 0.02 * v0) && ((v0 - vs / nv) < 0.02 * v0)
    if (ok) print "momentum balance holds"; else { print "FAIL"; exit 1 }
  }'
