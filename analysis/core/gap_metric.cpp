// granpen analysis: the overall gap, gap-metric v2 (see gap_metric.h).
#include "gap_metric.h"

#include <algorithm>
#include <cmath>
#include <complex>

#include <unsupported/Eigen/FFT>

namespace granpen {

const std::vector<double> &gap_spectrum_bands()
{
  static const std::vector<double> edges = {50, 150, 450, 1350, 4050};
  return edges;
}

namespace {

// bin of depth z: b holds (b w, (b + 1) w]; npos outside 0 < z <= zmax
constexpr std::size_t NO_BIN = (std::size_t) -1;
std::size_t bin_of(double z, double w, std::size_t nb)
{
  if (!(z > 0.0)) return NO_BIN;
  std::size_t b = (std::size_t) std::ceil(z / w - 1e-12);
  if (b == 0) b = 1;
  return --b < nb ? b : NO_BIN;
}

// the fluctuation of F about its bin means (or the line through the bin centres), in
// sample order, and the sample times
void fluctuation(const std::vector<double> &t, const std::vector<double> &z, const std::vector<double> &F, double w,
                 double zmax, Detrend detrend, std::vector<double> &y, std::vector<double> &ty)
{
  const std::size_t n = std::min({t.size(), z.size(), F.size()});
  const std::size_t nb = (std::size_t) std::floor(zmax / w + 1e-9);
  std::vector<double> sum(nb, 0.0);
  std::vector<std::size_t> cnt(nb, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t b = z[i] <= zmax ? bin_of(z[i], w, nb) : NO_BIN;
    if (b != NO_BIN) sum[b] += F[i], ++cnt[b];
  }
  std::vector<double> mean(nb, 0.0);
  for (std::size_t b = 0; b < nb; ++b) mean[b] = cnt[b] ? sum[b] / cnt[b] : 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t b = z[i] <= zmax ? bin_of(z[i], w, nb) : NO_BIN;
    if (b == NO_BIN) continue;
    double m = mean[b];
    if (detrend == Detrend::BinCentreLine) {
      const double u = std::clamp(z[i] / w - 0.5, 0.0, (double) nb - 1.0);
      const std::size_t c = std::min(nb - 1, (std::size_t) u);
      const double f = u - c;
      m = c + 1 < nb ? (1 - f) * mean[c] + f * mean[c + 1] : mean[c];
    }
    y.push_back(F[i] - m);
    ty.push_back(t[i]);
  }
}

}    // namespace

Periodogram fluctuation_periodogram(const std::vector<double> &t, const std::vector<double> &z,
                                    const std::vector<double> &F, double w, double zmax, Detrend detrend)
{
  Periodogram p;
  std::vector<double> y, ty;
  if (w > 0.0 && zmax >= w) fluctuation(t, z, F, w, zmax, detrend, y, ty);
  const std::size_t n = y.size();
  if (n < 8 || !(ty.back() > ty.front())) return p;
  p.n = n;
  p.dt = (ty.back() - ty.front()) / (n - 1);
  double wsum = 0.0;
  std::vector<double> yw(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double hann = 0.5 - 0.5 * std::cos(2.0 * M_PI * i / (n - 1));
    yw[i] = y[i] * hann;
    wsum += hann * hann;
  }
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> X;
  fft.fwd(X, yw);
  // one-sided, normalised so that the bins sum to the mean square of y (wsum = N mean(w^2))
  for (std::size_t j = 1; j <= n / 2; ++j) {
    p.freq.push_back(j / (n * p.dt));
    p.power.push_back(2.0 * std::norm(X[j]) / (n * wsum));
  }
  return p;
}

std::vector<double> band_rms(const Periodogram &p, const std::vector<double> &edges)
{
  const std::size_t nbands = edges.size() > 1 ? edges.size() - 1 : 0;
  std::vector<double> a(nbands, 0.0);
  for (std::size_t k = 0; k < nbands; ++k) {
    double s = 0.0;
    for (std::size_t j = 0; j < p.freq.size(); ++j)
      if (p.freq[j] >= edges[k] && p.freq[j] < edges[k + 1]) s += p.power[j];
    a[k] = std::sqrt(s);
  }
  return a;
}

std::vector<double> fluctuation_bands(const std::vector<double> &t, const std::vector<double> &z,
                                      const std::vector<double> &F, double w, double zmax,
                                      const std::vector<double> &edges, Detrend detrend)
{
  return band_rms(fluctuation_periodogram(t, z, F, w, zmax, detrend), edges);
}

EnsembleMoments ensemble_moments(const std::vector<std::vector<double>> &runs)
{
  EnsembleMoments m;
  m.runs = runs.size();
  if (runs.empty()) return m;
  const std::size_t p = runs[0].size();
  m.mean.assign(p, 0.0);
  m.sq_se.assign(p, 0.0);
  for (const auto &r : runs)
    for (std::size_t k = 0; k < p && k < r.size(); ++k) m.mean[k] += r[k] / runs.size();
  if (runs.size() < 2) return m;
  const double n = (double) runs.size();
  for (const auto &r : runs)
    for (std::size_t k = 0; k < p && k < r.size(); ++k) m.sq_se[k] += std::pow(r[k] - m.mean[k], 2) / ((n - 1) * n);
  return m;
}

double debiased_gap(const EnsembleMoments &real, const EnsembleMoments &sim, std::size_t k0, std::size_t k1)
{
  double num = 0.0, den = 0.0;
  const std::size_t end = std::min({k1, real.mean.size(), sim.mean.size()});
  for (std::size_t k = k0; k < end; ++k) {
    const double eR = k < real.sq_se.size() ? real.sq_se[k] : 0.0, eS = k < sim.sq_se.size() ? sim.sq_se[k] : 0.0;
    num += std::pow(real.mean[k] - sim.mean[k], 2) - eR - eS;
    den += real.mean[k] * real.mean[k];
  }
  return den > 0.0 ? std::sqrt(std::max(0.0, num) / den) : 0.0;
}

double gap_all(double G, double G_spec) { return std::hypot(G, G_spec); }

}    // namespace granpen
