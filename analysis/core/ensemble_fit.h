// granpen analysis: the paper's observables from ensembles of runs, each with its
// run-to-run uncertainty (plain arrays in, no files).
//
// Every number is computed on the ensemble mean (core/ensemble_average.h) as it would be on
// one trace (core/trace_fit.h, core/collapse.h); its uncertainty is a bootstrap over runs:
// B resamples, each drawing n of the n runs with replacement (every ensemble independently),
// averaging them bin by bin and computing the number again. The standard error is the
// replicates' standard deviation times sqrt(n / (n - 1)), which makes it, for a number
// linear in the runs (k_z, its intercept), the textbook se of a mean of n runs,
// sd(run values) / sqrt(n); ci95 = t95(n - 1) se.
// Why runs and not bins: the bins of one run are not independent (force chains span many
// grain diameters, and a bed's packing shifts the whole curve), so a weighted least-squares
// fit with the per-bin standard errors as independent errors would understate the
// uncertainty several-fold; the runs are the independent units. The bootstrap also carries
// the run-to-run scatter into numbers that are not linear in F: the peak (a maximum), the
// crossover (a first passage), the collapse's spread and the peak-law exponent.
// The resamples come from a fixed seed, so a result is the same on every run.
#ifndef GRANPEN_ENSEMBLE_FIT_H
#define GRANPEN_ENSEMBLE_FIT_H

#include "collapse.h"
#include "ensemble_average.h"
#include "trace_fit.h"

#include <string>
#include <vector>

namespace granpen {

struct BootstrapParams {
  int resamples = 1000;            // B: the se's own relative sampling error is about 1/sqrt(2B) = 2%
  unsigned long long seed = 20;    // the resamples' generator (std::mt19937_64)
};

// A number from an ensemble mean with its run-to-run uncertainty.
struct Estimate {
  bool ok = false;       // defined on the ensemble mean
  double value = 0.0;    // on the ensemble mean
  bool se_ok = false;    // at least 2 runs and 2 replicates where it is defined
  double se = 0.0;       // bootstrap standard error (see above)
  double ci95 = 0.0;     // t95(runs - 1) se
  int defined = 0;       // replicates in which it was defined (of resamples)
};

struct EnsembleFit {
  std::size_t runs = 0;
  int resamples = 0;
  TraceFit fit;    // of the ensemble mean: windows, notes, the values below
  Estimate k_z, intercept, alpha, k_z0, alpha0, peak_F, peak_z, wavelength;
};

// p as for fit_trace (the window, D, g, mu, rho_g, d_g).
EnsembleFit fit_ensemble(const EnsembleMean &e, const TraceFitParams &p, const BootstrapParams &b = {});

// One ensemble of a collapse: its mean, the case, and its depth term: k_z_fixed > 0 (from
// alpha, the same in every resample), else k_z fitted over kz_fit's window in each resample.
struct EnsembleCase {
  std::string name;
  double v0 = 0.0, D = 0.0, g = 0.0;
  EnsembleMean mean;
  double k_z_fixed = 0.0;
  TraceFitParams kz_fit;
};

struct EnsembleCollapse {
  CollapseResult result;    // core/collapse of the ensemble means: one curve per case
  int resamples = 0;
  int usable = 0;           // resamples in which every case had a positive k_z
  std::vector<Estimate> k_z, peak, t_star;    // per case (t_star: where the curve crossed)
  Estimate t_star_mean, t_star_ensemble, spread_z, spread_t, peak_exponent;
};

// Throws std::invalid_argument when a case's mean has no positive k_z (the caller leaves it
// out first: see ensemble_depth_term) or no case is given.
EnsembleCollapse collapse_ensembles(const std::vector<EnsembleCase> &cases, const CollapseParams &p,
                                    const BootstrapParams &b = {});

// The peak law of the ensemble means, its exponent's errors those over runs (the
// bootstrap's), not those of the means' residuals.
PeakLaw peak_law_of_means(const EnsembleCollapse &c);

// k_z of a case's mean (k_z_fixed, or the fit over kz_fit's window); 0 when undefined.
double ensemble_depth_term(const EnsembleCase &c);

}    // namespace granpen

#endif
