#!/usr/bin/env bash
# validation/results.sh's parts that wait for runs still under way (the dg10 column: its
# peak, flow and D parts; the bench sweeps with stiffer grains and weaker damping; the box
# series; dg10 in the 20 cm box), on
# stand-ins made of committed traces and tables with the names those runs will have: every
# line of a part must be what granpen gives on the same files directly (another route: the
# CLI called here, or the mid push's own lines for the flow tables), and a part with a file
# missing must be skipped with a note and add no line.
#   results_parts.sh CLI OUT
set -euo pipefail
CLI=$1 OUT=$2
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
rm -rf "$OUT"; mkdir -p "$OUT"
fail() { echo "FAIL: $*"; exit 1; }
BENCH=$ROOT/data/sims/validation_bench MID=$ROOT/data/sims/validation_mid
# a trace copied with its header's v0 (and D) set as the run it stands for
stand_in() { # SRC DEST V0 [D]
  sed -e "s/^# v0 = .*/# v0 = $3/" -e "${4:+s/^# D = .*/# D = $4/}" "$1" > "$2"
}

# ---- dg10: 3 beds x 5 speeds of peak pushes (the bench's beds 1, 2 and 1 again), 3 flow
# pushes (the mid push's tables), the D pushes
DG=$OUT/dg10
mkdir -p "$DG/beds" "$DG/dg10_peak" "$DG/dg10_flow" "$DG/dg10_D"
for s in 1 2 3; do cp "$BENCH/bed_bench_mu0.3_s$(( s == 2 ? 2 : 1 )).info" "$DG/beds/bed_dg10_mu0.3_s$s.info"; done
set -- 20:28 40:50 80:100 140:200 200:280
for vv in "$@"; do
  v=${vv%%:*} b=${vv##*:}
  for s in 1 2 3; do
    stand_in "$BENCH/bench_mu0.3_s$(( s == 2 ? 2 : 1 ))_v${b}_g981_D2.0.csv" "$DG/dg10_peak/dg10_mu0.3_s${s}_v${v}_g981_D2.0.csv" "$v"
  done
done
for vv in 40:30 100:90 200:240; do
  v=${vv%%:*} m=${vv##*:} id=dg10_mu0.3_s1_v${vv%%:*}_g981_D2.0
  stand_in "$MID/mid_mu0.3_s1_v${m}_g981_D2.0.csv" "$DG/dg10_flow/$id.csv" "$v"
  mkdir -p "$DG/dg10_flow/$id.flow"
  cp -r "$ROOT/docs/results/mid/flow" "$ROOT/docs/results/mid/surface" "$ROOT/docs/results/mid/momentum" \
    "$ROOT/docs/results/mid/window.txt" "$DG/dg10_flow/$id.flow/"
done
stand_in "$MID/mid_mu0.3_s1_v90_g981_D1.0.csv" "$DG/dg10_D/dg10_mu0.3_s1_v100_g981_D1.0.csv" 100
# ---- the stiffer bench: the bench's own traces (variant_peak against analyse_traces)
ST=$OUT/stiff
mkdir -p "$ST"
cp "$BENCH"/bench_mu0.3_s[12]_v*_g981_D2.0.csv "$BENCH"/bed_bench_mu0.3_s[12].info "$ST/"
# ---- the bench with weaker damping: the same stand-ins
DA=$OUT/damp
cp -r "$ST" "$DA"

# ---- the box series: the 8, 16 and 20 cm boxes' peak sweeps are the bench's own traces
# (beds 1 and 2 as the tiles 11 and 12), the 20 cm flow push the mid push's tables; 12 cm
# missing (its part, and the 20 cm box's peaks over it, must add no line)
BX=$OUT/box
for b in 8 16 20; do
  mkdir -p "$BX/box_bench${b}_peak"
  for s in 1 2; do
    cp "$BENCH/bed_bench_mu0.3_s$s.info" "$BX/box_bench${b}_peak/bed_bench_mu0.3_s1$s.info"
    for f in "$BENCH"/bench_mu0.3_s${s}_v*_g981_D2.0.csv; do
      cp "$f" "$BX/box_bench${b}_peak/$(basename "$f" | sed "s/_s${s}_/_s1${s}_/")"
    done
  done
done
id=bench_mu0.3_s11_v50_g981_D2.0
mkdir -p "$BX/box_bench20_flow/$id.flow"
stand_in "$MID/mid_mu0.3_s1_v90_g981_D2.0.csv" "$BX/box_bench20_flow/$id.csv" 50
cp -r "$ROOT/docs/results/mid/flow" "$ROOT/docs/results/mid/surface" "$ROOT/docs/results/mid/momentum" \
  "$ROOT/docs/results/mid/window.txt" "$BX/box_bench20_flow/$id.flow/"
# alpha against D in the 20 cm box: the bench's D = 1 and 2 cm pushes at 28 cm/s (beds 1 and 2
# as the tiles 11 and 12), and its 2 cm pushes read as D = 3 cm; the 8 cm box's D sweep and the
# frictionless shaft missing (they must add no line)
mkdir -p "$BX/box_bench20_D"
for s in 1 2; do
  cp "$BENCH/bed_bench_mu0.3_s$s.info" "$BX/box_bench20_D/bed_bench_mu0.3_s1$s.info"
  for D in 1.0 2.0; do cp "$BENCH/bench_mu0.3_s${s}_v28_g981_D$D.csv" "$BX/box_bench20_D/bench_mu0.3_s1${s}_v28_g981_D$D.csv"; done
  stand_in "$BENCH/bench_mu0.3_s${s}_v28_g981_D2.0.csv" "$BX/box_bench20_D/bench_mu0.3_s1${s}_v28_g981_D3.0.csv" 28 3
done

# ---- dg10 in the 20 cm box: its peak sweep the dg10 stand-ins above (the same 15 traces and
# bed .info files), its 40 cm/s flow push the mid push's tables, its D pushes the mid pushes
# of D = 1 and 2 cm and the 2 cm one read as D = 3 cm; the frictionless shaft missing (it must
# add no line)
B20=$OUT/dg10_box20
mkdir -p "$B20/dg10_box20_peak" "$B20/dg10_box20_D"
cp "$DG"/dg10_peak/*.csv "$DG"/beds/*.info "$B20/dg10_box20_peak/"
id=dg10_mu0.3_s1_v40_g981_D2.0
mkdir -p "$B20/dg10_box20_flow/$id.flow"
stand_in "$MID/mid_mu0.3_s1_v30_g981_D2.0.csv" "$B20/dg10_box20_flow/$id.csv" 40
cp -r "$ROOT/docs/results/mid/flow" "$ROOT/docs/results/mid/surface" "$ROOT/docs/results/mid/momentum" \
  "$ROOT/docs/results/mid/window.txt" "$B20/dg10_box20_flow/$id.flow/"
stand_in "$MID/mid_mu0.3_s1_v90_g981_D1.0.csv" "$B20/dg10_box20_D/dg10_mu0.3_s1_v100_g981_D1.0.csv" 100
stand_in "$MID/mid_mu0.3_s1_v90_g981_D2.0.csv" "$B20/dg10_box20_D/dg10_mu0.3_s1_v100_g981_D2.0.csv" 100
stand_in "$MID/mid_mu0.3_s1_v90_g981_D2.0.csv" "$B20/dg10_box20_D/dg10_mu0.3_s1_v100_g981_D3.0.csv" 100 3

GRANPEN_CLI=$CLI "$ROOT/validation/results.sh" --out "$OUT/res" --dumps /nonexistent --dg10 "$DG" --stiff "$ST" --damp "$DA" \
  --box "$BX" --dg10-box "$B20" > "$OUT/res.log" 2>&1 || { cat "$OUT/res.log"; fail "results.sh failed"; }
N=$OUT/res/numbers.txt
val() { awk -v k="$1" '$1 == k { sub(/  #.*/, ""); sub(/^[^=]*= /, ""); print; exit }' "$N"; }
same() { [ "$(val "$1")" = "$2" ] || fail "$1 = '$(val "$1")', expected '$2'"; }
num() { "$CLI" get "$1" "$2"; }    # the value at key path $2 of granpen's JSON $1
# COLUMN of granpen fit's CSV for one trace: fit_col TRACE COLUMN FIT_OPTION...
fit_col() { "$CLI" fit "$1" "${@:3}" --csv "$OUT/w.csv" > /dev/null
  awk -F, -v col="$2" 'NR == 1 { for (c = 1; c <= NF; c++) i[$c] = c; next } { print $i[col] }' "$OUT/w.csv"; }

# the peak law: granpen collapse on the 15 files directly
"$CLI" collapse "$DG"/dg10_peak/*.csv --alpha 35 --tbin 0.25 --json "$OUT/direct.json" > /dev/null
same dg10.peak_exponent "$(num "$OUT/direct.json" peak_exponent) +- $(num "$OUT/direct.json" peak_exponent_ci95) (95%)"
"$CLI" collapse $(ls "$DG"/dg10_peak/*.csv | grep -v _v20_) --alpha 35 --tbin 0.25 --json "$OUT/fast.json" > /dev/null
same dg10.peak_exponent_from_2vc "$(num "$OUT/fast.json" peak_exponent) +- $(num "$OUT/fast.json" peak_exponent_ci95) (95%)"
# the two-term peak law, c2 / (rho_g D^2) and c1 / c2 (the stand-ins' rho_g = 3, D = 2)
same dg10.peak_inertial "$(awk -v c="$(num "$OUT/fast.json" peak_two_term.quadratic)" -v e="$(num "$OUT/fast.json" peak_two_term.quadratic_se)" \
  'BEGIN { printf "%.4g +- %.2g\n", c / 12, e / 12 }')"
same dg10.peak_crossover_speed "$(awk -v c="$(num "$OUT/fast.json" peak_two_term.crossover_speed)" -v e="$(num "$OUT/fast.json" peak_two_term.crossover_speed_se)" \
  'BEGIN { printf "%.4g +- %.2g\n", c, e }')"
same dg10.phi_0 "$(grep -h '^phi_0' "$DG"/beds/*.info | awk '{ s += $3; ss += $3 * $3; n++ } END { m = s / n
  printf "%.4g +- %.2g n = %d\n", m, sqrt((ss - n * m * m) / (n - 1)), n }')"
# the stiffer bench through peak_law gives the bench's own lines of analyse_traces
for k in peak_exponent peak_exponent_ensemble peak_exponent_local peak_exponent_from_2vc peak_z \
  peak_exponent_ensemble_from_2vc peak_inertial peak_crossover_speed; do
  same "bench_stiff.$k" "$(val "bench.$k")"
  same "bench_damp.$k" "$(val "bench.$k")"
done
# each push paired with its bench twin: the stand-ins are the twins themselves
same bench_stiff.peak_over_bench "1 +- 0 n = 8"
same bench_damp.peak_over_bench "1 +- 0 n = 8"
# the box series: each complete box's peak law is the bench's own (the same traces through
# peak_law), the 16 cm box's peaks over the 8 cm box's are those of twins, the 20 cm box's
# flow rows the mid push's; the 12 cm box, and the 20 cm box's peaks over it, add no line
for b in 8 16 20; do
  for k in peak_exponent peak_exponent_ensemble peak_exponent_local peak_exponent_from_2vc peak_z \
    peak_exponent_ensemble_from_2vc peak_inertial peak_crossover_speed; do
    same "bench_box$b.$k" "$(val "bench.$k")"
  done
done
same bench_box16.peak_over_box8 "1 +- 0 n = 10"
for k in lambda_vz_D lambda_vz_local_D edge_phi_0 edge_slope phi_below_far phi_below_face surface_flux_sign_change_t drag_over_mu_g_Mmove M_move M_slow; do
  same "bench_box20.v50.$k" "$(val "mid.$k")"
done
# alpha against D in the 20 cm box: the bench's own lines for D = 1 and 2 (the same traces,
# the same window), D = 3 from granpen fit on the two stand-ins directly, and the ratio with
# the beds' spreads in quadrature
for D in 1 2; do same "bench_box20.alpha0_window.v28.D$D" "$(val "bench.alpha0_window.v28.g981.D$D")"; done
same bench_box20.alpha0_window.v28.D3 "$(for s in 1 2; do fit_col "$BX/box_bench20_D/bench_mu0.3_s1${s}_v28_g981_D3.0.csv" alpha0 --zmin 2; done |
  awk '{ s += $1; ss += $1 * $1; n++ } END { m = s / n; printf "%.4g +- %.2g n = %d\n", m, sqrt((ss - n * m * m) / (n - 1)), n }')"
# ... and the two-term fit's terms, from the same granpen fit on the files directly
for D in 1 2 3; do
  for k in alpha_a beta_b; do
    same "bench_box20.$k.v28.D$D" "$(for s in 1 2; do fit_col "$BX/box_bench20_D/bench_mu0.3_s1${s}_v28_g981_D$D.0.csv" "$k" --zmin 2; done |
      awk '{ s += $1; ss += $1 * $1; n++ } END { m = s / n; printf "%.4g +- %.2g n = %d\n", m, sqrt((ss - n * m * m) / (n - 1)), n }')"
  done
done
same bench_box20.alpha_D1_over_D2 "$(awk -v a="$(val bench_box20.alpha0_window.v28.D1 | awk '{print $1}')" -v ea="$(val bench_box20.alpha0_window.v28.D1 | awk '{print $3}')" \
  -v b="$(val bench_box20.alpha0_window.v28.D2 | awk '{print $1}')" -v eb="$(val bench_box20.alpha0_window.v28.D2 | awk '{print $3}')" \
  'BEGIN { r = a / b; printf "%.4g +- %.2g\n", r, r * sqrt((ea / a) ^ 2 + (eb / b) ^ 2) }')"
grep -q "^alpha(D = 1 cm) / alpha(D = 2 cm) (bench at 28 and dg10 at 100 cm/s),20,$(val bench_box20.alpha_D1_over_D2 | awk '{print $1}'),.*,bench grains at D/d_g = 5$" "$OUT/res/box.csv" ||
  fail "box.csv lacks the 20 cm box's alpha ratio"
grep -q "^alpha(D = 3 cm) / alpha(D = 2 cm) (bench at 28 and dg10 at 100 cm/s),20,$(val bench_box20.alpha_D3_over_D2 | awk '{print $1}'),.*,bench grains at D/d_g = 5$" "$OUT/res/box.csv" ||
  fail "box.csv lacks the 20 cm box's alpha(3 cm) / alpha(2 cm)"
! grep -q '^bench_box12\.\|^bench_box16\.v50\|^bench_box20\.peak_over\|^bench_box8\.v50\|^bench_box8.peak_over\|^bench_box8\.alpha\|^bench_box8_shaft\|^bench_box20_shaft' "$N" || fail "an incomplete box part added lines"
grep -q "box_bench8_D: 0 of 6 pushes" "$OUT/res.log" || fail "no note of the 8 cm box's missing D pushes"
grep -q "box 12 cm: 0 of 10 peak pushes" "$OUT/res.log" || fail "no note of the 12 cm box's missing pushes"
# the box table holds the 16 cm box's paired peaks, the 20 cm box's flow, and its figure was made
grep -q "^peak over the narrower box's (same bed and v0),16,1,0,.*,bench grains at D/d_g = 5$" "$OUT/res/box.csv" || fail "box.csv lacks the 16 cm box's paired peaks: $(cat "$OUT/res/box.csv")"
grep -q "^peak over the narrower box's (same bed and v0),20,,.*,bench grains at D/d_g = 5$" "$OUT/res/box.csv" || fail "box.csv has a 20 cm paired peak without the 12 cm box"
grep -q "^lambda_vz / D (bench at 50 and dg10 at 40 cm/s),20,$(val mid.lambda_vz_D | awk '{print $1}'),.*,bench grains at D/d_g = 5$" "$OUT/res/box.csv" || fail "box.csv lacks the 20 cm box's lambda_vz"
[ -s "$OUT/res/box/scaling.gp" ] || fail "no box figure"
# every row of box.csv has the header's nine fields, the last its series (the grain size)
awk -F, 'NR > 2 && (NF != 9 || ($9 != "bench grains at D/d_g = 5" && $9 != "dg10 grains at D/d_g = 10")) { print; bad = 1 } END { exit bad }' "$OUT/res/box.csv" ||
  fail "a box.csv row without nine fields or a known series"
# dg10 in the 20 cm box: its peak law is dg10's own (the same traces through peak_law), each
# peak over its 10 cm twin's that of the push itself, its flow rows the mid push's; alpha
# against D from granpen fit on the files directly; the shaft part adds no line
for k in phi_0 peak_exponent peak_exponent_ensemble peak_exponent_local peak_exponent_from_2vc peak_z \
  peak_exponent_ensemble_from_2vc peak_inertial peak_crossover_speed; do
  same "dg10_box20.$k" "$(val "dg10.$k")"
done
same dg10_box20.peak_over_box10 "1 +- 0 n = 15"
# the slow end push by push: the stand-ins are the 10 cm traces, so every peak is its twin's and
# no pair parts; the 10 cm beds' spread from each trace's largest force below 0.7 R (awk, the
# definition, not granpen collapse)
peak07() { awk -F, '!/^#/ && $1 != "t" && $2 > 0 && $2 < 0.7 && $3 > m { m = $3 } END { print m }' "$1"; }
# the mean drag over 0 < z <= 0.7 cm by another route: granpen fit's least-squares line over
# that window passes through the window's mean (z_bar, F_bar), and z is evenly spaced at a
# constant v0, so F_bar = k_z (z_first + z_last) / 2 + intercept (agrees with the rows' mean to
# 8 digits on these traces, far below the 4 printed)
fit_mean() { "$CLI" fit "$1" --zmin 0 --zmax 0.7 --csv "$OUT/m.csv" > /dev/null
  awk -F, 'NR == 1 { for (c = 1; c <= NF; c++) i[$c] = c; next } { printf "%.10g\n", $i["k_z"] * ($i["z_first"] + $i["z_last"]) / 2 + $i["intercept"] }' "$OUT/m.csv"; }
for v in 40 20; do
  same "dg10_box20.peak_over_box10.v$v" "1 +- 0 n = 3"
  same "dg10_box20.mean_below_07R_over_box10.v$v" "1 +- 0 n = 3"
  same "dg10.mean_below_07R_over_bed_mean.v$v" "$(for s in 1 2 3; do fit_mean "$DG/dg10_peak/dg10_mu0.3_s${s}_v${v}_g981_D2.0.csv"; done |
    awk '{ p[NR] = $1; s += $1 } END { for (i = 1; i <= NR; i++) print p[i] / (s / NR) }' |
    awk '{ s += $1; ss += $1 * $1; n++ } END { m = s / n; printf "%.4g +- %.2g n = %d\n", m, sqrt((ss - n * m * m) / (n - 1)), n }')"
  same "dg10_box10_20.t_part_ms.v$v" "undefined n = 0"
  same "dg10.peak_over_bed_mean.v$v" "$(for s in 1 2 3; do peak07 "$DG/dg10_peak/dg10_mu0.3_s${s}_v${v}_g981_D2.0.csv"; done |
    awk '{ p[NR] = $1; s += $1 } END { for (i = 1; i <= NR; i++) print p[i] / (s / NR) }' |
    awk '{ s += $1; ss += $1 * $1; n++ } END { m = s / n; printf "%.4g +- %.2g n = %d\n", m, sqrt((ss - n * m * m) / (n - 1)), n }')"
done
# the fast speeds' peak law (80 to 200 cm/s, both boxes): the stand-ins are the 10 cm traces, so
# the 20 cm box's lines are the 10 cm box's, and they are not the five speeds' (fewer traces)
for k in peak_exponent peak_exponent_ensemble peak_exponent_from_2vc peak_inertial; do
  [ -n "$(val "dg10_v80to200.$k")" ] || fail "no dg10_v80to200.$k"
  same "dg10_box20_v80to200.$k" "$(val "dg10_v80to200.$k")"
done
grep -q '^dg10_v80to200.peak_exponent = .*# granpen collapse, 9 traces' "$N" || fail "the fast speeds' peak law is not of 9 traces"
# every speed above v_c (40 to 200 cm/s): the 20 cm box's lines the 10 cm box's (the same
# stand-ins), and the 10 cm box's above-v_c lines from these 12 traces are its lines from all
# 15 (peak_above_vc leaves the 20 cm/s traces out): two routes to one number
for k in peak_exponent_from_2vc peak_exponent_ensemble_from_2vc peak_inertial peak_crossover_speed peak_z; do
  [ -n "$(val "dg10_v40to200.$k")" ] || fail "no dg10_v40to200.$k"
  same "dg10_box20_v40to200.$k" "$(val "dg10_v40to200.$k")"
  same "dg10_v40to200.$k" "$(val "dg10.$k")"
done
grep -q '^dg10_v40to200.peak_exponent = .*# granpen collapse, 12 traces' "$N" || fail "the peak law above v_c is not of 12 traces"
same dg10_box20_v40to200.peak_over_box10 "1 +- 0 n = 12"
for k in lambda_vz_D lambda_vz_local_D edge_phi_0 edge_slope phi_below_far phi_below_face surface_flux_sign_change_t drag_over_mu_g_Mmove M_move M_slow; do
  same "dg10_box20.v40.$k" "$(val "mid.$k")"
done
for D in 1 2 3; do
  f=$B20/dg10_box20_D/dg10_mu0.3_s1_v100_g981_D$D.0.csv
  for k in alpha0 alpha_a beta_b; do
    same "dg10_box20.$([ $k = alpha0 ] && echo alpha0_window || echo $k).v100.D$D" \
      "$(printf '%.4g +- %.2g n = 1' "$(fit_col "$f" $k --zmin 3)" "$(fit_col "$f" ${k}_se --zmin 3)")"
  done
done
same dg10_box20.alpha_D1_over_D2 "$(awk -v a="$(fit_col "$B20/dg10_box20_D/dg10_mu0.3_s1_v100_g981_D1.0.csv" alpha0 --zmin 3)" \
  -v ea="$(fit_col "$B20/dg10_box20_D/dg10_mu0.3_s1_v100_g981_D1.0.csv" alpha0_se --zmin 3)" \
  -v b="$(fit_col "$B20/dg10_box20_D/dg10_mu0.3_s1_v100_g981_D2.0.csv" alpha0 --zmin 3)" \
  -v eb="$(fit_col "$B20/dg10_box20_D/dg10_mu0.3_s1_v100_g981_D2.0.csv" alpha0_se --zmin 3)" \
  'BEGIN { r = a / b; printf "%.4g +- %.2g\n", r, r * sqrt((ea / a) ^ 2 + (eb / b) ^ 2) }')"
d1=$B20/dg10_box20_D/dg10_mu0.3_s1_v100_g981_D1.0.csv d2=$B20/dg10_box20_D/dg10_mu0.3_s1_v100_g981_D2.0.csv d3=$B20/dg10_box20_D/dg10_mu0.3_s1_v100_g981_D3.0.csv
# the 3 cm push: its stand-in is the 2 cm push's trace with D = 3 in its header, the same force
# at every z, so F_z(3 cm) / F_z(2 cm) = 1 is the known answer: alpha(3) / alpha(2) = 4/9 and
# the exponent from 2 to 3 cm is 0, within the 4 digits numbers.txt keeps of each alpha (up
# to 3.3e-4 of an alpha near 15): 5e-4 of the ratio, 2.2e-4 of 4/9 plus its own last digit,
# so 3e-4; on the exponent 5e-4 / ln 1.5 = 1.2e-3, so 1.5e-3
a1=$(fit_col "$d1" alpha0 --zmin 3) a2=$(fit_col "$d2" alpha0 --zmin 3) a3=$(fit_col "$d3" alpha0 --zmin 3)
near() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= t) }'; }
r=$(val dg10_box20.alpha_D3_over_D2) e=$(val dg10_box20.depth_term_D_exponent_D2to3)
near "${r%% *}" "$(awk 'BEGIN { print 4 / 9 }')" 3e-4 || fail "alpha(3) / alpha(2) = $r where the stand-in's force is the 2 cm push's: 4/9 expected"
near "$e" 0 1.5e-3 || fail "the exponent from 2 to 3 cm is $e where the force does not change with D: 0 expected"
same dg10_box20.alpha_D3_over_D2 "$(awk -v a="$a3" -v ea="$(fit_col "$d3" alpha0_se --zmin 3)" -v b="$a2" -v eb="$(fit_col "$d2" alpha0_se --zmin 3)" \
  'BEGIN { a = sprintf("%.4g", a); b = sprintf("%.4g", b); ea = sprintf("%.2g", ea); eb = sprintf("%.2g", eb)
           r = a / b; printf "%.4g +- %.2g\n", r, r * sqrt((ea / a) ^ 2 + (eb / b) ^ 2) }')"
# the rim term's prediction from the 1 and 2 cm rods alone, and its length over the three
# rods: B / A of alpha = A + B / D by the normal equations in closed form (x = 1 / D), against
# results.sh's least squares; 3 digits kept, so a relative 5e-3
same dg10_box20.alpha_D3_over_D2_rim "$(awk -v a="$a1" -v ea="$(fit_col "$d1" alpha0_se --zmin 3)" -v b="$a2" -v eb="$(fit_col "$d2" alpha0_se --zmin 3)" \
  'BEGIN { a = sprintf("%.4g", a); b = sprintf("%.4g", b); ea = sprintf("%.2g", ea); eb = sprintf("%.2g", eb)
           r = a / b; printf "%.4g +- %.2g", 4 / 3 - r / 3, r * sqrt((ea / a) ^ 2 + (eb / b) ^ 2) / 3 }')"
ba=$(awk -v y1="$a1" -v y2="$a2" -v y3="$a3" 'BEGIN { x1 = 1; x2 = 1 / 2; x3 = 1 / 3; mx = (x1 + x2 + x3) / 3; my = (y1 + y2 + y3) / 3
  b = ((x1 - mx) * (y1 - my) + (x2 - mx) * (y2 - my) + (x3 - mx) * (y3 - my)) / ((x1 - mx) ^ 2 + (x2 - mx) ^ 2 + (x3 - mx) ^ 2); print b / (my - b * mx) }')
near "$(val dg10_box20.rim_B_over_A_D1to3)" "$ba" "$(awk -v b="$ba" 'BEGIN { print (b < 0 ? -b : b) * 5e-3 }')" ||
  fail "rim B / A over the three rods = $(val dg10_box20.rim_B_over_A_D1to3), the closed form gives $ba"
p=$(val dg10_box20.depth_term_D_exponent)
near "${p%% *}" "$(awk -v y1="$a1" -v y2="$a2" -v y3="$a3" 'BEGIN { x1 = 0; x2 = log(2); x3 = log(3); u1 = log(y1); u2 = log(4 * y2); u3 = log(9 * y3)
  mx = (x1 + x2 + x3) / 3; mu = (u1 + u2 + u3) / 3
  print ((x1 - mx) * (u1 - mu) + (x2 - mx) * (u2 - mu) + (x3 - mx) * (u3 - mu)) / ((x1 - mx) ^ 2 + (x2 - mx) ^ 2 + (x3 - mx) ^ 2) }')" 5e-3 ||
  fail "the exponent of F_z in D over the three rods = $p, not the closed form's slope"
# ... and over the same depth in D (z = D to 2 D): the 1 cm push over 1 to 2 cm, the 2 cm push
# over 2 to 4 cm, the fits' errors in quadrature
same dg10_box20.alpha_D1_over_D2_zD1to2 "$(awk -v a="$(fit_col "$d1" alpha0 --zmin 1 --zmax 2)" -v ea="$(fit_col "$d1" alpha0_se --zmin 1 --zmax 2)" \
  -v b="$(fit_col "$d2" alpha0 --zmin 2 --zmax 4)" -v eb="$(fit_col "$d2" alpha0_se --zmin 2 --zmax 4)" \
  'BEGIN { a = sprintf("%.4g", a); b = sprintf("%.4g", b); ea = sprintf("%.2g", ea); eb = sprintf("%.2g", eb)
           r = a / b; printf "%.4g +- %.2g\n", r, r * sqrt((ea / a) ^ 2 + (eb / b) ^ 2) }')"
# each diameter's push over its 10 cm twin: the stand-ins are the twins' own files (the 1 cm
# push dg10_D's, the 2 cm push dg10_flow's 100 cm/s push), so every ratio is 1 with the fit's
# relative error times sqrt 2, each alpha granpen fit's on the file directly (rounded as
# printed), and no pair parts
for D in 1 2; do
  f=$B20/dg10_box20_D/dg10_mu0.3_s1_v100_g981_D$D.0.csv
  for w in 3:5 1:2 2:3 3:4 4:5; do
    same "dg10_box20.alpha0_over_box10.v100.D$D.z${w/:/-}" "$(awk -v a="$(fit_col "$f" alpha0 --zmin "${w%%:*}" --zmax "${w##*:}")" \
      -v e="$(fit_col "$f" alpha0_se --zmin "${w%%:*}" --zmax "${w##*:}")" \
      'BEGIN { a = sprintf("%.4g", a); e = sprintf("%.2g", e); printf "%.4g +- %.2g (%.4g over %.4g)\n", 1, sqrt(2) * e / a, a, a }')"
  done
  same "dg10_box10_20.t_part_ms.v100.D$D" none
  [ -s "$OUT/res/dg10_box20_D/box10/fig_parting_D$D/parting.png" ] || fail "no parting figure of the $D cm push"
done
# the box figure's dg10 series: the 10 cm box's row and the 20 cm box's, each the key's value
dg10_row() { # QUANTITY BOX KEY: the row of the dg10 series holds KEY's value (empty when KEY is not in numbers.txt)
  grep -q "^$1,$2,$(val "$3" | awk '{print $1}'),.*,dg10 grains at D/d_g = 10$" "$OUT/res/box.csv" || fail "box.csv: no dg10 row $1 at $2 cm with $3's value"
}
dg10_row "peak exponent (v_c to 10 v_c)" 10 dg10.peak_exponent
dg10_row "peak exponent (v_c to 10 v_c)" 20 dg10_box20.peak_exponent
dg10_row "peak exponent at 80 to 200 cm/s (ensemble means)" 20 dg10_box20_v80to200.peak_exponent_ensemble_from_2vc
dg10_row "peak exponent above v_c (ensemble means)" 10 dg10.peak_exponent_ensemble_from_2vc
dg10_row "peak exponent above v_c (ensemble means)" 20 dg10_box20_v40to200.peak_exponent_ensemble_from_2vc
dg10_row "peak over the narrower box's (same bed and v0)" 20 dg10_box20_v40to200.peak_over_box10
dg10_row "lambda_vz / D (bench at 50 and dg10 at 40 cm/s)" 20 dg10_box20.v40.lambda_vz_D
dg10_row "drag / (mu g M) (bench at 50 and dg10 at 40 cm/s)" 10 dg10.v40.drag_over_mu_g_Mmove
dg10_row "alpha(D = 1 cm) / alpha(D = 2 cm) (bench at 28 and dg10 at 100 cm/s)" 20 dg10_box20.alpha_D1_over_D2
dg10_row "alpha(D = 3 cm) / alpha(D = 2 cm) (bench at 28 and dg10 at 100 cm/s)" 20 dg10_box20.alpha_D3_over_D2
dg10_row "... the same with the shaft frictionless" 20 dg10_box20_shaft.alpha_D1_over_D2
! grep -q '^dg10_box20_shaft\.' "$N" || fail "the shaft part without its pushes added lines"
grep -q "dg10_box20_shaft: the pushes of D = 1.0 2.0 cm" "$OUT/res.log" || fail "no note of the shaft's missing pushes"
# the flow rows of each dg10 speed: the mid push's, from the same tables
for v in 40 100 200; do
  for k in lambda_vz_D lambda_vz_local_D edge_phi_0 edge_slope phi_below_far phi_below_face surface_flux_sign_change_t drag_over_mu_g_Mmove M_move M_slow; do
    same "dg10.v$v.$k" "$(val "mid.$k")"
  done
done
# alpha through the origin over z >= 3: granpen fit on each file directly
alpha0() { "$CLI" fit "$1" --zmin 3 --csv "$OUT/a.csv" > /dev/null
  awk -F, 'NR == 1 { for (c = 1; c <= NF; c++) i[$c] = c; next } { printf "%.4g +- %.2g n = 1\n", $i["alpha0"], $i["alpha0_se"] }' "$OUT/a.csv"; }
same dg10.alpha0_window.v100.D2 "$(alpha0 "$DG/dg10_flow/dg10_mu0.3_s1_v100_g981_D2.0.csv")"
same dg10.alpha0_window.v40.D2 "$(alpha0 "$DG/dg10_flow/dg10_mu0.3_s1_v40_g981_D2.0.csv")"
same dg10.alpha0_window.v100.D1 "$(alpha0 "$DG/dg10_D/dg10_mu0.3_s1_v100_g981_D1.0.csv")"
# the D ratio over a 1 cm window: granpen fit on the two files over that window directly
a1=$(fit_col "$DG/dg10_D/dg10_mu0.3_s1_v100_g981_D1.0.csv" alpha0 --zmin 3 --zmax 4)
a2=$(fit_col "$DG/dg10_flow/dg10_mu0.3_s1_v100_g981_D2.0.csv" alpha0 --zmin 3 --zmax 4)
same dg10.alpha0_ratio_D1_D2.z3-4 "$(awk -v a="$a1" -v b="$a2" 'BEGIN { printf "%.3g\n", a / b }')"
# ... and with an intercept at the slowest speed
"$CLI" fit "$DG/dg10_flow/dg10_mu0.3_s1_v40_g981_D2.0.csv" --zmin 3 --csv "$OUT/a.csv" > /dev/null
same dg10.alpha.v40.D2 "$(awk -F, 'NR == 1 { for (c = 1; c <= NF; c++) i[$c] = c; next } { printf "%.4g +- %.2g n = 1\n", $i["alpha"], $i["alpha_se"] }' "$OUT/a.csv")"
# k_z in the deep regime: granpen fit --tmin 1 on each flow push directly (the stand-in for
# 40 cm/s reaches t~ = 1 early enough, the one for 200 cm/s does not)
same dg10.k_z_deep.v40 "$(printf "%.4g +- 0 n = 1" "$(fit_col "$DG/dg10_flow/dg10_mu0.3_s1_v40_g981_D2.0.csv" k_z --tmin 1)")"
same dg10.k_z_deep.v200 "undefined"
# the collapse of the four full pushes: granpen collapse on them directly, F_z from the
# alpha through the origin at 40 cm/s checked above
a=$(val dg10.alpha0_window.v40.D2 | awk '{print $1}')
"$CLI" collapse "$DG"/dg10_flow/*.csv "$DG"/dg10_D/*.csv --alpha "$a" --tbin 0.25 --json "$OUT/all.json" > /dev/null
same dg10.t_star "$(num "$OUT/all.json" t_star_mean) +- $(num "$OUT/all.json" t_star_sd) n = $(num "$OUT/all.json" n_crossed) of 4"
same dg10.collapse_spread_z "$(num "$OUT/all.json" spread_z)"
same dg10.collapse_spread_t "$(num "$OUT/all.json" spread_t)"
[ -s "$OUT/res/dg10/fig/ratio.gp" ] || [ -n "$(ls "$OUT"/res/dg10/fig/*ratio* 2>/dev/null)" ] || fail "no dg10 ratio figure"
# every key once
dup=$(sed 's/ = .*//' "$N" | sort | uniq -d)
[ -z "$dup" ] || fail "keys given twice: $dup"
# the scaling table holds the dg10 values, and its figure was made
grep -q "^peak exponent (v_c to 10 v_c),10,$(val dg10.peak_exponent | awk '{print $1}')," "$OUT/res/scaling.csv" \
  || fail "scaling.csv lacks dg10's peak exponent: $(grep '^peak exponent (v_c' "$OUT/res/scaling.csv")"
[ -s "$OUT/res/scaling/scaling.gp" ] || fail "no scaling figure"

# a part with one push missing adds no line and says so
rm "$DG/dg10_flow/dg10_mu0.3_s1_v200_g981_D2.0.flow/window.txt" "$DG/dg10_D/dg10_mu0.3_s1_v100_g981_D1.0.csv"
rm "$B20/dg10_box20_peak/dg10_mu0.3_s3_v200_g981_D2.0.csv" "$B20/dg10_box20_flow/$id.flow/window.txt" \
  "$B20/dg10_box20_D/dg10_mu0.3_s1_v100_g981_D3.0.csv" "$B20/dg10_box20_peak/dg10_mu0.3_s2_v20_g981_D2.0.csv" \
  "$B20/dg10_box20_peak/dg10_mu0.3_s1_v40_g981_D2.0.csv" "$B20/dg10_box20_peak/dg10_mu0.3_s2_v40_g981_D2.0.csv" \
  "$B20/dg10_box20_peak/dg10_mu0.3_s3_v40_g981_D2.0.csv"
# KEY is VALUE in the run with pushes missing
same_in() { [ "$(awk -v k="$1" '$1 == k { sub(/  #.*/, ""); sub(/^[^=]*= /, ""); print; exit }' "$OUT/res2/numbers.txt")" = "$2" ] ||
  fail "with pushes missing: $1 is not '$2'"; }
GRANPEN_CLI=$CLI "$ROOT/validation/results.sh" --out "$OUT/res2" --dumps /nonexistent --dg10 "$DG" --stiff "$ST" --damp "$DA" \
  --dg10-box "$B20" > "$OUT/res2.log" 2>&1 || { cat "$OUT/res2.log"; fail "results.sh failed with a part missing"; }
! grep '^dg10_box20' "$OUT/res2/numbers.txt" | grep -q -v '^dg10_box20.\(peak_over_box10\|mean_below_07R_over_box10\).v20 \|^dg10_box20.alpha0_over_box10.v100.D2.\|^dg10_box20\.\(alpha0_window\|alpha_a\|beta_b\|alpha0_zD1to2\)\.\(v100\.\)\?D[12] \|^dg10_box20\.alpha_D1_over_D2\(_zD1to2\)\? ' ||
  fail "a dg10 20 cm box part with a push missing added lines"
# alpha against D push by push: with the 3 cm push missing, the 1 and 2 cm pushes' lines and
# their ratio (the row itself, also over the same depth in D) are those of the whole part
# (the same files, each fitted alone), and the 3 cm push adds none
for k in alpha0_window.v100.D1 alpha0_window.v100.D2 alpha_a.v100.D1 alpha_a.v100.D2 beta_b.v100.D1 beta_b.v100.D2 \
  alpha_D1_over_D2 alpha0_zD1to2.D1 alpha0_zD1to2.D2 alpha_D1_over_D2_zD1to2; do
  [ -n "$(val "dg10_box20.$k")" ] || fail "no dg10_box20.$k with all three pushes"
  same_in "dg10_box20.$k" "$(val "dg10_box20.$k")"
done
! grep -q '^dg10_box20\.[a-z_0-9]*\.v100\.D3 ' "$OUT/res2/numbers.txt" || fail "the missing 3 cm push added lines"
grep -q "^alpha(D = 1 cm) / alpha(D = 2 cm) (bench at 28 and dg10 at 100 cm/s),20,$(val dg10_box20.alpha_D1_over_D2 | awk '{print $1}'),.*,dg10 grains at D/d_g = 10$" "$OUT/res2/box.csv" ||
  fail "box.csv: no dg10 20 cm row of alpha(1 cm) / alpha(2 cm) with the 3 cm push missing"
# the D pushes over their 10 cm twins push by push: the 2 cm one's lines with the 3 cm push
# missing, none of the 1 cm one's with its 10 cm twin missing (a note instead)
[ "$(grep -c '^dg10_box20.alpha0_over_box10.v100.D2.z' "$OUT/res2/numbers.txt")" = 5 ] || fail "the 2 cm push over its twin not read with the 3 cm push missing"
grep -q '^dg10_box10_20.t_part_ms.v100.D2 = none ' "$OUT/res2/numbers.txt" || fail "the 2 cm push's parting not read with the 3 cm push missing"
! grep -q '^dg10_box20.alpha0_over_box10.v100.D1\|^dg10_box10_20.t_part_ms.v100.D1' "$OUT/res2/numbers.txt" || fail "the 1 cm push read over a missing twin"
grep -q "dg10, 20 cm box: the 1 cm push's 10 cm twin .* missing: skipped" "$OUT/res2.log" || fail "no note of the 1 cm push's missing twin"
# ... but the slow end goes push by push: 20 cm/s on the two beds still there, 40 cm/s on none
same_in dg10_box20.peak_over_box10.v20 "1 +- 0 n = 2"
same_in dg10_box20.mean_below_07R_over_box10.v20 "1 +- 0 n = 2"
grep -q "dg10, 20 cm box: no push at 40 cm/s committed in" "$OUT/res2.log" || fail "no note of the 20 cm box's missing 40 cm/s pushes"
grep -q "dg10, 20 cm box: 10 of 15 peak pushes" "$OUT/res2.log" || fail "no note of the 20 cm box's missing peak push"
grep -q "dg10, 20 cm box: 8 of 9 peak pushes at 80 to 200 cm/s" "$OUT/res2.log" || fail "no note of the 20 cm box's missing fast peak push"
grep -q "dg10, 20 cm box: 8 of 12 peak pushes at 40 to 200 cm/s" "$OUT/res2.log" || fail "no note of the 20 cm box's missing pushes above v_c"
grep -q "dg10, 20 cm box: its 40 cm/s flow push (with tables) not in" "$OUT/res2.log" || fail "no note of the 20 cm box's missing flow tables"
grep -q "dg10_box20_D: the pushes of D = 3.0 cm" "$OUT/res2.log" || fail "no note of the 20 cm box's missing D push"
! grep -q '^dg10\.v\|^dg10\.alpha0_window\|^dg10\.alpha\.\|^dg10\.k_z_deep\|^dg10\.t_star\|^dg10\.collapse' "$OUT/res2/numbers.txt" ||
  fail "a part with a push missing added lines"
grep -q "dg10 flow: the full pushes at 200 cm/s" "$OUT/res2.log" || fail "no note of the missing flow push"
grep -q "dg10 D: the pushes of D = 1.0 cm" "$OUT/res2.log" || fail "no note of the missing D push"
grep -q '^dg10.peak_exponent = ' "$OUT/res2/numbers.txt" || fail "the complete peak part was dropped"
echo "results.sh's waiting parts: every line as granpen gives it directly; incomplete parts skipped"
