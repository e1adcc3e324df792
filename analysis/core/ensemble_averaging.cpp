// granpen analysis: the ensembles averaged (see ensemble_averaging.h).
#include "ensemble_averaging.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace granpen {

EnsembleAveraging average_ensembles(const std::vector<EnsembleRuns> &ensembles, const EnsembleParams &p)
{
  EnsembleAveraging out;
  for (std::size_t i = 0; i < ensembles.size(); ++i) {
    const EnsembleRuns &e = ensembles[i];
    double lo = INFINITY, hi = -INFINITY;
    for (const auto &z : e.z)
      for (double v : z) lo = std::min(lo, v), hi = std::max(hi, v);
    if (p.bin > 0.0 && (hi - lo) / p.bin > (double) kMaxEnsembleBins) {
      out.bin_too_fine = true, out.too_fine = i, out.z_lo = lo, out.z_hi = hi;
      return out;
    }
    EnsembleMeanOutcome o;
    try {
      o.mean = ensemble_mean(e.z, e.F, p);
      o.ok = true;
    } catch (std::invalid_argument &x) {
      const std::string why = x.what();
      o.why = why.substr(why.find(": ") == std::string::npos ? 0 : why.find(": ") + 2);
    }
    out.ensembles.push_back(std::move(o));
  }
  return out;
}

}    // namespace granpen
