// granpen analysis: granpen fit's traces read for the fit (a trace file, its header's mu,
// rho_g and d_g or the defaults, the window: the input of core/fit_study.h, which fits) and
// its result files: JSON (units cgs; undefined values 0 with a false *_ok flag) and one CSV
// row per trace.
#ifndef GRANPEN_FIT_TABLES_H
#define GRANPEN_FIT_TABLES_H

#include "fit_study.h"
#include "json_writer.h"
#include "trace_fit.h"

#include <string>
#include <vector>

namespace granpen {

struct FitResult {
  std::string file;
  double v0 = 0, D = 0, g = 0;
  double mu = 0, rho_g = 0, d_g = 0;
  std::string mu_src, rho_src, dg_src;    // "option", "header" or "default"
  TraceFit fit;                           // the fit study's
};

struct FitFailure {
  std::string file, message;
};

// The window and the values given as options (mu, rho_g: <= 0 when not given).
struct FitWindow {
  double zmin = 3.0, zmax = 0.0;    // zmax: infinity for the deepest depth
  double tmin = -1.0;               // > 0: the window starts at t~ = tmin instead of zmin
  double mu = 0.0, rho_g = 0.0;
};

// One trace read for the fit (cgs): its record (fit not yet set) and the fit study's input
// (the window's start from --tmin a depth of this trace; a window beyond the data shortened).
struct FitTraceRead {
  FitResult result;
  FitStudyTrace trace;
};
// Throws InputError naming the file.
FitTraceRead read_fit_trace(const std::string &path, const FitWindow &w);

Json fit_results_json(const std::vector<FitResult> &results, const std::vector<FitFailure> &failures, const FitWindow &w);
std::string fit_results_csv(const std::vector<FitResult> &results);

}    // namespace granpen

#endif
