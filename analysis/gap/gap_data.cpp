#include "gap_data.h"

#include "collapse.h"
#include "gap_metric.h"
#include "scaling_laws.h"
#include "linear_fit.h"
#include "trace_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace granpen {

std::size_t GapGrid::nbins() const { return (std::size_t) std::floor(zmax / w + 1e-9); }
std::size_t GapGrid::nwindows() const { return (std::size_t) std::floor(zmax / window + 1e-9); }

RunFeatures run_features(const std::vector<double> &t, const std::vector<double> &z, const std::vector<double> &F,
                         const GapGrid &grid)
{
  RunFeatures r;
  const std::size_t nb = grid.nbins(), nw = grid.nwindows();
  std::vector<double> sum(nb, 0.0), sum2(nb, 0.0);
  std::vector<std::size_t> cnt(nb, 0);
  for (std::size_t i = 0; i < std::min(z.size(), F.size()); ++i) {
    if (!(z[i] > 0.0) || z[i] > grid.zmax) continue;
    // bin b holds (b w, (b + 1) w]
    std::size_t b = (std::size_t) std::ceil(z[i] / grid.w - 1e-12);
    if (b == 0) b = 1;
    if (--b >= nb) continue;
    sum[b] += F[i];
    sum2[b] += F[i] * F[i];
    ++cnt[b];
  }
  r.x.assign(grid.nfeatures(), 0.0);
  std::vector<double> sd(nb, 0.0);
  for (std::size_t b = 0; b < nb; ++b) {
    if (cnt[b] == 0) {
      r.note = "no samples in depth bin (" + std::to_string(b * grid.w) + ", " + std::to_string((b + 1) * grid.w) +
               "] cm: the run is shorter than the common depth";
      return r;
    }
    const double m = sum[b] / cnt[b];
    r.x[b] = m;
    sd[b] = cnt[b] > 1 ? std::sqrt(std::max(0.0, (sum2[b] - cnt[b] * m * m) / (cnt[b] - 1))) : 0.0;
  }
  const std::size_t per = nb / std::max<std::size_t>(1, nw);
  for (std::size_t k = 0; k < nw; ++k) {
    double s = 0.0;
    for (std::size_t b = k * per; b < (k + 1) * per; ++b) s += sd[b];
    r.x[nb + k] = s / per;
  }
  // spectrum of F about its bin means (the line through the bin centres) over the grid: the
  // metric's kernel (core/gap_metric.h) without the sawtooth of a rising F against its bins
  const std::size_t nbd = grid.nbands();
  if (nbd) {
    const Periodogram p = fluctuation_periodogram(t, z, F, grid.w, grid.zmax, Detrend::BinCentreLine);
    if (p.n < 8) {
      r.note = "fewer than 8 samples over the common depth: no spectrum";
      return r;
    }
    const auto a = band_rms(p, grid.bands);
    std::copy(a.begin(), a.end(), r.x.begin() + nb + nw);
  }
  r.ok = true;
  return r;
}

Ensemble make_ensemble(double v0, const std::vector<std::vector<double>> &runs)
{
  Ensemble e;
  e.v0 = v0;
  e.runs = runs;
  if (runs.empty()) return e;
  const std::size_t p = runs[0].size();
  e.mean.assign(p, 0.0);
  e.var.assign(p, 0.0);
  for (const auto &r : runs) {
    if (r.size() != p) throw std::invalid_argument("make_ensemble: runs of different lengths");
    for (std::size_t k = 0; k < p; ++k) e.mean[k] += r[k] / runs.size();
  }
  if (runs.size() > 1)
    for (const auto &r : runs)
      for (std::size_t k = 0; k < p; ++k) e.var[k] += std::pow(r[k] - e.mean[k], 2) / (runs.size() - 1);
  return e;
}

std::vector<double> pooled_cv2(const std::vector<const Ensemble *> &ensembles, const GapGrid &grid,
                               double min_cv2, int *dof)
{
  const std::size_t p = grid.nfeatures(), nb = grid.nbins();
  std::vector<double> s(p, 0.0);
  int d = 0;
  for (const Ensemble *e : ensembles) {
    if (!e || e->n() < 2 || e->mean.size() != p) continue;
    for (const auto &r : e->runs)
      for (std::size_t k = 0; k < p; ++k)
        if (std::abs(e->mean[k]) > 0.0) s[k] += std::pow((r[k] - e->mean[k]) / e->mean[k], 2);
    d += (int) e->n() - 1;
  }
  if (dof) *dof = d;
  std::vector<double> cv2(p, min_cv2);
  if (d == 0) return cv2;
  for (std::size_t k = 0; k < p; ++k) s[k] /= d;
  // smooth over the neighbours of the same kind (bins with bins, windows with windows):
  // each estimate rests on few runs, neighbouring depths share the physics
  const std::size_t nw = grid.nwindows();
  for (std::size_t k = 0; k < p; ++k) {
    const std::size_t lo = k < nb ? 0 : (k < nb + nw ? nb : nb + nw), hi = k < nb ? nb : (k < nb + nw ? nb + nw : p);
    double acc = 0.0;
    int m = 0;
    for (std::size_t j = (k > lo ? k - 1 : k); j <= std::min(hi - 1, k + 1); ++j) acc += s[j], ++m;
    cv2[k] = std::max(min_cv2, acc / m);
  }
  return cv2;
}

EnsembleMoments moments_of(const Ensemble &e)
{
  EnsembleMoments m;
  m.runs = e.n();
  m.mean = e.mean;
  m.sq_se.assign(e.mean.size(), 0.0);
  if (e.n() > 1)
    for (std::size_t k = 0; k < e.var.size() && k < m.sq_se.size(); ++k) m.sq_se[k] = e.var[k] / e.n();
  return m;
}

double gap_metric(const Ensemble &real, const Ensemble &sim, std::size_t b0, std::size_t b1)
{
  return debiased_gap(moments_of(real), moments_of(sim), b0, b1);
}

RunObservables run_observables(const std::vector<double> &z, const std::vector<double> &F, double v0, double D,
                               double g, double d_g, const GapGrid &grid, double z_transient_end)
{
  RunObservables o;
  TraceFitParams p;
  p.zlo = grid.zmax / 2.0;
  p.zhi = grid.zmax;
  p.v0 = v0;
  p.D = D;
  p.g = g;
  p.d_g = d_g;
  const TraceFit fit = fit_trace(z, F, p);
  o.peak_F = fit.peak_F;
  o.peak_z = fit.peak_z;
  o.k_z = fit.k_z;
  o.wavelength = fit.wavelength_ok ? fit.wavelength : 0.0;
  // fluctuation level about the deep fit
  double ss = 0.0, sm = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < z.size(); ++i)
    if (z[i] >= p.zlo && z[i] <= p.zhi) {
      ss += std::pow(F[i] - (fit.intercept + fit.k_z * z[i]), 2);
      sm += F[i];
      ++n;
    }
  o.fluct = (n > 1 && sm > 0.0) ? std::sqrt(ss / n) / (sm / n) : 0.0;
  // transient excess over F_z = k_z z between the peak region and the regime's end
  GapGrid bins_only = grid;
  bins_only.bands.clear();
  const RunFeatures rf = run_features(z, z, F, bins_only);    // bin means only (t unused)
  if (rf.ok)
    for (std::size_t b = 0; b < grid.nbins(); ++b) {
      const double zc = grid.centre(b);
      if (zc > peak_regime_end(D) && zc <= z_transient_end) o.excess += (rf.x[b] - o.k_z * zc) * grid.w;
    }
  if (o.k_z > 0.0) {
    CollapseInput in;
    in.z = z;
    in.F = F;
    in.v0 = v0;
    in.D = D;
    in.g = g;
    in.k_z = o.k_z;
    const CollapseResult c = collapse({in}, CollapseParams{});
    o.crossed = c.curves[0].crossed;
    o.t_star = c.curves[0].t_star;
  }
  return o;
}

}    // namespace granpen
