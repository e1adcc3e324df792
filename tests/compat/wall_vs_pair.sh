#!/usr/bin/env bash
# A 0.4 cm grain bounces obliquely (10 cm/s along x, 30 cm/s down, spinning at 5 rad/s) on
# the floor, once as fix wall/gran hertz/history and once as a 200 cm sphere of huge mass
# under pair gran/hertz/history (R_eff = 0.1996 cm against the flat's 0.2: 0.2%), in two
# LAMMPS builds. Prints the rotational and translational kinetic energy after the bounce.
# Passes when the pair law is the same in both builds (1e-9) and the first build's wall
# matches the pair law within 1% (what the 0.2% R_eff difference allows); the second
# build's wall is reported, not judged (docs/compat.md: fixed upstream after 22Jul2025).
#   wall_vs_pair.sh LMP_A LMP_B
set -euo pipefail
A=$1 B=$2
common() {
cat <<DECK
units cgs
atom_style sphere
atom_modify map array
newton off
comm_modify vel yes $1
DECK
}
{ common ""; cat <<'DECK'
boundary p p fm
region box block 0 4 0 4 0 4 units box
create_box 1 box
create_atoms 1 single 2.0 2.0 0.25 units box
set type 1 diameter 0.4
set type 1 density 3.0
group grain id 1
pair_style gran/hertz/history 1e9 1e9 1000 1000 0.3 1
pair_coeff * *
fix floor all wall/gran hertz/history 1e9 1e9 1000 1000 0.3 1 zplane 0.0 NULL
DECK
} > in.wall
{ common "cutoff 250"; cat <<'DECK'
boundary f f f
region box block -110 110 -110 110 -201 5 units box
create_box 1 box
create_atoms 1 single 2.0 2.0 0.25 units box
create_atoms 1 single 2.0 2.0 -100.0 units box
set atom 1 diameter 0.4
set atom 1 density 3.0
set atom 2 diameter 200.0
set atom 2 density 1e9
group grain id 1
pair_style gran/hertz/history 1e9 1e9 1000 1000 0.3 1
pair_coeff * *
neighbor 0.1 bin
DECK
} > in.pair
for f in in.wall in.pair; do cat >> $f <<'DECK'
velocity grain set 10 0 -30
set atom 1 omega 0 5 0
fix g grain gravity 981 vector 0 0 -1
fix integ grain nve/sphere
timestep 2e-6
compute ke grain ke
compute rke grain erotate/sphere
thermo_style custom step c_ke c_rke
run 1500
print "AFTER $(c_ke:%.12g) $(c_rke:%.12g)"
DECK
done
declare -A ke rke
for who in A B; do
  lmp=${!who}
  for f in wall pair; do
    "$lmp" -in in.$f -log ${f}_$who.log -screen none > /dev/null
    read -r k r < <(awk '/^AFTER/ {print $2, $3}' ${f}_$who.log)
    ke[$who$f]=$k rke[$who$f]=$r
    echo "build $who ($lmp), $f: translational KE $k erg, rotational $r erg after the bounce"
  done
done
rel() { awk -v a="$1" -v b="$2" 'BEGIN {d = (a - b) / b; printf "%.3g", (d < 0 ? -d : d)}'; }
echo "pair law, build A against B: rotational KE differs by $(rel "${rke[Apair]}" "${rke[Bpair]}")"
echo "wall against pair law: build A $(rel "${rke[Awall]}" "${rke[Apair]}"), build B $(rel "${rke[Bwall]}" "${rke[Bpair]}") (rotational KE)"
awk -v d="$(rel "${rke[Apair]}" "${rke[Bpair]}")" 'BEGIN {exit !(d < 1e-9)}' || { echo "FAIL: the pair law differs between the builds"; exit 1; }
awk -v d="$(rel "${rke[Awall]}" "${rke[Apair]}")" 'BEGIN {exit !(d < 0.01)}' || { echo "FAIL: build A's wall does not match the pair law"; exit 1; }
echo "ok"
