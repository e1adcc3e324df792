// granpen gap, stage 5 (features and noise model): per speed, the ensembles of run
// features of the measured runs, of the baseline on its signature and reference beds and
// of every effect knot; the noise model (relative run-to-run variance pooled over every
// ensemble on beds of its own); the measured target with its variances; and the null
// replicates of the targeted test (the reference beds split into a no-effect
// "measurement" and its reference). docs/gap.md, "Where" 3-5 and "Targeted test".
#ifndef GRANPEN_GAP_FEATURES_H
#define GRANPEN_GAP_FEATURES_H

#include "effects.h"
#include "gap_data.h"
#include "gap_fit.h"
#include "gap_runs.h"
#include "gap_sims.h"

#include <map>
#include <string>
#include <vector>

namespace granpen {

struct Features {
  std::vector<double> speeds;                            // the measured speeds, ascending
  std::vector<Ensemble> real, base, fresh;               // per speed: measured, signature baseline, reference
  std::map<std::string, std::vector<Ensemble>> knots;    // sweep name -> per speed
  std::vector<std::vector<double>> cv2;                  // per speed: the pooled relative variance per feature
  std::vector<std::vector<double>> fresh_err;            // per speed: the reference's variance of the mean
  Target target;                                         // the measured means and their variances
  std::vector<double> target_scale;                      // per speed: measured noise / the model's
  std::vector<Target> nulls;                             // null replicates
  std::vector<EnsembleMoments> spec_real, spec_fresh;    // per speed: the metric's band amplitudes (G_spec)
  int dof_min = 0;                                       // degrees of freedom of the noise model (fewest)
  int n_reference = 0;                                   // reference runs per speed (fewest)
  std::vector<std::string> notes;                        // said in the report
  std::size_t nspeeds() const { return speeds.size(); }
};

// The ensemble of run features of runs at speed v0; throws InputError naming a run whose
// features cannot be formed (too short for the grid).
Ensemble ensemble_of(const std::vector<TraceRun> &runs, const GapGrid &grid, double v0);

// The metric's band amplitudes (core/gap_metric.h: the fluctuation about each run's bin means
// over the grid) of every run, as an ensemble: for G_spec.
EnsembleMoments spectrum_moments(const std::vector<TraceRun> &runs, const GapGrid &grid);

// Variance of the mean per feature from the pooled relative noise model, times scale.
std::vector<double> model_err(const Ensemble &e, const std::vector<double> &cv2, double scale = 1.0);

// The measured side's noise relative to the model's: the mean ratio of its run-to-run
// variance to the model's when it has several runs, else its fluctuation level's squared
// ratio to the baseline's (at least 1).
double noise_scale(const Ensemble &measured, const Ensemble &baseline, const std::vector<double> &cv2,
                   const GapGrid &grid);

// Every subset of m of n indices (in order).
std::vector<std::vector<std::size_t>> subsets(std::size_t n, std::size_t m);

// The null replicates: every subset of m reference runs per speed as a measurement without
// any effect against the rest, referenced as the models are (f.fresh, f.fresh_err, f.cv2
// and f.base set on entry).
std::vector<Target> null_replicates(const Features &f, const GapGrid &grid, std::size_t m);

// Everything above, from aligned runs on the grid. n_real_files: the measured runs in all
// (the null replicates take as many runs per speed as the measurement has, at most all but
// two). Throws InputError when the reference beds have fewer than 3 runs at a speed.
Features build_features(const RunsBySpeed &real, const SimulatedRuns &sims, const std::vector<const Effect *> &effects,
                        const GapGrid &grid, std::size_t n_real_files);

// One line per ensemble and speed of means (and the noise model): for GRANPEN_GAP_DEBUG.
std::vector<std::string> feature_dump(const Features &f);

}    // namespace granpen

#endif
