// granpen gap, stage 7 (which): see gap_which.h.
#include "gap_which.h"

#include "gap_limits.h"
#include "gap_verdict.h"
#include "gap_where.h"
#include "text_util.h"

#include <algorithm>
#include <numeric>

namespace granpen {

namespace {

std::string fmt(double v, const char *f = "%.4g") { return printf_number(f, v); }

double mean_of(const std::vector<double> &v)
{
  return v.empty() ? 0.0 : std::accumulate(v.begin(), v.end(), 0.0) / v.size();
}

// variance of the mean of the paired differences knot - baseline, run by run on the same
// beds (same seed order), per feature; floor: 1e-4 relative, as for the ensembles
std::vector<double> paired_err(const Ensemble &knot, const Ensemble &base)
{
  const std::size_t P = knot.mean.size(), n = std::min(knot.n(), base.n());
  std::vector<double> dv(P, 0.0);
  for (std::size_t k = 0; k < P; ++k) {
    std::vector<double> dd;
    for (std::size_t i = 0; i < n; ++i) dd.push_back(knot.runs[i][k] - base.runs[i][k]);
    const double md = mean_of(dd);
    double ss = 0;
    for (double x : dd) ss += (x - md) * (x - md);
    const double var = n > 1 ? ss / (n - 1) : 0.0;
    dv[k] = std::max(var, 1e-4 * knot.mean[k] * knot.mean[k]) / std::max<std::size_t>(1, n);
  }
  return dv;
}

// knot 0 then e's knots, ascending, with their sweeps ("" = the signature baseline)
std::vector<std::pair<double, std::string>> knot_sweeps(const Effect &e)
{
  std::vector<std::pair<double, std::string>> ks{{0.0, ""}};
  for (double a : e.knots) ks.push_back({a, effect_sweep_name(e, a)});
  std::sort(ks.begin(), ks.end());
  return ks;
}

// The width of e's magnitude range over every knot the library gives e (a part of it, the
// cheap stage's transform knots, included): magnitude_range's rule on the whole effect.
double library_span(const Effect &e, const EffectData &ed)
{
  const Effect *whole = &e;
  for (const Effect &x : effect_library())
    if (x.name == e.name) whole = &x;
  EffectData w;
  w.knots = {0.0};
  w.knots.insert(w.knots.end(), whole->knots.begin(), whole->knots.end());
  std::sort(w.knots.begin(), w.knots.end());
  w.one_sided = ed.one_sided;
  w.reach = ed.reach;
  const auto [lo, hi] = magnitude_range(w);
  return hi - lo;
}

}    // namespace

EffectData effect_data(const Effect &e, const Features &f)
{
  const std::size_t ns = f.nspeeds();
  EffectData ed;
  ed.name = e.name;
  ed.paired = !e.pour_level;
  ed.one_sided = e.one_sided;
  for (const auto &[a, name] : knot_sweeps(e)) {
    ed.knots.push_back(a);
    Table m, er, de;
    for (std::size_t s = 0; s < ns; ++s) {
      const Ensemble &en = name.empty() ? f.base[s] : f.knots.at(name)[s];
      m.push_back(en.mean);
      er.push_back(model_err(en, f.cv2[s]));
      de.push_back(ed.paired && !name.empty() ? paired_err(en, f.base[s]) : std::vector<double>(en.mean.size(), 0.0));
    }
    ed.mean.push_back(m);
    ed.err.push_back(er);
    ed.diff_err.push_back(de);
  }
  // referenced to the reference beds: every knot shifted by B_ref - B_sig, knot 0's
  // variance the reference's, the signature baseline's carried by ref_err
  const std::size_t j0 = (std::size_t) (std::find(ed.knots.begin(), ed.knots.end(), 0.0) - ed.knots.begin());
  ed.ref_err.assign(1, Table());
  for (std::size_t s = 0; s < ns; ++s) {
    for (auto &knot : ed.mean)
      for (std::size_t k = 0; k < knot[s].size(); ++k) knot[s][k] += f.fresh[s].mean[k] - f.base[s].mean[k];
    ed.ref_err[0].push_back(ed.err[j0][s]);
    ed.err[j0][s] = f.fresh_err[s];
  }
  // every candidate fitted jointly with a force scale within a lab's calibration bound: a
  // nuisance, not a cause (gap_thresholds.h, calibration_scale_bound)
  ed.scale_bound = GapThresholds::calibration_scale_bound;
  ed.is_scale = e.uniform_scale;
  ed.library_span = library_span(e, ed);
  ed.noise_r2 = noise_residual(f.nulls, ed);
  return ed;
}

EffectFit fit_candidate(const EffectData &ed, const Features &f)
{
  EffectFit fit = fit_effect(f.target, ed);
  for (const auto &t : f.nulls) fit.lr_nulls.push_back(effect_lr(t, ed));
  fit.lr_null_mean = f.nulls.empty() ? 0.0 : mean_of(fit.lr_nulls);
  fit.lr_threshold = lr_threshold(fit.lr_null_mean);
  fit.detected = fit.lr > fit.lr_threshold && !fit.at_edge;
  return fit;
}

FalseAlarms null_false_alarms(const std::vector<const Effect *> &effects, const std::map<std::string, EffectData> &data,
                              const std::vector<EffectFit> &fits, const Features &f)
{
  FalseAlarms fa;
  const std::size_t P = f.nspeeds() && !f.real.empty() ? f.real[0].mean.size() : 0;
  for (std::size_t i = 0; i < f.nulls.size(); ++i) {
    std::vector<EffectFit> ranking;
    for (const Effect *e : effects) {
      const EffectData &ed = data.at(e->name);
      EffectFit fit = fit_effect(f.nulls[i], ed);
      // the threshold from the other replicates: replicate i must not calibrate its own test
      const auto it = std::find_if(fits.begin(), fits.end(), [&](const EffectFit &x) { return x.name == e->name; });
      std::vector<double> others;
      for (std::size_t j = 0; it != fits.end() && j < it->lr_nulls.size(); ++j)
        if (j != i) others.push_back(it->lr_nulls[j]);
      fit.lr_null_mean = others.empty() ? 0.0 : mean_of(others);
      fit.lr_threshold = lr_threshold(fit.lr_null_mean);
      fit.detected = fit.lr > fit.lr_threshold && !fit.at_edge;
      ranking.push_back(fit);
    }
    const double chi2_0 = omnibus_chi2(f.nulls[i], f);
    const bool omnibus = chi2_sf(chi2_0, (double) (f.nspeeds() * P)) < GapThresholds::significance_p;
    const Verdict v = decide_verdict(fit_evidence(omnibus, std::move(ranking))).verdict;
    ++fa.replicates, ++fa.verdicts[verdict_name(v)];
    fa.not_none += v != Verdict::none;
  }
  return fa;
}

std::string packing_note(const EffectData &ed, double a, const std::vector<double> &phi, double phi_baseline)
{
  std::size_t i = 0;
  while (i + 2 < ed.knots.size() && a > ed.knots[i + 1]) ++i;
  const double w = (a - ed.knots[i]) / (ed.knots[i + 1] - ed.knots[i]);
  const double p = (1 - w) * phi[i] + w * phi[i + 1];
  return "pour friction " + fmt(0.3 + a, "%.3f") + ": phi_0 " + fmt(p, "%.4f") + " against the baseline's " +
         fmt(phi_baseline, "%.4f");
}

FittedCandidates fit_candidates(const std::vector<const Effect *> &effects, const Features &f,
                                const std::function<double(const std::string &)> &phi0, const Significance &omnibus)
{
  FittedCandidates out;
  std::vector<EffectFit> fits;
  for (const Effect *e : effects) {
    EffectData ed = effect_data(*e, f);
    fits.push_back(fit_candidate(ed, f));
    if (e->pour_mu_at) {
      // packing: the phi_0 the fitted pour friction makes, interpolated between the beds'
      std::vector<double> phi;
      for (const auto &[a, name] : knot_sweeps(*e)) phi.push_back(phi0(name.empty() ? "baseline" : name));
      out.magnitude_note[e->name] = packing_note(ed, fits.back().magnitude, phi, phi0("baseline"));
    }
    out.data[e->name] = std::move(ed);
  }
  // the top two told apart by the data, not only by the evidence margin (gap_verdict.h)
  const NoiseFactors now(f.target.mean.size(), 1.0);
  const auto &data = out.data;
  out.evidence = fit_evidence(omnibus.significant, std::move(fits), [&](const EffectFit &a, const EffectFit &b) {
    return prediction_separation2(data.at(a.name), a.magnitude, a.scale, data.at(b.name), b.magnitude, b.scale, f.target, now);
  }, [&](const EffectFit &top, const EffectFit &other) {
    const BelowLimitMimic m = below_limit_mimic(data.at(top.name), top, data.at(other.name), other, f.target);
    return std::make_pair(m.separation2, m.magnitude);
  });
  out.evidence.chi2_0 = omnibus.chi2_0, out.evidence.p_value = omnibus.p_value, out.evidence.nfeatures = omnibus.nfeatures;
  out.evidence.n_null = (int) f.nulls.size();
  return out;
}

}    // namespace granpen
