#!/usr/bin/env bash
# A sweep with pour_checkpoint = yes: the runner is killed (-9) once the pour has written a
# checkpoint; the rerun resumes the pour at that chunk (manifest: "resumed at step N"), not
# from the start, and the bed it finishes is a settled tiny bed whose checkpoint files are
# gone. (A resumed pour is another trajectory of the same protocol: LAMMPS rebuilds neighbour
# lists on restart steps, so its z_s is compared with the tiny bed's range, not bit for bit.)
#   pour_resume.sh GRANPEN_CLI OUT
set -euo pipefail
CLI=$1 OUT=$2
rm -rf "$OUT"; mkdir -p "$OUT"
printf 'name = pour_resume\npreset = tiny\nseeds = 5\nv0 = 200\ndepth = 0.3\npour_checkpoint = yes\n' > "$OUT/p.sweep"
"$CLI" sweep "$OUT/p.sweep" --jobs 1 --out "$OUT" > "$OUT/first.out" 2>&1 &
runner=$!
state=$OUT/pour_resume/beds/bed_tiny_s5.pour.state
for _ in $(seq 1 1200); do [ -f "$state" ] && break; sleep 0.1; done
[ -f "$state" ] || { echo "FAIL: no checkpoint state appeared"; kill -9 $runner; exit 1; }
kill -9 $runner; wait $runner 2>/dev/null || true
sleep 1    # the child dies with the runner (PR_SET_PDEATHSIG)
step=$(awk '$2 == "step_saved" {print $4}' "$state")
"$CLI" sweep "$OUT/p.sweep" --jobs 1 --out "$OUT" > "$OUT/second.out" 2>&1
case "$("$CLI" get "$OUT/pour_resume/manifest.json" 'runs[id=bed_tiny_s5].action')" in "resumed at step "*) ;; *) false ;; esac || { echo "FAIL: the pour was not resumed"; cat "$OUT/second.out"; exit 1; }
info=$OUT/pour_resume/beds/bed_tiny_s5.info
zs=$(awk -F' = ' '$1 == "z_s" {print $2}' "$info")
awk -v z="$zs" 'BEGIN {exit !(z > 3.1 && z < 3.35)}' || { echo "FAIL: z_s = $zs outside the tiny bed's 3.1-3.35 cm"; exit 1; }
ls "$OUT"/pour_resume/beds/*.pour.* >/dev/null 2>&1 && { echo "FAIL: checkpoint files left"; exit 1; }
echo "pour resumed from step $step, z_s = $zs cm; the push ran: $(ls "$OUT"/pour_resume/traces/*.done | wc -l) done"
