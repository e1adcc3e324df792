#!/usr/bin/env bash
# `granpen gap --slurm FILE` writes the cache's runs as two SLURM job arrays, the pours (one
# task per pour) and the pushes (one task per push) with --dependency=afterok on the pours.
# Checked by running the script with a stand-in `sbatch` on PATH that runs each array's
# tasks here, in the background as SLURM would, a job waiting only for the job its
# --dependency names; `srun` stands in by dropping its -n R; fake_lmp is lmp. Checks: two
# arrays of the planned sizes; no push task starts before every pour task has ended; every
# task succeeds; the cache is then complete (a --prepare-only run finds nothing to do); and
# without the dependency (the script edited) a push does start early: the check can fail.
#   gap_slurm_arrays.sh CLI FAKE_LMP INPUTS OUT
set -euo pipefail
CLI=$1 FAKE=$2 INPUTS=$3 OUT=$4
rm -rf "$OUT"; mkdir -p "$OUT/bin" "$OUT/jobs"
fail() { echo "gap_slurm_arrays: $*"; exit 1; }

cat > "$OUT/bin/sbatch" <<'SB'
#!/usr/bin/env bash
# stand-in sbatch: --array=A-B --wrap="CMD" [--dependency=afterok:ID]; prints the job id
set -euo pipefail
jobs=$SBATCH_STANDIN_JOBS dep="" array="" wrap="" name=job
for a in "$@"; do
  case "$a" in
    --dependency=afterok:*) dep=${a#--dependency=afterok:} ;;
    --array=*) array=${a#--array=} ;;
    --wrap=*) wrap=${a#--wrap=} ;;
    --job-name=*) name=${a#--job-name=} ;;
  esac
done
id=$(( $(ls "$jobs" | grep -c '\.job$' || true) + 100 )); touch "$jobs/$id.job"
(
  if [ -n "$dep" ]; then
    while [ ! -e "$jobs/$dep.ended" ]; do sleep 0.05; done
    [ -e "$jobs/$dep.ok" ] || { touch "$jobs/$id.ended"; exit 0; }    # afterok never met
  fi
  ok=1
  for i in $(seq "${array%-*}" "${array#*-}"); do
    echo "start $name $i $(date +%s.%N)" >> "$jobs/log"
    SLURM_ARRAY_TASK_ID=$i bash -c "$wrap" > "$jobs/$id.$i.out" 2>&1 && r=0 || { r=$?; ok=0; }
    echo "end $name $i $r $(date +%s.%N)" >> "$jobs/log"
  done
  [ $ok = 1 ] && touch "$jobs/$id.ok"; touch "$jobs/$id.ended"
) > /dev/null 2>&1 &
echo "$id"
SB
cat > "$OUT/bin/srun" <<'SR'
#!/usr/bin/env bash
[ "$1" = -n ] && shift 2
exec "$@"
SR
chmod +x "$OUT/bin/sbatch" "$OUT/bin/srun"
export PATH="$OUT/bin:$PATH" SBATCH_STANDIN_JOBS="$OUT/jobs"

gap() { "$CLI" gap --scenario tiny --v0 "50 100" --effects measurement_chain,packing --cache "$OUT/cache" \
          --lmp "$FAKE" --inputs "$INPUTS" "$@"; }
gap --slurm "$OUT/submit.sh" --ranks 2 > "$OUT/write.txt" 2>&1 || { cat "$OUT/write.txt"; fail "--slurm failed"; }
grep -c -- "--array=" "$OUT/submit.sh" | grep -qx 2 || fail "expected two job arrays in submit.sh"
grep -q -- "-push --ntasks=2 --dependency=afterok:\$pours --array=" "$OUT/submit.sh" || fail "the pushes do not wait for the pours"
npour=$(sed -n 's/.*: \([0-9]*\) pours, then \([0-9]*\) pushes.*/\1/p' "$OUT/write.txt")
npush=$(sed -n 's/.*: \([0-9]*\) pours, then \([0-9]*\) pushes.*/\2/p' "$OUT/write.txt")
[ -n "$npour" ] && [ "$npour" -gt 0 ] && [ "$npush" -gt 0 ] || { cat "$OUT/write.txt"; fail "no counts said"; }

wait_all() {    # every submitted job ended
  for _ in $(seq 1 3000); do
    n=$(ls "$SBATCH_STANDIN_JOBS" | grep -c '\.job$' || true); e=$(ls "$SBATCH_STANDIN_JOBS" | grep -c '\.ended$' || true)
    [ "$n" -gt 0 ] && [ "$n" = "$e" ] && return 0; sleep 0.1
  done
  fail "the jobs did not end in 300 s"
}
bash "$OUT/submit.sh" > "$OUT/submit.txt"
wait_all
log=$SBATCH_STANDIN_JOBS/log
[ "$(grep -c '^start .*-pour ' "$log")" = "$npour" ] || fail "expected $npour pour tasks"
[ "$(grep -c '^start .*-push ' "$log")" = "$npush" ] || fail "expected $npush push tasks"
if grep '^end ' "$log" | awk '$4 != 0' | grep -q .; then
  grep '^end ' "$log" | awk '$4 != 0' | head -3; cat "$SBATCH_STANDIN_JOBS"/*.out | tail -20; fail "a task failed"
fi
last_pour_end=$(grep -n '^end .*-pour ' "$log" | tail -1 | cut -d: -f1)
first_push_start=$(grep -n '^start .*-push ' "$log" | head -1 | cut -d: -f1)
[ "$last_pour_end" -lt "$first_push_start" ] || fail "a push task started before every pour task had ended"
# the cache is complete: a prepare-only run starts nothing
gap --prepare-only --jobs 2 > "$OUT/after.txt" 2>&1 || { cat "$OUT/after.txt"; fail "the rerun failed"; }
! grep -q "^  start " "$OUT/after.txt" || fail "the arrays left runs undone"

# the check can fail: the same script without the dependency lets a push start early
rm -rf "$OUT/cache" "$SBATCH_STANDIN_JOBS"; mkdir -p "$SBATCH_STANDIN_JOBS"
sed 's/ --dependency=afterok:\$pours//' "$OUT/submit.sh" > "$OUT/no_dependency.sh"
bash "$OUT/no_dependency.sh" > /dev/null
wait_all
last_pour_end=$(grep -n '^end .*-pour ' "$log" | tail -1 | cut -d: -f1)
first_push_start=$(grep -n '^start .*-push ' "$log" | head -1 | cut -d: -f1)
[ "$first_push_start" -lt "$last_pour_end" ] || fail "without the dependency no push started early: the check sees nothing"
echo "gap_slurm_arrays: $npour pour tasks, then $npush push tasks after every pour ended"
