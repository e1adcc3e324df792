#!/bin/sh
# granpen gap: a force scale is a nuisance, not a cause (issue 37, section 0). The synthetic
# selftest's no-effect traces with F scaled by 1 + SCALE (a sensor's gain off, or grains
# denser than the header's by as much), diagnosed against the selftest's cache: prints the
# verdict, the tie and the scale found; exits 1 when the verdict names a physical effect
# alone (`explained`).
#   tests/analysis/gap/scale_is_not_a_cause.sh SYNTH_DIR CLI FAKE_LMP INPUTS [SCALE]
set -eu
synth=$1 cli=$2 lmp=$3 inputs=$4 scale=${5:-0.10}
real=$synth/scale_real out=$synth/scale_out
rm -rf "$real" "$out"
mkdir -p "$real"
for f in "$synth"/tiny/real_none/*.csv; do
  awk -F, -v OFS=, -v k="$scale" '/^#/ { print; next }
    !h { h = 1; for (c = 1; c <= NF; c++) if ($c == "F") col = c; print; next }
    { $col = sprintf("%.6g", (1 + k) * $col); print }' "$f" > "$real/$(basename "$f")"
done
"$cli" gap --real "$real" --scenario tiny --out "$out" --cache "$synth/tiny/cache" --lmp "$lmp" --inputs "$inputs" \
  > "$synth/scale.log" 2>&1 || { echo "gap failed: $synth/scale.log"; exit 1; }
j=$out/diagnosis.json
# the diagnosis's values asked of granpen get in one call, a tab between them (as the test's
# pass pattern reads them); scale_only.scale may be missing ("none"), and so, with one call,
# may the verdict and the tie: always written, a missing one matches no pass pattern
values=$("$cli" get "$j" verdict tie scale_only.scale --missing none)
tab=$(printf '\t')
IFS=$tab read -r verdict tie scale <<VALUES
$values
VALUES
echo "\"verdict\": \"$verdict\""
echo "\"tie\": $tie"
echo "scale $scale"
sed -n '/^## In short/,/^# \|^Scenario/p' "$out/report.md" | head -12
[ "$verdict" != explained ]
