// granpen collapse TRACE-OR-FOLDER...: F/F_z against t~ = (z/v0) sqrt(g/D) over a set of
// traces, the crossover t~*, the collapse quality and the peak law; with --ensemble the same
// from the ensemble means with run-to-run uncertainties (core/collapse_study.h runs them all).
#include "atomic_file.h"
#include "collapse_options.h"
#include "collapse.h"
#include "collapse_study.h"
#include "ensemble_groups.h"
#include "ensemble_tables.h"
#include "json_text.h"
#include "collapse_tables.h"
#include "json_writer.h"
#include "subcommands.h"
#include "trace_files.h"
#include "trace_reader.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

using granpen::json_number;

namespace {

using namespace granpen;

std::string pm(const Estimate &e, const char *f)
{
  if (!e.ok) return "not reached";
  return json_number(f, e.value) + (e.se_ok ? " +- " + json_number(f, e.se) : std::string());
}

std::string percent(int k, int of) { return of > 0 ? json_number("%.0f", 100.0 * k / of) + "%" : "-"; }

// The peak as c1 v0 + c2 v0^2 (what is fitted: "" for the traces, or a note in brackets).
void print_two_term(const PeakLaw &law, const char *what)
{
  if (!law.two_term_ok) return;
  std::printf("peak law, two terms%s: peak = c1 v0 + c2 v0^2, c1 = %.4g +- %.2g, c2 = %.4g +- %.2g (standard errors); "
              "crossover speed c1/c2 = %s\n",
              what, law.linear, law.linear_se, law.quadratic, law.quadratic_se,
              law.crossover_ok ? (json_number("%.3g", law.crossover_speed) + " +- " +
                                  json_number("%.2g", law.crossover_speed_se) + " cm/s")
                                     .c_str()
                               : "none (c2 <= 0)");
}

void print_result(const CollapseResult &r, const CollapseParams &p)
{
  for (const auto &c : r.curves)
    std::printf("  %s: v0 = %g cm/s, g = %g, D = %g, k_z = %.4g dyne/cm, peak %.4g dyne at z = %.3g cm, t~* = %s\n",
                c.name.c_str(), c.v0, c.g, c.D, c.k_z, c.peak, c.peak_z,
                c.crossed ? json_number("%.2f", c.t_star).c_str() : "not reached");
  std::printf("crossover: t~* = %.2f +- %.2f over %d of %zu traces (paper: 1)\n", r.t_star_mean, r.t_star_sd,
              r.n_crossed, r.curves.size());
  if (r.ens_crossed)
    std::printf("ensemble crossover: the mean of F/F_z over the traces stays within 1 +- %g from t~* = %.2f "
                "(bins with at least %d traces)\n",
                p.band, r.t_star_ensemble, std::min<int>(p.min_curves, static_cast<int>(r.curves.size())));
  else
    std::printf("ensemble crossover: the mean of F/F_z over the traces does not stay within 1 +- %g\n", p.band);
  std::printf("collapse quality: spread of F/F_z across traces %.3f against z, %.3f against t~ (ratio %.2f)\n",
              r.spread_z, r.spread_t, r.spread_z > 0 ? r.spread_t / r.spread_z : 0.0);
  if (r.peak_law.ok)
    std::printf("peak law: peak ~ v0^%.2f +- %.2f (95%%; over %zu traces; paper: 2)\n", r.peak_law.exponent,
                r.peak_law.exponent_ci95, r.peak_law.points);
  print_two_term(r.peak_law, "");
  if (!r.peak_law.ok)
    std::printf("peak law: needs at least 3 traces over 2 or more speeds\n");
}

void print_ensembles(const std::vector<TraceGroup> &groups, const EnsembleCollapse &c, const CollapseParams &p)
{
  const CollapseResult &r = c.result;
  std::size_t runs = 0;
  for (const auto &g : groups) runs += g.mean.runs;
  std::printf("\ngranpen collapse --ensemble: %zu ensemble%s of %zu runs; +-: standard error over runs "
              "(bootstrap, %d resamples, %d with a positive k_z in every ensemble)\n",
              groups.size(), groups.size() == 1 ? "" : "s", runs, c.resamples, c.usable);
  for (std::size_t i = 0; i < groups.size(); ++i) {
    std::puts(ensemble_summary(groups[i]).c_str());
    std::printf("  mean: k_z = %s dyne/cm, peak %s dyne at z = %.3g cm, t~* = %s (crossed in %s of the resamples)\n",
                pm(c.k_z[i], "%.4g").c_str(), pm(c.peak[i], "%.4g").c_str(), r.curves[i].peak_z,
                pm(c.t_star[i], "%.2f").c_str(), percent(c.t_star[i].defined, c.usable).c_str());
  }
  std::printf("crossover: t~* = %s over %d of %zu ensembles (paper: 1)\n", pm(c.t_star_mean, "%.2f").c_str(),
              r.n_crossed, r.curves.size());
  std::printf("ensemble crossover: the mean of F/F_z over the ensembles %s\n",
              r.ens_crossed ? ("stays within 1 +- " + json_number("%g", p.band) + " from t~* = " +
                               pm(c.t_star_ensemble, "%.2f")).c_str()
                            : ("does not stay within 1 +- " + json_number("%g", p.band)).c_str());
  if (r.curves.size() > 1)
    std::printf("collapse quality: spread of F/F_z across ensembles %s against z, %s against t~\n",
                pm(c.spread_z, "%.3f").c_str(), pm(c.spread_t, "%.3f").c_str());
  else
    std::printf("collapse quality: needs 2 or more ensembles\n");
  if (c.peak_exponent.ok)
    std::printf("peak law: peak ~ v0^%s (95%%: +- %s, over runs; %zu ensembles; paper: 2)\n",
                pm(c.peak_exponent, "%.2f").c_str(), json_number("%.2f", c.peak_exponent.ci95).c_str(),
                r.peak_law.points);
  else
    std::printf("peak law: needs ensembles at 3 or more speeds\n");
  print_two_term(r.peak_law, " (of the ensemble means, errors from their residuals)");
}

// The notes of the study's depth terms: windows shortened, then the traces left out.
void print_depth_notes(const std::vector<Trace> &traces, const std::vector<DepthTermOutcome> &depth,
                       std::size_t &left_out_count, std::vector<std::string> &left_out)
{
  for (std::size_t i = 0; i < depth.size(); ++i)
    if (depth[i].window_shortened) std::printf("note: %s\n", (traces[i].path + ": " + depth[i].window_note).c_str());
  for (std::size_t i = 0; i < depth.size(); ++i) {
    const DepthTermOutcome &d = depth[i];
    if (d.ok) continue;
    left_out.push_back(traces[i].path + ": no positive depth term over the k_z window z = " + json_number("%g", d.zlo) +
                       ".." + json_number("%.3g", d.zhi) + " cm (k_z = " + json_number("%.3g", d.k_z) +
                       " dyne/cm); left out (--kz-zmin/--kz-zmax, --alpha or --ensemble may help)");
    std::printf("note: %s\n", left_out.back().c_str());
  }
  left_out_count = left_out.size();
}

// --ensemble: the groups' averaging problems and the ensembles the study left out (named),
// then the collapse of the means with the peak law of every ensemble; false: none usable.
bool ensembles_of_study(const CollapseStudy &s, std::vector<TraceGroup> &groups, std::vector<std::string> left,
                        EnsembleCollapse &out)
{
  for (std::size_t i : s.ensembles.left_out)
    left.push_back("ensemble " + groups[i].label() + ": no positive depth term on the mean of its " +
                   std::to_string(groups[i].mean.runs) + " runs; left out");
  for (const auto &m : left) std::printf("note: %s\n", m.c_str());
  if (s.refused) throw std::invalid_argument(s.refusal);
  if (s.ensembles.kept.empty()) return false;
  out = s.ensembles.collapse;
  out.peak_exponent = s.ensemble_peaks.peak_exponent;    // every ensemble, with or without k_z
  out.result.peak_law = s.ensemble_peak_law;
  std::vector<TraceGroup> kept;
  for (std::size_t i : s.ensembles.kept) kept.push_back(groups[i]);
  groups = std::move(kept);
  return true;
}

}    // namespace

int granpen::cli::run_collapse(const CollapseOptions &o)
{
  const std::string &csv = o.csv, &json = o.json;
  const CollapseParams &p = o.params;
  const DepthTerm &dt = o.depth;
  const EnsembleOptions &ens = o.ensemble;
  std::vector<std::string> problems, left_out, ens_problems;
  const auto files = expand_trace_paths(o.traces, problems);
  const std::vector<std::pair<std::string, std::string>> outputs = {{"--csv", csv}, {"--json", json}};
  refuse_shared_outputs(outputs);
  for (const auto &output : outputs)
    if (!output.second.empty()) refuse_overwriting_inputs(output.second, output.first, files);
  const std::vector<Trace> traces = read_traces(files, problems);
  std::vector<TraceGroup> groups;
  if (ens.on) groups = averaged_groups(traces, ens.mean, ens_problems);
  CollapseStages stages;
  stages.peaks = true;
  stages.ensembles = stages.ensemble_peaks = ens.on;
  const CollapseStudy s = run_collapse_study(collapse_traces(traces, dt), collapse_ensemble_inputs(groups, dt),
                                             collapse_study_params(p, dt, ens.boot), stages);
  const bool refused_on_traces = s.refused && s.refused_at <= CollapseStage::peaks;
  if (s.refused && s.refused_at == CollapseStage::depth_terms) throw std::invalid_argument(s.refusal);
  for (const auto &m : problems) std::fprintf(stderr, "granpen collapse: %s\n", m.c_str());
  std::size_t n_left = 0;
  print_depth_notes(traces, s.depth, n_left, left_out);
  if (refused_on_traces) throw std::invalid_argument(s.refusal);

  CollapseResult r;
  if (s.collapsed) {
    r = s.result;
    r.peak_law = s.peaks.peak_law;    // the peak law needs no depth term: from every trace read
    std::printf("granpen collapse: %zu traces%s, band 1 +- %g, t~ bins of %g\n", r.curves.size(),
                n_left == 0 ? "" : (" (" + std::to_string(n_left) + " left out)").c_str(), p.band, p.tbin);
    print_result(r, p);
  } else if (!ens.on) {
    std::fprintf(stderr, "granpen collapse: no usable trace\n");
    return EXIT_FAILED;
  } else {
    std::printf("granpen collapse: no single trace has a positive k_z over the window; ensembles only\n");
  }
  EnsembleCollapse ec;
  const bool have_ens = ens.on && ensembles_of_study(s, groups, ens_problems, ec);
  if (ens.on && !have_ens) {
    std::fprintf(stderr, "granpen collapse: no usable ensemble\n");
    return EXIT_FAILED;
  }
  if (have_ens) print_ensembles(groups, ec, p);

  if (!csv.empty()) {
    write_file_atomic(csv, collapse_curves_csv(r) + (have_ens ? ensemble_collapse_csv_rows(groups, ec) : ""));
    std::printf("wrote %s\n", csv.c_str());
  }
  if (!json.empty()) {
    Json j = collapse_json(r, p);
    j["left_out"] = left_out;
    if (have_ens) j["ensemble"] = ensemble_collapse_json(groups, ec);
    write_json(json, j, 1);
    std::printf("wrote %s\n", json.c_str());
  }
  return problems.empty() ? EXIT_OK : EXIT_FAILED;
}

int granpen::cli::collapse(int argc, char **argv) { return run_parsed(parse_collapse, run_collapse, argc, argv); }
