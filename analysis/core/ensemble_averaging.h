// granpen analysis: the stage "averages" of granpen fit, collapse and plot --ensemble: the
// runs of each ensemble averaged (core/ensemble_average.h ensemble_mean), each outcome typed
// (a mean, or why not), so that the front ends word them and the fit and collapse studies
// take the means (no files, no printing).
#ifndef GRANPEN_ENSEMBLE_AVERAGING_H
#define GRANPEN_ENSEMBLE_AVERAGING_H

#include "ensemble_average.h"

#include <cstddef>
#include <string>
#include <vector>

namespace granpen {

// The runs of one ensemble (cgs) and its name.
struct EnsembleRuns {
  std::string name;
  std::vector<std::vector<double>> z, F;
};

// One ensemble averaged, or why not (ensemble_mean's refusal, its "ensemble_mean: " cut off).
struct EnsembleMeanOutcome {
  bool ok = false;
  EnsembleMean mean;
  std::string why;
};

// Every ensemble averaged, in order, up to the first whose given bin (p.bin > 0) makes more
// than kMaxEnsembleBins bins over its runs' depths: that one is refused before any memory is
// taken (bin_too_fine, its index and its runs' depths; those after it are not averaged), so
// that a front end can name the option that set the bin.
struct EnsembleAveraging {
  std::vector<EnsembleMeanOutcome> ensembles;    // up to the refused one (excluded)
  bool bin_too_fine = false;
  std::size_t too_fine = 0;                      // its index
  double z_lo = 0.0, z_hi = 0.0;                 // its runs' depths
};
EnsembleAveraging average_ensembles(const std::vector<EnsembleRuns> &ensembles, const EnsembleParams &p);

}    // namespace granpen

#endif
