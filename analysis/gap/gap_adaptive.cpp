// granpen gap: the adaptive plan's decision and its record (see gap_adaptive.h).
#include "gap_adaptive.h"

#include "gap_fit.h"
#include "gap_thresholds.h"
#include "text_util.h"

#include <algorithm>
#include <cmath>

namespace granpen {

namespace {

using Flat = std::vector<double>;

double dot(const Flat &a, const Flat &b)
{
  double s = 0;
  for (std::size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
  return s;
}

// x less its projection on the orthonormal basis
Flat orthogonal(Flat x, const std::vector<Flat> &basis)
{
  for (const Flat &e : basis) {
    const double c = dot(x, e);
    for (std::size_t i = 0; i < x.size(); ++i) x[i] -= c * e[i];
  }
  return x;
}

// a table [speed][feature] over sqrt(var), flattened
Flat whitened(const std::vector<std::vector<double>> &t, const std::vector<std::vector<double>> &var)
{
  Flat out;
  for (std::size_t s = 0; s < t.size(); ++s)
    for (std::size_t k = 0; k < t[s].size(); ++k) out.push_back(var[s][k] > 0 ? t[s][k] / std::sqrt(var[s][k]) : 0.0);
  return out;
}

// the least residual |y - c b|^2 over |c| <= bound, and its residual
double scaled_residual(const Flat &y, const Flat &b, double bound, Flat &res)
{
  const double bb = dot(b, b);
  const double c = bb > 0 ? std::clamp(dot(y, b) / bb, -bound, bound) : 0.0;
  res = y;
  for (std::size_t i = 0; i < y.size(); ++i) res[i] -= c * b[i];
  return dot(res, res);
}

// the chi^2 quantile with k degrees of freedom at upper tail p (bisection on chi2_sf)
double chi2_quantile(double p, double k)
{
  double lo = 0, hi = 100 + 20 * k;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (chi2_sf(mid, k) > p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// The directions the fit's path can take (docs/gap.md, "The bound with a prior"): per
// magnitude a on a grid of magnitude_range (gap_fit.h), the signature's coefficients on the
// knots (the interpolation weights less the baseline's; the baseline's signature is 0), in
// the order of in.signature. Every point of the path is a non-negative multiple of one of
// them, so what the fit can remove is what one of these directions takes, with its length free.
std::vector<Flat> path_coefficients(const PriorBoundInput &in)
{
  const std::size_t K = in.signature.size();
  std::vector<std::pair<double, std::size_t>> m{{0.0, K}};    // (magnitude, knot; K = the baseline)
  for (std::size_t j = 0; j < K; ++j) m.push_back({j < in.magnitude.size() ? in.magnitude[j] : (double) (j + 1), j});
  std::sort(m.begin(), m.end());
  EffectData e;
  for (const auto &[a, j] : m) e.knots.push_back(a);
  e.one_sided = in.one_sided, e.reach = in.reach;
  const auto [lo, hi] = magnitude_range(e);
  std::vector<double> grid;
  const int n = PRIOR_PATH_POINTS;
  for (int i = 0; i <= n; ++i) grid.push_back(lo + (hi - lo) * i / n);
  for (const auto &[a, j] : m) grid.push_back(a);
  std::vector<Flat> out;
  for (double a : grid) {
    if (a == 0.0 || !(a > in.beyond)) continue;
    std::size_t i = 0;    // the segment [m[i], m[i + 1]], extrapolated at the ends
    while (i + 2 < m.size() && a > m[i + 1].first) ++i;
    const double f = (a - m[i].first) / (m[i + 1].first - m[i].first);
    Flat c(K, 0.0);
    if (m[i].second < K) c[m[i].second] += 1.0 - f;
    if (m[i + 1].second < K) c[m[i + 1].second] += f;
    out.push_back(c);
  }
  return out;
}

// One point of the path (coefficients c on the knots): the likelihood ratio the prior's knots
// earn there, and what the diagnosis's knots, the prior's tilted by their noise, add to it.
PriorBound point_bound(const PriorBoundInput &in, const Flat &c, const std::vector<Flat> &sig, const Flat &y, const Flat &b,
                       double w0, double q, bool &choosable, double &gain)
{
  PriorBound out;
  const std::size_t n = y.size();
  Flat x(n, 0.0), r(n);
  for (std::size_t j = 0; j < c.size(); ++j)
    for (std::size_t i = 0; i < n; ++i) x[i] += c[j] * sig[j][i];
  // the nuisance scale at this point, fitted with fixed weights as gap_fit does
  for (std::size_t i = 0; i < n; ++i) r[i] = y[i] - x[i];
  const double bb = dot(b, b), cs = bb > 0 ? std::clamp(dot(r, b) / bb, -in.scale_bound, in.scale_bound) : 0.0;
  for (std::size_t i = 0; i < n; ++i) r[i] -= cs * b[i];
  const double xx = dot(x, x), alpha = xx > 0 ? std::max(0.0, dot(y, x)) / xx : 0.0;
  // per whitened feature, of the combination c (|c_j|-weighted standard deviations added,
  // whatever the knots' noise shares, the signature baseline's included): the diagnosis's
  // knots' own variance t, the tilt's v (both ensembles' noise) and the prior's share w
  double lr = w0, coherent = 0, var_u = 0, mean_v = 0, var_v = 0, fixed = 0;
  double coherent_f = 0, var_f = 0, mean_f = 0, var_vf = 0;    // the same with fixed weights (1 + t -> 1)
  std::size_t i = 0;
  for (std::size_t s = 0; s < in.gap.size(); ++s)
    for (std::size_t k = 0; k < in.gap[s].size(); ++k, ++i) {
      const double V = in.var[s][k];
      if (!(V > 0)) continue;
      double sv = 0, sw = 0, su = 0;
      for (std::size_t j = 0; j < c.size(); ++j) {
        const double cj = std::abs(c[j]);
        su += cj * std::sqrt(in.knot_var[j][s][k] / V);
        if (j < in.own.size() && in.own[j]) continue;    // the diagnosis's own signature: no tilt
        sv += cj * std::sqrt((in.knot_var[j][s][k] + in.prior_var[j][s][k]) / V);
        sw += cj * std::sqrt(in.prior_var[j][s][k] / V);
      }
      const double t = su * su, v = sv * sv / (1 + t);
      lr -= r[i] * r[i] / (1 + t) + std::log1p(t), fixed += r[i] * r[i];
      coherent += alpha * sw * sw / (1 + t), var_u += r[i] * r[i] * v / (1 + t);
      mean_v += v, var_v += 2 * v * v;
      coherent_f += alpha * sw * sw, var_f += r[i] * r[i] * sv * sv, mean_f += sv * sv, var_vf += 2 * std::pow(sv, 4);
    }
  // the diagnosis's point is x + d: it changes -sum r^2 / (1 + t) by 2 u - |d|^2_t, u = sum r d /
  // (1 + t): r holds -alpha e_p (the signal's part the prior's own noise turned away), so u has
  // a coherent part alpha sum w / (1 + t) and a random one of variance sum r^2 v / (1 + t); for
  // Gaussian d, u and |d|^2_t are uncorrelated, so 2 u - |d|^2_t has mean 2 coherent - sum v /
  // (1 + t) and variance 4 var(u) + 2 sum (v / (1 + t))^2, taken at sqrt(q) standard deviations
  // (q the chi^2_K quantile); at most u^2 / |d|^2_t (Cauchy-Schwarz), u and |d|^2_t each at
  // their quantile
  const double u = coherent + std::sqrt(q * var_u), d2 = std::max(0.0, mean_v - std::sqrt(q * var_v));
  out.projection2 = w0 - fixed;
  out.margin_noise = lr - out.projection2;
  out.margin_direction = std::max(0.0, 2 * coherent - mean_v + std::sqrt(q * (4 * var_u + var_v)));
  if (d2 > 0) out.margin_direction = std::min(out.margin_direction, u * u / d2);
  // the fit chooses its magnitude by the fixed-weight residual (gap_fit.h, best_magnitude), and
  // magnitude 0 removes 0 of it: a point whose fixed-weight gain, with the tilt's at its upper
  // quantile, stays below 0 is never the fit's
  const double tilt_f = 2 * coherent_f - mean_f + std::sqrt(q * (4 * var_f + var_vf));
  gain = out.projection2 + tilt_f;    // the most fixed-weight squared gap the point removes (explained's)
  choosable = gain >= 0;
  return out;
}

}    // namespace

PriorBound prior_bound(const PriorBoundInput &in)
{
  PriorBound out;
  const Flat y = whitened(in.gap, in.var), b = whitened(in.scale_dir, in.var);
  if (y.empty() || in.signature.empty()) return out;
  std::vector<Flat> sig;
  for (const auto &s : in.signature) sig.push_back(whitened(s, in.var));
  Flat res0;
  const double w0 = scaled_residual(y, b, in.scale_bound, res0);
  const double q = chi2_quantile(PRIOR_BOUND_P, (double) in.signature.size());
  double best = 0, gain = 0;    // magnitude 0: the likelihood ratio 0, and nothing removed
  for (const Flat &c : path_coefficients(in)) {
    bool choosable = true;
    double g = 0;
    const PriorBound p = point_bound(in, c, sig, y, b, w0, q, choosable, g);
    if (choosable && p.bound() > best) best = p.bound(), out = p;
    if (choosable) gain = std::max(gain, g);
  }
  out.gain = gain, out.w0 = w0;
  return out;
}

double explain_gain_needed(double w0, double n, double fraction)
{
  if (!(n > 0.0)) return fraction * std::max(0.0, w0);
  return fraction * std::max(w0 - n, GapThresholds::chi2_noise_sigmas * std::sqrt(2.0 * n));
}

std::vector<PurchaseDecision> decide_purchases(const CheapStageSeen &seen, const std::vector<PlanCandidate> &candidates,
                                               double lr_floor, double margin)
{
  std::vector<PlanCandidate> order = candidates;
  std::stable_sort(order.begin(), order.end(), [](const PlanCandidate &a, const PlanCandidate &b) { return a.cost < b.cost; });
  // a physical cheap candidate that explains the gap stands unless another comes within the
  // margin of its evidence (a tie) or beyond; a scale names no cause, so its look-alikes
  // (the pour-level signatures near a uniform scale) are needed whatever it explains
  const bool stands = seen.best_explains && !seen.best_is_scale;
  const double needed = stands ? std::max(lr_floor, seen.best_evidence - margin) : lr_floor;
  std::vector<PurchaseDecision> out;
  for (const PlanCandidate &c : order) {
    PurchaseDecision d;
    d.effect = c.effect;
    d.push_only = c.push_only;
    d.cost = c.cost;
    d.cold_cost = c.cold_cost;
    d.needed = needed;
    const std::optional<double> along_dir = c.prior ? std::optional<double>(c.prior->bound()) : c.projection2;
    d.bound = along_dir ? std::min(*along_dir, seen.chi2_0) : seen.chi2_0;
    d.simulate = d.bound >= needed;
    d.prior = c.prior;
    std::string along = c.projection2 ? "the squared gap along its signature" : "the whole squared gap (its direction unknown)";
    if (c.prior)
      along = "the prior's bound (the likelihood ratio along the fit's path: the squared gap its point removes, " +
              printf_number("%.1f", c.prior->projection2) + ", + the direction's margin " +
              printf_number("%.1f", c.prior->margin_direction) + " + the noise's " + printf_number("%.1f", c.prior->margin_noise) + ")";
    else if (!c.no_prior.empty())
      along += " (no prior direction: " + c.no_prior + ")";
    const std::string against = stands ? "within the evidence margin of " + seen.best + "'s " + printf_number("%.1f", seen.best_evidence) +
                                              " (and its threshold)"
                                        : "its threshold";
    d.why = (d.simulate ? "simulated: " : "skipped: ") + along + ", " + printf_number("%.1f", d.bound) +
            (d.simulate ? ", can reach " : ", cannot reach ") + printf_number("%.1f", needed) + ", " + against;
    if (c.pair_partner && seen.unexplained) {
      d.simulate = true;
      d.why = "simulated: the cheap stage's verdict is unexplained, and the pair stage may pair it with the filter (a pair "
              "explains what neither alone does), whatever its own bound (" + printf_number("%.1f", d.bound) + " against " +
              printf_number("%.1f", needed) + ")";
      out.push_back(d);
      continue;
    }
    // the explain gate: on an unexplained verdict that stands, a candidate that cannot remove
    // a quarter of the gap's excess changes nothing, whatever its likelihood ratio reaches
    if (d.simulate && seen.unexplained_stands && c.prior) {
      d.gain = c.prior->gain;
      d.gain_needed = explain_gain_needed(c.prior->w0, c.prior->noise, GapThresholds::between_knots_min_explained);
      if (d.gain < d.gain_needed) {
        d.simulate = false;
        d.why = "skipped: the gap is unexplained on the omnibus test and only a candidate that explains " +
                printf_number("%.2f", GapThresholds::between_knots_min_explained) +
                " of it can change that; the most squared gap its fit can remove is " + printf_number("%.1f", d.gain) +
                " (the prior's bound), of the " + printf_number("%.1f", d.gain_needed) + " that needs (its likelihood ratio " +
                "could reach " + printf_number("%.1f", d.bound) + ")";
      }
    }
    out.push_back(d);
  }
  return out;
}

std::string plan_record_text(const PlanRecord &r)
{
  std::string s = "Cost (probe pours of core time; wall time at --jobs " + std::to_string(r.jobs) + "): this run " +
                  printf_number("%.3g", r.spent) + " (" + printf_number("%.3g", r.wall_spent) + " of wall time) within the plan's " +
                  printf_number("%.3g", r.least) + " to " + printf_number("%.3g", r.most) + " (" +
                  printf_number("%.3g", r.wall_least) + " to " + printf_number("%.3g", r.wall_most) +
                  " of wall time), counted as a cold cache runs it; where a run lands: " + r.decides + ".";
  // push-only candidates are decided first, then the pour-level ones
  for (const bool push : {true, false}) {
    int simulated = 0, skipped = 0;
    for (const auto &d : r.decisions)
      if (d.push_only == push) ++(d.simulate ? simulated : skipped);
    if (simulated + skipped > 0)
      s += std::string(push ? " Push-only" : " Pour-level") + " candidates: " + std::to_string(simulated) + " simulated, " +
           std::to_string(skipped) + " skipped.";
  }
  // a candidate's cost counted cold, as the range and "this run" are; what this cache lacked beside it
  for (const auto &d : r.decisions)
    s += "\n- " + d.effect + " (" + printf_number("%.3g", d.cold_cost) + " probe pours" +
         (d.cost != d.cold_cost ? ", " + printf_number("%.3g", d.cost) + " with this cache" : "") + "): " + d.why;
  if (!r.confirmation.empty()) {
    s += "\n- the confirmation: ";
    for (std::size_t i = 0; i < r.confirmation.size(); ++i) s += (i ? ", " : "") + r.confirmation[i];
  }
  return s;
}

}    // namespace granpen
