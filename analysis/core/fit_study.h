// granpen analysis: what granpen fit and granpen plot force and kz derive from traces and
// from the ensembles' means, as named stages on arrays (no files, no printing), each with a
// typed result:
//   1. fits           each trace's fit (core/trace_fit.h) with its own window and case
//   2. ensemble_fits  each ensemble mean's fit with its errors over runs (core/ensemble_fit.h)
//   3. run_fits       each run of an ensemble whose mean has k_z, fitted on the mean's
//                     aligned bins with the mean's window (granpen plot kz's single runs:
//                     their k_z average to the ensemble's, the fit being linear in F)
// The front ends read the traces, average the ensembles (core/ensemble_averaging.h),
// choose the stages and word what the results say.
#ifndef GRANPEN_FIT_STUDY_H
#define GRANPEN_FIT_STUDY_H

#include "ensemble_average.h"
#include "ensemble_fit.h"
#include "trace_fit.h"

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace granpen {

// One trace (cgs): its arrays and its fit's window and case.
struct FitStudyTrace {
  std::string name;
  std::vector<double> z, F;
  TraceFitParams params;
};

// One ensemble: the mean of its runs and its fit's window and case.
struct FitStudyEnsemble {
  std::string name;
  EnsembleMean mean;
  TraceFitParams params;
};

struct FitStudyParams {
  BootstrapParams boot;    // the ensembles' errors over runs
};

// Stage 1, per trace: the fit, or the fit's refusal (its std::invalid_argument).
struct TraceFitOutcome {
  bool refused = false;
  std::string why;
  TraceFit fit;
};

enum class FitStage { fits, ensemble_fits, run_fits };
const char *fit_stage_name(FitStage s);
// Called as each stage starts and after each trace or ensemble (done of of).
using FitProgress = std::function<void(FitStage, std::size_t done, std::size_t of)>;

struct FitStages {
  bool fits = true, ensemble_fits = false, run_fits = false;
};

struct FitStudy {
  std::vector<TraceFitOutcome> fits;           // stage 1, per trace (empty: not run)
  std::vector<EnsembleFit> ensembles;          // stage 2, per ensemble (empty: not run)
  // stage 3, per ensemble: its runs' fits, empty where the mean has no k_z (or not run)
  std::vector<std::vector<TraceFit>> run_fits;
};

// The stages one by one.
TraceFitOutcome fit_study_trace(const FitStudyTrace &t);
// Every run of e on its mean's bins, with the mean's window; empty when the mean has no
// k_z (mean_fit.k_z not ok).
std::vector<TraceFit> fit_ensemble_runs(const FitStudyEnsemble &e, const EnsembleFit &mean_fit);

// The chosen stages in order (run_fits needs ensemble_fits). The ensembles' fits may throw
// std::invalid_argument (core/ensemble_fit.h); the traces' refusals are per trace.
FitStudy run_fit_study(const std::vector<FitStudyTrace> &traces, const std::vector<FitStudyEnsemble> &ensembles,
                       const FitStudyParams &p, const FitStages &stages, const FitProgress &progress = {});

}    // namespace granpen

#endif
