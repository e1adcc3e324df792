#!/bin/sh
# io_reads_writes.sh: fails when a file of analysis/io calls a fit or collapse kernel of
# analysis/core (issue 32: io reads and writes; the studies of core compute, the CLI calls
# them and hands the results to io's writers and figures). The kernels: fit_trace,
# fit_ensemble, fit_exponential, linear_fit(_origin), dominant_wavelength, ensemble_mean,
# average_ensembles, collapse, collapse_ensembles, peak_law_of_means, ensemble_depth_term, compare_drag,
# calibration_table and the stages of the studies (core/collapse_study.h, fit_study.h,
# flow_table_study.h, calibration_study.h). Comments and string literals are not code. An
# allow-list file (one "path kernel" a line, # comments) can name calls still to be moved
# (none is, since issue 32's section 3 was done); an entry that no longer matches a call is
# reported as stale. ctest architecture_io_reads_writes, with a self-test.
#   io_reads_writes.sh [--allow FILE] [--self-test] [ROOT]
# Exit: 0 no call outside the list, 1 some (each printed as file:line: code), 2 usage.
# Needs only sh, find, awk and grep (and code_lines.sh beside it).
set -u
root=.
allow=
self_test=no
while [ $# -gt 0 ]; do
  case "$1" in
    --allow) allow=$2; shift 2 ;;
    --self-test) self_test=yes; shift ;;
    -h|--help) sed -n '2,13p' "$0"; exit 0 ;;
    -*) echo "io_reads_writes.sh: unknown option $1" >&2; exit 2 ;;
    *) root=$1; shift ;;
  esac
done

KERNELS='fit_trace|fit_ensemble|fit_exponential|linear_fit|linear_fit_origin|dominant_wavelength|ensemble_mean|average_ensembles|collapse|collapse_ensembles|peak_law_of_means|ensemble_depth_term|calibration_table|run_collapse_study|collapse_depth_terms|collapse_ensemble_means|peaks_of_traces|peaks_of_ensembles|run_fit_study|fit_study_trace|fit_ensemble_runs|run_flow_table_study|fit_edge_line|local_exponential_fits|run_calibration_study|fit_calibration_push|compare_drag'
# a call: the name (not part of a longer one, nor a member) and its opening parenthesis
CALL="(^|[^A-Za-z0-9_.>])($KERNELS) *\\("

# code_lines ROOT EXCLUDE DIR...: FILE:LINE: CODE, comments and string literals blanked
. "$(dirname "$0")/code_lines.sh"

# "path kernel" of each call
calls_of() {
  printf '%s\n' "$1" | grep -E "$CALL" | while IFS= read -r line; do
    path=${line%%:*}
    printf '%s\n' "$line" | grep -oE "$CALL" | sed -E 's/^[^A-Za-z_]*//; s/ *\($//' | while read -r k; do
      echo "$path $k"
    done
  done | sort -u
}

check() {
  [ -d "$1/analysis/io" ] || { echo "io_reads_writes.sh: $1 has no analysis/io" >&2; return 2; }
  code=$(code_lines "$1" "" analysis/io)
  allowed=
  [ -n "$2" ] && allowed=$(grep -v -E '^[[:space:]]*(#|$)' "$2" | awk '{ print $1, $2 }' | sort -u)
  found=$(calls_of "$code")
  bad=0
  printf '%s\n' "$found" | while read -r path k; do
    [ -n "$path" ] || continue
    printf '%s\n' "$allowed" | grep -qxF "$path $k" && continue
    echo "$path calls $k (io reads and writes: run it in a core study, hand io the result):"
    printf '%s\n' "$code" | grep -E "^$path:" | grep -E "(^|[^A-Za-z0-9_.>])$k *\\(" | sed 's/^/  /'
  done > "$tmp_out"
  [ -s "$tmp_out" ] && { cat "$tmp_out"; bad=1; }
  printf '%s\n' "$allowed" | while read -r path k; do
    [ -n "$path" ] || continue
    printf '%s\n' "$found" | grep -qxF "$path $k" || echo "stale entry in the allow list: $path $k (no such call now)"
  done > "$tmp_out"
  [ -s "$tmp_out" ] && { cat "$tmp_out"; bad=1; }
  [ $bad -eq 0 ] && echo "ok: no file of analysis/io calls a fit or collapse kernel$([ -n "$allowed" ] && echo " but the $(printf '%s\n' "$allowed" | wc -l | tr -d ' ') listed calls")"
  return $bad
}

tmp_out=$(mktemp) || exit 2
trap 'rm -f "$tmp_out"' EXIT

if [ "$self_test" = yes ]; then
  # a fixture tree: io that reads and writes passes (names that contain a kernel's, members,
  # declarations in comments and strings); each planted call fails, named; an allowed call
  # passes and a stale entry fails
  tmp=$(mktemp -d) || exit 2
  trap 'rm -rf "$tmp" "$tmp_out"' EXIT
  t="$tmp/tree"
  mkdir -p "$t/analysis/io"
  cat > "$t/analysis/io/writer.cpp" <<'IO'
// the curves of collapse(in, p) and fit_trace(z, F, p), as written by granpen collapse
Json collapse_json(const CollapseResult &r, const CollapseParams &p);
FitResult fit_trace_file(const std::string &path, const FitWindow &w);
const std::string help = "fit_trace(z, F) and collapse(in)";
/* linear_fit(x, y) */
const double k = s.collapse.result.t_star_mean, e = study->collapse(3);
std::string csv = collapse_curves_csv(r) + ensemble_collapse_csv_rows(g, ec);
std::vector<EnsembleRuns> runs = ensemble_runs(groups); std::vector<FitStudyTrace> t = fit_study_traces(traces, o, w);
IO
  out=$(check "$t" "") || { echo "$out"; echo "SELF-TEST FAILED: io that only reads and writes fails"; exit 1; }
  n=0
  for planted in 'const TraceFit fit = fit_trace(tr.z, tr.F, par);' \
                 'r = collapse(in, run.opt.collapse);' \
                 'r = granpen::collapse(in, p);' \
                 'const LinearFit lf = linear_fit(x, y);' \
                 'ec = collapse_ensembles (cases, p, b);' \
                 'const auto rows = calibration_table(beds, pushes);' \
                 'const CollapseStudy s = run_collapse_study(t, {}, sp, st);' \
                 'keep_averaged(groups, average_ensembles(ensemble_runs(groups), p), p, problems);' \
                 'const FitStudy s = run_fit_study(fit_study_traces(traces, o, w), {}, sp, st);' \
                 'const EdgeLine e = fit_edge_line(c.I, c.phi);'; do
    n=$((n + 1))
    printf '%s\n' "$planted" > "$t/analysis/io/copy.cpp"
    out=$(check "$t" ""); rc=$?
    [ $rc -eq 1 ] || { echo "$out"; echo "SELF-TEST FAILED: a call ($planted) gives exit $rc, 1 expected"; exit 1; }
    case "$out" in *"analysis/io/copy.cpp:1:"*) ;; *) echo "$out"; echo "SELF-TEST FAILED: the call not named"; exit 1 ;; esac
  done
  printf 'const TraceFit fit = fit_trace(tr.z, tr.F, par);\n' > "$t/analysis/io/copy.cpp"
  printf '# still to move\nanalysis/io/copy.cpp fit_trace\n' > "$tmp/allow"
  check "$t" "$tmp/allow" > /dev/null || { echo "SELF-TEST FAILED: an allowed call fails"; exit 1; }
  printf 'analysis/io/copy.cpp fit_trace\nanalysis/io/writer.cpp collapse\n' > "$tmp/allow"
  out=$(check "$t" "$tmp/allow"); rc=$?
  [ $rc -eq 1 ] && case "$out" in *"stale entry"*"writer.cpp collapse"*) ;; *) rc=0 ;; esac
  [ $rc -eq 1 ] || { echo "$out"; echo "SELF-TEST FAILED: a stale entry passes"; exit 1; }
  echo "self-test passed: $n planted calls fail, io that reads and writes passes, the allow list excuses and goes stale"
  exit 0
fi

check "$root" "$allow"
