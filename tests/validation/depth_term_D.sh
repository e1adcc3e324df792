#!/usr/bin/env bash
# How the depth term grows with the rod's diameter (issue: physics in the paper's box;
# docs/results.md, "alpha against D"): the paper's F_z = alpha mu rho_g g D^2 z has F_z ~ D^2.
# On the committed rods of D = 1, 2, 3 and 4 cm in the 20 cm bench box (box_bench20_D and
# box_bench20_D4: 28 cm/s, 4 cm deep, beds 11 and 12), with alpha through the origin over
# z >= 2 cm per push (granpen fit --zmin 2) and p the least-squares slope of ln(alpha D^2)
# on ln D over the pushes (its standard error from the residuals):
#  1. F_z grows slower than D^2: p over D = 1 to 4 cm lies below 2 by more than three
#     standard errors (three: the slope's error rests on 6 degrees of freedom, whose t at
#     99% is 3.7, at 98% 3.1; the measured gap is about 8);
#  2. not the thin rod's alone: p over D = 2 to 4 cm lies below 2 by more than two of its
#     standard errors (4 degrees of freedom; the measured gap is about 3.7);
#  3. it steepens with D, towards the paper's 2 (as a rim term, A D^2 + B D, would): the
#     exponent from 1 to 2 cm, log2(F(2 cm) / F(1 cm)) of the beds' mean alphas, lies below
#     p over 2 to 4 cm by more than two of the latter's standard errors.
#   depth_term_D.sh CLI ROOT WORK   (ROOT: a tree with data/sims/box_bench as the repository's)
set -euo pipefail
CLI=$1 ROOT=$2 WORK=$3
B=$ROOT/data/sims/box_bench
rm -rf "$WORK" && mkdir -p "$WORK"
fail() { echo "FAIL: $*"; exit 1; }
traces=("$B"/box_bench20_D/bench_mu0.3_s1[12]_v28_g981_D[123].0.csv "$B"/box_bench20_D4/bench_mu0.3_s1[12]_v28_g981_D4.0.csv)
[ "${#traces[@]}" = 8 ] && for f in "${traces[@]}"; do [ -f "$f" ] || fail "${f#$ROOT/} missing"; done
"$CLI" fit "${traces[@]}" --zmin 2 --csv "$WORK/fit.csv" > /dev/null
# "D alpha0" per push
awk -F, 'NR == 1 { for (c = 1; c <= NF; c++) i[$c] = c; next } { print $i["D"], $i["alpha0"] }' "$WORK/fit.csv" > "$WORK/alpha.txt"
[ "$(wc -l < "$WORK/alpha.txt")" = 8 ] || fail "granpen fit gave $(wc -l < "$WORK/alpha.txt") rows, not 8"
slope() { # MIN_D: "P SE N" of ln(alpha D^2) on ln D over the pushes with D >= MIN_D
  awk -v min="$1" '$1 >= min { x = log($1); y = log($2 * $1 * $1); sx += x; sy += y; sxx += x * x; sxy += x * y; n++; X[n] = x; Y[n] = y }
    END { b = (n * sxy - sx * sy) / (n * sxx - sx * sx); a = (sy - b * sx) / n
          for (k = 1; k <= n; k++) r += (Y[k] - a - b * X[k]) ^ 2
          printf "%.6g %.6g %d\n", b, sqrt(r / (n - 2) / (sxx - sx * sx / n)), n }' "$WORK/alpha.txt"; }
read -r p1 e1 n1 < <(slope 1)
read -r p2 e2 n2 < <(slope 2)
low=$(awk '$1 == 1 { a += $2; n++ } END { print a / n }' "$WORK/alpha.txt")
two=$(awk '$1 == 2 { a += $2; n++ } END { print a / n }' "$WORK/alpha.txt")
p12=$(awk -v a="$low" -v b="$two" 'BEGIN { printf "%.6g", log(4 * b / a) / log(2) }')
echo "F_z ~ D^p: p = $p1 +- $e1 over D = 1 to 4 cm ($n1 pushes), $p2 +- $e2 over 2 to 4 cm ($n2), $p12 from 1 to 2 cm (the beds' mean alphas $low and $two)"
awk -v p="$p1" -v e="$e1" 'BEGIN { exit !(2 - p > 3 * e) }' || fail "1. p over 1 to 4 cm = $p1 +- $e1: within three errors of 2"
awk -v p="$p2" -v e="$e2" 'BEGIN { exit !(2 - p > 2 * e) }' || fail "2. p over 2 to 4 cm = $p2 +- $e2: within two errors of 2"
awk -v a="$p12" -v p="$p2" -v e="$e2" 'BEGIN { exit !(p - a > 2 * e) }' || fail "3. p from 1 to 2 cm = $p12, not below p over 2 to 4 cm ($p2 +- $e2) by two errors"
echo "depth_term_D: F_z grows slower than D^2 over 1 to 4 cm, also without the 1 cm rod, and steepens with D"
