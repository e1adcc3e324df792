// granpen analysis: the fit study's stages (see fit_study.h).
#include "fit_study.h"

#include <stdexcept>

namespace granpen {

const char *fit_stage_name(FitStage s)
{
  switch (s) {
    case FitStage::fits: return "fits";
    case FitStage::ensemble_fits: return "ensemble fits";
    case FitStage::run_fits: return "run fits";
  }
  return "?";
}

TraceFitOutcome fit_study_trace(const FitStudyTrace &t)
{
  TraceFitOutcome o;
  try {
    o.fit = fit_trace(t.z, t.F, t.params);
  } catch (std::invalid_argument &e) {
    o.refused = true, o.why = e.what();
  }
  return o;
}

std::vector<TraceFit> fit_ensemble_runs(const FitStudyEnsemble &e, const EnsembleFit &mean_fit)
{
  std::vector<TraceFit> out;
  if (!mean_fit.k_z.ok) return out;
  for (const auto &F : e.mean.per_run) out.push_back(fit_trace(e.mean.z, F, e.params));
  return out;
}

FitStudy run_fit_study(const std::vector<FitStudyTrace> &traces, const std::vector<FitStudyEnsemble> &ensembles,
                       const FitStudyParams &p, const FitStages &stages, const FitProgress &progress)
{
  FitStudy s;
  const auto stage = [&](FitStage x, std::size_t done, std::size_t of) {
    if (progress) progress(x, done, of);
  };
  if (stages.fits) {
    stage(FitStage::fits, 0, traces.size());
    for (std::size_t i = 0; i < traces.size(); ++i) {
      s.fits.push_back(fit_study_trace(traces[i]));
      stage(FitStage::fits, i + 1, traces.size());
    }
  }
  if (stages.ensemble_fits) {
    stage(FitStage::ensemble_fits, 0, ensembles.size());
    for (std::size_t i = 0; i < ensembles.size(); ++i) {
      s.ensembles.push_back(fit_ensemble(ensembles[i].mean, ensembles[i].params, p.boot));
      stage(FitStage::ensemble_fits, i + 1, ensembles.size());
    }
  }
  if (stages.ensemble_fits && stages.run_fits) {
    stage(FitStage::run_fits, 0, ensembles.size());
    for (std::size_t i = 0; i < ensembles.size(); ++i) {
      s.run_fits.push_back(fit_ensemble_runs(ensembles[i], s.ensembles[i]));
      stage(FitStage::run_fits, i + 1, ensembles.size());
    }
  }
  return s;
}

}    // namespace granpen
