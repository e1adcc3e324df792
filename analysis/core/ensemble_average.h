// granpen analysis: an ensemble of force traces of one case (same v0, g and D) averaged on
// a common depth grid, the paper's "average of five runs" (plain arrays in, no files):
//   1. align: each run's depths shifted so that its force onset sits at the runs' mean onset
//      (core/onset_alignment.h; the gap diagnosis aligns the same way);
//   2. bin: bins [k w, (k + 1) w) over the depths every aligned run covers; a run's value in
//      a bin is the mean of its samples there, or, when a coarser run has none, its linear
//      interpolation at the bin centre;
//   3. per bin the mean over runs, their standard deviation and the standard error of the
//      mean sd / sqrt(n) (the run-to-run band), and n.
// The runs' bin values are kept: resample_mean() averages any subset (with repeats) of them,
// the bootstrap over runs of core/ensemble_fit.h.
#ifndef GRANPEN_ENSEMBLE_AVERAGE_H
#define GRANPEN_ENSEMBLE_AVERAGE_H

#include "onset_alignment.h"

#include <cstddef>
#include <string>
#include <vector>

namespace granpen {

// The most bins of an ensemble mean (each run keeps a value a bin, and the bootstrap a mean
// a bin per resample): a default bin is widened to stay within it; a given bin finer than
// that is refused.
constexpr std::size_t kMaxEnsembleBins = 100000;

struct EnsembleParams {
  double bin = 0.0;      // bin width, cm; <= 0: the largest median depth step of the runs
  bool align = true;     // shift the runs to their mean force onset first
  // grouping (io/ensemble_tables): > 0: runs whose v0 lie within this fraction of the
  // slowest of their group are one case (a lab's measured speeds about one nominal);
  // 0: v0 equal to 6 digits
  double v0_tolerance = 0.0;
};

struct EnsembleMean {
  std::size_t runs = 0;
  double bin = 0.0;                     // cm
  OnsetAlignment alignment;             // shifts applied (all 0 without align)
  double z_first = 0.0, z_last = 0.0;   // the depth range every aligned run covers
  std::vector<double> z;                // bin centres, cm
  std::vector<double> mean, sd, se;     // dyne; se = sd / sqrt(n), 0 for one run
  std::vector<int> n;                   // runs in each bin (every run, by construction)
  std::vector<std::vector<double>> per_run;    // per_run[i][k]: run i's value in bin k
  std::vector<std::string> notes;       // runs without onset, range cut to the common part
};

// Throws std::invalid_argument when there is no run, a run's z and F differ in length, a
// run has fewer than 2 finite samples, the aligned runs share no bin, or p.bin makes more
// than kMaxEnsembleBins bins. The default bin: the largest of the runs' median depth steps,
// their mean steps and the common range / kMaxEnsembleBins.
EnsembleMean ensemble_mean(const std::vector<std::vector<double>> &z, const std::vector<std::vector<double>> &F,
                           const EnsembleParams &p = {});

// The mean over bins of the runs picked (indices into the runs, repeats allowed): out[k].
void resample_mean(const EnsembleMean &e, const std::vector<std::size_t> &pick, std::vector<double> &out);

}    // namespace granpen

#endif
