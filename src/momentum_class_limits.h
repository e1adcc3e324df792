/* -*- c++ -*- ----------------------------------------------------------
   LAMMPS - Large-scale Atomic/Molecular Massively Parallel Simulator
   https://www.lammps.org/, Sandia National Laboratories
   Steve Plimpton, sjplimp@sandia.gov

   Copyright (2003) Sandia Corporation.  Under the terms of Contract
   DE-AC04-94AL85000 with Sandia Corporation, the U.S. Government retains
   certain rights in this software.  This software is distributed under
   the GNU General Public License.

   See the README file in the top-level LAMMPS directory.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   Contributing author: granpen developers
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   GRANPEN package: the vertical-speed classes of the paper's "Temporal
   Flows" section, as pure kernels (no LAMMPS type, no I/O). Written once,
   called by compute momentum/vbin and by the post-processor's
   analysis/core/momentum_classes:
     fast          v_z >= f1 v0            (f1 = 1/10)
     intermediate  f2 v0 <= v_z < f1 v0    (f2 = 1/80)
     slow          f3 v0 <  v_z < f2 v0    (f3 = 1/320)
     noise         f4 v0 <  v_z <= f3 v0   (f4 = 1/640)
   and M_move counts v_z > v_move (v0/320 by default, f3 v0 with user
   thresholds, or mfrac v0). The log-spaced classes of the compute's
   logbins keyword live here too. C++11, like the rest of src/.
------------------------------------------------------------------------- */

#ifndef LMP_MOMENTUM_CLASS_LIMITS_H
#define LMP_MOMENTUM_CLASS_LIMITS_H

#include <vector>

namespace granpen {

const int MOMENTUM_NCLASS = 4;
extern const char *const MOMENTUM_CLASS_NAMES[MOMENTUM_NCLASS];    // fast ... noise

struct MomentumClasses {
  double v0;
  double bound[MOMENTUM_NCLASS];    // velocities, fastest first
  double vmove;
  MomentumClasses() : v0(0.0), bound{0.0, 0.0, 0.0, 0.0}, vmove(0.0) {}
};

// The paper's classes: v0/10, v0/80, v0/320, v0/640 (divided, so exact whenever these
// are), v_move = v0/320. Throws std::invalid_argument unless v0 > 0.
MomentumClasses momentum_classes(double v0);
// User fractions f1 > f2 > f3 > f4 > 0 of v0 (frac null: the paper's classes); v_move =
// mfrac v0 when mfrac > 0, else f3 v0 (v0/320 for the paper's). Throws
// std::invalid_argument for v0 <= 0, fractions not > 0 and strictly decreasing, or
// mfrac < 0.
MomentumClasses momentum_classes(double v0, const double *frac, double mfrac = 0.0);

// Class of a grain moving up at vz (0 = fast ... 3 = noise), or -1 (in no class).
int momentum_class(const MomentumClasses &c, double vz);

// The most log classes (logbins N): a row of 3 sums each in compute momentum/vbin.
const int MOMENTUM_MAX_LOG_CLASSES = 10000;

// logbins N fmin fmax: N + 1 ascending bounds v0 fmin q^k (q = (fmax / fmin)^(1/N)), the
// last exactly v0 fmax. Throws std::invalid_argument unless v0 > 0,
// 1 <= N <= MOMENTUM_MAX_LOG_CLASSES and 0 < fmin < fmax.
std::vector<double> momentum_log_edges(double v0, int n, double fmin, double fmax);
// Row of vz among log classes (0 = the fastest, [edges[N-1], edges[N])), or -1 outside
// [edges[0], edges[N]).
int momentum_log_class(const std::vector<double> &edges, double vz);

}    // namespace granpen

#endif
