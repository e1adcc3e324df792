/* ----------------------------------------------------------------------
   granpen analysis: observables of one force trace (see trace_fit.h).
------------------------------------------------------------------------- */

#include "trace_fit.h"

#include "linear_fit.h"
#include "scaling_laws.h"

#include <unsupported/Eigen/FFT>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <numeric>
#include <stdexcept>
#include <utility>

namespace granpen {

namespace {

constexpr double PI = 3.14159265358979323846;

std::string fmt(double v)
{
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::size_t largest_prime_factor(std::size_t n)
{
  std::size_t p = 1;
  for (std::size_t f = 2; f * f <= n; ++f)
    while (n % f == 0) p = f, n /= f;
  return n > 1 ? std::max(p, n) : p;
}

// the largest number <= n whose prime factors are 2, 3 and 5 (kissfft's fast radices)
std::size_t smooth_at_most(std::size_t n)
{
  std::size_t best = 1;
  for (std::size_t a = 1; a <= n; a *= 2)
    for (std::size_t b = a; b <= n; b *= 3)
      for (std::size_t c = b; c <= n; c *= 5) best = std::max(best, c);
  return best;
}

// the finite samples with wlo <= z <= whi
void window_samples(const std::vector<double> &z, const std::vector<double> &F, double wlo, double whi,
                    std::vector<double> &zw, std::vector<double> &Fw)
{
  zw.clear(), Fw.clear();
  for (std::size_t i = 0; i < z.size(); ++i)
    if (z[i] >= wlo && z[i] <= whi && std::isfinite(F[i])) {
      zw.push_back(z[i]);
      Fw.push_back(F[i]);
    }
}

std::size_t distinct_depths(std::vector<double> zw)
{
  std::sort(zw.begin(), zw.end());
  return (std::size_t) (std::unique(zw.begin(), zw.end()) - zw.begin());
}

std::string window_name(double zlo, double zhi)
{
  return std::isfinite(zhi) ? "z = " + fmt(zlo) + ".." + fmt(zhi) + " cm" : "z >= " + fmt(zlo) + " cm";
}

}    // namespace

Wavelength dominant_wavelength(const std::vector<double> &z, const std::vector<double> &y)
{
  Wavelength w;
  if (z.size() != y.size()) throw std::invalid_argument("dominant_wavelength: z and y differ in length");

  // sort by z, average repeated depths
  std::vector<std::pair<double, double>> pts;
  pts.reserve(z.size());
  for (std::size_t i = 0; i < z.size(); ++i)
    if (std::isfinite(z[i]) && std::isfinite(y[i])) pts.emplace_back(z[i], y[i]);
  std::sort(pts.begin(), pts.end());
  std::vector<double> zs, ys;
  for (std::size_t i = 0; i < pts.size();) {
    std::size_t j = i;
    double sum = 0.0;
    while (j < pts.size() && pts[j].first == pts[i].first) sum += pts[j++].second;
    zs.push_back(pts[i].first);
    ys.push_back(sum / (double) (j - i));
    i = j;
  }
  if (zs.size() < 8) {
    w.note = "too few distinct depths (" + std::to_string(zs.size()) + ", at least 8 needed)";
    return w;
  }

  // uniform grid of spacing the median dz
  std::vector<double> dzs(zs.size() - 1);
  for (std::size_t i = 0; i + 1 < zs.size(); ++i) dzs[i] = zs[i + 1] - zs[i];
  std::sort(dzs.begin(), dzs.end());
  const std::size_t m = dzs.size();
  const double median_dz = (m % 2) ? dzs[m / 2] : 0.5 * (dzs[m / 2 - 1] + dzs[m / 2]);
  const double span = zs.back() - zs.front();
  const double floor_dz = std::max(span / (4.0 * (double) m), span / (double) (kMaxSpectrumPoints - 1));
  double dz = median_dz;
  if (dz < floor_dz) dz = floor_dz, w.grid_limited = true;
  std::size_t n = (std::size_t) std::floor(span / dz * (1.0 + 1e-12)) + 1;
  n = std::min(n, kMaxSpectrumPoints);
  if ((double) n * (double) largest_prime_factor(n) > kMaxFftWork) {
    n = smooth_at_most(n);
    dz = span / (double) (n - 1);
    w.grid_limited = true;
  }
  w.dz = dz;
  w.n = n;
  w.length = (double) n * dz;
  if (n < 8) {
    w.note = "too few grid points (" + std::to_string(n) + ", at least 8 needed)";
    return w;
  }
  std::vector<double> grid(n);
  std::size_t j = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double zi = std::min(zs.front() + (double) i * dz, zs.back());
    while (j + 2 < zs.size() && zs[j + 1] < zi) ++j;
    const double u = (zi - zs[j]) / (zs[j + 1] - zs[j]);
    grid[i] = ys[j] + std::clamp(u, 0.0, 1.0) * (ys[j + 1] - ys[j]);
  }

  // mean removed, Hann window, power spectrum
  const double mean = std::accumulate(grid.begin(), grid.end(), 0.0) / (double) n;
  for (std::size_t i = 0; i < n; ++i)
    grid[i] = (grid[i] - mean) * 0.5 * (1.0 - std::cos(2.0 * PI * (double) i / (double) (n - 1)));
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> spec;
  fft.fwd(spec, grid);
  const std::size_t kmax = n / 2;
  std::vector<double> P(kmax + 1);
  for (std::size_t k = 0; k <= kmax; ++k) P[k] = std::norm(spec[k]);
  double total = 0.0;
  for (std::size_t k = 1; k <= kmax; ++k) total += P[k];
  if (!(total > 0.0)) {
    w.note = "no fluctuations (zero power)";
    return w;
  }

  // largest power at k >= 2
  std::size_t best = 2;
  for (std::size_t k = 3; k <= kmax; ++k)
    if (P[k] > P[best]) best = k;
  if (!(P[best] > 0.0)) {
    w.note = "no power above the lowest two bins";
    return w;
  }
  // refined between bins when it is a local maximum with both neighbours
  double delta = 0.0;
  if (best < kmax && P[best] > P[best - 1] && P[best] >= P[best + 1] && P[best - 1] > 0.0 && P[best + 1] > 0.0) {
    const double lm = std::log(P[best - 1]), l0 = std::log(P[best]), lp = std::log(P[best + 1]);
    const double den = lm - 2.0 * l0 + lp;
    if (den < 0.0) delta = std::clamp(0.5 * (lm - lp) / den, -0.5, 0.5);
  }
  w.lowest_bin = best == 2;
  w.ok = true;
  w.bin = best;
  w.wavelength = w.length / ((double) best + delta);
  w.power_fraction = P[best] / total;
  return w;
}

TraceFit fit_trace(const std::vector<double> &z, const std::vector<double> &F, const TraceFitParams &p)
{
  if (z.size() != F.size()) throw std::invalid_argument("fit_trace: z and F differ in length");
  TraceFit r;
  r.params = p;
  double zdeep = 0.0, zshallow = 0.0;
  bool any = false;
  for (double v : z)
    if (std::isfinite(v)) {
      zdeep = any ? std::max(zdeep, v) : v;
      zshallow = any ? std::min(zshallow, v) : v;
      any = true;
    }
  r.zlo = std::isfinite(p.zlo) ? p.zlo : zshallow;
  r.zhi = std::isfinite(p.zhi) ? p.zhi : zdeep;

  // depth term over the window
  std::vector<double> zw, Fw;
  double wlo = p.zlo, whi = p.zhi;
  window_samples(z, F, wlo, whi, zw, Fw);
  if (p.shorten_window && any && zdeep > 0.0) {
    if (distinct_depths(zw) < 3) {
      const std::string was = window_name(p.zlo, p.zhi);
      wlo = 0.5 * zdeep, whi = zdeep;
      window_samples(z, F, wlo, whi, zw, Fw);
      r.zlo = wlo, r.zhi = whi;
      r.window_shortened = true;
      r.notes.push_back("k_z window " + was + " does not fit the data (deepest z = " + fmt(zdeep) +
                        " cm): shortened to z = " + fmt(wlo) + ".." + fmt(whi) + " cm, the deeper half of the trace");
    } else if (std::isfinite(p.zhi) && p.zhi > zdeep) {
      r.zhi = zdeep;
      r.notes.push_back("k_z window end " + fmt(p.zhi) + " cm lies beyond the deepest z = " + fmt(zdeep) +
                        " cm: fitted to " + fmt(zdeep) + " cm");
    }
  }
  r.n_window = zw.size();
  if (!zw.empty()) {
    r.z_first = *std::min_element(zw.begin(), zw.end());
    r.z_last = *std::max_element(zw.begin(), zw.end());
  }
  LinearFit lf;
  try {
    lf = linear_fit(zw, Fw);
    r.slope_ok = true;
    r.k_z = lf.b;
    r.k_z_se = lf.se_b;
    r.intercept = lf.a;
    r.intercept_se = lf.se_a;
    r.rms = lf.rms;
    double szz = 0.0, szf = 0.0;
    for (std::size_t i = 0; i < zw.size(); ++i) szz += zw[i] * zw[i], szf += zw[i] * Fw[i];
    if (szz > 0.0) {
      r.k_z0 = szf / szz;
      double ss = 0.0;
      for (std::size_t i = 0; i < zw.size(); ++i) ss += (Fw[i] - r.k_z0 * zw[i]) * (Fw[i] - r.k_z0 * zw[i]);
      r.k_z0_se = std::sqrt(ss / (zw.size() - 1) / szz);
    }
    const QuadraticFit q = quadratic_fit_origin(zw, Fw);    // linear_fit passed: >= 3 points, 2 distinct z
    r.quad_ok = true;
    r.quad_a = q.a, r.quad_a_se = q.se_a, r.quad_b = q.b, r.quad_b_se = q.se_b;
  } catch (std::invalid_argument &) {
    r.notes.push_back("k_z undefined: " + std::to_string(zw.size()) + " points in the window z = " +
                      fmt(wlo) + ".." + (std::isfinite(whi) ? fmt(whi) : std::string("end")) +
                      " cm (at least 3 at distinct depths needed; deepest z = " + fmt(zdeep) + " cm)");
  }

  // alpha = k_z / (mu rho_g g D^2): k_z's scale at alpha = 1
  const double scale = k_z_from_alpha(1.0, p.mu, p.rho_g, p.g, p.D);
  if (r.slope_ok && scale > 0.0 && std::isfinite(scale)) {
    r.alpha_ok = true;
    r.alpha = r.k_z / scale;
    r.alpha_se = r.k_z_se / scale;
    r.alpha0 = r.k_z0 / scale;
    r.alpha0_se = r.k_z0_se / scale;
    if (r.quad_ok) {
      r.alpha_a = r.quad_a / scale, r.alpha_a_se = r.quad_a_se / scale;
      r.beta_b = r.quad_b * p.D / scale, r.beta_b_se = r.quad_b_se * p.D / scale;    // scale / D = mu rho_g g D
    }
  } else if (r.slope_ok) {
    r.notes.push_back("alpha undefined: mu rho_g g D^2 = " + fmt(scale) + " is not positive");
  } else {
    r.notes.push_back("alpha undefined: no k_z");
  }

  // transient peak over 0 < z < 0.7 R
  r.peak_zmax = peak_regime_end(p.D);
  for (std::size_t i = 0; i < z.size(); ++i)
    if (in_peak_regime(z[i], p.D) && std::isfinite(F[i])) {
      if (!r.n_peak || F[i] > r.peak_F) {
        r.peak_F = F[i];
        r.peak_z = z[i];
      }
      ++r.n_peak;
    }
  r.peak_ok = r.n_peak > 0;
  if (!r.peak_ok)
    r.notes.push_back("peak undefined: no points at 0 < z < 0.7 R = " + fmt(r.peak_zmax) + " cm");

  // fluctuation wavelength of the residuals about the fit
  if (r.slope_ok) {
    std::vector<double> res(zw.size());
    for (std::size_t i = 0; i < zw.size(); ++i) res[i] = Fw[i] - (lf.a + lf.b * zw[i]);
    r.spectrum = dominant_wavelength(zw, res);
    r.wavelength_ok = r.spectrum.ok;
    if (r.spectrum.ok) {
      r.wavelength = r.spectrum.wavelength;
      if (p.d_g > 0.0) r.wavelength_dg = r.wavelength / p.d_g;
      if (r.spectrum.lowest_bin)
        r.notes.push_back("wavelength at the lowest bin allowed (about the window length " +
                          fmt(r.spectrum.length) + " cm / 2): longer wavelengths are not resolved");
    } else {
      r.notes.push_back("wavelength undefined: " + r.spectrum.note);
    }
  } else {
    r.spectrum.note = "no linear fit in the window";
    r.notes.push_back("wavelength undefined: no linear fit in the window");
  }
  return r;
}

}    // namespace granpen
