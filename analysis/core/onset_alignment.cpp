// granpen analysis: depth alignment at the force onset (see onset_alignment.h).
#include "onset_alignment.h"

#include <algorithm>
#include <limits>

namespace granpen {

double force_onset(const std::vector<double> &z, const std::vector<double> &F, double frac, double search)
{
  const std::size_t n = std::min(z.size(), F.size());
  double fmax = 0.0;
  for (std::size_t i = 0; i < n; ++i) fmax = std::max(fmax, F[i]);
  if (!(fmax > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  // first touch: F above 2% of the run's largest force (well above a sensor's noise floor)
  std::size_t first = 0;
  while (first < n && F[first] <= 0.02 * fmax) ++first;
  double fp = 0.0;
  for (std::size_t i = first; i < n && z[i] <= z[first] + search; ++i) fp = std::max(fp, F[i]);
  const double level = frac * fp;
  for (std::size_t i = first; i < n; ++i)
    if (F[i] >= level) {
      if (i == 0 || F[i - 1] >= level) return z[i];
      const double f = (level - F[i - 1]) / (F[i] - F[i - 1]);
      return z[i - 1] + f * (z[i] - z[i - 1]);
    }
  return std::numeric_limits<double>::quiet_NaN();
}

OnsetAlignment align_onsets(const std::vector<double> &onsets, double reference)
{
  OnsetAlignment a;
  a.onset = onsets;
  a.shift.assign(onsets.size(), 0.0);
  if (std::isnan(reference)) {
    double sum = 0.0;
    std::size_t n = 0;
    for (double o : onsets)
      if (std::isfinite(o)) sum += o, ++n;
    reference = n ? sum / (double) n : NAN;
  }
  a.reference = reference;
  for (std::size_t i = 0; i < onsets.size(); ++i) {
    if (!std::isfinite(onsets[i]) || !std::isfinite(reference)) {
      a.without_onset.push_back(i);
      continue;
    }
    a.shift[i] = reference - onsets[i];
    a.max_shift = std::max(a.max_shift, std::fabs(a.shift[i]));
  }
  return a;
}

void shift_depths(std::vector<double> &z, double shift)
{
  for (auto &v : z) v += shift;
}

double deepest_common(const std::vector<const std::vector<double> *> &z_of_runs)
{
  double m = INFINITY;
  for (const auto *z : z_of_runs) m = std::min(m, z->empty() ? -INFINITY : *std::max_element(z->begin(), z->end()));
  return m;
}

}    // namespace granpen
