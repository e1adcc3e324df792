// granpen analysis: what granpen collapse (and granpen plot ratio and peak) derive from a
// set of traces, as named stages on arrays (no files, no printing), each with a typed
// result:
//   1. depth_terms     each trace's depth term: given (k_z from alpha), else fitted over
//                      the k_z window (core/trace_fit.h, the window shortened onto the data)
//   2. collapse        the collapse (core/collapse.h) of the traces with a positive one
//   3. peaks           the collapse of every trace with k_z = 1: its peaks and peak law
//                      (a peak needs no depth term)
//   4. ensembles       per ensemble mean its depth term, the collapse of those with a
//                      positive one with bootstrap errors over runs (core/ensemble_fit.h),
//                      and each binned F/F_z's standard error over runs
//   5. ensemble_peaks  the collapse of every ensemble with k_z = 1: the peak law of the
//                      means, its errors over runs
// The front ends choose the stages and word what the results say.
#ifndef GRANPEN_COLLAPSE_STUDY_H
#define GRANPEN_COLLAPSE_STUDY_H

#include "collapse.h"
#include "ensemble_average.h"
#include "ensemble_fit.h"

#include <cstddef>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace granpen {

struct CollapseStudyParams {
  CollapseParams collapse;
  double kz_zmin = 3.0, kz_zmax = std::numeric_limits<double>::infinity();    // the k_z window, cm
  BootstrapParams boot;    // the ensembles' errors over runs
};

// One trace (cgs): its arrays, its case, and its depth term when given (k_z_given: e.g.
// alpha mu rho_g g D^2, taken as it is), else fitted over the window.
struct CollapseTrace {
  std::string name;
  std::vector<double> z, F;
  double v0 = 0.0, D = 0.0, g = 0.0;
  bool k_z_given = false;
  double k_z_fixed = 0.0;
};

// One ensemble: the mean of its runs (core/ensemble_average.h), its case, its depth term
// when given (as CollapseTrace's; a given one that is not positive leaves it out).
struct CollapseEnsemble {
  std::string name;
  double v0 = 0.0, D = 0.0, g = 0.0;
  EnsembleMean mean;
  bool k_z_given = false;
  double k_z_fixed = 0.0;
};

// Stage 1, per trace: the depth term, or why there is none.
struct DepthTermOutcome {
  bool ok = false;                // a depth term to collapse with: given, or fitted and positive
  double k_z = 0.0;               // dyne/cm (the fit's, also when not positive)
  bool fitted = false;            // from the window (not given)
  double zlo = 0.0, zhi = 0.0;    // the window fitted (an infinite end: the data's end)
  bool window_shortened = false;
  std::string window_note;        // core/trace_fit's note when it was shortened
};

// Stage 4's result.
struct EnsembleCollapseStudy {
  std::vector<std::size_t> kept, left_out;    // indices into the ensembles given
  EnsembleCollapse collapse;                  // of the kept ones, in their order (empty: none kept)
  // per kept ensemble, per t~ bin of its curve: the standard error over runs of the runs'
  // own F/F_z averaged in that bin (0 with fewer than 2 runs)
  std::vector<std::vector<double>> ratio_se;
};

enum class CollapseStage { depth_terms, collapse, peaks, ensembles, ensemble_peaks };
const char *collapse_stage_name(CollapseStage s);
// Called as each stage starts.
using CollapseProgress = std::function<void(CollapseStage)>;

// Which stages run: depth_terms with collapse, which runs only with a trace that has a
// depth term; peaks only with a trace; the ensemble stages only with an ensemble.
struct CollapseStages {
  bool collapse = true, peaks = false, ensembles = false, ensemble_peaks = false;
};

struct CollapseStudy {
  std::vector<DepthTermOutcome> depth;    // stage 1, per trace
  bool collapsed = false;                 // stage 2 ran
  CollapseResult result;
  bool peaks_done = false;                // stage 3 ran
  CollapseResult peaks;
  bool ensembles_done = false;            // stage 4 ran
  EnsembleCollapseStudy ensembles;
  bool ensemble_peaks_done = false;       // stage 5 ran
  EnsembleCollapse ensemble_peaks;
  PeakLaw ensemble_peak_law;              // of the means, its exponent's errors over runs
  // a stage the kernels refused (their std::invalid_argument: a non-positive v0, D, g or
  // k_z): the stages before it hold their results, none from it on ran
  bool refused = false;
  CollapseStage refused_at = CollapseStage::depth_terms;
  std::string refusal;    // the kernel's message
};

// The stages one by one. collapse_of_traces takes the traces with a positive depth term
// (depth as collapse_depth_terms gives it); peaks_of_traces every trace.
std::vector<DepthTermOutcome> collapse_depth_terms(const std::vector<CollapseTrace> &traces,
                                                   const CollapseStudyParams &p);
std::vector<CollapseInput> collapse_inputs(const std::vector<CollapseTrace> &traces,
                                           const std::vector<DepthTermOutcome> &depth);
CollapseResult peaks_of_traces(const std::vector<CollapseTrace> &traces, const CollapseStudyParams &p);
// Stage 4 into out: kept and left_out are set before the collapse, so that a refused one
// (std::invalid_argument) still tells which ensembles were left out.
void collapse_ensemble_means(const std::vector<CollapseEnsemble> &ensembles, const CollapseStudyParams &p,
                             EnsembleCollapseStudy &out);
EnsembleCollapse peaks_of_ensembles(const std::vector<CollapseEnsemble> &ensembles, const CollapseStudyParams &p);

// The chosen stages in order, up to the first the kernels refuse (see CollapseStudy::refused;
// the stage functions above throw std::invalid_argument instead).
CollapseStudy run_collapse_study(const std::vector<CollapseTrace> &traces,
                                 const std::vector<CollapseEnsemble> &ensembles, const CollapseStudyParams &p,
                                 const CollapseStages &stages, const CollapseProgress &progress = {});

}    // namespace granpen

#endif
