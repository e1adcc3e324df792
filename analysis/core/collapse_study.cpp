// granpen analysis: the collapse study's stages (see collapse_study.h).
#include "collapse_study.h"

#include "scaling_laws.h"
#include "trace_fit.h"

#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

namespace granpen {

namespace {

TraceFitParams window_of(const CollapseStudyParams &p, double v0, double D, double g)
{
  TraceFitParams fp;
  fp.zlo = p.kz_zmin, fp.zhi = p.kz_zmax, fp.v0 = v0, fp.D = D, fp.g = g;
  fp.shorten_window = true;    // a window the data do not fill: the deeper half, with a note
  return fp;
}

EnsembleCase case_of(const CollapseEnsemble &e, const CollapseStudyParams &p)
{
  EnsembleCase c;
  c.name = e.name, c.v0 = e.v0, c.D = e.D, c.g = e.g, c.mean = e.mean;
  if (e.k_z_given) c.k_z_fixed = e.k_z_fixed;
  else c.kz_fit = window_of(p, e.v0, e.D, e.g);
  return c;
}

// each run's F/F_z averaged in the curve's t~ bins (as core/collapse bins them), their
// standard error over runs
std::vector<double> ratio_se_over_runs(const EnsembleCase &c, const CollapseCurve &cv, const CollapseParams &p)
{
  const EnsembleMean &m = c.mean;
  std::map<long, std::vector<std::pair<double, int>>> bins;    // bin -> per run (sum, count)
  for (std::size_t k = 0; k < m.z.size(); ++k) {
    if (m.z[k] < p.zmin) continue;
    auto &b = bins[(long) std::floor(t_tilde(m.z[k], c.v0, c.g, c.D) / p.tbin)];
    b.resize(m.runs);
    for (std::size_t r = 0; r < m.runs; ++r) b[r].first += m.per_run[r][k] / (cv.k_z * m.z[k]), ++b[r].second;
  }
  std::vector<double> se;
  for (double t : cv.t) {
    const auto it = bins.find((long) std::floor(t / p.tbin));
    double mean = 0, s2 = 0;
    const double n = (double) m.runs;
    if (it == bins.end() || m.runs < 2) {
      se.push_back(0.0);
      continue;
    }
    for (const auto &v : it->second) mean += v.first / v.second;
    mean /= n;
    for (const auto &v : it->second) s2 += std::pow(v.first / v.second - mean, 2);
    se.push_back(std::sqrt(s2 / (n - 1) / n));
  }
  return se;
}

}    // namespace

const char *collapse_stage_name(CollapseStage s)
{
  switch (s) {
    case CollapseStage::depth_terms: return "depth terms";
    case CollapseStage::collapse: return "collapse";
    case CollapseStage::peaks: return "peaks";
    case CollapseStage::ensembles: return "ensembles";
    case CollapseStage::ensemble_peaks: return "ensemble peaks";
  }
  return "?";
}

std::vector<DepthTermOutcome> collapse_depth_terms(const std::vector<CollapseTrace> &traces,
                                                   const CollapseStudyParams &p)
{
  std::vector<DepthTermOutcome> out;
  for (const auto &t : traces) {
    DepthTermOutcome d;
    if (t.k_z_given) {
      d.ok = true, d.k_z = t.k_z_fixed;    // core/collapse refuses a non-positive one
    } else {
      const TraceFit fit = fit_trace(t.z, t.F, window_of(p, t.v0, t.D, t.g));
      d.fitted = true;
      d.zlo = fit.zlo, d.zhi = fit.zhi, d.k_z = fit.k_z;
      d.window_shortened = fit.window_shortened;
      if (fit.window_shortened) d.window_note = fit.notes.front();
      d.ok = fit.slope_ok && fit.k_z > 0.0;
    }
    out.push_back(d);
  }
  return out;
}

std::vector<CollapseInput> collapse_inputs(const std::vector<CollapseTrace> &traces,
                                           const std::vector<DepthTermOutcome> &depth)
{
  std::vector<CollapseInput> in;
  for (std::size_t i = 0; i < traces.size() && i < depth.size(); ++i) {
    if (!depth[i].ok) continue;
    const CollapseTrace &t = traces[i];
    CollapseInput c;
    c.name = t.name, c.z = t.z, c.F = t.F, c.v0 = t.v0, c.D = t.D, c.g = t.g, c.k_z = depth[i].k_z;
    in.push_back(std::move(c));
  }
  return in;
}

CollapseResult peaks_of_traces(const std::vector<CollapseTrace> &traces, const CollapseStudyParams &p)
{
  std::vector<CollapseInput> in;
  for (const auto &t : traces) {
    CollapseInput c;
    c.name = t.name, c.z = t.z, c.F = t.F, c.v0 = t.v0, c.D = t.D, c.g = t.g;
    c.k_z = 1.0;    // the peaks and their law do not depend on k_z
    in.push_back(std::move(c));
  }
  return collapse(in, p.collapse);
}

void collapse_ensemble_means(const std::vector<CollapseEnsemble> &ensembles, const CollapseStudyParams &p,
                             EnsembleCollapseStudy &out)
{
  out = EnsembleCollapseStudy();
  std::vector<EnsembleCase> cases;
  for (std::size_t i = 0; i < ensembles.size(); ++i) {
    EnsembleCase c = case_of(ensembles[i], p);
    // a given depth term is used as it is (a non-positive one: left out), else the fit's
    const bool usable = ensembles[i].k_z_given ? ensembles[i].k_z_fixed > 0.0 : ensemble_depth_term(c) > 0.0;
    if (!usable) {
      out.left_out.push_back(i);
      continue;
    }
    out.kept.push_back(i);
    cases.push_back(std::move(c));
  }
  if (cases.empty()) return;
  out.collapse = collapse_ensembles(cases, p.collapse, p.boot);
  for (std::size_t i = 0; i < cases.size(); ++i)
    out.ratio_se.push_back(ratio_se_over_runs(cases[i], out.collapse.result.curves[i], p.collapse));
}

EnsembleCollapse peaks_of_ensembles(const std::vector<CollapseEnsemble> &ensembles, const CollapseStudyParams &p)
{
  std::vector<EnsembleCase> cases;
  for (const auto &e : ensembles) {
    EnsembleCase c;
    c.name = e.name, c.v0 = e.v0, c.D = e.D, c.g = e.g, c.mean = e.mean;
    c.k_z_fixed = 1.0;    // as peaks_of_traces
    cases.push_back(std::move(c));
  }
  return collapse_ensembles(cases, p.collapse, p.boot);
}

CollapseStudy run_collapse_study(const std::vector<CollapseTrace> &traces,
                                 const std::vector<CollapseEnsemble> &ensembles, const CollapseStudyParams &p,
                                 const CollapseStages &stages, const CollapseProgress &progress)
{
  CollapseStudy s;
  CollapseStage at = CollapseStage::depth_terms;
  const auto stage = [&](CollapseStage x) {
    at = x;
    if (progress) progress(x);
  };
  try {
    if (stages.collapse) {    // the depth terms serve the collapse only
      stage(CollapseStage::depth_terms);
      s.depth = collapse_depth_terms(traces, p);
      const std::vector<CollapseInput> in = collapse_inputs(traces, s.depth);
      if (!in.empty()) {
        stage(CollapseStage::collapse);
        s.result = collapse(in, p.collapse);
        s.collapsed = true;
      }
    }
    // the peak law goes with the collapse when both are asked for
    if (stages.peaks && !traces.empty() && (!stages.collapse || s.collapsed)) {
      stage(CollapseStage::peaks);
      s.peaks = peaks_of_traces(traces, p);
      s.peaks_done = true;
    }
    if (stages.ensembles && !ensembles.empty()) {
      stage(CollapseStage::ensembles);
      collapse_ensemble_means(ensembles, p, s.ensembles);
      s.ensembles_done = true;
    }
    // the ensembles' peak law goes with their collapse when both are asked for
    if (stages.ensemble_peaks && !ensembles.empty() && (!stages.ensembles || !s.ensembles.kept.empty())) {
      stage(CollapseStage::ensemble_peaks);
      s.ensemble_peaks = peaks_of_ensembles(ensembles, p);
      s.ensemble_peak_law = peak_law_of_means(s.ensemble_peaks);
      s.ensemble_peaks_done = true;
    }
  } catch (std::invalid_argument &e) {
    s.refused = true, s.refused_at = at, s.refusal = e.what();
  }
  return s;
}

}    // namespace granpen
