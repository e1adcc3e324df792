#!/usr/bin/env bash
# Every knob of in.pour, in.push and model/contact.lmp out of its physical range is refused
# by name before anything runs (issue: reliability on the new surfaces, class "silently wrong"
# and "messages"): exit status 1, an "ERROR: NAME = VALUE" line, and no bed or trace
# written. Before, a negative ramp ran a push that never reached the bed and said "done", a
# negative mu_roll, mount_k or cohesion ran as none, g_push < 0 pulled the grains up under a
# trace that says g = 981, and a negative mu_wall, mu_push or box ended in LAMMPS's generic
# "Illegal ... command". Two or more inputs per class; the valid edge (0 where 0 means none)
# runs past the check (a push with ramp = 0 is the suite's every push).
#   deck_knobs.sh LMP_GRANPEN INPUTS TINY_BED.restart WORKDIR
set -uo pipefail
LMP=$1 INPUTS=$2 BED=$3 WORK=$4
mkdir -p "$WORK"; cd "$WORK"
fails=0 n=0
# refused DECK PATTERN -var NAME VALUE...: exit status 1, the named error, nothing written
refused() {
  local deck=$1 pat=$2 out st f; shift 2
  rm -f knob.csv knob.restart knob.info
  out=$("$LMP" -in "$INPUTS/$deck" -var inputs "$INPUTS" -var preset tiny -var bed "$BED" -var trace knob.csv \
    -var out knob -var depth 0.5 "$@" -log none 2>&1); st=$?
  n=$((n + 1))
  if ! echo "$out" | grep -q "$pat"; then
    echo "FAIL: $deck $*: no /$pat/, got: $(echo "$out" | grep -m1 -E 'ERROR|granpen' )"; fails=$((fails + 1))
  elif [ "$st" != 1 ]; then echo "FAIL: $deck $*: exit status $st, not 1"; fails=$((fails + 1)); fi
  for f in knob.csv knob.restart knob.info; do [ ! -e "$f" ] || { echo "FAIL: $deck $*: wrote $f"; fails=$((fails + 1)); }; done
}

# in.push, the push's own knobs
refused in.push "ERROR: ramp = -0.2 is negative" -var ramp -0.2
refused in.push "ERROR: ramp = -1e-9 is negative" -var ramp -1e-9
refused in.push "ERROR: mount_k = -5 is negative" -var mount_k -5
refused in.push "ERROR: mount_c = -1 is negative" -var mount_k 1e7 -var mount_c -1
refused in.push "ERROR: mount_m = 0 is not a positive mass" -var mount_k 1e7 -var mount_m 0
refused in.push "ERROR: g_push = -981 is not a positive gravity" -var g_push -981
refused in.push "ERROR: g_push = 0 is not a positive gravity" -var g_push 0
refused in.push "ERROR: v0 = -50 is not a positive push speed" -var v0 -50
refused in.push "ERROR: the rod needs D, rod_len, rod_sphere and rod_spacing > 0 (D = -2" -var D -2
refused in.push "ERROR: the rod needs .*rod_spacing = 0)" -var rod_spacing 0
refused in.push "ERROR: dt_push = -1e-6 and rate" -var dt_push -1e-6
refused in.push "ERROR: surface_grid = 0 is not a whole number" -var surface_grid 0
# model/contact.lmp through the push (a bed is read first) and through the pour
refused in.push "ERROR: the friction mu = -0.1 is negative" -var mu_push -0.1
refused in.push "ERROR: mu_roll = -0.1 is negative" -var mu_roll -0.1
refused in.push "ERROR: cohesion = -300 is negative" -var cohesion -300
refused in.push "ERROR: cohesion_dmt = -100 is negative" -var cohesion_dmt -100
refused in.push "ERROR: cohesion_dmt = 100 combines with the bench law only" -var cohesion_dmt 100 -var mu_roll 0.1
refused in.pour "ERROR: cohesion_dmt = 100 needs grains of one diameter" -var cohesion_dmt 100 -var poly 0.25
refused in.push "ERROR: the rod-grain friction mu_rod = -0.2 is negative" -var dmu_rod -0.5
refused in.push "ERROR: the shaft-grain friction mu_shaft = -0.1 is negative" -var mu_shaft -0.1
refused in.push "ERROR: the shaft-grain friction mu_shaft = -1e-9 is negative" -var mu_shaft -1e-9
refused in.pour "ERROR: mu_wall = -0.2 is negative" -var walls 1 -var mu_wall -0.2
refused in.pour "ERROR: mu_roll = -1 is negative" -var mu_roll -1
refused in.pour "ERROR: walls = 2 is neither 0" -var walls 2
refused in.pour "ERROR: k_roll = 0 is not positive" -var mu_roll 0.1 -var k_roll 0
refused in.pour "ERROR: the friction mu = -0.3 is negative" -var mu -0.3
# in.pour's geometry and time step
refused in.pour "ERROR: box = -8 and zbox" -var box -8
refused in.pour "ERROR: box = 0 and zbox" -var box 0
refused in.pour "ERROR: d_g = 0.4, rho_g = 3.0 and lat = -0.5 must be positive" -var lat -0.5
refused in.pour "ERROR: lat = 0.2 cm is below the grain diameter" -var lat 0.2
refused in.pour "ERROR: dt_pour = -5e-6 is not a positive time step" -var dt_pour -5e-6
refused in.pour "ERROR: surface_grid = 2.5 is not a whole number" -var surface_grid 2.5
refused in.pour "ERROR: rod_types = 3 is neither 1" -var rod_types 3
refused in.pour "ERROR: rod_types = 0 is neither 1" -var rod_types 0
echo "$n knobs out of range tried, $fails failures"
[ "$fails" = 0 ] && echo "deck knobs refused by name"
