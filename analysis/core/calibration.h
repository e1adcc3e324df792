/* -*- c++ -*- ----------------------------------------------------------
   granpen analysis: the friction-calibration table (the paper's Simulation
   Calibration: mu sets phi_0 through the pour, and phi_0 and mu set k_z).
   Plain records in, one row per (mu, v0) out: phi_0 over the beds poured at
   that mu, k_z and alpha over the pushes at that mu and v0. Knows nothing of
   files.
------------------------------------------------------------------------- */

#ifndef GRANPEN_CALIBRATION_H
#define GRANPEN_CALIBRATION_H

#include <cstddef>
#include <string>
#include <vector>

namespace granpen {

struct CalibrationBed {
  std::string name;
  double mu = 0.0, seed = 0.0, phi_0 = 0.0;
};

struct CalibrationPush {
  std::string name;    // e.g. the trace file
  std::string bed;     // the bed it was pushed into
  double mu = 0.0, seed = 0.0, v0 = 0.0;
  double k_z = 0.0;      // dyne/cm
  double alpha = 0.0;    // k_z / (mu rho_g g D^2)
};

// mean and sample standard deviation (n - 1 in the denominator); sd = 0 for n < 2,
// everything 0 for n = 0
struct Stat {
  std::size_t n = 0;
  double mean = 0.0, sd = 0.0;
};
Stat mean_sd(const std::vector<double> &values);

struct CalibrationRow {
  double mu = 0.0;
  double v0 = 0.0;    // 0 when this mu has no pushes
  Stat phi_0;         // over the beds of this mu (the same in every row of this mu)
  Stat k_z;           // over the pushes of this mu and v0
  Stat alpha;
  std::vector<CalibrationBed> beds;      // the points behind phi_0
  std::vector<CalibrationPush> pushes;   // the points behind k_z and alpha
};

// Rows sorted by mu then v0. mu values (and v0 values) that agree to a relative
// 1e-9 are one group. A mu with beds but no pushes gives one row with v0 = 0 and
// empty k_z; a mu with pushes but no beds poured at it (mu raised in a poured bed) takes
// phi_0 over the beds its pushes were pushed into.
std::vector<CalibrationRow> calibration_table(const std::vector<CalibrationBed> &beds,
                                              const std::vector<CalibrationPush> &pushes);

}    // namespace granpen

#endif
