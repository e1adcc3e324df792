// granpen analysis: what granpen calibration derives from a sweep's beds and pushes, as
// named stages on arrays (no files, no printing), each with a typed result:
//   1. fits   each push's depth term k_z and alpha = k_z / (mu rho_g g D^2) over the window
//             z = zmin..zmax (core/trace_fit.h)
//   2. table  the rows by (mu, v0): phi_0 over the beds, k_z and alpha over the pushes
//             (core/calibration.h)
// The front end reads the folder (io/calibration_sweep.h) and words what the results say.
#ifndef GRANPEN_CALIBRATION_STUDY_H
#define GRANPEN_CALIBRATION_STUDY_H

#include "calibration.h"

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace granpen {

struct CalibrationStudyParams {
  double zmin = 1.0, zmax = 3.0;    // the k_z window, cm (the bench scenario's)
};

// A push read (cgs): what the table needs of it (k_z and alpha are the fit's), its arrays,
// and the case the fit needs.
struct CalibrationTrace {
  CalibrationPush push;
  std::vector<double> z, F;
  double D = 0.0, g = 0.0, rho_g = 0.0, d_g = 0.0;
};

// Stage 1, per push: fitted, or why not.
struct CalibrationFitOutcome {
  bool ok = false;         // k_z defined: the push is in the table
  bool alpha_ok = false;   // alpha defined (else counted as 0)
  bool refused = false;    // the fit refused the arrays (its std::invalid_argument in why)
  std::string why;         // not ok: the fit's note ("k_z undefined" without one), or the refusal
};

enum class CalibrationStage { fits, table };
const char *calibration_stage_name(CalibrationStage s);
// Called as each stage starts, and in fits after each push (done of of).
using CalibrationProgress = std::function<void(CalibrationStage, std::size_t done, std::size_t of)>;

struct CalibrationStudy {
  std::vector<CalibrationFitOutcome> fits;    // per push given
  std::vector<CalibrationPush> pushes;        // those fitted, in order, k_z and alpha set
  std::vector<CalibrationRow> rows;           // the table
};

// Stage 1 on one push.
CalibrationFitOutcome fit_calibration_push(const CalibrationTrace &t, const CalibrationStudyParams &p,
                                           CalibrationPush &fitted);

// Both stages.
CalibrationStudy run_calibration_study(const std::vector<CalibrationBed> &beds,
                                       const std::vector<CalibrationTrace> &pushes, const CalibrationStudyParams &p,
                                       const CalibrationProgress &progress = {});

}    // namespace granpen

#endif
