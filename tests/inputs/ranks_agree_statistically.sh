#!/usr/bin/env bash
# One rank and two ranks give the same physics: three tiny beds poured and pushed (2 cm at
# 100 cm/s) on one rank, and the same three seeds on two ranks. Once
# the decomposition changes the order of force sums, the trajectories part (bit-identity is
# not expected past the first centimetre of a push or the first chunks of a pour), so the
# check is statistical: for phi_0, z_s and the mean drag over z = 1-2 cm, the two ensemble
# means must agree within t(0.995, 4 dof) = 4.60 standard errors of their difference
# (Welch, n = 3 each; about 1% false alarms for a true equality). A rank-dependent bug of a
# few percent of the drag (a force summed on one rank only, a grain counted twice) is many
# standard errors: the bed-to-bed spread of the tiny bed's drag is about 3%.
# Also required: the two-rank runs cut the box in columns (2 by 1 by 1), not along z.
#   ranks_agree_statistically.sh LMP_GRANPEN INPUTS WORKDIR
set -euo pipefail
LMP=$1 INPUTS=$2 WORK=$3
mkdir -p "$WORK"; cd "$WORK"
SEEDS="11 12 13"
for np in 1 2; do
  run=("$LMP"); [ "$np" -gt 1 ] && run=(mpirun -np "$np" "$LMP")
  for s in $SEEDS; do
    if [ ! -f "bed_np${np}_s$s.info" ]; then
      "${run[@]}" -in "$INPUTS/in.pour" -var inputs "$INPUTS" -var preset tiny -var seed "$s" \
        -var out "bed_np${np}_s$s" -log "pour_np${np}_s$s.log" -screen none >/dev/null
    fi
    "${run[@]}" -in "$INPUTS/in.push" -var inputs "$INPUTS" -var preset tiny -var bed "bed_np${np}_s$s.restart" \
      -var v0 100 -var depth 2.0 -var trace "push_np${np}_s$s.csv" -log "push_np${np}_s$s.log" -screen none >/dev/null
    grep -q "granpen push: done" "push_np${np}_s$s.log" || { echo "FAIL: push np $np seed $s did not finish"; exit 1; }
    if [ "$np" -gt 1 ]; then
      for l in "pour_np${np}_s$s.log" "push_np${np}_s$s.log"; do
        grep -q "^ *2 by 1 by 1 MPI processor grid" "$l" || { echo "FAIL: $l: not cut in columns"; grep "processor grid" "$l"; exit 1; }
      done
    fi
  done
done
info() { awk -F' = ' -v k="$2" '$1 == k {print $2}' "$1"; }
meanf() { awk -F, '!/^#/ && $1 != "t" && $2 >= 1.0 && $2 <= 2.0 {s += $3; n++} END {printf "%.9g\n", s / n}' "$1"; }
status=0
for q in phi_0 z_s drag; do
  vals=()
  for np in 1 2; do
    line=""
    for s in $SEEDS; do
      if [ "$q" = drag ]; then v=$(meanf "push_np${np}_s$s.csv"); else v=$(info "bed_np${np}_s$s.info" "$q"); fi
      line="$line $v"
    done
    vals+=("$line")
  done
  awk -v a="${vals[0]}" -v b="${vals[1]}" -v q="$q" 'function stats(str, arr,   n, i, m, v) {
      n = split(str, arr, " "); m = 0; for (i = 1; i <= n; i++) m += arr[i]; m /= n
      v = 0; for (i = 1; i <= n; i++) v += (arr[i] - m)^2; v /= (n - 1); M = m; V = v; N = n }
    BEGIN { stats(a, x); m1 = M; v1 = V; n1 = N; stats(b, y); m2 = M; v2 = V; n2 = N
      se = sqrt(v1 / n1 + v2 / n2); d = m2 - m1
      printf "%s: 1 rank %.6g (sd %.3g), 2 ranks %.6g (sd %.3g), difference %.3g = %.2f standard errors\n",
        q, m1, sqrt(v1), m2, sqrt(v2), d, (se > 0 ? d / se : 0)
      exit ((d < 0 ? -d : d) <= 4.60 * se ? 0 : 1) }' || { echo "FAIL: $q differs between 1 and 2 ranks"; status=1; }
done
[ $status = 0 ] && echo "ranks agree statistically"
exit $status
