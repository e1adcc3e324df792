#!/usr/bin/env bash
# When the boxes part (issue: physics in the paper's box; docs/results.md, "When the boxes
# part"): two pushes over the same grains in a box of width L and a wider one give the same
# drag until what the rod sent out comes back from the narrower box's cell boundary (L / 2
# from the axis, where the image rod's disturbance meets this one's). granpen parting reads
# each pair in 0.5 ms windows after contact; the parting is the first of two windows in a
# row 3% or more apart on one side (3% lies above the 1 to 2.9% the
# pairs drift before it; one, 12 / 20 cm at 50 cm/s on bed 11, has a single window 5% off
# the millisecond before its parting, which two in a row pass over). The echo
# reading, on the committed bench box series (the two pairs with the same grains under the
# rod, 8 / 16 and 12 / 20 cm, at 50 to 280 cm/s, above v_c = 28, on both beds), must hold:
#  1. every pair parts within its push;
#  2. the 12 cm box parts later than the 8 cm box, at every speed and on every bed (its
#     boundary is further);
#  3. in proportion to the width: the mean over speeds and beds of t_part(12 / 20) /
#     t_part(8 / 16) lies within 0.25 of 12 / 8 = 1.5 (one pair's ratio carries the 0.5 ms
#     windows' rounding, up to 0.25 / 2.5 + 0.25 / 4 = 16% at the fast end where the
#     partings are 2.5 and 4 ms; the mean over eight, about a third of that: 0.25 is two of
#     the worst ratio's rounding);
#  4. at a time, not at a depth: the slope of ln t_part against ln v0 (each pair, both
#     beds) lies above -0.7, where a flow front reaching the boundary at a fixed depth gives
#     -1 (t = z / v0); the windows' rounding moves the slope over the factor 5.6 in speed by
#     at most ln(1.1 * 1.05) / ln 5.6 = 0.08.
#  5. no sooner than an echo could be back: on each bed and at each speed, the parting's
#     window ends no sooner than twice the time the rod's first front takes to reach the
#     narrower box's boundary (granpen arrival --factor 10 on the 16 cm box's rings at 4 and
#     6 cm, box_bench16_arrival_far: stock computes, another route than the drag). The
#     window's end, not its start: the parting lies somewhere in its window.
# And on the committed dg10 pushes in the 20 cm box (80 to 200 cm/s, three beds, against the
# 10 cm box's on the same tiles) once all nine are in: 1 and 4 (slope above -0.7; over the
# factor 2.5 in speed the rounding moves it by at most ln(1.13 * 1.06) / ln 2.5 = 0.2).
# Printed beside: each pair's t_part, its depth, and the wave speed L / t_part it implies;
# and the dg10 pushes at 40 and 20 cm/s as they are committed, not checked.
#   box_parting.sh CLI BOX_BENCH DG10_PEAK DG10_BOX20_PEAK WORK
set -euo pipefail
CLI=$1 BOX=$2 NARROW10=$3 WIDE20=$4 WORK=$5
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$WORK" && mkdir -p "$WORK"
# t_part (ms) and z_part (cm) of a pair, "T Z"; fails when the pair does not part
part() { # NARROW WIDE NAME
  "$CLI" parting "$1" "$2" --json "$WORK/$3.json" > "$WORK/$3.txt"
  [ "$("$CLI" get "$WORK/$3.json" parted)" = true ] || fail "$3: the pushes do not part within the push ($(tail -1 "$WORK/$3.txt"))"
  "$CLI" get "$WORK/$3.json" t_part_ms z_part | tr '\t' ' '
}
slope() { awk '{ x = log($1); y = log($2); sx += x; sy += y; sxx += x * x; sxy += x * y; n++ } END { printf "%.3f\n", (n * sxy - sx * sy) / (n * sxx - sx * sx) }'; }
ratios=""
for v in 50 100 200 280; do
  for s in 11 12; do
    id=bench_mu0.3_s${s}_v${v}_g981_D2.0.csv
    for b in 8 12 16 20; do [ -f "$BOX/box_bench${b}_peak/$id" ] || { echo "the bench box series lacks $id in box_bench${b}_peak: skipped (validation/box.sh bench)"; exit 77; }; done
    read -r t8 z8 <<< "$(part "$BOX/box_bench8_peak/$id" "$BOX/box_bench16_peak/$id" "b8_16_s${s}_v$v")"
    read -r t12 z12 <<< "$(part "$BOX/box_bench12_peak/$id" "$BOX/box_bench20_peak/$id" "b12_20_s${s}_v$v")"
    echo "v0 $v, bed $s: 8 / 16 cm part at $t8 ms (z = $z8 cm; 8 cm / t = $(awk -v t="$t8" 'BEGIN { printf "%.0f", 80 / t }') m/s), 12 / 20 cm at $t12 ms (z = $z12 cm; $(awk -v t="$t12" 'BEGIN { printf "%.0f", 120 / t }') m/s)"
    awk -v a="$t12" -v b="$t8" 'BEGIN { exit !(a > b) }' || fail "v0 $v, bed $s: the 12 cm box parts at $t12 ms, not after the 8 cm box's $t8 ms"
    ratios="$ratios $(awk -v a="$t12" -v b="$t8" 'BEGIN { print a / b }')"
    echo "$v $t8" >> "$WORK/slope8"
    echo "$v $t12" >> "$WORK/slope12"
  done
done
mean=$(echo $ratios | tr ' ' '\n' | awk '{ s += $1; n++ } END { printf "%.3f\n", s / n }')
echo "t_part(12 / 20) / t_part(8 / 16): mean $mean over 8 (the widths' ratio 1.5)"
awk -v m="$mean" 'BEGIN { exit !(m > 1.25 && m < 1.75) }' || fail "the partings scale as $mean, not within 0.25 of the widths' 1.5"
for p in 8 12; do
  e=$(slope < "$WORK/slope$p")
  echo "bench $p cm pair: ln t_part against ln v0, slope $e (a front at a fixed depth: -1)"
  awk -v e="$e" 'BEGIN { exit !(e > -0.7) }' || fail "the $p cm pair parts at a depth (slope $e), not at a time"
done
FAR=$BOX/box_bench16_arrival_far
for v in 50 100 200 280; do
  for s in 11 12; do
    f=$FAR/bench_mu0.3_s${s}_v${v}_g981_D2.0.csv
    [ -f "$f.arrival.txt" ] || fail "no arrival rings for bed $s at $v cm/s in $FAR (validation/box.sh bench)"
    "$CLI" arrival "$f" --factor 10 --json "$WORK/far_s${s}_v$v.json" > /dev/null
    for p in 8:1:4 12:2:6; do
      n=${p%%:*} k=${p#*:} k=${k%%:*} r=${p##*:}
      [ "$("$CLI" get "$WORK/far_s${s}_v$v.json" "rings[$k].arrived")" = true ] || fail "bed $s, $v cm/s: the first front never reaches $r cm"
      echo_ms=$(awk -v t="$("$CLI" get "$WORK/far_s${s}_v$v.json" "rings[$k].t_after_ms")" 'BEGIN { print 2 * t }')
      part=$("$CLI" get "$WORK/b${n}_$((n + 8))_s${s}_v$v.json" t_part_ms)
      echo "v0 $v, bed $s: the $n cm box's echo back no sooner than $echo_ms ms (the front $r cm out at half that); its pair parts in $part to $(awk -v p="$part" 'BEGIN { print p + 0.5 }') ms"
      awk -v p="$part" -v e="$echo_ms" 'BEGIN { exit !(p + 0.5 >= e) }' || fail "v0 $v, bed $s: the $n cm pair parts by $(awk -v p="$part" 'BEGIN { print p + 0.5 }') ms, before an echo could be back ($echo_ms ms)"
    done
  done
done
echo "bench: the boxes part at a time set by the narrower box's width (an echo from its boundary)"
for v in 80 140 200; do for s in 1 2 3; do
  [ -f "$WIDE20/dg10_mu0.3_s${s}_v${v}_g981_D2.0.csv" ] || { echo "dg10: the 20 cm push of bed $s at $v cm/s not committed: its part skipped"; exit 0; }
done; done
for v in 80 140 200; do
  for s in 1 2 3; do
    id=dg10_mu0.3_s${s}_v${v}_g981_D2.0.csv
    read -r t z <<< "$(part "$NARROW10/$id" "$WIDE20/$id" "dg10_s${s}_v$v")"
    echo "dg10 v0 $v, bed $s: 10 / 20 cm part at $t ms (z = $z cm; 10 cm / t = $(awk -v t="$t" 'BEGIN { printf "%.0f", 100 / t }') m/s)"
    echo "$v $t" >> "$WORK/slope10"
  done
done
e=$(slope < "$WORK/slope10")
echo "dg10 10 / 20 cm: ln t_part against ln v0, slope $e (a front at a fixed depth: -1)"
awk -v e="$e" 'BEGIN { exit !(e > -0.7) }' || fail "dg10: the boxes part at a depth (slope $e), not at a time"
echo "dg10: the boxes part at a time, as the bench boxes"
# the slow pushes as they arrive (40 and 20 cm/s): printed beside, not checked
for v in 40 20; do
  for s in 1 2 3; do
    id=dg10_mu0.3_s${s}_v${v}_g981_D2.0.csv
    [ -f "$WIDE20/$id" ] || continue
    "$CLI" parting "$NARROW10/$id" "$WIDE20/$id" > "$WORK/dg10_s${s}_v$v.txt"
    echo "not checked: dg10 v0 $v, bed $s: $(tail -1 "$WORK/dg10_s${s}_v$v.txt")"
  done
done
