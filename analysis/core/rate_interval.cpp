// granpen analysis: a rate with its exact interval (see rate_interval.h).
#include "rate_interval.h"

#include <cmath>
#include <stdexcept>

namespace granpen {

double binomial_cdf(int k, int n, double p)
{
  if (k < 0) return 0;
  if (k >= n) return 1;
  if (p <= 0) return 1;
  if (p >= 1) return 0;
  const double lp = std::log(p), lq = std::log1p(-p);
  double s = 0;
  for (int i = 0; i <= k; ++i)
    s += std::exp(std::lgamma(n + 1.0) - std::lgamma(i + 1.0) - std::lgamma(n - i + 1.0) + i * lp + (n - i) * lq);
  return s > 1 ? 1 : s;
}

namespace {

// the p in (0, 1) where the decreasing function f(p) crosses target, by bisection: 200
// halvings reach double precision from any start, and f is monotone in p (the binomial
// CDF falls as p rises), so the crossing is unique
template <class F> double crossing(F f, double target)
{
  double lo = 0, hi = 1;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (f(mid) > target) lo = mid; else hi = mid;
  }
  return 0.5 * (lo + hi);
}

}    // namespace

RateInterval clopper_pearson(int k, int n, double level)
{
  if (n < 1) throw std::invalid_argument("clopper_pearson: n must be at least 1");
  if (k < 0 || k > n) throw std::invalid_argument("clopper_pearson: k must lie in 0..n");
  if (!(level > 0 && level < 1)) throw std::invalid_argument("clopper_pearson: level must lie in (0, 1)");
  const double tail = (1 - level) / 2;
  RateInterval r;
  r.rate = double(k) / n;
  // lower: P(X >= k | p) = tail, i.e. P(X <= k - 1 | p) = 1 - tail
  r.low = k == 0 ? 0.0 : crossing([&](double p) { return binomial_cdf(k - 1, n, p); }, 1 - tail);
  // upper: P(X <= k | p) = tail
  r.high = k == n ? 1.0 : crossing([&](double p) { return binomial_cdf(k, n, p); }, tail);
  return r;
}

}    // namespace granpen
