// granpen gap, stage 6 (where): see gap_where.h.
#include "gap_where.h"
#include "gap_fit.h"
#include "gap_thresholds.h"
#include "scaling_laws.h"

#include "text_util.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

namespace granpen {

namespace {

double mean_of(const std::vector<double> &v)
{
  return v.empty() ? 0.0 : std::accumulate(v.begin(), v.end(), 0.0) / v.size();
}

using Observations = std::map<std::string, std::vector<double>>;    // observable -> one value per run

Observations observations(const std::vector<TraceRun> &runs, double v, const Scenario &sc, const GapGrid &grid,
                          double z_transient_end)
{
  Observations o;
  for (const auto &r : runs) {
    const auto x = run_observables(r.z, r.F, v, sc.D, sc.g, sc.d_g, grid, z_transient_end);
    o["peak_F"].push_back(x.peak_F);
    o["peak_z"].push_back(x.peak_z);
    o["excess"].push_back(x.excess);
    o["k_z"].push_back(x.k_z);
    if (x.crossed) o["t_star"].push_back(x.t_star);
    o["fluct"].push_back(x.fluct);
    if (x.wavelength > 0) o["wavelength"].push_back(x.wavelength);
  }
  return o;
}

}    // namespace

namespace {

// G_all of the measurement against the reference beds' runs times 1 + scale: every bin mean
// and band amplitude scales with F, their squared standard errors with its square
double gap_within_scale(const Features &f, const GapGrid &grid, double scale)
{
  const double x = 1.0 + scale;
  double G = 0, G_spec = 0;
  for (std::size_t s = 0; s < f.nspeeds(); ++s) {
    Ensemble e = f.fresh[s];
    for (auto &run : e.runs)
      for (double &v : run) v *= x;
    for (double &m : e.mean) m *= x;
    for (double &v : e.var) v *= x * x;
    G += gap_metric(f.real[s], e, 0, grid.nbins()) / f.nspeeds();
    if (s < f.spec_real.size() && s < f.spec_fresh.size()) {
      EnsembleMoments m = f.spec_fresh[s];
      for (double &a : m.mean) a *= x;
      for (double &v : m.sq_se) v *= x * x;
      G_spec += debiased_gap(f.spec_real[s], m) / f.nspeeds();
    }
  }
  return gap_all(G, G_spec);
}

}    // namespace

GapCurves gap_curves(const Features &f, const GapGrid &grid)
{
  const std::size_t ns = f.nspeeds(), nb = grid.nbins();
  GapCurves out;
  out.n_real_min = 1 << 30;
  GapParts parts;
  for (std::size_t s = 0; s < ns; ++s) {
    SpeedCurves c;
    c.v0 = f.speeds[s];
    c.n_real = (int) f.real[s].n();
    c.n_base = (int) f.fresh[s].n();
    out.n_real_min = std::min(out.n_real_min, c.n_real);
    const auto errB = model_err(f.fresh[s], f.cv2[s]);
    for (std::size_t b = 0; b < nb; ++b) {
      c.z.push_back(grid.centre(b));
      c.real.push_back(f.real[s].mean[b]);
      c.real_se.push_back(std::sqrt(f.target.err[s][b]));
      c.base.push_back(f.fresh[s].mean[b]);
      c.base_se.push_back(std::sqrt(errB[b]));
      c.gap.push_back(f.real[s].mean[b] - f.fresh[s].mean[b]);
      c.band.push_back(2.0 * std::sqrt(f.target.err[s][b] + errB[b]));
    }
    c.G_before = gap_metric(f.real[s], f.fresh[s], 0, nb);
    c.Gs_before = s < f.spec_real.size() && s < f.spec_fresh.size() ? debiased_gap(f.spec_real[s], f.spec_fresh[s]) : 0.0;
    parts.G += c.G_before / ns, parts.G_spec += c.Gs_before / ns;
    out.speeds.push_back(c);
  }
  out.n_sim = f.n_reference;    // the baseline the gap is measured against: the reference beds
  parts.runs_real = out.n_real_min, parts.runs_sim = out.n_sim;
  out.parts = parts;
  out.gap = parts.all();
  out.scale_within_bound = baseline_scale_within_bound(f.target, f);
  out.gap_within_bound = gap_within_scale(f, grid, out.scale_within_bound);
  return out;
}

std::vector<double> transient_ends(const Features &f, const RunsBySpeed &fresh, const Scenario &sc, const GapGrid &grid)
{
  std::vector<double> ends;
  for (std::size_t s = 0; s < f.nspeeds(); ++s) {
    const double v = f.speeds[s];
    const auto &runs = fresh.at(v);
    std::vector<double> ts;
    for (const auto &r : runs) {
      const auto o = run_observables(r.z, r.F, v, sc.D, sc.g, sc.d_g, grid, grid.zmax);
      if (o.crossed) ts.push_back(o.t_star);
    }
    const double zc = ts.size() == runs.size() && !ts.empty() ? depth_at_t_tilde(mean_of(ts), v, sc.g, sc.D) : grid.zmax;
    ends.push_back(std::clamp(zc, peak_regime_end(sc.D), grid.zmax));
  }
  return ends;
}

ObservableFindings observable_findings(const Features &f, const RunsBySpeed &real, const SimulatedRuns &sims,
                                       const Scenario &sc, const GapGrid &grid, const std::vector<double> &z_transient_end)
{
  const std::map<std::string, std::string> regime = {{"peak_F", "peak"},     {"peak_z", "peak"},
                                                     {"excess", "transient"}, {"t_star", "transient"},
                                                     {"k_z", "linear"},       {"fluct", "linear"},
                                                     {"wavelength", "linear"}};
  ObservableFindings out;
  for (std::size_t s = 0; s < f.nspeeds(); ++s) {
    const double v = f.speeds[s], zt = z_transient_end[s];
    const Observations oR = observations(real.at(v), v, sc, grid, zt), oB = observations(sims.fresh.at(v), v, sc, grid, zt);
    std::map<std::string, std::pair<double, int>> pooled;    // sum of squares, dof
    auto pool = [&](const Observations &o) {
      for (const auto &[name, xs] : o) {
        if (xs.size() < 2) continue;
        const double m = mean_of(xs);
        for (double x : xs) pooled[name].first += (x - m) * (x - m);
        pooled[name].second += (int) xs.size() - 1;
      }
    };
    pool(oB);
    for (auto &[name, by] : sims.knots) pool(observations(by.at(v), v, sc, grid, zt));
    const double scale = f.target_scale[s];
    for (const auto &[name, reg] : regime) {
      if (!oR.count(name) || !oB.count(name) || !pooled.count(name)) continue;
      if (name == "excess" && zt <= peak_regime_end(sc.D) + grid.w) continue;    // no transient regime in range
      const double var1 = pooled[name].first / pooled[name].second;    // one run's variance
      const double level = std::abs(mean_of(oB.at(name)));
      if (!(var1 > 0.0) || std::sqrt(var1) <= 1e-9 * level) {
        // every run gave the same value (t_star lands on the grid's bins): a z-score would
        // divide by 0, or by the rounding of the mean (1e-16 of it) when the values are equal
        out.notes.push_back("where: " + name + " at v0 = " + printf_number("%g", v) +
                            " has no scatter over the simulated runs (all equal): no z-score");
        continue;
      }
      const std::vector<double> &xr = oR.at(name), &xb = oB.at(name);
      Finding w;
      w.regime = reg;
      w.observable = name;
      w.v0 = v;
      w.real = mean_of(xr);
      w.sim = mean_of(xb);
      w.real_se = std::sqrt(scale * var1 / xr.size());
      w.sim_se = std::sqrt(var1 / xb.size());
      w.zscore = (w.real - w.sim) / std::sqrt(w.real_se * w.real_se + w.sim_se * w.sim_se + 1e-300);
      w.significant = std::abs(w.zscore) > 3.0;
      out.findings.push_back(w);
    }
  }
  std::sort(out.findings.begin(), out.findings.end(),
            [](const Finding &a, const Finding &b) { return std::abs(a.zscore) > std::abs(b.zscore); });
  return out;
}

namespace {

// the reference beds' baseline as a one-knot model (its means, their variances)
EffectData reference_model(const Features &f)
{
  EffectData null;
  null.knots = {0.0};
  null.mean = {Table()};
  null.err = {Table()};
  for (std::size_t s = 0; s < f.nspeeds(); ++s) {
    null.mean[0].push_back(f.fresh[s].mean);
    null.err[0].push_back(f.fresh_err[s]);
  }
  return null;
}

std::vector<std::size_t> every_speed(const Features &f)
{
  std::vector<std::size_t> all(f.nspeeds());
  std::iota(all.begin(), all.end(), 0);
  return all;
}

}    // namespace

double baseline_scale_within_bound(const Target &t, const Features &f)
{
  EffectData null = reference_model(f);
  null.scale_bound = GapThresholds::calibration_scale_bound;
  return nuisance_scale(t, null, 0.0, every_speed(f));
}

double omnibus_chi2(const Target &t, const Features &f, double scale)
{
  return effect_chi2(t, reference_model(f), 0.0, every_speed(f), scale);
}

Significance gap_significance(const Features &f, const GapGrid &grid)
{
  Significance out;
  out.chi2_0 = omnibus_chi2(f.target, f);
  out.scale_within_bound = baseline_scale_within_bound(f.target, f);
  out.chi2_within_bound = omnibus_chi2(f.target, f, out.scale_within_bound);
  out.nfeatures = f.nspeeds() * grid.nfeatures();
  out.p_value = chi2_sf(out.chi2_0, (double) out.nfeatures);
  out.significant = out.p_value < GapThresholds::significance_p;
  return out;
}

HeldOut heldout_speed(const std::vector<SpeedCurves> &speeds)
{
  std::size_t hs = 0;
  for (std::size_t s = 0; s < speeds.size(); ++s)
    if (speeds[s].all_before() > speeds[hs].all_before()) hs = s;
  HeldOut h;
  h.index = hs;
  h.v0 = speeds.empty() ? 0.0 : speeds[hs].v0;
  h.gap = speeds.empty() ? 0.0 : speeds[hs].all_before();
  return h;
}

WhereResult where_stage(const Features &f, const RunsBySpeed &real, const SimulatedRuns &sims, const Scenario &sc,
                        const GapGrid &grid)
{
  WhereResult w;
  w.before = gap_curves(f, grid);
  const std::vector<double> ends = transient_ends(f, sims.fresh, sc, grid);
  for (std::size_t s = 0; s < w.before.speeds.size() && s < ends.size(); ++s) w.before.speeds[s].z_transient_end = ends[s];
  ObservableFindings found = observable_findings(f, real, sims, sc, grid, ends);
  w.findings = std::move(found.findings);
  w.notes = std::move(found.notes);
  w.omnibus = gap_significance(f, grid);
  w.heldout = heldout_speed(w.before.speeds);
  for (const auto &r : sims.fresh)
    for (const auto &x : r.second) w.baseline_files.push_back(x.path);
  return w;
}

RegimeGaps gap_by_regime(const GapGrid &grid, double peak_end, const std::vector<SpeedCurves> &speeds)
{
  const std::size_t nb = grid.nbins();
  RegimeGaps out;
  for (const char *reg : {"peak", "transient", "linear"}) {
    double sb = 0, sa = 0;
    int n = 0;
    for (const auto &c : speeds) {
      std::size_t b0 = 0, b1 = 0;
      for (std::size_t b = 0; b < nb; ++b) {
        const double z = grid.centre(b);
        const std::string r = z <= peak_end ? "peak" : (z <= c.z_transient_end ? "transient" : "linear");
        if (r == reg) {
          if (b1 == 0) b0 = b;
          b1 = b + 1;
        }
      }
      if (b1 == 0) continue;
      Ensemble R, B, C;
      R.mean = c.real, B.mean = c.base, C.mean = c.corr;
      R.runs.resize(1), B.runs.resize(1), C.runs.resize(1);    // the debiasing is in the overall G
      sb += gap_metric(R, B, b0, b1);
      sa += gap_metric(R, C, b0, b1);
      ++n;
    }
    if (n) out[reg] = {sb / n, sa / n};
  }
  return out;
}

}    // namespace granpen
