// granpen gap: the adaptive plan's decision and its record (see gap_adaptive.h).
#include "gap_adaptive.h"

#include "gap_fit.h"
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

}    // namespace

PriorBound prior_bound(const PriorBoundInput &in)
{
  PriorBound out;
  const Flat y = whitened(in.gap, in.var), b = whitened(in.scale_dir, in.var);
  const std::size_t n = y.size();
  if (n == 0) return out;
  // the knots' span, orthonormalised (a signature within round-off of the others adds nothing)
  std::vector<Flat> basis;
  std::vector<Flat> unit_var;    // per knot: the noise's variance per whitened feature (both knots')
  for (std::size_t j = 0; j < in.signature.size(); ++j) {
    Flat s = whitened(in.signature[j], in.var), q = orthogonal(s, basis);
    const double norm = std::sqrt(dot(q, q));
    if (norm > 1e-9 * std::sqrt(dot(s, s)) && norm > 0) {
      for (double &x : q) x /= norm;
      basis.push_back(q);
    }
  }
  Flat res0, res;
  const double w0 = scaled_residual(y, b, in.scale_bound, res0);
  const double r_min = scaled_residual(orthogonal(y, basis), orthogonal(b, basis), in.scale_bound, res);
  out.projection2 = std::max(0.0, w0 - r_min);
  // direction error: the diagnosis's knots are the prior's signatures plus d_j = e_d - e_p,
  // the two ensembles' noise (independent beds), variance v = (U_j + W_j) / V per whitened
  // feature. What d_j adds is at most (r . d_j)^2 / |d_j|^2 (Cauchy-Schwarz), r the residual
  // after the prior's span; r holds -alpha e_p (the signal's part the prior's noise missed,
  // alpha = A / |S_j|, A^2 = projection2), so r . d_j has a coherent part alpha |e_p|^2 ~
  // alpha sum W / V, and a random one of variance sum r^2 v, taken at the chi^2_K quantile
  const double K = (double) std::max<std::size_t>(1, in.signature.size());
  const double A = std::sqrt(out.projection2), q = chi2_quantile(PRIOR_BOUND_P, K);
  double margin = 0, absorbed = 0;
  Flat tmax(n, 0.0);
  for (std::size_t j = 0; j < in.signature.size(); ++j) {
    double sum_v = 0, sum_w = 0, sum_rv = 0, s2 = 0;
    std::size_t i = 0;
    for (std::size_t s = 0; s < in.gap.size(); ++s)
      for (std::size_t k = 0; k < in.gap[s].size(); ++k, ++i) {
        const double V = in.var[s][k];
        if (!(V > 0)) continue;
        const double v = (in.knot_var[j][s][k] + in.prior_var[j][s][k]) / V;
        sum_v += v, sum_w += in.prior_var[j][s][k] / V, sum_rv += res[i] * res[i] * v;
        s2 += in.signature[j][s][k] * in.signature[j][s][k] / V;
        tmax[i] = std::max(tmax[i], in.knot_var[j][s][k] / V);
      }
    if (!(sum_v > 0)) continue;
    const double alpha = s2 > 0 ? A / std::sqrt(s2) : 0.0;
    margin = std::max(margin, std::pow(alpha * sum_w + std::sqrt(q * sum_rv), 2) / sum_v);
  }
  out.margin_direction = margin;
  // the signature's own variance t = U / V in the likelihood: a residual r per feature costs
  // r / (1 + t) + log(1 + t) instead of r
  for (std::size_t i = 0; i < n; ++i) absorbed += res[i] * res[i] * tmax[i] / (1 + tmax[i]) - std::log1p(tmax[i]);
  out.margin_noise = std::max(0.0, absorbed);
  return out;
}

std::vector<PurchaseDecision> decide_purchases(const CheapStageSeen &seen, const std::vector<PourCandidate> &candidates,
                                               double lr_floor, double margin)
{
  std::vector<PourCandidate> order = candidates;
  std::stable_sort(order.begin(), order.end(), [](const PourCandidate &a, const PourCandidate &b) { return a.cost < b.cost; });
  // a physical cheap candidate that explains the gap stands unless another comes within the
  // margin of its evidence (a tie) or beyond; a scale names no cause, so its look-alikes
  // (the pour-level signatures near a uniform scale) are needed whatever it explains
  const bool stands = seen.best_explains && !seen.best_is_scale;
  const double needed = stands ? std::max(lr_floor, seen.best_evidence - margin) : lr_floor;
  std::vector<PurchaseDecision> out;
  for (const PourCandidate &c : order) {
    PurchaseDecision d;
    d.effect = c.effect;
    d.cost = c.cost;
    d.needed = needed;
    const std::optional<double> along_dir = c.prior ? std::optional<double>(c.prior->bound()) : c.projection2;
    d.bound = along_dir ? std::min(*along_dir, seen.chi2_0) : seen.chi2_0;
    d.simulate = d.bound >= needed;
    d.prior = c.prior;
    std::string along = c.projection2 ? "the squared gap along its signature" : "the whole squared gap (its direction unknown)";
    if (c.prior)
      along = "the prior's bound (the gap's squared projection on its knots' signatures and the scale, " +
              printf_number("%.1f", c.prior->projection2) + ", + the direction's margin " +
              printf_number("%.1f", c.prior->margin_direction) + " + the noise's " + printf_number("%.1f", c.prior->margin_noise) + ")";
    else if (!c.no_prior.empty())
      along += " (no prior direction: " + c.no_prior + ")";
    const std::string against = stands ? "within the evidence margin of " + seen.best + "'s " + printf_number("%.1f", seen.best_evidence) +
                                              " (and its threshold)"
                                        : "its threshold";
    d.why = (d.simulate ? "simulated: " : "skipped: ") + along + ", " + printf_number("%.1f", d.bound) +
            (d.simulate ? ", can reach " : ", cannot reach ") + printf_number("%.1f", needed) + ", " + against;
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
  int skipped = 0;
  for (const auto &d : r.decisions) skipped += !d.simulate;
  if (!r.decisions.empty())
    s += " Pour-level candidates: " + std::to_string(r.decisions.size() - skipped) + " simulated, " + std::to_string(skipped) +
         " skipped.";
  for (const auto &d : r.decisions) s += "\n- " + d.effect + " (" + printf_number("%.3g", d.cost) + " probe pours): " + d.why;
  if (!r.confirmation.empty()) {
    s += "\n- the confirmation: ";
    for (std::size_t i = 0; i < r.confirmation.size(); ++i) s += (i ? ", " : "") + r.confirmation[i];
  }
  return s;
}

}    // namespace granpen
