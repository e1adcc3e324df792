/* -*- c++ -*- ----------------------------------------------------------
   granpen analysis: the grains' upward momentum by vertical-speed class
   (paper: "Temporal Flows", figure mom_count) from grain snapshots, on plain
   arrays. The classes are src/momentum_class_limits.h's, the kernel compute
   momentum/vbin calls, and the selection is the compute's
   (docs/compute_momentum_vbin.rst):
     fast          v_z >= f1 v0            (f1 = 1/10)
     intermediate  f2 v0 <= v_z < f1 v0    (f2 = 1/80)
     slow          f3 v0 <  v_z < f2 v0    (f3 = 1/320)
     noise         f4 v0 <  v_z <= f3 v0   (f4 = 1/640)
   of the grains with r > R (strictly) about the rod axis, minimum image in
   periodic x, y. M_slow = mass of the slow class; M_move = mass of every
   selected grain with v_z > v_move (v0/320 by default, f3 v0 with user
   thresholds, or mthreshold v0), the paper's mu g M(v_z > v0/320).
   Also: F at a frame's time or depth from a force trace's columns, and the
   comparison of F with mu g M_move (fit through the origin, mean ratio).
------------------------------------------------------------------------- */

#ifndef GRANPEN_MOMENTUM_CLASSES_H
#define GRANPEN_MOMENTUM_CLASSES_H

#include "linear_fit.h"
#include "momentum_class_limits.h"

#include <cstddef>
#include <string>
#include <vector>

namespace granpen {

// MomentumClasses, momentum_classes, momentum_class, MOMENTUM_CLASS_NAMES:
// src/momentum_class_limits.h (the kernels compute momentum/vbin calls too).

struct MomentumTally {
  double count[MOMENTUM_NCLASS] = {0, 0, 0, 0};
  double mass[MOMENTUM_NCLASS] = {0, 0, 0, 0};
  double p_up[MOMENTUM_NCLASS] = {0, 0, 0, 0};    // sum m v_z
  double M_move = 0.0;                            // mass with v_z > v_move
  double M_slow = 0.0;                            // mass of the slow class
  std::size_t selected = 0;                       // grains with r > rmin
};

// Grains i < n (no rod atoms) with r > rmin about (axis_x, axis_y); period_x, period_y:
// box lengths of periodic directions (0: not periodic).
MomentumTally tally_momentum(const MomentumClasses &c, const double *x, const double *y, const double *vz,
                             const double *mass, std::size_t n, double axis_x, double axis_y, double rmin,
                             double period_x, double period_y);

// Where x first reaches x0: the fractional index i + f of the first interval [x_i, x_i+1]
// holding x0 (x need not be monotone), or -1 when none does.
double locate_first(const std::vector<double> &x, double x0);
// y at a fractional index from locate_first (linear interpolation); NaN for -1.
double value_at(const std::vector<double> &y, double pos);

// F against mu g M_move over the frames with mu_g_M > 0 and finite F: the slope k of
// F = k mu g M (least squares through the origin, with its standard error: the paper's
// 1:1 line is k = 1) and the mean ratio F / (mu g M) with its standard error.
struct DragComparison {
  bool ok = false;
  std::size_t n = 0;
  LinearFit fit;                   // b = k, se_b
  double ratio_mean = 0.0, ratio_se = 0.0;
  std::string note;                // why not ok
};
DragComparison compare_drag(const std::vector<double> &mu_g_M, const std::vector<double> &F);

}    // namespace granpen

#endif
