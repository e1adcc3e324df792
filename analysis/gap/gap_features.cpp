// granpen gap, stage 5 (features and noise model): see gap_features.h.
#include "gap_features.h"

#include "text_util.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

namespace granpen {

Ensemble ensemble_of(const std::vector<TraceRun> &runs, const GapGrid &grid, double v0)
{
  std::vector<std::vector<double>> x;
  for (const auto &r : runs) {
    const RunFeatures f = run_features(r.t, r.z, r.F, grid);
    if (!f.ok) throw InputError(r.path + ": " + f.note);
    x.push_back(f.x);
  }
  return make_ensemble(v0, x);
}

EnsembleMoments spectrum_moments(const std::vector<TraceRun> &runs, const GapGrid &grid)
{
  std::vector<std::vector<double>> a;
  for (const auto &r : runs) a.push_back(fluctuation_bands(r.t, r.z, r.F, grid.w, grid.zmax));
  return ensemble_moments(a);
}

std::vector<double> model_err(const Ensemble &e, const std::vector<double> &cv2, double scale)
{
  std::vector<double> v(e.mean.size());
  for (std::size_t k = 0; k < v.size(); ++k) v[k] = scale * cv2[k] * e.mean[k] * e.mean[k] / std::max<std::size_t>(1, e.n());
  return v;
}

double noise_scale(const Ensemble &eR, const Ensemble &eB, const std::vector<double> &cv2, const GapGrid &grid)
{
  const std::size_t P = grid.nfeatures(), nb = grid.nbins();
  if (eR.n() > 1) {
    double r = 0;
    for (std::size_t k = 0; k < P; ++k) r += eR.var[k] / (cv2[k] * eR.mean[k] * eR.mean[k] + 1e-300);
    return std::max(1.0, r / P);
  }
  double fr = 0, fs = 0;
  for (std::size_t k = nb; k < nb + grid.nwindows(); ++k) fr += eR.mean[k], fs += eB.mean[k];
  return fs > 0 ? std::max(1.0, std::pow(fr / fs, 2)) : 1.0;
}

std::vector<std::vector<std::size_t>> subsets(std::size_t n, std::size_t m)
{
  std::vector<std::vector<std::size_t>> out;
  std::vector<std::size_t> cur;
  std::function<void(std::size_t)> rec = [&](std::size_t i) {
    if (cur.size() == m) return out.push_back(cur);
    for (std::size_t j = i; j < n; ++j) cur.push_back(j), rec(j + 1), cur.pop_back();
  };
  if (m >= 1 && m <= n) rec(0);
  return out;
}

std::vector<Target> null_replicates(const Features &f, const GapGrid &grid, std::size_t m)
{
  const std::size_t ns = f.nspeeds(), P = grid.nfeatures(), nf = (std::size_t) f.n_reference;
  std::vector<Target> nulls;
  for (const auto &pick : subsets(nf, m)) {
    Target t;
    for (std::size_t s = 0; s < ns; ++s) {
      std::vector<std::vector<double>> x, y;
      for (std::size_t i = 0; i < nf; ++i)
        (std::find(pick.begin(), pick.end(), i) != pick.end() ? x : y).push_back(f.fresh[s].runs[i]);
      // against the models referenced to all reference beds: shifted by (all - rest), with the
      // variance of the rest in place of that of all of them
      const Ensemble e = make_ensemble(f.speeds[s], x), b = make_ensemble(f.speeds[s], y);
      const auto eb = model_err(b, f.cv2[s]);
      auto err = model_err(e, f.cv2[s], noise_scale(e, f.base[s], f.cv2[s], grid));
      std::vector<double> mean(P);
      for (std::size_t k = 0; k < P; ++k)
        mean[k] = e.mean[k] - b.mean[k] + f.fresh[s].mean[k], err[k] += std::max(0.0, eb[k] - f.fresh_err[s][k]);
      t.mean.push_back(mean);
      t.err.push_back(err);
    }
    nulls.push_back(t);
  }
  return nulls;
}

namespace {

// per speed: the ensembles, the noise model pooled over the ensembles on beds of their own,
// the measured target
void speed_ensembles(Features &f, std::size_t s, const RunsBySpeed &real, const SimulatedRuns &sims,
                     const std::vector<const Effect *> &effects, const GapGrid &grid)
{
  const double v = f.speeds[s];
  f.real[s] = ensemble_of(real.at(v), grid, v);
  f.spec_real[s] = spectrum_moments(real.at(v), grid);
  f.base[s] = ensemble_of(sims.base.at(v), grid, v);
  // the noise model pools ensembles on beds of their own: a push-only effect's runs
  // repeat the baseline's beds, and would count the same bed-to-bed difference again. The
  // reference beds (seeds 11 to 14) are beds of their own too: with them a library of
  // push-only effects alone (--effects measurement_chain) still has 4 degrees of freedom
  // per speed, not the baseline's 1 (with 1, 3 of 6 null replicates came out unexplained)
  f.fresh[s] = ensemble_of(sims.fresh.at(v), grid, v);
  std::vector<const Ensemble *> pool{&f.base[s], &f.fresh[s]};
  for (auto &[name, by] : sims.knots) {
    f.knots[name].resize(f.nspeeds());
    f.knots[name][s] = ensemble_of(by.at(v), grid, v);
  }
  for (const Effect *e : effects)
    if (e->pour_level)
      for (double a : e->knots) pool.push_back(&f.knots[effect_sweep_name(*e, a)][s]);
  int dof = 0;
  f.cv2[s] = pooled_cv2(pool, grid, 1e-4, &dof);
  f.dof_min = std::min(f.dof_min, dof);
  const double scale = noise_scale(f.real[s], f.base[s], f.cv2[s], grid);
  if (scale > 1.5)
    f.notes.push_back("v0 = " + printf_number("%.4g", v) + ": the measured runs scatter " +
                      printf_number("%.2f", std::sqrt(scale)) + " times more than the simulated ones; their noise is taken as that");
  f.target_scale.push_back(scale);
  f.target.mean.push_back(f.real[s].mean);
  f.target.err.push_back(model_err(f.real[s], f.cv2[s], scale));
}

}    // namespace

Features build_features(const RunsBySpeed &real, const SimulatedRuns &sims, const std::vector<const Effect *> &effects,
                        const GapGrid &grid, std::size_t n_real_files)
{
  Features f;
  for (const auto &[v, _] : real) f.speeds.push_back(v);
  const std::size_t ns = f.nspeeds();
  f.real.resize(ns), f.base.resize(ns), f.fresh.resize(ns), f.cv2.resize(ns), f.fresh_err.resize(ns);
  f.spec_real.resize(ns), f.spec_fresh.resize(ns);
  f.dof_min = 1 << 30;
  for (std::size_t s = 0; s < ns; ++s) speed_ensembles(f, s, real, sims, effects, grid);
  // The fits see the gap against the baseline on the reference beds (seeds 11 to 14), not
  // against the signature beds (1, 2): an effect's signature is a difference to the
  // signature beds, and a gap measured against those same beds would share their noise
  // with every signature (a pure-noise "gap" would then look like each effect). So every
  // effect's model is referenced to them: M(a) = B_ref + (I(a) - B_sig) (EffectData::
  // ref_err); its residual at magnitude 0 is T - B_ref, independent of the signatures.
  for (std::size_t s = 0; s < ns; ++s) {
    f.fresh_err[s] = model_err(f.fresh[s], f.cv2[s]);
    f.spec_fresh[s] = spectrum_moments(sims.fresh.at(f.speeds[s]), grid);
  }
  // null replicates: the reference beds split in two, one part taken as a measurement
  // without any effect (as many runs as the measurement has, leaving at least two), the rest
  // as its reference, processed as the measurement is
  std::size_t nf = 1 << 30;
  for (std::size_t s = 0; s < ns; ++s) nf = std::min(nf, sims.fresh.at(f.speeds[s]).size());
  if (nf < 3) throw InputError("the reference beds (sweep fresh_baseline) need at least 3 runs per speed for the null replicates");
  f.n_reference = (int) nf;
  const std::size_t m = std::clamp<std::size_t>(n_real_files / std::max<std::size_t>(1, ns), 1, nf - 2);
  f.nulls = null_replicates(f, grid, m);
  f.notes.push_back("noise model: run-to-run scatter of every simulated ensemble pooled per speed and feature (" +
                    std::to_string(f.dof_min) + " degrees of freedom), relative to the mean, smoothed over neighbouring depths");
  return f;
}

std::vector<std::string> feature_dump(const Features &f)
{
  std::vector<std::string> out;
  for (std::size_t s = 0; s < f.nspeeds(); ++s) {
    auto row = [&](const char *name, const std::vector<double> &x) {
      char head[64];
      std::snprintf(head, sizeof head, "%-28s v0 %-5g", name, f.speeds[s]);
      std::string line = head;
      for (double y : x) line += printf_number(" %9.4g", y);
      out.push_back(line);
    };
    row("measured", f.real[s].mean);
    row("baseline", f.base[s].mean);
    row("reference baseline", f.fresh[s].mean);
    for (auto &[name, es] : f.knots) row(name.c_str(), es[s].mean);
    row("cv2", f.cv2[s]);
  }
  return out;
}

}    // namespace granpen
