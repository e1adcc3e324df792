// granpen analysis: what granpen momentum derives from a push's frames, on plain arrays:
// per frame the grains' upward momentum by class outside the rod, the trace's F at the
// frame's depth (or time) and mu g M_move; over the frames F against mu g M_move
// (core/momentum_classes.h's kernels).
#ifndef GRANPEN_MOMENTUM_STUDY_H
#define GRANPEN_MOMENTUM_STUDY_H

#include "momentum_classes.h"
#include "param_choice.h"
#include "scaling_laws.h"

#include <string>
#include <vector>

namespace granpen {

struct MomentumStudyParams {
  MomentumClasses classes;
  double v0 = 0.0, g = 0.0, D = 0.0;    // the trace's v0 and g, the rod diameter
  double mu = DEFAULT_MU;               // friction for mu g M
  double z_s = 0.0;                     // bed surface: z_tip = z_s - tip
  bool by_time = false;                 // F at t = (timestep - push_step) dt, else at the depth
  long long push_step = 0;
  double dt = 0.0;
};

// Where the study's parameters (all but z_s) come from (param_choice.h): the options, the
// push's trace header, the defaults.
struct MomentumParamSources {
  double v0 = 0.0, g = 0.0;           // the trace's
  ParamChoice D, mu, dt;              // D falls back on D_trace; mu on DEFAULT_MU; dt on nothing
  double D_trace = 0.0;
  const double *thresholds = nullptr;    // the classes' bounds F1..F4 as fractions of v0 (null: the paper's)
  double mthreshold = 0.0;            // M_move counts v_z > mthreshold v0 (0: the classes' own bound)
  bool by_time = false;               // F matched by time from push_step, else by depth
  long long push_step = 0;
};
// Which source each came from ("option", "trace", "default"), and the classes' ("option",
// or the paper's).
struct MomentumParamOrigins {
  std::string D, mu, dt, classes;
};

// The parameters but z_s (the caller's: option, trace, else the first frame). Throws
// std::invalid_argument for classes momentum_classes refuses and for by_time without a
// dt from option or trace.
MomentumStudyParams momentum_study_params(const MomentumParamSources &s, MomentumParamOrigins &from);

// The force trace's columns F is read from.
struct TraceColumns {
  const std::vector<double> &t, &z, &F;
};

// One frame's grains (x, y, v_z, mass), the rod axis and tip.
struct MomentumFrameInput {
  const double *x = nullptr, *y = nullptr, *vz = nullptr, *mass = nullptr;
  std::size_t n = 0;
  double axis_x = 0.0, axis_y = 0.0, period_x = 0.0, period_y = 0.0, tip = 0.0;
  long long timestep = 0;
  std::string where;    // FILE:LINE
};

struct MomentumFrameRecord {
  long long timestep = 0;
  std::string where;
  double tip = 0, z_tip = 0, t = 0, t_tilde = 0, F = 0, mu_g_M = 0;
  bool matched = false;    // F defined: the frame within the trace's range
  MomentumTally tally;
};

MomentumFrameRecord momentum_frame(const MomentumStudyParams &p, const TraceColumns &trace, const MomentumFrameInput &f);

// F against mu g M_move over the matched frames with the tip in the bed.
DragComparison drag_over_frames(const std::vector<MomentumFrameRecord> &frames);

}    // namespace granpen

#endif
