#!/usr/bin/env bash
# superpose_agree on a known answer: scaled copies of two committed pushes, baseline B = T,
# push part P = 1.2 T, packing K = 0.9 T, direct D = 1.15 T, which is exactly P + 0.5 (K - B)
# bed by bed. Every G of gap-metric.md is then homogeneous: with one run a side (no standard
# error to subtract) G(D, B) = 0.15 / 1.15 = 0.130, G(D, P) = 0.05 / 1.15 = 0.043, G(D, S) = 0,
# and the fluctuation bands scale alike (G_spec the same). With two beds a side the mean
# force changes are exact: +15.0, +20.0, -10.0, -5.0 and +15.0%.
#   superpose_agree_test.sh SUPERPOSE_AGREE TRACE1 TRACE2 WORKDIR
set -euo pipefail
AGREE=$1 T1=$2 T2=$3 W=$4
rm -rf "$W"; mkdir -p "$W"
i=0
for t in "$T1" "$T2"; do
  i=$((i + 1))
  for x in "base 1.0" "push 1.2" "pack 0.9" "direct 1.15"; do
    set -- $x
    awk -F, -v OFS=, -v k="$2" '/^#/ || $1 == "t" { print; next } { $3 = sprintf("%.9g", $3 * k); print }' "$t" > "$W/$1_$i.csv"
  done
done
fail=0
expect() {    # OUTPUT PATTERN WHAT
  if grep -q -- "$2" <<< "$1"; then echo "ok: $3"; else echo "FAILED: $3 (no line matching '$2')"; fail=1; fi
}
one=$("$AGREE" --v0 100 --base "$W/base_1.csv" --direct "$W/direct_1.csv" --push "$W/push_1.csv" --pack "$W/pack_1.csv" --w 0.5)
echo "$one"
expect "$one" "signature) G 0.130  G_spec 0.130  G_all 0.184" "G(D, B) = 0.15 / 1.15 in bin means and bands"
expect "$one" "push part alone  *G 0.043  G_spec 0.043" "G(D, P) = 0.05 / 1.15"
expect "$one" "superposed  *G 0.000" "G(D, S) = 0: D is the superposition"
two=$("$AGREE" --v0 100 --base "$W/base_1.csv,$W/base_2.csv" --direct "$W/direct_1.csv,$W/direct_2.csv" \
      --push "$W/push_1.csv,$W/push_2.csv" --pack "$W/pack_1.csv,$W/pack_2.csv" --w 0.5)
echo "$two"
for row in "direct .*+15.0%" "push .*+20.0%" "packing .*-10.0%" "pack(w) .*-5.0%" "superposed .*+15.0%"; do
  expect "$two" "$row" "two beds: $row"
done
# bad input: a named error and exit 2
set +e
"$AGREE" --v0 100 --base "$W/base_1.csv" --direct "$W/none.csv" > /dev/null 2> "$W/err"; rc=$?
set -e
[ "$rc" = 2 ] && grep -q "none.csv" "$W/err" && echo "ok: a missing trace is named, exit 2" || { echo "FAILED: missing trace (rc $rc)"; fail=1; }
set +e
"$AGREE" --v0 100 --base "$W/base_1.csv,$W/base_2.csv" --direct "$W/direct_1.csv" --push "$W/push_1.csv" \
  --pack "$W/pack_1.csv" --w 0.5 > /dev/null 2> "$W/err"; rc=$?
set -e
[ "$rc" = 2 ] && grep -q "one run per --base bed" "$W/err" && echo "ok: unpaired beds refused, exit 2" || { echo "FAILED: unpaired beds (rc $rc)"; fail=1; }
exit $fail
