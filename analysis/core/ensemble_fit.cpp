// granpen analysis: observables of ensembles with bootstrap uncertainties (see ensemble_fit.h).
#include "ensemble_fit.h"

#include <cmath>
#include <random>
#include <stdexcept>

namespace granpen {

namespace {

// The replicate values of one number, and its Estimate.
struct Replicates {
  std::vector<double> v;
  void add(bool ok, double x)
  {
    if (ok && std::isfinite(x)) v.push_back(x);
  }
  Estimate estimate(bool ok, double value, std::size_t runs) const
  {
    Estimate e;
    e.ok = ok;
    e.value = ok ? value : 0.0;
    e.defined = (int) v.size();
    if (runs < 2 || v.size() < 2) return e;
    double m = 0.0, s2 = 0.0;
    for (double x : v) m += x;
    m /= (double) v.size();
    for (double x : v) s2 += (x - m) * (x - m);
    const double sd = std::sqrt(s2 / (double) (v.size() - 1));
    e.se_ok = true;
    e.se = sd * std::sqrt((double) runs / (double) (runs - 1));
    if (e.se <= 1e-12 * std::fabs(value)) e.se = 0.0;    // the same in every resample: round-off only
    e.ci95 = t95((int) runs - 1) * e.se;
    return e;
  }
};

// n draws of 0 .. n-1 with replacement
void draw(std::mt19937_64 &gen, std::size_t n, std::vector<std::size_t> &pick)
{
  std::uniform_int_distribution<std::size_t> u(0, n - 1);
  pick.resize(n);
  for (auto &i : pick) i = u(gen);
}

int resamples_for(std::size_t runs, const BootstrapParams &b) { return runs >= 2 ? std::max(0, b.resamples) : 0; }

}    // namespace

EnsembleFit fit_ensemble(const EnsembleMean &e, const TraceFitParams &p, const BootstrapParams &b)
{
  EnsembleFit out;
  out.runs = e.runs;
  out.fit = fit_trace(e.z, e.mean, p);
  out.resamples = resamples_for(e.runs, b);
  Replicates kz, a, al, kz0, al0, pf, pz, wl;
  std::mt19937_64 gen(b.seed);
  std::vector<std::size_t> pick;
  std::vector<double> F;
  for (int r = 0; r < out.resamples; ++r) {
    draw(gen, e.runs, pick);
    resample_mean(e, pick, F);
    const TraceFit f = fit_trace(e.z, F, p);
    kz.add(f.slope_ok, f.k_z), a.add(f.slope_ok, f.intercept), kz0.add(f.slope_ok, f.k_z0);
    al.add(f.alpha_ok, f.alpha), al0.add(f.alpha_ok, f.alpha0);
    pf.add(f.peak_ok, f.peak_F), pz.add(f.peak_ok, f.peak_z);
    wl.add(f.wavelength_ok, f.wavelength);
  }
  const TraceFit &f = out.fit;
  const std::size_t n = e.runs;
  out.k_z = kz.estimate(f.slope_ok, f.k_z, n);
  out.intercept = a.estimate(f.slope_ok, f.intercept, n);
  out.k_z0 = kz0.estimate(f.slope_ok, f.k_z0, n);
  out.alpha = al.estimate(f.alpha_ok, f.alpha, n);
  out.alpha0 = al0.estimate(f.alpha_ok, f.alpha0, n);
  out.peak_F = pf.estimate(f.peak_ok, f.peak_F, n);
  out.peak_z = pz.estimate(f.peak_ok, f.peak_z, n);
  out.wavelength = wl.estimate(f.wavelength_ok, f.wavelength, n);
  return out;
}

namespace {

double depth_term_of(const EnsembleCase &c, const std::vector<double> &F)
{
  if (c.k_z_fixed > 0.0) return c.k_z_fixed;
  const TraceFit f = fit_trace(c.mean.z, F, c.kz_fit);
  return f.slope_ok && f.k_z > 0.0 ? f.k_z : 0.0;
}

CollapseInput input_of(const EnsembleCase &c, const std::vector<double> &F, double k_z)
{
  CollapseInput in;
  in.name = c.name;
  in.z = c.mean.z;
  in.F = F;
  in.v0 = c.v0, in.D = c.D, in.g = c.g;
  in.k_z = k_z;
  return in;
}

}    // namespace

double ensemble_depth_term(const EnsembleCase &c) { return depth_term_of(c, c.mean.mean); }

EnsembleCollapse collapse_ensembles(const std::vector<EnsembleCase> &cases, const CollapseParams &p,
                                    const BootstrapParams &b)
{
  if (cases.empty()) throw std::invalid_argument("collapse_ensembles: no ensemble");
  std::vector<CollapseInput> in;
  std::size_t fewest = cases.front().mean.runs;
  for (const auto &c : cases) {
    const double k = ensemble_depth_term(c);
    if (!(k > 0.0)) throw std::invalid_argument(c.name + ": no positive depth term on the ensemble mean");
    in.push_back(input_of(c, c.mean.mean, k));
    fewest = std::min(fewest, c.mean.runs);
  }
  EnsembleCollapse out;
  out.result = collapse(in, p);
  out.resamples = resamples_for(fewest, b);
  const std::size_t nc = cases.size();
  std::vector<Replicates> kz(nc), peak(nc), tstar(nc);
  Replicates tmean, tens, sz, st, pe;
  std::mt19937_64 gen(b.seed);
  std::vector<std::size_t> pick;
  std::vector<double> F;
  for (int r = 0; r < out.resamples; ++r) {
    std::vector<CollapseInput> rin;
    bool usable = true;
    for (const auto &c : cases) {
      draw(gen, c.mean.runs, pick);
      resample_mean(c.mean, pick, F);
      const double k = depth_term_of(c, F);
      usable = usable && k > 0.0;
      rin.push_back(input_of(c, F, k));
    }
    if (!usable) continue;    // a resample without a positive k_z: no F/F_z
    ++out.usable;
    const CollapseResult cr = collapse(rin, p);
    for (std::size_t i = 0; i < nc; ++i) {
      kz[i].add(true, cr.curves[i].k_z);
      peak[i].add(cr.curves[i].peak > 0.0, cr.curves[i].peak);
      tstar[i].add(cr.curves[i].crossed, cr.curves[i].t_star);
    }
    tmean.add(cr.n_crossed > 0, cr.t_star_mean);
    tens.add(cr.ens_crossed, cr.t_star_ensemble);
    sz.add(true, cr.spread_z), st.add(true, cr.spread_t);
    pe.add(cr.peak_law.ok, cr.peak_law.exponent);
  }
  const CollapseResult &R = out.result;
  for (std::size_t i = 0; i < nc; ++i) {
    const std::size_t n = cases[i].mean.runs;
    out.k_z.push_back(kz[i].estimate(true, R.curves[i].k_z, n));
    if (cases[i].k_z_fixed > 0.0) out.k_z.back().se_ok = false, out.k_z.back().se = out.k_z.back().ci95 = 0.0;    // given
    out.peak.push_back(peak[i].estimate(R.curves[i].peak > 0.0, R.curves[i].peak, n));
    out.t_star.push_back(tstar[i].estimate(R.curves[i].crossed, R.curves[i].t_star, n));
  }
  out.t_star_mean = tmean.estimate(R.n_crossed > 0, R.t_star_mean, fewest);
  out.t_star_ensemble = tens.estimate(R.ens_crossed, R.t_star_ensemble, fewest);
  out.spread_z = sz.estimate(true, R.spread_z, fewest);
  out.spread_t = st.estimate(true, R.spread_t, fewest);
  out.peak_exponent = pe.estimate(R.peak_law.ok, R.peak_law.exponent, fewest);
  return out;
}

PeakLaw peak_law_of_means(const EnsembleCollapse &c)
{
  PeakLaw law = c.result.peak_law;
  law.exponent_se = c.peak_exponent.se, law.exponent_ci95 = c.peak_exponent.ci95;
  return law;
}

}    // namespace granpen
