#!/usr/bin/env bash
# Regenerates every number and figure of docs/results.md (issue: validation) from the
# validation sweeps' traces and dumps, with granpen's own commands (fit, collapse, flow,
# momentum, plot); values of their JSON outputs are asked of `granpen get` by key path, and
# awk only averages their outputs over beds.
#
#   validation/results.sh [--out DIR] [--bench DIR] [--mid DIR] [--dumps DIR] [--dg10 DIR] [--stiff DIR]
#                         [--damp DIR] [--box DIR] [--dg10-box DIR] [--cli PATH]
#
#   --bench DIR  traces and bed .info files of the bench validation sweep
#                (default data/sims/validation_bench)
#   --mid DIR    the same for the mid preset (default data/sims/validation_mid; skipped
#                with a note when missing)
#   --dumps DIR  the mid sweep's traces folder with the dumps of its 90 cm/s, g = 981 push
#                (runs/validation_mid/traces; dumps are not committed, they are 100s of MB;
#                without them the flow rows are read from the tables they gave, committed in
#                docs/results/mid: flow/, surface/, momentum/, window.txt)
#   --dg10 DIR   the committed units of validation/dg10.sh (default data/sims/dg10): each
#                part (dg10_peak, dg10_flow, dg10_D) is analysed once all its pushes are
#                there, and skipped with a note before, so that the numbers of a part never
#                change as its pushes arrive
#   --stiff DIR  the traces of validation/peak_sweep.sh peak_stiffness (default
#                data/sims/peak_stiffness; skipped with a note until all 10 are there)
#   --damp DIR   the same of peak_damping (default data/sims/peak_damping)
#   --box DIR    the committed units of validation/box.sh bench (default data/sims/box_bench):
#                each box's peak law once its 10 pushes are there, its flow rows once its
#                flow push and tables are
#   --dg10-box DIR  the committed units of validation/box.sh dg10 (default
#                data/sims/dg10_box20; scale name dg10_box20): its peak part once its 15
#                pushes are there (the 9 of 80 to 200 cm/s and the 12 above v_c, 40 to
#                200 cm/s, each once they are), its flow rows once its 40 cm/s push and
#                tables are, alpha against D once its 3 (and the frictionless shaft's 2) pushes are
#   --out DIR    where numbers.txt, scaling.csv and the figures go (default docs/results)
#
# numbers.txt: one line per measured quantity, "KEY = VALUE [+- ERROR] [n = N]  # how".
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
OUT=$ROOT/docs/results BENCH=$ROOT/data/sims/validation_bench MID=$ROOT/data/sims/validation_mid
DUMPS=$ROOT/runs/validation_mid/traces CLI=${GRANPEN_CLI:-$ROOT/build/analysis/granpen-cli} DG10=$ROOT/data/sims/dg10 STIFF=$ROOT/data/sims/peak_stiffness
DAMP=$ROOT/data/sims/peak_damping BOX=$ROOT/data/sims/box_bench DG10BOX=$ROOT/data/sims/dg10_box20
while [ $# -gt 0 ]; do
  case $1 in
    --out) OUT=$2; shift 2 ;;
    --bench) BENCH=$2; shift 2 ;;
    --mid) MID=$2; shift 2 ;;
    --dumps) DUMPS=$2; shift 2 ;;
    --dg10) DG10=$2; shift 2 ;;
    --stiff) STIFF=$2; shift 2 ;;
    --damp) DAMP=$2; shift 2 ;;
    --box) BOX=$2; shift 2 ;;
    --dg10-box) DG10BOX=$2; shift 2 ;;
    --cli) CLI=$2; shift 2 ;;
    *) echo "results.sh: unknown argument $1 (see the header of $0)" >&2; exit 2 ;;
  esac
done
# Paths inside the checkout are given to granpen relative to it (the script runs from its
# root), so that the committed outputs, which name their inputs, do not depend on where the
# checkout lies; a path outside it is made absolute.
in_tree() {
  local p=$1
  case $p in /*) ;; *) p=$PWD/$p ;; esac
  case $p in "$ROOT"/*) printf '%s' "${p#"$ROOT"/}" ;; *) printf '%s' "$p" ;; esac
}
case $CLI in */*) case $CLI in /*) ;; *) CLI=$PWD/$CLI ;; esac ;; esac
OUT=$(in_tree "$OUT") BENCH=$(in_tree "$BENCH") MID=$(in_tree "$MID") DUMPS=$(in_tree "$DUMPS")
DG10=$(in_tree "$DG10") STIFF=$(in_tree "$STIFF") DAMP=$(in_tree "$DAMP") BOX=$(in_tree "$BOX") DG10BOX=$(in_tree "$DG10BOX")
cd "$ROOT"
mkdir -p "$OUT"
NUM=$OUT/numbers.txt.partial
: > "$NUM"
say() { echo "== $*" >&2; }
put() { echo "$*" | tee -a "$NUM"; }

# mean +- sample sd (n) of the numbers on stdin
stats() { awk '{ s += $1; ss += $1 * $1; n++ }
  END { if (n == 0) { print "undefined n = 0"; exit }
        m = s / n; sd = n > 1 ? sqrt((ss - n * m * m) / (n - 1)) : 0
        printf "%.4g +- %.2g n = %d\n", m, sd, n }'; }

# least-squares slope of ln Y against ln X over lines "X Y" (t_part against v0, F against D), with its
# standard error: "SLOPE +- SE n = N"
log_slope() { awk '{ x = log($1); y = log($2); sx += x; sy += y; sxx += x * x; sxy += x * y; n++; X[n] = x; Y[n] = y }
  END { if (n < 3) { print "undefined n = " n; exit }
        b = (n * sxy - sx * sy) / (n * sxx - sx * sx); a = (sy - b * sx) / n
        for (i = 1; i <= n; i++) r += (Y[i] - a - b * X[i]) ^ 2
        printf "%.3g +- %.2g n = %d\n", b, sqrt(r / (n - 2) / (sxx - sx * sx / n)), n }'; }

# the rim term's length B / A (cm) of alpha = A + B / D, by least squares of alpha on 1 / D
# over lines "D ALPHA"
rim_length() { awk '{ x = 1 / $1; y = $2; sx += x; sy += y; sxx += x * x; sxy += x * y; n++ }
  END { b = (n * sxy - sx * sy) / (n * sxx - sx * sx); a = (sy - b * sx) / n; printf "%.3g", b / a }'; }

# the value at key path KEY of a granpen JSON output: jget FILE KEY
jget() { "$CLI" get "$1" "$2"; }

# the peak law of granpen collapse --ensemble's JSON: "VALUE +- SE (fit; 95% over runs: CI)"
ensemble_peak() {
  "$CLI" get "$1" ensemble.peak_exponent.value ensemble.peak_exponent.se ensemble.peak_exponent.ci95 |
    awk -F'\t' '{ printf "%.4g +- %.2g (fit; 95%% over runs: %.2g)\n", $1, $2, $3 }'
}

# when two pushes on the same grains part (granpen parting)
parting_ms() { # NARROW WIDE JSON: t_part in ms, or "none" when they do not part
  "$CLI" parting "$1" "$2" --json "$3" > /dev/null
  [ "$(jget "$3" parted)" = true ] && jget "$3" t_part_ms || echo none
}

# each number on stdin over their mean
over_mean() { awk '{ p[NR] = $1; s += $1 } END { for (i = 1; i <= NR; i++) print p[i] / (s / NR) }'; }

# the mean drag of a granpen trace (t,z,F rows) over 0 < z <= ZMAX: mean_drag_below TRACE ZMAX
mean_drag_below() { awk -F, -v zmax="$2" '!/^#/ && $1 != "t" && $2 > 0 && $2 <= zmax { s += $3; n++ } END { if (n) printf "%.10g\n", s / n }' "$1"; }

# "FILE V0 PEAK" per trace of granpen collapse's JSON (tab-separated)
trace_peaks() { "$CLI" get "$1" 'traces[*].file' 'traces[*].v0' 'traces[*].peak'; }

# the local exponent of the peak law between successive speeds, from the mean peak over the
# runs of each speed in granpen collapse's JSON: "V1-V2: E, ..." (does it approach 2 at speed?)
local_peak_exponents() {
  trace_peaks "$1" |
    awk '{ s[$2] += $3; n[$2]++ } END { k = 0; for (v in s) vs[++k] = v + 0
           for (i = 1; i <= k; i++) for (j = i + 1; j <= k; j++) if (vs[j] < vs[i]) { t = vs[i]; vs[i] = vs[j]; vs[j] = t }
           out = ""; for (i = 1; i < k; i++) { a = s[vs[i]] / n[vs[i]]; b = s[vs[i + 1]] / n[vs[i + 1]]
             out = out (i > 1 ? ", " : "") sprintf("%g-%g: %.2f", vs[i], vs[i + 1], log(b / a) / log(vs[i + 1] / vs[i])) }
           print out }'
}

# column NAME of a CSV with a header row, for the rows where column KEY equals VALUE (repeatable)
col() { # col FILE NAME [KEY VALUE]...
  local f=$1 name=$2; shift 2
  awk -F, -v name="$name" -v conds="$*" '
    NR == 1 { for (c = 1; c <= NF; c++) idx[$c] = c; nc = split(conds, cv, " "); next }
    { ok = 1; for (i = 1; i < nc; i += 2) if ($idx[cv[i]] + 0 != cv[i + 1] + 0) ok = 0
      if (ok) print $idx[name] }' "$f"
}

# peak positions (cm) of `granpen collapse`'s text output: "... peak F dyne at z = Z cm ..."
peak_z() { grep -o 'dyne at z = [-0-9.e+]* cm' "$1" | awk '{print $5}'; }
# the peak law above v_c, the paper's range from 2 v_c (40 to 240 cm/s): at v_c the largest
# force within 0.7 R is the depth term's, not an impact peak. Per trace, of the ensemble means,
# and as two terms, peak = c1 v0 + c2 v0^2 (granpen collapse): the inertial coefficient
# c2 / (rho_g D^2) and the crossover speed c1 / c2 below which the linear term dominates.
peak_above_vc() { # KEY OUTDIR SLOW_V0 ALPHA TRACE...
  local key=$1 o=$2 slow=$3 alpha=$4 f fast=() rho D; shift 4
  for f in "$@"; do case $f in *_v${slow}_*) ;; *) fast+=("$f") ;; esac; done
  "$CLI" collapse "${fast[@]}" --alpha "$alpha" --tbin 0.25 --json "$o/collapse_peak_fast.json" > "$o/collapse_peak_fast.txt"
  put "$key.peak_exponent_from_2vc = $(jget "$o/collapse_peak_fast.json" peak_exponent) +- $(jget "$o/collapse_peak_fast.json" peak_exponent_ci95) (95%)  # granpen collapse, the ${#fast[@]} traces above v0 = $slow"
  put "$key.peak_z = $(peak_z "$o/collapse_peak_fast.txt" | stats)  # peak position over the ${#fast[@]} traces above v0 = $slow, cm"
  "$CLI" collapse "${fast[@]}" --alpha "$alpha" --tbin 0.25 --ensemble --ensemble-bin 0.02 --json "$o/collapse_peak_fast_ensemble.json" > "$o/collapse_peak_fast_ensemble.txt"
  put "$key.peak_exponent_ensemble_from_2vc = $(ensemble_peak "$o/collapse_peak_fast_ensemble.json")  # granpen collapse --ensemble --ensemble-bin 0.02, above v0 = $slow"
  rho=$(awk '/^# rho_g = / { print $4; exit }' "${fast[0]}") D=$(awk '/^# D = / { print $4; exit }' "${fast[0]}")
  put "$key.peak_inertial = $(two_term "$o/collapse_peak_fast.json" quadratic "$(awk -v r="$rho" -v d="$D" 'BEGIN { print r * d * d }')")  # granpen collapse: c2 / (rho_g D^2) of peak = c1 v0 + c2 v0^2 above v0 = $slow; standard error"
  put "$key.peak_crossover_speed = $(two_term "$o/collapse_peak_fast.json" crossover_speed 1)  # granpen collapse: c1 / c2 (cm/s), where the linear term equals the inertial one"
}
# FIELD of granpen collapse's peak_two_term divided by DIVISOR: "VALUE +- SE" ("undefined"
# when the collapse wrote no such term)
two_term() { # JSON FIELD DIVISOR
  "$CLI" get "$1" "peak_two_term.$2" "peak_two_term.$2_se" --missing undefined |
    awk -F'\t' -v s="$3" '{ if ($1 == "undefined") print "undefined"; else printf "%.4g +- %.2g\n", $1 / s, $2 / s }'
}

# k_z against v0 in the deep regime t~ >= 1, where the push reaches it (>= 0.5 cm of window
# that starts at t~ = 1: fit shortens a window the data do not fill to the trace's deeper
# half, which is not the deep regime), g = 981, D = 2: KEY FIT_CSV (granpen fit --tmin 1)
deep_kz() {
  local key=$1 csv=$2 v n
  for v in $(col "$csv" v0 g 981 D 2 | sort -gu); do
    n=$(awk -F, -v v="$v" 'NR == 1 { for (c = 1; c <= NF; c++) i[$c] = c; next }
      $i["v0"] + 0 == v && $i["g"] + 0 == 981 && $i["D"] + 0 == 2 && $i["z_last"] - $i["z_first"] >= 0.5 &&
      $i["zlo"] >= $i["v0"] * sqrt($i["D"] / $i["g"]) * (1 - 1e-9)' "$csv" | wc -l)
    [ "$n" -gt 0 ] || { put "$key.k_z_deep.v$v = undefined  # t~ >= 1 not reached by 0.5 cm before the push ends"; continue; }
    put "$key.k_z_deep.v$v = $(col "$csv" k_z v0 "$v" g 981 D 2 | stats)  # granpen fit --tmin 1, g = 981, D = 2"
  done
}

# the crossover and the collapse quality of granpen collapse's JSON over every trace:
# KEY JSON NTRACES ALPHA
collapse_numbers() {
  put "$1.t_star = $(jget "$2" t_star_mean) +- $(jget "$2" t_star_sd) n = $(jget "$2" n_crossed) of $3  # granpen collapse --alpha $4, every v0, g, D"
  put "$1.t_star_ensemble = $(jget "$2" t_star_ensemble) (crossed: $(jget "$2" ensemble_crossed))  # the mean of F/F_z over the traces"
  put "$1.collapse_spread_z = $(jget "$2" spread_z)  # spread of F/F_z across traces against z"
  put "$1.collapse_spread_t = $(jget "$2" spread_t)  # ... against t~"
}

# one preset's traces: PRESET DIR ZMIN (k_z window start of the slow speed: the paper's 3 cm
# where the push goes deep enough, else 2 cm)
analyse_traces() {
  local preset=$1 dir=$2 zmin=$3 o=$OUT/$1
  mkdir -p "$o"
  say "$preset: bed packing fractions"
  put "$preset.phi_0 = $(grep -h '^phi_0' "$dir"/bed_*.info | awk '{print $3}' | stats)  # bed .info files, mu = 0.3"

  if [ -f "$dir/manifest.json" ]; then
    say "$preset: cost of each run (the sweep's manifest: wall seconds, two runs at a time on 2 cores)"
    "$CLI" get "$dir/manifest.json" 'runs[*].kind' 'runs[*].v0' 'runs[*].g' 'runs[*].D' 'runs[*].wall_seconds_run' --missing '' |
      awk -F'\t' -v preset="$preset" '$1 == "pour" || $1 == "push" {
        key = $1 ($1 == "push" ? ".v" $2 ".g" $3 ".D" $4 : "")
        s[key] += $5; c[key]++ }
      END { for (k in s) printf "%s.cost.%s = %.0f s n = %d  # wall seconds per run, the sweep manifest\n", preset, k, s[k] / c[k], c[k] }' |
      sort -t= -k1,1 -V | tee -a "$NUM"
  fi
  say "$preset: linear fits (granpen fit)"
  "$CLI" fit "$dir" --zmin "$zmin" --csv "$o/fit_z$zmin.csv" > "$o/fit_z$zmin.txt"
  "$CLI" fit "$dir" --tmin 1 --csv "$o/fit_deep.csv" > "$o/fit_deep.txt"
  local vmin
  vmin=$(col "$o/fit_z$zmin.csv" v0 | sort -g | head -1)
  for g in $(col "$o/fit_z$zmin.csv" g | sort -gu); do
    put "$preset.alpha.v$vmin.g$g.D2 = $(col "$o/fit_z$zmin.csv" alpha v0 "$vmin" g "$g" D 2 | stats)  # granpen fit --zmin $zmin, v0 = $vmin"
    put "$preset.alpha0.v$vmin.g$g.D2 = $(col "$o/fit_z$zmin.csv" alpha0 v0 "$vmin" g "$g" D 2 | stats)  # the same through the origin (F_z = k_z0 z)"
  done
  for D in $(col "$o/fit_z$zmin.csv" D | sort -gu); do
    [ "$D" = 2 ] && continue    # above
    put "$preset.alpha.v$vmin.g981.D$D = $(col "$o/fit_z$zmin.csv" alpha v0 "$vmin" g 981 D "$D" | stats)  # granpen fit --zmin $zmin"
  done
  # the depth term through the origin over the paper's kind of window (z >= zmin; the
  # transient is still in it at the fast speeds) for every (v0, g, D) of the sweep
  for key in $(awk -F, 'NR == 1 { for (c = 1; c <= NF; c++) i[$c] = c; next }
                 { print $i["v0"] ":" $i["g"] ":" $i["D"] }' "$o/fit_z$zmin.csv" | sort -t: -k3,3g -k2,2g -k1,1g -u); do
    IFS=: read -r v g D <<< "$key"
    put "$preset.alpha0_window.v$v.g$g.D$D = $(col "$o/fit_z$zmin.csv" alpha0 v0 "$v" g "$g" D "$D" | stats)  # granpen fit --zmin $zmin: k_z0 / (mu rho_g g D^2)"
  done
  deep_kz "$preset" "$o/fit_deep.csv"

  say "$preset: peak law and collapse (granpen collapse)"
  local v0set=() f
  for f in "$dir"/*_g981_D2.0.csv; do v0set+=("$f"); done
  # F_z = alpha0 mu rho_g g D^2 z from the slow speed (g = 981, D = 2), through the origin as
  # the paper writes it: the fast pushes do not reach the deep regime in these beds, so
  # their own k_z fits are not depth terms
  local alpha
  alpha=$(col "$o/fit_z$zmin.csv" alpha0 v0 "$vmin" g 981 D 2 | stats | awk '{print $1}')
  # t~ bins of 0.25: at the slowest speeds that is about a grain diameter of travel, the
  # wavelength of the force's fluctuations
  "$CLI" collapse "${v0set[@]}" --alpha "$alpha" --tbin 0.25 --json "$o/collapse_v0.json" > "$o/collapse_v0.txt"
  "$CLI" collapse "$dir" --alpha "$alpha" --tbin 0.25 --json "$o/collapse_all.json" > "$o/collapse_all.txt"
  put "$preset.peak_exponent = $(jget "$o/collapse_v0.json" peak_exponent) +- $(jget "$o/collapse_v0.json" peak_exponent_ci95) (95%)  # granpen collapse, g = 981, D = 2, every v0"
  # the peak of each speed's ensemble mean (beds aligned at their onsets, 0.02 cm bins, the
  # 1e-4 s trace window at 200 cm/s): the largest of many noisy samples inflates the peak of a
  # slow push, which samples its first 0.7 R more densely, and so lowers the per-trace exponent
  "$CLI" collapse "${v0set[@]}" --alpha "$alpha" --tbin 0.25 --ensemble --ensemble-bin 0.02 --json "$o/collapse_v0_ensemble.json" > "$o/collapse_v0_ensemble.txt"
  put "$preset.peak_exponent_ensemble = $(ensemble_peak "$o/collapse_v0_ensemble.json")  # granpen collapse --ensemble --ensemble-bin 0.02, g = 981, D = 2, every v0"
  put "$preset.peak_exponent_local = $(local_peak_exponents "$o/collapse_v0.json")  # between successive v0, the beds' mean peaks"
  peak_above_vc "$preset" "$o" "$vmin" "$alpha" "${v0set[@]}"
  collapse_numbers "$preset" "$o/collapse_all.json" "$(ls "$dir"/*.csv | wc -l)" "$alpha"

  say "$preset: figures (granpen plot)"
  "$CLI" plot force "${v0set[@]}" --out "$o/fig" > /dev/null
  "$CLI" plot peak "${v0set[@]}" --alpha "$alpha" --out "$o/fig" > /dev/null
  "$CLI" plot kz "${v0set[@]}" --kz-zmin "$zmin" --out "$o/fig" > /dev/null
  "$CLI" plot ratio "$dir" --alpha "$alpha" --tbin 0.25 --out "$o/fig" > /dev/null
}

analyse_traces bench "$BENCH" 2
if [ -d "$MID" ]; then analyse_traces mid "$MID" 3; else say "mid: $MID missing, skipped"; fi

# the figures of one push's flow from validation/push_flow.sh's outputs in SRC, into
# DEST/{flow,surface,momentum}/fig (default DEST = SRC)
plot_flow() {
  local src=$1 dest=${2:-$1}
  "$CLI" plot flow "$src/flow" --out "$dest/flow/fig" > /dev/null
  "$CLI" plot flow "$src/surface" --out "$dest/surface/fig" > /dev/null
  "$CLI" plot momentum "$src/momentum" --out "$dest/momentum/fig" > /dev/null
}

# the flow rows of one push (KEY.lambda_vz_D, ...) from validation/push_flow.sh's outputs in DIR
# lambda_vz / D of granpen flow's JSON: "VALUE +- SE"
lambda_D() { echo "$(jget "$1" profile_below.lambda_vz.lambda_D) +- $(jget "$1" profile_below.lambda_vz.lambda_D_se)"; }
flow_numbers() {
  local key=$1 dir=$2 fj=$2/flow/flow.json mj=$2/momentum/momentum.json steps
  steps=$(awk '{print $1 " (tip " $2 " to " $3 " cm deep)"}' "$dir/window.txt")
  put "$key.lambda_vz_D = $(lambda_D "$fj")  # granpen flow --steps $steps"
  # the same fit over each window of R below the face (granpen plot flow's panel (c)): how far
  # any part of the profile is from the paper's 0.98 D, whatever range a reading fits
  local pf; pf=$(mktemp -d)
  "$CLI" plot flow "$dir/flow" --out "$pf" > /dev/null
  put "$key.lambda_vz_local_D = $("$CLI" get "$pf/flow.json" numbers.profile.local.lambda_over_D_min numbers.profile.local.lambda_over_D_max numbers.profile.local.z_at_max numbers.profile.local.not_fitted |
    awk -F'\t' '{ printf "%.3g to %.3g (largest in the window centred %.2g cm below the face; windows not fitted: %d)\n", $1, $2, -$3, $4 }')  # granpen plot flow: lambda / D of the weighted exponential fit over each window of R of the profile below the face"
  rm -rf "$pf"
  put "$key.edge_phi_0 = $(jget "$fj" edge.fit.phi_0) +- $(jget "$fj" edge.fit.phi_0_se)  # phi = phi_0 + b I at the rod edge"
  put "$key.edge_slope = $(jget "$fj" edge.fit.slope) +- $(jget "$fj" edge.fit.slope_se)"
  put "$key.phi_below_far = $(awk -F, 'NR == 2 { printf "%.4g\n", $4 }' "$dir/flow/flow_profile_below.csv")  # phi on the axis below the rod, the bin farthest below the tip (about 4 cm)"
  put "$key.phi_below_face = $(awk -F, 'NR > 1 { p = $4 } END { printf "%.4g\n", p }' "$dir/flow/flow_profile_below.csv")  # ... the bin nearest the tip (the rod's face)"
  put "$key.surface_flux_sign_change_t = $(jget "$dir/surface/flow.json" surface.crossing_t_tilde)  # granpen flow: t~ where v_z of the strip's top grain layer (0.5-1.5 cm from the shaft) last turns from up to down"
  put "$key.drag_over_mu_g_Mmove = $(jget "$mj" drag.k) +- $(jget "$mj" drag.k_se)  # F = k mu g M(v_z > v0/320), granpen momentum"
  # the moving mass and its slow class (v0/320 to v0/80), mean over the frames with the tip
  # 1 to 4 cm deep: what the fixed threshold counts, which grows with the box
  local masses
  masses=$("$CLI" get "$mj" 'frames[*].z_tip' 'frames[*].M_move' 'frames[*].M_slow' | awk '$1 >= 1 - 1e-6 && $1 <= 4 + 1e-6')
  put "$key.M_move = $(printf '%s' "$masses" | awk '{ print $2 }' | stats)  # g, granpen momentum, frames with the tip 1 to 4 cm deep"
  put "$key.M_slow = $(printf '%s' "$masses" | awk '{ print $3 }' | stats)  # g, the same frames, v0/320 < v_z <= v0/80"
}

# the flow of one push (mid, 90 cm/s, g = 981, D = 2, seed 1) from its dumps
push=mid_mu0.3_s1_v90_g981_D2.0
if ls "$DUMPS/$push.csv".*.dump.gz > /dev/null 2>&1; then
  say "mid flow: validation/push_flow.sh on the dumps of $push"
  "$ROOT/validation/push_flow.sh" "$DUMPS/$push.csv" "$OUT/mid" --cli "$CLI" > /dev/null
  plot_flow "$OUT/mid"
  flow_numbers mid "$OUT/mid"
elif [ -f "$ROOT/docs/results/mid/window.txt" ]; then
  # without the dumps the rows come from the tables they gave, as committed
  say "mid flow: no dumps of $push in $DUMPS: the rows from the committed tables in docs/results/mid"
  flow_numbers mid "$ROOT/docs/results/mid"
else
  say "mid flow: no dumps of $push in $DUMPS and no committed tables, skipped"
fi
# ---------------------------------------------------------------- D/d_g = 10
# The committed units of validation/dg10.sh (docs/presets.md, "dg10"). Each part is analysed
# once every push of it is committed, so that its numbers do not move as pushes arrive.
# the value and the error (the number after +-) of KEY among the numbers so far; "" when
# absent or undefined
nval() { awk -v k="$1" '$1 == k && $3 != "undefined" { print $3; exit }' "$NUM"; }
nerr() { awk -v k="$1" '$1 == k && $4 == "+-" { print $5; exit }' "$NUM"; }
# KEY1 / KEY2 and its error, the relative errors in quadrature (a missing error counts 0), at
# full precision for the caller to round; "" when either value is missing
quad_ratio() { # KEY1 KEY2
  local a b; a=$(nval "$1") b=$(nval "$2")
  [ -n "$a" ] && [ -n "$b" ] || return 0
  awk -v a="$a" -v b="$b" -v ea="$(nerr "$1")" -v eb="$(nerr "$2")" \
    'BEGIN { ea += 0; eb += 0; r = a / b; printf "%.17g %.17g", r, r * sqrt((ea / a) ^ 2 + (eb / b) ^ 2) }'
}

dg10_beds() {
  local n; n=$(ls "$DG10"/beds/bed_dg10_mu0.3_s[123].info 2>/dev/null | wc -l)
  [ "$n" = 3 ] || { say "dg10 beds: $n of 3 committed: skipped"; return 0; }
  put "dg10.phi_0 = $(grep -h '^phi_0' "$DG10"/beds/bed_dg10_mu0.3_s[123].info | awk '{print $3}' | stats)  # bed .info files, mu = 0.3 (2 x 2 tiles)"
}

# The peak law of a set of short pushes (g = 981, D = 2): KEY OUTDIR SLOWEST TRACE... (SLOWEST:
# the v0 at v_c, left out of the "from 2 v_c" fit). --alpha: the paper's 35, for F/F_z,
# which these lines do not report; the peak (max F over z < 0.7 R) does not depend on it.
peak_law() {
  local key=$1 o=$2 slow=$3; shift 3
  mkdir -p "$o"
  "$CLI" collapse "$@" --alpha 35 --tbin 0.25 --json "$o/collapse_peak.json" > "$o/collapse_peak.txt"
  put "$key.peak_exponent = $(jget "$o/collapse_peak.json" peak_exponent) +- $(jget "$o/collapse_peak.json" peak_exponent_ci95) (95%)  # granpen collapse, $# traces, every v0"
  "$CLI" collapse "$@" --alpha 35 --tbin 0.25 --ensemble --ensemble-bin 0.02 --json "$o/collapse_peak_ensemble.json" > "$o/collapse_peak_ensemble.txt"
  put "$key.peak_exponent_ensemble = $(ensemble_peak "$o/collapse_peak_ensemble.json")  # granpen collapse --ensemble --ensemble-bin 0.02"
  put "$key.peak_exponent_local = $(local_peak_exponents "$o/collapse_peak.json")  # between successive v0, the beds' mean peaks"
  peak_above_vc "$key" "$o" "$slow" 35 "$@"
  "$CLI" plot force "$@" --out "$o/fig" > /dev/null
  "$CLI" plot peak "$@" --alpha 35 --out "$o/fig" > /dev/null
}

dg10_peak() {
  local d=$DG10/dg10_peak traces=() f
  for f in "$d"/dg10_mu0.3_s[123]_v*_g981_D2.0.csv; do [ -f "$f" ] && traces+=("$f"); done
  [ "${#traces[@]}" = 15 ] || { say "dg10 peak: ${#traces[@]} of 15 pushes committed in $d: skipped until all are"; return 0; }
  say "dg10: the peak law on 3 beds x 5 speeds (granpen collapse, plot)"
  peak_law dg10 "$OUT/dg10" 20 "${traces[@]}"
}

# a bench peak sweep with one contact parameter changed (validation/peak_sweep.sh NAME): its
# peak law, beside the bench sweep's own lines (the same seeds, speeds, g = 981 and D = 2)
variant_peak() { # KEY DIR WHAT
  local key=$1 d=$2 what=$3 traces=() f
  for f in "$d"/bench_mu0.3_s[12]_v*_g981_D2.0.csv; do [ -f "$f" ] && traces+=("$f"); done
  [ "${#traces[@]}" = 10 ] || { say "$what: ${#traces[@]} of 10 pushes in $d: skipped (validation/peak_sweep.sh)"; return 0; }
  say "bench, $what: the peak law (granpen collapse, plot)"
  put "$key.phi_0 = $(grep -h '^phi_0' "$d"/bed_*.info | awk '{print $3}' | stats)  # bed .info files, $what"
  peak_law "$key" "$OUT/$key" 28 "${traces[@]}"
  # each push's peak over its bench twin's (the same seed and v0), above v_c
  put "$key.peak_over_bench = $(peak_pairs "$OUT/$key/collapse_peak_fast.json" "$OUT/bench/collapse_peak_fast.json" | stats)  # granpen collapse: peak / the bench push's of the same seed and v0, above v0 = 28"
}
# "RATIO" per push of JSON1 whose file name is in JSON2 too: peak1 / peak2
peak_pairs() { # JSON1 JSON2
  awk 'FNR == NR { k = $1; sub(/.*\//, "", k); p[k] = $3; next }
       { k = $1; sub(/.*\//, "", k); if ((k in p) && p[k] > 0) print $3 / p[k] }' <(trace_peaks "$2") <(trace_peaks "$1")
}

# COLUMN (and COLUMN_se) of the one push of (V0, D) in a granpen fit CSV: "VALUE +- SE n = 1"
one_fit() { # CSV COLUMN V0 D
  awk -F, -v col="$2" -v v="$3" -v D="$4" 'NR == 1 { for (c = 1; c <= NF; c++) i[$c] = c; next }
    $i["v0"] + 0 == v + 0 && $i["D"] + 0 == D + 0 { n++; a = $i[col]; e = $i[col "_se"] }
    END { if (n == 1) printf "%.4g +- %.2g n = 1\n", a, e; else print "undefined n = " n + 0 }' "$1"
}
# alpha through the origin of the one push of (V0, D): one_alpha0 CSV V0 D
one_alpha0() { one_fit "$1" alpha0 "$2" "$3"; }

dg10_flow() {
  local d=$DG10/dg10_flow o=$OUT/dg10 v id missing=""
  for v in 40 100 200; do
    id=dg10_mu0.3_s1_v${v}_g981_D2.0
    [ -f "$d/$id.csv" ] && [ -f "$d/$id.flow/window.txt" ] || missing="$missing $v"
  done
  [ -z "$missing" ] || { say "dg10 flow: the full pushes at$missing cm/s (with their flow tables) not all in $d: skipped"; return 0; }
  mkdir -p "$o"
  say "dg10: the full pushes at 40, 100, 200 cm/s (granpen fit, collapse) and their flow"
  "$CLI" fit "$d"/dg10_mu0.3_s1_v*_g981_D2.0.csv --zmin 3 --csv "$o/fit_z3.csv" > "$o/fit_z3.txt"
  for v in 40 100 200; do
    put "dg10.alpha0_window.v$v.D2 = $(one_alpha0 "$o/fit_z3.csv" "$v" 2)  # granpen fit --zmin 3: k_z0 / (mu rho_g g D^2), bed 1; the fit's standard error"
  done
  put "dg10.alpha.v40.D2 = $(one_fit "$o/fit_z3.csv" alpha 40 2)  # the same at the slowest speed as a straight line with an intercept"
  "$CLI" fit "$d"/dg10_mu0.3_s1_v*_g981_D2.0.csv --tmin 1 --csv "$o/fit_deep.csv" > "$o/fit_deep.txt"
  deep_kz dg10 "$o/fit_deep.csv"
  for v in 40 100 200; do
    id=dg10_mu0.3_s1_v${v}_g981_D2.0
    flow_numbers "dg10.v$v" "$d/$id.flow"
    [ -d "$d/$id.flow/lambda_checks" ] && for c in "$d/$id.flow"/lambda_checks/*/flow.json; do
      put "dg10.v$v.lambda_vz_D.$(basename "$(dirname "$c")") = $(lambda_D "$c")  # granpen flow on the dumps, read another way (lambda_checks/README.md)"
    done
    plot_flow "$d/$id.flow" "$o/flow_v$v"
  done
}

dg10_D() {
  local d=$DG10/dg10_D o=$OUT/dg10 D traces=() missing=""
  for D in 1.0; do    # D = 3 cm: not run (inputs/sweeps/dg10_D.sweep)
    [ -f "$d/dg10_mu0.3_s1_v100_g981_D$D.csv" ] && traces+=("$d/dg10_mu0.3_s1_v100_g981_D$D.csv") || missing="$missing $D"
  done
  [ -f "$DG10/dg10_flow/dg10_mu0.3_s1_v100_g981_D2.0.csv" ] || missing="$missing 2.0"
  [ -z "$missing" ] || { say "dg10 D: the pushes of D =$missing cm at 100 cm/s not all committed: skipped"; return 0; }
  mkdir -p "$o"
  say "dg10: alpha against D at 100 cm/s (granpen fit)"
  "$CLI" fit "${traces[@]}" "$DG10/dg10_flow/dg10_mu0.3_s1_v100_g981_D2.0.csv" --zmin 3 --csv "$o/fit_D.csv" > "$o/fit_D.txt"
  for D in 1; do    # D = 2: dg10_flow's push at 100 cm/s, above
    put "dg10.alpha0_window.v100.D$D = $(one_alpha0 "$o/fit_D.csv" 100 "$D")  # granpen fit --zmin 3, bed 1, v0 = 100; the fit's standard error"
  done
  # the same ratio over 1 cm windows of the push: how it grows with depth
  local w a1 a2
  for w in 1:2 2:3 3:4 4:5; do
    "$CLI" fit "${traces[@]}" "$DG10/dg10_flow/dg10_mu0.3_s1_v100_g981_D2.0.csv" --zmin "${w%%:*}" --zmax "${w##*:}" \
      --csv "$o/fit_D_z$w.csv" > /dev/null
    a1=$(one_alpha0 "$o/fit_D_z$w.csv" 100 1 | awk '{print $1}') a2=$(one_alpha0 "$o/fit_D_z$w.csv" 100 2 | awk '{print $1}')
    put "dg10.alpha0_ratio_D1_D2.z${w/:/-} = $(awk -v a="$a1" -v b="$a2" 'BEGIN { printf "%.3g\n", a / b }')  # alpha through the origin, D = 1 over D = 2 cm, granpen fit --zmin ${w%%:*} --zmax ${w##*:}"
  done
}

# t~* and the collapse over the four full pushes (three speeds, two diameters), F_z from
# the slowest speed's alpha through the origin, as for bench and mid
dg10_collapse() {
  local a o=$OUT/dg10 traces
  a=$(nval dg10.alpha0_window.v40.D2)
  [ -n "$a" ] && [ -n "$(nval dg10.alpha0_window.v100.D1)" ] ||
    { say "dg10 collapse: waits for the flow and D parts: skipped"; return 0; }
  traces=("$DG10"/dg10_flow/dg10_mu0.3_s1_v*_g981_D2.0.csv "$DG10"/dg10_D/dg10_mu0.3_s1_v100_g981_D1.0.csv)
  say "dg10: the collapse of the four full pushes (granpen collapse, plot ratio)"
  "$CLI" collapse "${traces[@]}" --alpha "$a" --tbin 0.25 --json "$o/collapse_all.json" > "$o/collapse_all.txt"
  collapse_numbers dg10 "$o/collapse_all.json" "${#traces[@]}" "$a"
  "$CLI" plot ratio "${traces[@]}" --alpha "$a" --tbin 0.25 --out "$o/fig" > /dev/null
}

variant_peak bench_stiff "$STIFF" "k_n = k_t = 1e10 (ten times stiffer)"
variant_peak bench_damp "$DAMP" "gamma_n = gamma_t = 100 in the push (damping ten times weaker)"
if [ -d "$DG10" ]; then dg10_beds; dg10_peak; dg10_flow; dg10_D; dg10_collapse; else say "dg10: $DG10 missing, skipped"; fi

# ---------------------------------------------------------------- the box series
# The committed units of validation/box.sh bench (docs/presets.md, "The paper's box"): bench
# grains in boxes of 8 to 20 cm built from the same two tiles. Per box, once all its pushes
# are in: the peak law (key bench_boxB), the flow rows of its 50 cm/s push, and each peak over
# the push of the same bed and speed in the box 8 cm narrower (the first contact, which the
# box should not change: against the spread over the two beds). The rod stands at the box's
# centre: a tile corner in the 8 and 16 cm boxes (2 x 2, 4 x 4 tiles), a tile centre in the
# 12 and 20 cm ones, so only boxes 8 cm apart put the same grains under the rod.
box_bench() {
  local b d traces f n
  for b in 8 12 16 20; do
    d=$BOX/box_bench${b}_peak traces=()
    for f in "$d"/bench_mu0.3_s1[12]_v*_g981_D2.0.csv; do [ -f "$f" ] && traces+=("$f"); done
    if [ "${#traces[@]}" = 10 ]; then
      say "box $b cm: the peak law on 2 beds x 5 speeds"
      put "bench_box$b.phi_0 = $(grep -h '^phi_0' "$BOX/box_bench${b}_peak"/bed_*.info 2>/dev/null | awk '{print $3}' | stats)  # bed .info files, ${b} cm box of 4 cm tiles, 2 cm columns"
      peak_law "bench_box$b" "$OUT/box_bench$b" 28 "${traces[@]}"
      n=$((b - 8))
      [ "$n" -lt 8 ] || [ ! -f "$OUT/box_bench$n/collapse_peak.json" ] ||
        put "bench_box$b.peak_over_box$n = $(peak_pairs "$OUT/box_bench$b/collapse_peak.json" "$OUT/box_bench$n/collapse_peak.json" | stats)  # granpen collapse: peak / the $n cm box's push of the same bed and v0 (the same grains under the rod), every v0"
    else say "box $b cm: ${#traces[@]} of 10 peak pushes in $d: skipped until all are (validation/box.sh bench)"; fi
    f=$BOX/box_bench${b}_flow/bench_mu0.3_s11_v50_g981_D2.0
    if [ -f "$f.csv" ] && [ -f "$f.flow/window.txt" ]; then
      say "box $b cm: the flow of its 50 cm/s push"
      flow_numbers "bench_box$b.v50" "$f.flow"
    else say "box $b cm: its flow push (with tables) not in $BOX/box_bench${b}_flow: skipped"; fi
  done
  for b in 8 20; do box_alpha_D "box_bench${b}_D" "bench_box$b"; done
  for b in 8 20; do box_alpha_D "box_bench${b}_shaft" "bench_box${b}_shaft"; done
  box_wide_rod
  box_flow_D
}
# lambda_vz against D: the 20 cm box's 50 cm/s flow push (bed 11) with rods of 1, 2 and 4 cm
# (box_bench20_flow_D beside box_bench20_flow): lambda / D per rod, lambda in cm, and the
# slope of ln lambda on ln D (1: the decay follows D, as lambda / D constant says; 0: a length
# of its own)
box_flow_D() {
  local f D id lines=""
  for D in 1.0 4.0; do
    f=$BOX/box_bench20_flow_D/bench_mu0.3_s11_v50_g981_D$D
    [ -f "$f.csv" ] && [ -f "$f.flow/window.txt" ] ||
      { say "box_bench20_flow_D: the $D cm rod's flow push (with tables) not in $BOX/box_bench20_flow_D: skipped"; return 0; }
  done
  [ -n "$(nval bench_box20.v50.lambda_vz_D)" ] || { say "box_bench20_flow_D: waits for box_bench20_flow: skipped"; return 0; }
  say "box_bench20_flow_D: lambda_vz against D (granpen flow tables)"
  for D in 1.0 2.0 4.0; do
    id=bench_mu0.3_s11_v50_g981_D$D
    case $D in 2.0) f=$BOX/box_bench20_flow/$id ;; *) f=$BOX/box_bench20_flow_D/$id ;; esac
    [ "$D" = 2.0 ] || put "bench_box20.v50.D${D%.0}.lambda_vz_D = $(lambda_D "$f.flow/flow/flow.json")  # granpen flow, the tip $(awk '{print $2 " to " $3}' "$f.flow/window.txt") cm deep"
    put "bench_box20.v50.D${D%.0}.lambda_vz = $(jget "$f.flow/flow/flow.json" profile_below.lambda_vz.lambda) +- $(jget "$f.flow/flow/flow.json" profile_below.lambda_vz.lambda_se)  # cm, the same fit"
    lines="$lines${D%.0} $(jget "$f.flow/flow/flow.json" profile_below.lambda_vz.lambda)
"
  done
  put "bench_box20.v50.lambda_vz_D_exponent = $(printf '%s' "$lines" | log_slope)  # ln lambda on ln D, D = 1, 2, 4 cm: 1 if the decay follows D, 0 if it is a length of its own"
}
# the 4 cm rod in the 20 cm box (box_bench20_D4, the same beds and speed as box_bench20_D):
# alpha over z >= 2 cm as the others, and over z = 2 to 3 cm (the bed is 5.7 cm deep: at 4 cm
# the tip is 0.43 D above the floor), each over the 2 cm rod's in the same window; against
# the rim term's alpha(4) / alpha(2) = 3/2 - r/2 (alpha = A + B / D through D = 1 and 2 cm)
box_wide_rod() {
  local d=$BOX/box_bench20_D4 o=$OUT/box_bench20_D4 n q w
  n=$( (ls "$d"/bench_mu0.3_s1[12]_v28_g981_D4.0.csv 2>/dev/null || true) | wc -l)
  [ "$n" = 2 ] || { say "box_bench20_D4: $n of 2 pushes in $d: skipped until both are (validation/box.sh bench)"; return 0; }
  [ -n "$(nval bench_box20.alpha_D1_over_D2)" ] || { say "box_bench20_D4: waits for box_bench20_D: skipped"; return 0; }
  say "box_bench20_D4: the 4 cm rod's alpha (granpen fit --zmin 2)"
  mkdir -p "$o"
  "$CLI" fit "$d"/bench_mu0.3_s1[12]_v28_g981_D4.0.csv --zmin 2 --csv "$o/fit_z2.csv" > "$o/fit_z2.txt"
  put "bench_box20.alpha0_window.v28.D4 = $(col "$o/fit_z2.csv" alpha0 | stats)  # granpen fit --zmin 2: k_z0 / (mu rho_g g D^2), 2 beds"
  q=$(quad_ratio bench_box20.alpha0_window.v28.D4 bench_box20.alpha0_window.v28.D2)
  put "bench_box20.alpha_D4_over_D2 = $(printf '%.4g +- %.2g' $q)  # the beds' spreads in quadrature"
  q=$(quad_ratio bench_box20.alpha0_window.v28.D1 bench_box20.alpha0_window.v28.D2)
  put "bench_box20.alpha_D4_over_D2_rim = $(awk -v r="${q% *}" -v e="${q#* }" 'BEGIN { printf "%.4g +- %.2g", 3 / 2 - r / 2, e / 2 }')  # alpha = A + B / D through D = 1 and 2 cm: 3/2 - alpha_D1_over_D2 / 2"
  # away from the floor: both rods over z = 2 to 3 cm
  "$CLI" fit "$d"/bench_mu0.3_s1[12]_v28_g981_D4.0.csv --zmin 2 --zmax 3 --csv "$o/fit_z2to3.csv" > /dev/null
  "$CLI" fit "$BOX"/box_bench20_D/bench_mu0.3_s1[12]_v28_g981_D2.0.csv --zmin 2 --zmax 3 --csv "$o/fit_z2to3_D2.csv" > /dev/null
  for w in D4:fit_z2to3 D2:fit_z2to3_D2; do
    put "bench_box20.alpha0_z2to3.v28.${w%%:*} = $(col "$o/${w##*:}.csv" alpha0 | stats)  # granpen fit --zmin 2 --zmax 3, 2 beds"
  done
  q=$(quad_ratio bench_box20.alpha0_z2to3.v28.D4 bench_box20.alpha0_z2to3.v28.D2)
  put "bench_box20.alpha_D4_over_D2_z2to3 = $(printf '%.4g +- %.2g' $q)  # the two above, the beds' spreads in quadrature"
  # how F_z grows with D over the four rods: the slope of ln(alpha D^2) on ln D, every push
  # (4 diameters x 2 beds), with its standard error (the paper's F_z ~ D^2: 2); and without
  # the 1 cm rod
  # every push's fit, D = 1 to 4 cm: box_bench20_D's table and the 4 cm rods' rows
  local fits; fits=$(cat "$OUT/box_bench20_D/fit_z2.csv" <(tail -n +2 "$o/fit_z2.csv"))
  d_exponent() { printf '%s\n' "$fits" | awk -F, -v min="$1" '
      NR == 1 { for (c = 1; c <= NF; c++) i[$c] = c; next } $i["D"] >= min { print $i["D"], $i["alpha0"] * $i["D"] ^ 2 }' | log_slope; }
  put "bench_box20.depth_term_D_exponent = $(d_exponent 1)  # granpen fit --zmin 2: ln(alpha0 D^2) on ln D, D = 1 to 4 cm, 2 beds"
  put "bench_box20.depth_term_D_exponent_D2to4 = $(d_exponent 2)  # the same without the 1 cm rod"
  # the rim term's length B / A of alpha = A + B / D: through the 1 and 2 cm rods' means
  # (2 (r - 1) / (2 - r)), and by least squares of alpha on 1 / D over the 2 to 4 cm pushes
  put "bench_box20.rim_B_over_A_D1to2 = $(awk -v r="$(nval bench_box20.alpha_D1_over_D2)" 'BEGIN { printf "%.3g", 2 * (r - 1) / (2 - r) }')  # cm, alpha = A + B / D through the 1 and 2 cm rods"
  put "bench_box20.rim_B_over_A_D2to4 = $(printf '%s\n' "$fits" | awk -F, '
      NR == 1 { for (c = 1; c <= NF; c++) i[$c] = c; next } $i["D"] >= 2 { print $i["D"], $i["alpha0"] }' | rim_length)  # cm, least squares of alpha on 1 / D, the 2 to 4 cm pushes"
  return 0
}
# alpha against D in one box (DIR under $BOX, its 2 beds x 3 or 2 diameters at 28 cm/s): the
# depth term through the origin over z >= 2 cm (the bench row's window) per D, mean over the
# beds, and alpha(1 cm) / alpha(2 cm) with the errors in quadrature
box_alpha_D() { # SWEEP KEY
  local d=$BOX/$1 key=$2 o=$OUT/$1 n want D a1 a2
  n=$( (ls "$d"/bench_mu0.3_s1[12]_v28_g981_D*.csv 2>/dev/null || true) | wc -l)
  case $1 in *shaft) want=4 ;; *) want=6 ;; esac
  [ "$n" = "$want" ] || { say "$1: $n of $want pushes in $d: skipped until all are (validation/box.sh bench)"; return 0; }
  say "$1: alpha against D (granpen fit --zmin 2)"
  mkdir -p "$o"
  "$CLI" fit "$d" --zmin 2 --csv "$o/fit_z2.csv" > "$o/fit_z2.txt"
  for D in $(col "$o/fit_z2.csv" D | sort -gu); do
    put "$key.alpha0_window.v28.D$D = $(col "$o/fit_z2.csv" alpha0 D "$D" | stats)  # granpen fit --zmin 2: k_z0 / (mu rho_g g D^2), 2 beds"
    put "$key.alpha_a.v28.D$D = $(col "$o/fit_z2.csv" alpha_a D "$D" | stats)  # granpen fit --zmin 2, F = a z + b z^2: a / (mu rho_g g D^2), 2 beds"
    put "$key.beta_b.v28.D$D = $(col "$o/fit_z2.csv" beta_b D "$D" | stats)  # ... b / (mu rho_g g D): the shaft-like term"
  done
  local q; q=$(quad_ratio "$key.alpha0_window.v28.D1" "$key.alpha0_window.v28.D2")
  [ -n "$q" ] && put "$key.alpha_D1_over_D2 = $(printf '%.4g +- %.2g' $q)  # the two above, the beds' spreads in quadrature"
  # a term at the tip's rim, F = mu rho_g g z (A D^2 + B D), i.e. alpha = A + B / D:
  # through the 1 and 2 cm rods it puts the 3 cm rod at alpha(3) / alpha(2) = 4/3 - r/3
  # (r = alpha(1) / alpha(2), its error over 3), against the measured ratio
  [ -n "$q" ] && [ -n "$(nval "$key.alpha0_window.v28.D3")" ] || return 0
  put "$key.alpha_D3_over_D2 = $(printf '%.4g +- %.2g' $(quad_ratio "$key.alpha0_window.v28.D3" "$key.alpha0_window.v28.D2"))  # the beds' spreads in quadrature"
  put "$key.alpha_D3_over_D2_rim = $(awk -v r="${q% *}" -v e="${q#* }" 'BEGIN { printf "%.4g +- %.2g", 4 / 3 - r / 3, e / 3 }')  # alpha = A + B / D through D = 1 and 2 cm: 4/3 - alpha_D1_over_D2 / 3"
  return 0
}
if [ -d "$BOX" ]; then box_bench; else say "box series: $BOX missing, skipped"; fi

# The committed units of validation/box.sh dg10 (docs/presets.md, "The paper's box"): dg10
# grains (D/d_g = 10) in the paper's 20 cm box, 4 x 4 copies of the 10 cm box's three tiles
# (scale name dg10_box20). Each part once all its pushes are in, else skipped with a note:
# the peak law as dg10's, and each peak over the 10 cm box's push of the same bed and speed
# (the rod stands on a tile corner in both boxes, so over the same grains: the first contact,
# which the box should not change); the flow rows of the 40 cm/s push read as the 10 cm one's;
# alpha against D over z >= 3 cm as the 10 cm box's, with F = a z + b z^2 per diameter, with
# the shaft's friction and without.
dg10_box20() {
  local d=$DG10BOX/dg10_box20_peak o=$OUT/dg10_box20 traces=() f id
  for f in "$d"/dg10_mu0.3_s[123]_v*_g981_D2.0.csv; do [ -f "$f" ] && traces+=("$f"); done
  if [ "${#traces[@]}" = 15 ]; then
    say "dg10, 20 cm box: the peak law on 3 beds x 5 speeds"
    put "dg10_box20.phi_0 = $(grep -h '^phi_0' "$d"/bed_dg10_mu0.3_s[123].info 2>/dev/null | awk '{print $3}' | stats)  # bed .info files, 20 cm box of 5 cm tiles, 2.5 cm columns"
    peak_law dg10_box20 "$o" 20 "${traces[@]}"
    [ ! -f "$OUT/dg10/collapse_peak.json" ] ||
      put "dg10_box20.peak_over_box10 = $(peak_pairs "$o/collapse_peak.json" "$OUT/dg10/collapse_peak.json" | stats)  # granpen collapse: peak / the 10 cm box's push of the same bed and v0 (the same grains under the rod), every v0"
  else say "dg10, 20 cm box: ${#traces[@]} of 15 peak pushes in $d: skipped until all are (validation/box.sh dg10)"; fi
  # before the slow pushes (3.6 and 7.3 core-hours each, longer than a session: docs/presets.md)
  # the peak law of 80, 140 and 200 cm/s on three beds, in both boxes on the same traces' twins
  local fast=() ten=()
  for f in "$d"/dg10_mu0.3_s[123]_v{80,140,200}_g981_D2.0.csv; do [ -f "$f" ] && fast+=("$f"); done
  if [ "${#fast[@]}" = 9 ]; then
    say "dg10, 20 and 10 cm box: the peak law of 80, 140 and 200 cm/s on 3 beds"
    for f in "${fast[@]}"; do ten+=("$DG10/dg10_peak/${f##*/}"); done
    peak_law dg10_box20_v80to200 "$o/v80to200" 20 "${fast[@]}"
    peak_law dg10_v80to200 "$OUT/dg10/v80to200" 20 "${ten[@]}"
  else say "dg10, 20 cm box: ${#fast[@]} of 9 peak pushes at 80 to 200 cm/s in $d: their peak law skipped until all are"; fi
  # every speed above v_c (40 to 200 cm/s) on three beds: the traces of the 10 cm box's row
  # "above v_c" (dg10.*_from_2vc), in both boxes, before the 20 cm/s pushes of beds 2 and 3
  # (the campaign's last part, 7.3 core-hours each); with each peak over its 10 cm twin's
  local above=() ten_above=()
  for f in "$d"/dg10_mu0.3_s[123]_v{40,80,140,200}_g981_D2.0.csv; do [ -f "$f" ] && above+=("$f"); done
  if [ "${#above[@]}" = 12 ]; then
    say "dg10, 20 and 10 cm box: the peak law above v_c, 40 to 200 cm/s on 3 beds"
    for f in "${above[@]}"; do ten_above+=("$DG10/dg10_peak/${f##*/}"); done
    peak_law dg10_box20_v40to200 "$o/v40to200" 20 "${above[@]}"
    peak_law dg10_v40to200 "$OUT/dg10/v40to200" 20 "${ten_above[@]}"
    put "dg10_box20_v40to200.peak_over_box10 = $(peak_pairs "$o/v40to200/collapse_peak.json" "$OUT/dg10/v40to200/collapse_peak.json" | stats)  # granpen collapse: peak / the 10 cm box's push of the same bed and v0, 40 to 200 cm/s"
  else say "dg10, 20 cm box: ${#above[@]} of 12 peak pushes at 40 to 200 cm/s in $d: their peak law skipped until all are"; fi
  dg10_box20_slow "$d" "$o/slow"
  id=dg10_mu0.3_s1_v40_g981_D2.0 d=$DG10BOX/dg10_box20_flow
  if [ -f "$d/$id.csv" ] && [ -f "$d/$id.flow/window.txt" ]; then
    say "dg10, 20 cm box: the flow of its 40 cm/s push"
    flow_numbers dg10_box20.v40 "$d/$id.flow"
    plot_flow "$d/$id.flow" "$o/flow_v40"
  else say "dg10, 20 cm box: its 40 cm/s flow push (with tables) not in $d: skipped"; fi
  dg10_box20_D_twins
  dg10_box20_alpha_D dg10_box20_D dg10_box20 "1.0 2.0 3.0"
  dg10_box20_alpha_D dg10_box20_shaft dg10_box20_shaft "1.0 2.0"
}
# The slow end of the 20 cm box's peak sweep, push by push as each is committed (the whole
# law waits for all 15): at 40 and 20 cm/s the peak may come after the boxes part (at 20 cm/s
# the 10 cm push's largest force below 0.7 R comes some 29 ms after contact, the parting at 80
# to 200 cm/s 4 to 5 ms), so each 20 cm push's peak is read over its 10 cm twin's (the same
# bed's grains under the rod), beside how far the 10 cm box's own three beds spread at that
# speed: a box effect is a ratio outside that spread.
dg10_box20_slow() { # PEAK_DIR OUT
  local d=$1 o=$2 v s f wide=() t m
  mkdir -p "$o"
  for v in 40 20; do
    wide=() t="" m=""
    for s in 1 2 3; do
      f=dg10_mu0.3_s${s}_v${v}_g981_D2.0.csv
      [ -f "$d/$f" ] || continue
      wide+=("$d/$f")
      t="$t $(parting_ms "$DG10/dg10_peak/$f" "$d/$f" "$o/parting_s${s}_v$v.json")"
      m="$m $(awk -v a="$(mean_drag_below "$d/$f" 0.7)" -v b="$(mean_drag_below "$DG10/dg10_peak/$f" 0.7)" 'BEGIN { print a / b }')"
    done
    [ "${#wide[@]}" -gt 0 ] || { say "dg10, 20 cm box: no push at $v cm/s committed in $d: its slow-end lines skipped"; continue; }
    say "dg10, 20 cm box: the peak at $v cm/s on ${#wide[@]} bed(s) over the 10 cm box's"
    "$CLI" collapse "${wide[@]}" --alpha 35 --tbin 0.25 --json "$o/collapse_v$v.json" > /dev/null
    "$CLI" collapse "$DG10/dg10_peak"/dg10_mu0.3_s[123]_v${v}_g981_D2.0.csv --alpha 35 --tbin 0.25 --json "$o/collapse_box10_v$v.json" > /dev/null
    put "dg10_box20.peak_over_box10.v$v = $(peak_pairs "$o/collapse_v$v.json" "$o/collapse_box10_v$v.json" | stats)  # granpen collapse: the 20 cm push's peak (largest force below 0.7 R) / the 10 cm push's of the same bed, the beds committed so far"
    put "dg10.peak_over_bed_mean.v$v = $(trace_peaks "$o/collapse_box10_v$v.json" | awk '{ print $3 }' | over_mean | stats)  # the 10 cm box's three beds' peaks over their mean at this speed: the spread a box effect must leave"
    put "dg10_box20.mean_below_07R_over_box10.v$v = $(echo $m | tr ' ' '\n' | stats)  # the mean drag over 0 < z <= 0.7 cm (0.7 R, the peak's window), the 20 cm push over its 10 cm twin: the box in the force itself, not in its largest sample"
    put "dg10.mean_below_07R_over_bed_mean.v$v = $(for s in 1 2 3; do mean_drag_below "$DG10/dg10_peak/dg10_mu0.3_s${s}_v${v}_g981_D2.0.csv" 0.7; done | over_mean | stats)  # ... the 10 cm box's three beds' means over their mean: the spread a box effect must leave"
    put "dg10_box10_20.t_part_ms.v$v = $(echo $t | tr ' ' '\n' | grep -v none | stats)  # granpen parting: when the 10 cm box's push parts from the 20 cm box's on the same grains, ms after contact, the beds committed so far"
  done
}

# Each diameter's 100 cm/s push in the 20 cm box over its 10 cm twin (bed 1: the same grains
# under the rod), push by push as each is committed, before the D part is whole: alpha through
# the origin over z >= 3 cm and over 1 cm windows of depth, each 20 cm over 10 cm with the fits'
# errors in quadrature, and when the two pushes part. The 10 cm twins: dg10_D's 1 cm push and
# dg10_flow's 2 cm push at 100 cm/s. alpha(1 cm) / alpha(2 cm) is "the box" only if a wider box
# moves the two diameters' alpha apart; these lines say how far each moves.
dg10_box20_D_twins() {
  local d=$DG10BOX/dg10_box20_D o=$OUT/dg10_box20_D/box10 D f ten w r
  for D in 1 2; do
    f=dg10_mu0.3_s1_v100_g981_D$D.0.csv
    if [ "$D" = 1 ]; then ten=$DG10/dg10_D/$f; else ten=$DG10/dg10_flow/$f; fi
    [ -f "$d/$f" ] || { say "dg10, 20 cm box: its $D cm push at 100 cm/s not in $d: its lines over the 10 cm twin skipped"; continue; }
    [ -f "$ten" ] || { say "dg10, 20 cm box: the $D cm push's 10 cm twin $ten missing: skipped"; continue; }
    mkdir -p "$o"
    say "dg10, 20 cm box: the $D cm push at 100 cm/s over its 10 cm twin (granpen fit, parting)"
    for w in 3:5 1:2 2:3 3:4 4:5; do
      "$CLI" fit "$d/$f" --zmin "${w%%:*}" --zmax "${w##*:}" --csv "$o/fit_D${D}_z${w/:/-}_box20.csv" > /dev/null
      "$CLI" fit "$ten" --zmin "${w%%:*}" --zmax "${w##*:}" --csv "$o/fit_D${D}_z${w/:/-}_box10.csv" > /dev/null
      r=$(paste <(one_alpha0 "$o/fit_D${D}_z${w/:/-}_box20.csv" 100 "$D") <(one_alpha0 "$o/fit_D${D}_z${w/:/-}_box10.csv" 100 "$D") |
        awk '$1 + 0 > 0 && $7 + 0 > 0 { r = $1 / $7; printf "%.4g +- %.2g (%.4g over %.4g)", r, r * sqrt(($3 / $1) ^ 2 + ($9 / $7) ^ 2), $1, $7 }')
      put "dg10_box20.alpha0_over_box10.v100.D$D.z${w/:/-} = ${r:-undefined}  # granpen fit --zmin ${w%%:*} --zmax ${w##*:}, bed 1: alpha through the origin, the 20 cm push over its 10 cm twin (the fits' errors in quadrature)"
    done
    put "dg10_box10_20.t_part_ms.v100.D$D = $(parting_ms "$ten" "$d/$f" "$o/dg10_10_20_D${D}_v100.json")  # granpen parting: ms after contact when the $D cm push in the 10 cm box parts from its 20 cm twin (the 10 cm box's 50 ms push)"
    "$CLI" plot parting "$o/dg10_10_20_D${D}_v100.json" --out "$o/fig_parting_D$D" > /dev/null
  done
  return 0
}

# alpha against D in the 20 cm box (DIR under $DG10BOX: bed 1, 100 cm/s, the diameters given),
# over z >= 3 cm as dg10_D: alpha through the origin, the two terms of F = a z + b z^2, and
# alpha(1 cm) / alpha(2 cm) with the fits' errors in quadrature. Push by push, as each is
# committed (a 20 cm push is 2 to 3 hours here): each diameter's lines once its push is in, the
# ratio once the 1 and 2 cm pushes are (the row "alpha against D" is that ratio; the 3 cm push
# adds its own point)
dg10_box20_alpha_D() { # SWEEP KEY "D..."
  local d=$DG10BOX/$1 key=$2 o=$OUT/$1 D traces=() here="" missing=""
  for D in $3; do
    if [ -f "$d/dg10_mu0.3_s1_v100_g981_D$D.csv" ]; then traces+=("$d/dg10_mu0.3_s1_v100_g981_D$D.csv") here="$here $D"
    else missing="$missing $D"; fi
  done
  [ -z "$missing" ] || say "$1: the pushes of D =$missing cm at 100 cm/s not in $d: their lines wait for them (validation/box.sh dg10)"
  [ "${#traces[@]}" -gt 0 ] || return 0
  say "$1: alpha against D (granpen fit --zmin 3), D =$here cm"
  mkdir -p "$o"
  "$CLI" fit "${traces[@]}" --zmin 3 --csv "$o/fit_z3.csv" > "$o/fit_z3.txt"
  for D in $here; do
    put "$key.alpha0_window.v100.D${D%.0} = $(one_alpha0 "$o/fit_z3.csv" 100 "$D")  # granpen fit --zmin 3: k_z0 / (mu rho_g g D^2), bed 1; the fit's standard error"
    put "$key.alpha_a.v100.D${D%.0} = $(one_fit "$o/fit_z3.csv" alpha_a 100 "$D")  # granpen fit --zmin 3, F = a z + b z^2: a / (mu rho_g g D^2)"
    put "$key.beta_b.v100.D${D%.0} = $(one_fit "$o/fit_z3.csv" beta_b 100 "$D")  # ... b / (mu rho_g g D): the shaft-like term"
  done
  local q; q=$(quad_ratio "$key.alpha0_window.v100.D1" "$key.alpha0_window.v100.D2")
  [ -n "$q" ] && put "$key.alpha_D1_over_D2 = $(printf '%.4g +- %.2g' $q)  # the two above, the fits' errors in quadrature"
  # the 3 cm rod against the rim term, alpha = A + B / D through the 1 and 2 cm rods, which
  # puts it at alpha(3) / alpha(2) = 4/3 - r/3 (r = alpha(1) / alpha(2), its error over 3);
  # F_z ~ D^2 puts it at 1
  [ -n "$q" ] && [ -n "$(nval "$key.alpha0_window.v100.D3")" ] || return 0
  put "$key.alpha_D3_over_D2 = $(printf '%.4g +- %.2g' $(quad_ratio "$key.alpha0_window.v100.D3" "$key.alpha0_window.v100.D2"))  # the fits' errors in quadrature"
  put "$key.alpha_D3_over_D2_rim = $(awk -v r="${q% *}" -v e="${q#* }" 'BEGIN { printf "%.4g +- %.2g", 4 / 3 - r / 3, e / 3 }')  # alpha = A + B / D through D = 1 and 2 cm: 4/3 - alpha_D1_over_D2 / 3"
  # how F_z grows with D over the three rods: the slope of ln(alpha D^2) on ln D (the paper's
  # F_z ~ D^2: 2; its error on one degree of freedom), the exponent from 2 to 3 cm alone, and
  # the rim term's length B / A by least squares of alpha on 1 / D over the three rods
  local a1 a2 a3; a1=$(nval "$key.alpha0_window.v100.D1") a2=$(nval "$key.alpha0_window.v100.D2") a3=$(nval "$key.alpha0_window.v100.D3")
  put "$key.depth_term_D_exponent = $(printf '1 %s\n2 %s\n3 %s\n' "$a1" "$(awk -v a="$a2" 'BEGIN { print 4 * a }')" "$(awk -v a="$a3" 'BEGIN { print 9 * a }')" | log_slope)  # ln(alpha0 D^2) on ln D, D = 1, 2, 3 cm (one push each, z >= 3 cm)"
  put "$key.depth_term_D_exponent_D2to3 = $(awk -v a="$a2" -v b="$a3" 'BEGIN { printf "%.3g", log(9 * b / (4 * a)) / log(3 / 2) }')  # ln(F(3 cm) / F(2 cm)) / ln(3/2) at the same z"
  put "$key.rim_B_over_A_D1to3 = $(printf '1 %s\n2 %s\n3 %s\n' "$a1" "$a2" "$a3" | rim_length)  # cm, least squares of alpha on 1 / D, D = 1, 2, 3 cm"
  return 0
}
if [ -d "$DG10BOX" ]; then dg10_box20; else say "dg10, 20 cm box: $DG10BOX missing, skipped"; fi

# When the boxes part (docs/results.md, "When the boxes part"): two pushes over the same
# grains in boxes of width L and a wider one give the same drag until something comes back
# from the narrower box's cell boundary, L / 2 from the axis. granpen parting: the first of
# two 0.5 ms windows in a row, after each push's contact, where the mean drag of the two
# differs by 3% or more on one side. An echo (a wave there and back, L at speed c) parts them
# at t = L / c, a time: t_part scales with L and changes little with v0. A flow front at a
# fixed depth would part them at z / v0: t_part ~ v0^-1. Pairs: 8 / 16 and 12 / 20 cm (the
# only bench boxes with the same grains under the rod) above v_c, 2 beds; dg10 10 / 20 cm at
# 80 to 200 cm/s, 3 beds, once those nine pushes are in.
box_parting() {
  local o=$OUT/box_parting pair n w v s t a b pts ratios
  mkdir -p "$o"
  for pair in 8:16 12:20; do
    n=${pair%%:*} w=${pair##*:} pts=""
    for v in 50 100 200 280; do
      t=""
      for s in 11 12; do
        a=$BOX/box_bench${n}_peak/bench_mu0.3_s${s}_v${v}_g981_D2.0.csv b=$BOX/box_bench${w}_peak/bench_mu0.3_s${s}_v${v}_g981_D2.0.csv
        [ -f "$a" ] && [ -f "$b" ] || { say "box parting: $a or $b missing: skipped"; return 0; }
        t="$t $(parting_ms "$a" "$b" "$o/bench_${n}_${w}_s${s}_v${v}.json")"
        pts="$pts $v ${t##* }"
      done
      put "bench_box${n}_${w}.t_part_ms.v$v = $(echo $t | tr ' ' '\n' | grep -v none | stats)  # granpen parting (0.5 ms windows, 3%, two in a row): ms after contact when the $n cm box's push parts from the $w cm box's on the same grains, 2 beds"
    done
    put "bench_box${n}_${w}.parting_speed_exponent = $(echo $pts | xargs -n 2 | grep -v none | log_slope)  # ln t_part against ln v0, 50 to 280 cm/s, 2 beds: a wave of fixed speed 0, one faster the harder the push below 0, a flow front at a fixed depth -1"
  done
  for pair in 8_16 12_20; do
    "$CLI" plot parting "$o"/bench_${pair}_s1{1,2}_v{50,100,200,280}.json --out "$o/fig_$pair" > /dev/null
  done
  # each bed and speed's two partings, read once: their ratio here, their difference below
  local -A t8 t12
  ratios=""
  for v in 50 100 200 280; do for s in 11 12; do
    t8[$s.$v]=$(jget "$o/bench_8_16_s${s}_v${v}.json" t_part_ms) t12[$s.$v]=$(jget "$o/bench_12_20_s${s}_v${v}.json" t_part_ms)
    ratios="$ratios $(awk -v a="${t12[$s.$v]}" -v b="${t8[$s.$v]}" 'BEGIN { print a / b }')"
  done; done
  put "bench_box.parting_width_ratio = $(echo $ratios | tr ' ' '\n' | stats)  # t_part(12 / 20 cm) / t_part(8 / 16 cm), same bed and v0, 50 to 280 cm/s: an echo from the narrower box's boundary gives 12 / 8 = 1.5"
  # the speed of the echo from the parting: the 12 cm box's boundary lies 2 cm further out
  # than the 8 cm box's, 4 cm more there and back, so (12 - 8 cm) / (t_part(12 / 20) -
  # t_part(8 / 16)) per bed; beside it the front's speed by its arrival at rings of grains
  # in the 16 cm box (granpen arrival, box_bench16_arrival: another route, stock computes)
  local arr=$BOX/box_bench16_arrival sp c
  for v in 50 100 200 280; do
    sp=""
    for s in 11 12; do
      sp="$sp $(awk -v a="${t12[$s.$v]}" -v b="${t8[$s.$v]}" 'BEGIN { if (a > b) print 40 / (a - b) }')"
    done
    put "bench_box.parting_speed_m_s.v$v = $(echo $sp | tr ' ' '\n' | stats)  # 4 cm / (t_part(12 / 20 cm) - t_part(8 / 16 cm)), 2 beds (a pair that does not part later in the wider box left out)"
    c=""
    for s in 11 12; do
      f=$arr/bench_mu0.3_s${s}_v${v}_g981_D2.0.csv
      [ -f "$f" ] && [ -f "$f.arrival.txt" ] || continue
      "$CLI" arrival "$f" --json "$o/arrival_s${s}_v${v}.json" > /dev/null
      [ "$(jget "$o/arrival_s${s}_v${v}.json" fitted)" = true ] && c="$c $(jget "$o/arrival_s${s}_v${v}.json" speed_m_s)"
    done
    [ -z "$c" ] || put "bench_box16.arrival_speed_m_s.v$v = $(echo $c | tr ' ' '\n' | stats)  # granpen arrival (rings at 1.5, 2.5, 3.5 cm, the top 1.5 cm, the kinetic energy 100 x its background), 16 cm box, 2 beds"
    # the earliest an echo could be back: twice the first front's arrival (10 x the background)
    # at the 8 and 12 cm boxes' boundaries, 4 and 6 cm out (box_bench16_arrival_far)
    local e4="" e6="" j
    for s in 11 12; do
      f=$BOX/box_bench16_arrival_far/bench_mu0.3_s${s}_v${v}_g981_D2.0.csv j=$o/arrival_far_s${s}_v${v}.json
      [ -f "$f" ] && [ -f "$f.arrival.txt" ] || continue
      "$CLI" arrival "$f" --factor 10 --json "$j" > /dev/null
      [ "$(jget "$j" 'rings[1].arrived')" = true ] && e4="$e4 $(awk -v t="$(jget "$j" 'rings[1].t_after_ms')" 'BEGIN { print 2 * t }')"
      [ "$(jget "$j" 'rings[2].arrived')" = true ] && e6="$e6 $(awk -v t="$(jget "$j" 'rings[2].t_after_ms')" 'BEGIN { print 2 * t }')"
    done
    [ -z "$e4" ] || put "bench_box16.echo_ms.L8.v$v = $(echo $e4 | tr ' ' '\n' | stats)  # granpen arrival --factor 10: twice the first front's arrival 4 cm out (the 8 cm box's boundary), ms after contact, 2 beds"
    [ -z "$e6" ] || put "bench_box16.echo_ms.L12.v$v = $(echo $e6 | tr ' ' '\n' | stats)  # ... 6 cm out (the 12 cm box's boundary)"
  done
  local d=$DG10BOX/dg10_box20_peak
  for v in 80 140 200; do for s in 1 2 3; do
    [ -f "$d/dg10_mu0.3_s${s}_v${v}_g981_D2.0.csv" ] || { say "box parting: the dg10 20 cm push of bed $s at $v cm/s not in $d: dg10 skipped"; return 0; }
  done; done
  pts=""
  for v in 80 140 200; do
    t=""
    for s in 1 2 3; do
      t="$t $(parting_ms "$DG10/dg10_peak/dg10_mu0.3_s${s}_v${v}_g981_D2.0.csv" "$d/dg10_mu0.3_s${s}_v${v}_g981_D2.0.csv" "$o/dg10_10_20_s${s}_v${v}.json")"
      pts="$pts $v ${t##* }"
    done
    put "dg10_box10_20.t_part_ms.v$v = $(echo $t | tr ' ' '\n' | grep -v none | stats)  # granpen parting as above: when the 10 cm box's dg10 push parts from the 20 cm box's on the same grains, 3 beds"
  done
  put "dg10_box10_20.parting_speed_exponent = $(echo $pts | xargs -n 2 | grep -v none | log_slope)  # ln t_part against ln v0, 80 to 200 cm/s, 3 beds"
  "$CLI" plot parting "$o"/dg10_10_20_s{1,2,3}_v{80,140,200}.json --out "$o/fig_dg10_10_20" > /dev/null
}
if [ -d "$BOX" ] && [ -d "$DG10BOX" ]; then box_parting; else say "box parting: $BOX or $DG10BOX missing, skipped"; fi

# alpha against D over the same depth in D (docs/results.md, "... nor the depth over D"): a
# window z >= 2 cm is 2 D deep for the 1 cm rod and 1 D for the 2 cm rod, so a depth term that
# grows with z / D would favour the thin rod. Here each rod is fitted over z = D to 2 D
# (granpen fit --zmin D --zmax 2D, alpha through the origin): the 1 cm rod over 1 to 2 cm, the
# 2 cm rod over 2 to 4 cm. Where the excess is the depth over D, the ratio falls to 1.
# Per setting: alpha per D (mean +- sd over beds, or the fit's error for one bed) and the
# ratio with the errors in quadrature. KEY OUTDIR TRACE... (traces of D = 1 and 2 cm only)
alpha_same_depth_in_D() {
  local key=$1 o=$2 f D one=() two=(); shift 2
  for f in "$@"; do [ -f "$f" ] || { say "$key: ${f#$ROOT/} not there: same depth in D skipped"; return 0; }; done
  for f in "$@"; do case ${f##*_D} in 1.0.csv) one+=("$f") ;; 2.0.csv) two+=("$f") ;; esac; done
  [ "${#one[@]}" -gt 0 ] && [ "${#two[@]}" = "${#one[@]}" ] || { say "$key: same depth in D needs as many 1 as 2 cm pushes: skipped"; return 0; }
  mkdir -p "$o"
  "$CLI" fit "${one[@]}" --zmin 1 --zmax 2 --csv "$o/fit_zD1to2_D1.csv" > /dev/null
  "$CLI" fit "${two[@]}" --zmin 2 --zmax 4 --csv "$o/fit_zD1to2_D2.csv" > /dev/null
  for D in 1 2; do
    if [ "${#one[@]}" = 1 ]; then
      put "$key.alpha0_zD1to2.D$D = $(one_alpha0 "$o/fit_zD1to2_D$D.csv" "$(col "$o/fit_zD1to2_D$D.csv" v0)" "$D")  # granpen fit --zmin $D --zmax $((2 * D)): z from D to 2 D, alpha through the origin; the fit's error"
    else
      put "$key.alpha0_zD1to2.D$D = $(col "$o/fit_zD1to2_D$D.csv" alpha0 | stats)  # granpen fit --zmin $D --zmax $((2 * D)): z from D to 2 D, alpha through the origin; sd over the beds"
    fi
  done
  local q; q=$(quad_ratio "$key.alpha0_zD1to2.D1" "$key.alpha0_zD1to2.D2")
  [ -n "$q" ] && put "$key.alpha_D1_over_D2_zD1to2 = $(printf '%.4g +- %.2g' $q)  # the two above, errors in quadrature: the thin rod's excess at the same depth in D"
  return 0
}
same_depth_in_D() {
  say "alpha against D over the same depth in D (z = D to 2 D)"
  alpha_same_depth_in_D bench "$OUT/bench/same_depth_in_D" "$BENCH"/bench_mu0.3_s[12]_v28_g981_D[12].0.csv
  alpha_same_depth_in_D mid "$OUT/mid/same_depth_in_D" "$MID"/mid_mu0.3_s[12]_v90_g981_D[12].0.csv
  alpha_same_depth_in_D dg10 "$OUT/dg10/same_depth_in_D" "$DG10/dg10_D/dg10_mu0.3_s1_v100_g981_D1.0.csv" "$DG10/dg10_flow/dg10_mu0.3_s1_v100_g981_D2.0.csv"
  local b
  for b in 8 20; do
    alpha_same_depth_in_D "bench_box$b" "$OUT/box_bench${b}_D/same_depth_in_D" "$BOX/box_bench${b}_D"/bench_mu0.3_s1[12]_v28_g981_D[12].0.csv
    alpha_same_depth_in_D "bench_box${b}_shaft" "$OUT/box_bench${b}_shaft/same_depth_in_D" "$BOX/box_bench${b}_shaft"/bench_mu0.3_s1[12]_v28_g981_D[12].0.csv
  done
  # the 20 cm dg10 box once its 1 and 2 cm pushes are committed, as dg10_box20_alpha_D
  alpha_same_depth_in_D dg10_box20 "$OUT/dg10_box20_D/same_depth_in_D" "$DG10BOX/dg10_box20_D"/dg10_mu0.3_s1_v100_g981_D{1,2}.0.csv
}
same_depth_in_D

# ---------------------------------------------------------------- against D/d_g
# The rows that differ from the paper, at D/d_g = 5 (bench), 6.67 (mid) and 10 (dg10; empty
# until measured): scaling.csv, drawn by granpen plot scaling. Errors: the peak exponent's
# 95% half-width / 1.96; a ratio's the relative errors of its parts in quadrature (spread
# over the beds); the flow rows' fit standard errors.
say "against D/d_g: scaling.csv (granpen plot scaling)"
# one row: QUANTITY RATIO VALUE ERROR PAPER PAPER_ERROR (VALUE "" when not measured), then
# the axis unit and a label in gnuplot's enhanced text where the name alone reads badly
row() {
  local unit="" label=""
  case $1 in
    "peak v0^2 coefficient c2/(rho_g D^2)") label="peak v_0^2 coefficient c_2/(ρ_g D^2)" ;;
    "peak crossover speed c1/c2") unit="cm/s" label="peak crossover c_1/c_2" ;;
    "peak exponent above v_c (ensemble means)") label="peak exponent (means above v_c)" ;;
    # the flow rows: mid's push at 90 cm/s against dg10's at 100 (its 40 cm/s one: the table); no commas (CSV)
    "lambda_vz / D") label="λ_{vz} / D (90 and 100 cm/s)" ;;
    "phi at r = R (I -> 0)") label="φ at r = R for I → 0 (90 and 100 cm/s)" ;;
    "d phi / d I at r = R") label="dφ/dI at r = R (90 and 100 cm/s)" ;;
    "phi at the face / far below") label="φ at the face / far below (90 and 100 cm/s)" ;;
    "drag / (mu g M)") label="drag / (μ g M) (90 and 100 cm/s)" ;;
    # the box figure's rows (no commas: CSV)
    "lambda_vz / D (bench at 50 and dg10 at 40 cm/s)") label="λ_{vz} / D (bench at 50 and dg10 at 40 cm/s)" ;;
    "drag / (mu g M) (bench at 50 and dg10 at 40 cm/s)") label="drag / (μ g M) (bench at 50 and dg10 at 40 cm/s)" ;;
    "alpha(D = 1 cm) / alpha(D = 2 cm) (bench at 28 and dg10 at 100 cm/s)") label="α(D = 1 cm) / α(D = 2 cm) (bench at 28 and dg10 at 100 cm/s)" ;;
    "alpha(D = 3 cm) / alpha(D = 2 cm) (bench at 28 and dg10 at 100 cm/s)") label="α(3 cm) / α(2 cm) (bench at 28 and dg10 at 100 cm/s)" ;;
    "... the same with the shaft frictionless") label="α(D = 1 cm) / α(D = 2 cm) with the shaft frictionless" ;;
  esac
  printf '%s,%s,%s,%s,%s,%s,%s,%s%s\n' "$1" "$2" "$3" "$4" "$5" "$6" "$unit" "$label" "${ROW_SERIES+,$ROW_SERIES}"
}
# KEY's value and error as a row; empty when not measured; SCALE divides the error
row_of() { # QUANTITY RATIO KEY PAPER PAPER_ERROR [ERROR_DIVISOR]
  local v e; v=$(nval "$3"); e=$(nerr "$3")
  [ -n "$v" ] && e=$(awk -v e="${e:-0}" -v s="${6:-1}" 'BEGIN { printf "%.4g", e / s }')
  row "$1" "$2" "$v" "${v:+$e}" "$4" "$5"
}
# the ratio of KEY1 to KEY2 with the relative errors in quadrature; empty when either is missing
ratio_of() { # QUANTITY RATIO KEY1 KEY2 PAPER PAPER_ERROR
  local q; q=$(quad_ratio "$3" "$4")
  if [ -n "$q" ]; then row "$1" "$2" $(printf '%.4g %.3g' $q) "$5" "$6"
  else row "$1" "$2" "" "" "$5" "$6"; fi
}
{
  echo "# paper_D_over_dg = 10"
  echo "quantity,D_over_dg,value,error,paper,paper_error,unit,label"
  row_of "phi_0" 5 bench.phi_0 0.61 ""; row_of "phi_0" 6.67 mid.phi_0 0.61 ""; row_of "phi_0" 10 dg10.phi_0 0.61 ""
  row_of "peak exponent (v_c to 10 v_c)" 5 bench.peak_exponent 2 "" 1.96
  row_of "peak exponent (v_c to 10 v_c)" 6.67 mid.peak_exponent 2 "" 1.96
  row_of "peak exponent (v_c to 10 v_c)" 10 dg10.peak_exponent 2 "" 1.96
  for p in "bench 5" "mid 6.67" "dg10 10"; do set -- $p
    row_of "peak exponent above v_c (ensemble means)" "$2" "$1.peak_exponent_ensemble_from_2vc" 2 ""
  done
  # the peak as c1 v0 + c2 v0^2: the paper gives no number for either (its v0^2 would be v_x -> 0)
  for p in "bench 5" "mid 6.67" "dg10 10"; do set -- $p
    row_of "peak v0^2 coefficient c2/(rho_g D^2)" "$2" "$1.peak_inertial" "" ""
  done
  for p in "bench 5" "mid 6.67" "dg10 10"; do set -- $p
    row_of "peak crossover speed c1/c2" "$2" "$1.peak_crossover_speed" "" ""
  done
  ratio_of "alpha(D = 1 cm) / alpha(D = 2 cm)" 5 bench.alpha0_window.v28.g981.D1 bench.alpha0_window.v28.g981.D2 1 ""
  ratio_of "alpha(D = 1 cm) / alpha(D = 2 cm)" 6.67 mid.alpha0_window.v90.g981.D1 mid.alpha0_window.v90.g981.D2 1 ""
  ratio_of "alpha(D = 1 cm) / alpha(D = 2 cm)" 10 dg10.alpha0_window.v100.D1 dg10.alpha0_window.v100.D2 1 ""
  row_of "lambda_vz / D" 6.67 mid.lambda_vz_D 0.98 0.15; row_of "lambda_vz / D" 10 dg10.v100.lambda_vz_D 0.98 0.15
  row_of "phi at r = R (I -> 0)" 6.67 mid.edge_phi_0 0.57 ""; row_of "phi at r = R (I -> 0)" 10 dg10.v100.edge_phi_0 0.57 ""
  row_of "d phi / d I at r = R" 6.67 mid.edge_slope -0.35 ""; row_of "d phi / d I at r = R" 10 dg10.v100.edge_slope -0.35 ""
  ratio_of "phi at the face / far below" 6.67 mid.phi_below_face mid.phi_below_far 0.97 ""
  ratio_of "phi at the face / far below" 10 dg10.v100.phi_below_face dg10.v100.phi_below_far 0.97 ""
  row_of "drag / (mu g M)" 6.67 mid.drag_over_mu_g_Mmove 1 ""; row_of "drag / (mu g M)" 10 dg10.v100.drag_over_mu_g_Mmove 1 ""
} > "$OUT/scaling.csv.partial" && mv "$OUT/scaling.csv.partial" "$OUT/scaling.csv"
"$CLI" plot scaling "$OUT/scaling.csv" --out "$OUT/scaling" > /dev/null

# ---------------------------------------------------------------- against the box width
# The four rows the box series is to settle, one series per grain size: bench grains (D/d_g =
# 5) in boxes of 8 to 20 cm, dg10 grains (the paper's, D/d_g = 10) in the 10 and the 20 cm box
# (a row without a value is a run still to come: no point yet). box.csv, drawn by granpen plot
# scaling against box_cm. Errors as in scaling.csv; the peak over the push of the same bed and
# speed in the narrower box (bench: 8 cm narrower, dg10: 10 cm) carries its spread over pairs.
# Each grain size is read at its own speeds (the quantity's name says which).
if ls "$BOX"/box_bench*_peak/*.csv > /dev/null 2>&1; then
  say "against the box width: box.csv (granpen plot scaling)"
  {
    echo "# paper_box_cm = 20"
    echo "quantity,box_cm,value,error,paper,paper_error,unit,label,series"
    # a row of each grain size's series (the last column)
    bench_grains() { ROW_SERIES="bench grains at D/d_g = 5" "$@"; }
    dg10_grains() { ROW_SERIES="dg10 grains at D/d_g = 10" "$@"; }
    q="peak exponent (v_c to 10 v_c)"
    for b in 8 12 16 20; do bench_grains row_of "$q" "$b" "bench_box$b.peak_exponent" 2 "" 1.96; done
    dg10_grains row_of "$q" 10 dg10.peak_exponent 2 "" 1.96; dg10_grains row_of "$q" 20 dg10_box20.peak_exponent 2 "" 1.96
    q="peak exponent above v_c (ensemble means)"
    for b in 8 12 16 20; do bench_grains row_of "$q" "$b" "bench_box$b.peak_exponent_ensemble_from_2vc" 2 ""; done
    # the 20 cm box's from its 12 pushes above v_c, the same traces' twins as the 10 cm box's
    # (its key from all 15 pushes is the same number, once the 20 cm/s pushes are in)
    dg10_grains row_of "$q" 10 dg10.peak_exponent_ensemble_from_2vc 2 ""; dg10_grains row_of "$q" 20 dg10_box20_v40to200.peak_exponent_ensemble_from_2vc 2 ""
    # the speeds the 20 cm box has on all three beds so far (its slow end comes last)
    q="peak exponent at 80 to 200 cm/s (ensemble means)"
    dg10_grains row_of "$q" 10 dg10_v80to200.peak_exponent_ensemble_from_2vc 2 ""; dg10_grains row_of "$q" 20 dg10_box20_v80to200.peak_exponent_ensemble_from_2vc 2 ""
    q="peak over the narrower box's (same bed and v0)"
    for b in 16 20; do bench_grains row_of "$q" "$b" "bench_box$b.peak_over_box$((b - 8))" 1 ""; done
    # dg10 above v_c, where the largest force within 0.7 R is an impact peak (peak_above_vc)
    dg10_grains row_of "$q" 20 dg10_box20_v40to200.peak_over_box10 1 ""
    q="lambda_vz / D (bench at 50 and dg10 at 40 cm/s)"
    for b in 8 12 16 20; do bench_grains row_of "$q" "$b" "bench_box$b.v50.lambda_vz_D" 0.98 0.15; done
    dg10_grains row_of "$q" 10 dg10.v40.lambda_vz_D 0.98 0.15; dg10_grains row_of "$q" 20 dg10_box20.v40.lambda_vz_D 0.98 0.15
    q="drag / (mu g M) (bench at 50 and dg10 at 40 cm/s)"
    for b in 8 12 16 20; do bench_grains row_of "$q" "$b" "bench_box$b.v50.drag_over_mu_g_Mmove" 1 ""; done
    dg10_grains row_of "$q" 10 dg10.v40.drag_over_mu_g_Mmove 1 ""; dg10_grains row_of "$q" 20 dg10_box20.v40.drag_over_mu_g_Mmove 1 ""
    q="alpha(D = 1 cm) / alpha(D = 2 cm) (bench at 28 and dg10 at 100 cm/s)"
    for b in 8 20; do bench_grains row_of "$q" "$b" "bench_box$b.alpha_D1_over_D2" 1 ""; done
    dg10_grains ratio_of "$q" 10 dg10.alpha0_window.v100.D1 dg10.alpha0_window.v100.D2 1 ""; dg10_grains row_of "$q" 20 dg10_box20.alpha_D1_over_D2 1 ""
    # the rim term's test: a term A + B / D puts the 3 cm rod below the 2 cm rod's alpha, F_z ~ D^2 at 1
    q="alpha(D = 3 cm) / alpha(D = 2 cm) (bench at 28 and dg10 at 100 cm/s)"
    for b in 8 20; do bench_grains row_of "$q" "$b" "bench_box$b.alpha_D3_over_D2" 1 ""; done
    dg10_grains row_of "$q" 20 dg10_box20.alpha_D3_over_D2 1 ""
    q="... the same with the shaft frictionless"
    for b in 8 20; do bench_grains row_of "$q" "$b" "bench_box${b}_shaft.alpha_D1_over_D2" 1 ""; done
    dg10_grains row_of "$q" 20 dg10_box20_shaft.alpha_D1_over_D2 1 ""
  } > "$OUT/box.csv.partial" && mv "$OUT/box.csv.partial" "$OUT/box.csv"
  "$CLI" plot scaling "$OUT/box.csv" --out "$OUT/box" > /dev/null
fi

mv "$NUM" "$OUT/numbers.txt"
say "wrote $OUT/numbers.txt"
