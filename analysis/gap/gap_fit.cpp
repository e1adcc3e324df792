#include "gap_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace granpen {

namespace {

// Interpolation weights over the knots at magnitude a (they sum to 1).
std::vector<double> weights(const std::vector<double> &k, double a)
{
  std::vector<double> w(k.size(), 0.0);
  if (k.size() == 1) {
    w[0] = 1.0;
    return w;
  }
  std::size_t i = 0;    // segment [k[i], k[i + 1]]
  while (i + 2 < k.size() && a > k[i + 1]) ++i;
  const double f = (a - k[i]) / (k[i + 1] - k[i]);
  w[i] = 1.0 - f;
  w[i + 1] = f;
  return w;
}

std::size_t zero_knot(const EffectData &e)
{
  for (std::size_t j = 0; j < e.knots.size(); ++j)
    if (e.knots[j] == 0.0) return j;
  return 0;
}

}    // namespace

void knot_combination_var(const EffectData &e, const std::vector<double> &c, std::size_t s, bool with_reference,
                          std::vector<double> &var)
{
  const std::size_t p = e.mean[0][s].size(), j0 = zero_knot(e);
  const double sum = std::accumulate(c.begin(), c.end(), 0.0);
  var.assign(p, 0.0);
  for (std::size_t j = 0; j < c.size(); ++j) {
    if (c[j] == 0.0 || j == j0) continue;
    const Table &own = e.paired ? e.diff_err[j] : e.err[j];
    for (std::size_t k = 0; k < p; ++k) var[k] += c[j] * c[j] * own[s][k];
  }
  const bool referenced = !e.paired && !e.ref_err.empty();
  // the signature baseline B: mean[j] = R + K_j - B carries -B for every j != j0
  if (referenced)
    for (std::size_t k = 0; k < p; ++k) var[k] += (sum - c[j0]) * (sum - c[j0]) * e.ref_err[0][s][k];
  if (!with_reference) return;
  // the reference R: in every knot's mean (paired, or referenced) or in knot j0's alone
  const double cr = e.paired || referenced ? sum : c[j0];
  for (std::size_t k = 0; k < p; ++k) var[k] += cr * cr * e.err[j0][s][k];
}

void effect_predict(const EffectData &e, double a, std::size_t s, std::vector<double> &mean, std::vector<double> &var)
{
  const auto w = weights(e.knots, a);
  const std::size_t p = e.mean[0][s].size();
  mean.assign(p, 0.0);
  for (std::size_t j = 0; j < w.size(); ++j)
    if (w[j] != 0.0)
      for (std::size_t k = 0; k < p; ++k) mean[k] += w[j] * e.mean[j][s][k];
  knot_combination_var(e, w, s, true, var);
}

void effect_signature(const EffectData &e, double a, std::size_t s, std::vector<double> &u, std::vector<double> &var)
{
  std::vector<double> m0, v0;
  effect_predict(e, a, s, u, var);
  effect_predict(e, 0.0, s, m0, v0);
  for (std::size_t k = 0; k < u.size(); ++k) u[k] -= m0[k];
  // u = M(a) - M(0): the knots' weights less the reference at a = 0; the reference's own noise
  // is in the fit's weights (the target is compared with it), not in the signature's
  auto c = weights(e.knots, a);
  c[zero_knot(e)] -= 1.0;
  knot_combination_var(e, c, s, false, var);
}

double signature_baseline_share(const EffectData &e, double a)
{
  if (e.paired || e.ref_err.empty()) return 0.0;
  return 1.0 - weights(e.knots, a)[zero_knot(e)];
}

double effect_chi2(const Target &t, const EffectData &e, double a, const std::vector<std::size_t> &speeds, double scale)
{
  // against the model with its own variance (reported; the fit uses fixed weights)
  double chi2 = 0.0;
  std::vector<double> m, v;
  for (std::size_t s : speeds) {
    effect_predict(e, a, s, m, v);
    for (std::size_t k = 0; k < m.size(); ++k) chi2 += std::pow(t.mean[s][k] - (1.0 + scale) * m[k], 2) / (t.err[s][k] + v[k]);
  }
  return chi2;
}

namespace {

// the weights of weighted_residual at speed s, feature k: the baseline comparison's variance
double fixed_weight(const Target &t, const EffectData &e, std::size_t s, std::size_t k)
{
  return t.err[s][k] + e.err[zero_knot(e)][s][k];
}

}    // namespace

double nuisance_scale(const Target &t, const EffectData &e, double a, const std::vector<std::size_t> &speeds)
{
  if (!(e.scale_bound > 0.0) || (e.is_scale && a != 0.0)) return 0.0;
  double num = 0.0, den = 0.0;
  std::vector<double> m, v;
  for (std::size_t s : speeds) {
    effect_predict(e, a, s, m, v);
    for (std::size_t k = 0; k < m.size(); ++k) {
      const double w = fixed_weight(t, e, s, k);
      num += (t.mean[s][k] - m[k]) * m[k] / w, den += m[k] * m[k] / w;
    }
  }
  return den > 0.0 ? std::clamp(num / den, -e.scale_bound, e.scale_bound) : 0.0;
}

namespace {

// Squared residual weighted by the baseline comparison's variances (fixed, whatever a):
// the fraction of it an effect removes is what it explains. (With the model's own
// variance in the weights, a magnitude whose prediction is merely less certain would
// seem to explain more.) The prediction carries the nuisance scale (nuisance_scale).
double weighted_residual(const Target &t, const EffectData &e, double a, const std::vector<std::size_t> &speeds)
{
  const double c = nuisance_scale(t, e, a, speeds);
  double r2 = 0.0;
  std::vector<double> m, v;
  for (std::size_t s : speeds) {
    effect_predict(e, a, s, m, v);
    for (std::size_t k = 0; k < m.size(); ++k) r2 += std::pow(t.mean[s][k] - (1.0 + c) * m[k], 2) / fixed_weight(t, e, s, k);
  }
  return r2;
}

// -2 log likelihood at magnitude a (less its value's constant), as the likelihood ratio
// needs it: the residual weighted by the baseline comparison's variances V plus the
// signature's own U (effect_signature: the knots' ensembles, from their numbers of beds;
// for a pour-level effect also the signature baseline's, as a difference of two ensembles
// carries both), plus log((V + U) / V), the Gaussian's normalization. At a = 0 (U = 0) it
// is weighted_residual; elsewhere a signature resting on few, noisy beds pays for its
// noise (about U / V per feature), so it earns less evidence for the same fit.
double signature_residual(const Target &t, const EffectData &e, double a, const std::vector<std::size_t> &speeds)
{
  const std::size_t j0 = zero_knot(e);
  const double c = nuisance_scale(t, e, a, speeds);
  double r2 = 0.0;
  std::vector<double> m, v, u, uv;
  for (std::size_t s : speeds) {
    effect_predict(e, a, s, m, v);
    effect_signature(e, a, s, u, uv);
    for (std::size_t k = 0; k < m.size(); ++k) {
      const double V = t.err[s][k] + e.err[j0][s][k];
      r2 += std::pow(t.mean[s][k] - (1.0 + c) * m[k], 2) / (V + uv[k]) + std::log1p(uv[k] / V);
    }
  }
  return r2;
}

}    // namespace

double noise_of(const EffectData &e, const std::vector<std::size_t> &speeds)
{
  double n = 0.0;
  for (std::size_t s : speeds) n += s < e.noise_r2.size() ? e.noise_r2[s] : 0.0;
  return n;
}

// The excess is taken at least at 3 standard deviations of a chi^2 with n degrees of
// freedom: a residual within the noise has little to explain, and a fraction of nearly
// nothing would say nothing.
double explained_fraction(double w0, double w, double n)
{
  if (!(w0 > 0.0)) return 0.0;
  if (!(n > 0.0)) return 1.0 - w / w0;
  const double excess = std::max(w0 - n, GapThresholds::chi2_noise_sigmas * std::sqrt(2.0 * n));
  return std::min(1.0, (w0 - w) / excess);
}

std::pair<double, double> magnitude_range(const EffectData &e)
{
  const double lo0 = e.knots.front(), hi0 = e.knots.back();
  double lo = e.one_sided && lo0 >= 0.0 ? lo0 : lo0 - e.reach * (e.knots.size() > 1 ? e.knots[1] - e.knots[0] : 0.0);
  double hi = hi0 + e.reach * (e.knots.size() > 1 ? hi0 - e.knots[e.knots.size() - 2] : 0.0);
  // a two-sided effect simulated on one side only: linear response through the baseline
  // out to the mirror of its farthest knot (the confirming runs check the prediction)
  if (!e.one_sided && lo0 >= 0.0) lo = std::min(lo, -hi0);
  if (!e.one_sided && hi0 <= 0.0) hi = std::max(hi, -lo0);
  return {lo, hi};
}

double same_magnitude_tolerance(const EffectData &e)
{
  if (e.library_span > 0.0) return GapThresholds::same_magnitude_of_range * e.library_span;
  const auto [lo, hi] = magnitude_range(e);
  return GapThresholds::same_magnitude_of_range * (hi - lo);
}

double refined_magnitude(const EffectData &e, double a, double c)
{
  const auto [lo, hi] = magnitude_range(e);
  return std::clamp(a * (1.0 + c), lo, hi);
}

namespace {

// Best magnitude over the allowed range (least squared residual with the fixed weights of
// weighted_residual): a fine grid, then golden-section refinement. Fixed weights: with the
// prediction's own variance in them, magnitudes between knots (where the interpolation
// averages two ensembles and its variance drops) would be favoured for that alone.
double best_magnitude(const Target &t, const EffectData &e, const std::vector<std::size_t> &speeds, bool *edge)
{
  const auto [lo, hi] = magnitude_range(e);
  const int n = 400;
  double best = 0.0, bestc = std::numeric_limits<double>::infinity();
  int ib = 0;
  for (int i = 0; i <= n; ++i) {
    const double a = lo + (hi - lo) * i / n;
    const double c = weighted_residual(t, e, a, speeds);
    if (c < bestc) bestc = c, best = a, ib = i;
  }
  double x0 = lo + (hi - lo) * std::max(0, ib - 1) / n, x1 = lo + (hi - lo) * std::min(n, ib + 1) / n;
  for (int it = 0; it < 40; ++it) {
    const double m1 = x0 + 0.382 * (x1 - x0), m2 = x0 + 0.618 * (x1 - x0);
    if (weighted_residual(t, e, m1, speeds) < weighted_residual(t, e, m2, speeds)) x1 = m2;
    else x0 = m1;
  }
  const double a = 0.5 * (x0 + x1);
  if (weighted_residual(t, e, a, speeds) < bestc) best = a;
  if (edge) *edge = (ib == 0 || ib == n);
  return best;
}

}    // namespace

EffectFit fit_effect(const Target &t, const EffectData &e)
{
  EffectFit f;
  f.name = e.name;
  const std::size_t ns = t.mean.size();
  std::vector<std::size_t> all(ns);
  std::iota(all.begin(), all.end(), 0);
  f.nfeatures = ns ? ns * t.mean[0].size() : 0;
  f.magnitude = best_magnitude(t, e, all, &f.at_edge);
  f.scale = nuisance_scale(t, e, f.magnitude, all);
  f.is_scale = e.is_scale;
  f.chi2_0 = effect_chi2(t, e, 0.0, all);
  f.chi2 = effect_chi2(t, e, f.magnitude, all);
  f.chi2_0_within_bound = effect_chi2(t, e, 0.0, all, nuisance_scale(t, e, 0.0, all));
  f.chi2_within_bound = effect_chi2(t, e, f.magnitude, all, f.scale);
  const double w0 = weighted_residual(t, e, 0.0, all), wa = weighted_residual(t, e, f.magnitude, all);
  f.explained = explained_fraction(w0, wa, noise_of(e, all));
  f.lr = std::max(0.0, w0 - signature_residual(t, e, f.magnitude, all));
  {
    const auto [lo, hi] = magnitude_range(e);
    const double h = 0.01 * (hi - lo), a = std::clamp(f.magnitude, lo + h, hi - h);
    const double c2 = signature_residual(t, e, a + h, all) - 2.0 * signature_residual(t, e, a, all) +
                      signature_residual(t, e, a - h, all);
    if (c2 > 0.0) f.magnitude_error = h * std::sqrt(2.0 / c2);
  }
  // leave one speed out: fit on the others, predict the one left out
  double sum = 0.0;
  int used = 0;
  for (std::size_t h = 0; h < ns; ++h) {
    std::vector<std::size_t> rest;
    for (std::size_t s = 0; s < ns; ++s)
      if (s != h) rest.push_back(s);
    double a = f.magnitude;
    if (!rest.empty()) a = best_magnitude(t, e, rest, nullptr);
    f.loso_magnitude.push_back(a);
    const double p = (double) t.mean[h].size();
    const double c0 = effect_chi2(t, e, 0.0, {h});
    // a speed counts when its own gap stands out of the noise (chi^2 above p + 3 sigma)
    double ex_h = std::numeric_limits<double>::quiet_NaN();
    if (c0 - p > GapThresholds::chi2_noise_sigmas * std::sqrt(2.0 * p)) {
      ex_h = explained_fraction(weighted_residual(t, e, 0.0, {h}), weighted_residual(t, e, a, {h}), noise_of(e, {h}));
    }
    f.loso_explained.push_back(ex_h);
    if (std::isfinite(ex_h)) sum += ex_h, ++used;
  }
  f.heldout_explained = used ? sum / used : f.explained;
  f.score = std::min(f.explained, f.heldout_explained);
  return f;
}

double effect_lr(const Target &t, const EffectData &e)
{
  std::vector<std::size_t> all(t.mean.size());
  std::iota(all.begin(), all.end(), 0);
  const double a = best_magnitude(t, e, all, nullptr);
  return std::max(0.0, weighted_residual(t, e, 0.0, all) - signature_residual(t, e, a, all));
}

std::vector<double> noise_residual(const std::vector<Target> &nulls, const EffectData &e)
{
  std::vector<double> n(e.mean.empty() ? 0 : e.mean[0].size(), 0.0);
  for (const auto &t : nulls)
    for (std::size_t s = 0; s < n.size(); ++s) n[s] += weighted_residual(t, e, 0.0, {s}) / nulls.size();
  return n;
}

double lr_threshold(double lr_null_mean) { return std::max(1.0, lr_null_mean) * GapThresholds::lr_chi2_1_p1e4; }

double chi2_sf(double x, double k)
{
  // regularized upper incomplete gamma Q(k/2, x/2): series or continued fraction
  const double a = 0.5 * k, y = 0.5 * x;
  if (!(y > 0.0)) return 1.0;
  const double lg = std::lgamma(a);
  if (y < a + 1.0) {
    double sum = 1.0 / a, term = sum;
    for (int n = 1; n < 1000; ++n) {
      term *= y / (a + n);
      sum += term;
      if (std::abs(term) < std::abs(sum) * 1e-15) break;
    }
    return std::max(0.0, 1.0 - sum * std::exp(-y + a * std::log(y) - lg));
  }
  double b = y + 1.0 - a, c = 1e300, d = 1.0 / b, h = d;
  for (int i = 1; i < 1000; ++i) {
    const double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < 1e-300) d = 1e-300;
    c = b + an / c;
    if (std::abs(c) < 1e-300) c = 1e-300;
    d = 1.0 / d;
    const double del = d * c;
    h *= del;
    if (std::abs(del - 1.0) < 1e-15) break;
  }
  return std::exp(-y + a * std::log(y) - lg) * h;
}

}    // namespace granpen
