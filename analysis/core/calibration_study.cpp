// granpen analysis: the calibration study's stages (see calibration_study.h).
#include "calibration_study.h"

#include "trace_fit.h"

#include <stdexcept>

namespace granpen {

const char *calibration_stage_name(CalibrationStage s)
{
  switch (s) {
    case CalibrationStage::fits: return "fits";
    case CalibrationStage::table: return "table";
  }
  return "?";
}

CalibrationFitOutcome fit_calibration_push(const CalibrationTrace &t, const CalibrationStudyParams &p,
                                           CalibrationPush &fitted)
{
  CalibrationFitOutcome o;
  TraceFitParams par;
  par.zlo = p.zmin, par.zhi = p.zmax;
  par.v0 = t.push.v0, par.D = t.D, par.g = t.g;
  par.mu = t.push.mu, par.rho_g = t.rho_g, par.d_g = t.d_g;
  TraceFit fit;
  try {
    fit = fit_trace(t.z, t.F, par);
  } catch (std::invalid_argument &e) {
    o.refused = true, o.why = e.what();
    return o;
  }
  if (!fit.slope_ok) {
    o.why = fit.notes.empty() ? std::string("k_z undefined") : fit.notes.front();
    return o;
  }
  o.ok = true, o.alpha_ok = fit.alpha_ok;
  fitted = t.push;
  fitted.k_z = fit.k_z;
  fitted.alpha = fit.alpha_ok ? fit.alpha : 0.0;
  return o;
}

CalibrationStudy run_calibration_study(const std::vector<CalibrationBed> &beds,
                                       const std::vector<CalibrationTrace> &pushes, const CalibrationStudyParams &p,
                                       const CalibrationProgress &progress)
{
  CalibrationStudy s;
  const auto stage = [&](CalibrationStage x, std::size_t done, std::size_t of) {
    if (progress) progress(x, done, of);
  };
  stage(CalibrationStage::fits, 0, pushes.size());
  for (std::size_t i = 0; i < pushes.size(); ++i) {
    CalibrationPush fitted;
    s.fits.push_back(fit_calibration_push(pushes[i], p, fitted));
    if (s.fits.back().ok) s.pushes.push_back(fitted);
    stage(CalibrationStage::fits, i + 1, pushes.size());
  }
  stage(CalibrationStage::table, 0, 1);
  s.rows = calibration_table(beds, s.pushes);
  return s;
}

}    // namespace granpen
