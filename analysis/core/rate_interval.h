/* -*- c++ -*- ----------------------------------------------------------
   granpen analysis: a rate of k events in n trials (the false-alarm rate of
   granpen gap on data without an effect, validation/gap_bench.sh) with its
   exact two-sided confidence interval (Clopper-Pearson): the lower end is the
   p at which P(X >= k) = (1 - level) / 2, the upper the p at which
   P(X <= k) = (1 - level) / 2, X binomial (n, p); 0 and 1 at k = 0 and k = n.
   Exact, so never narrower than the nominal level: 0 of 20 gives [0, 0.168].
------------------------------------------------------------------------- */

#ifndef GRANPEN_RATE_INTERVAL_H
#define GRANPEN_RATE_INTERVAL_H

namespace granpen {

struct RateInterval {
  double rate = 0;    // k / n
  double low = 0;     // the interval's ends
  double high = 1;
};

// P(X <= k) for X binomial (n, p), summed in logs (exact to rounding for n up to 1e6).
double binomial_cdf(int k, int n, double p);

// The rate k / n and its Clopper-Pearson interval at `level` (0.95: 95%). Throws
// std::invalid_argument for n < 1, k outside 0..n, or level outside (0, 1).
RateInterval clopper_pearson(int k, int n, double level = 0.95);

}    // namespace granpen

#endif
