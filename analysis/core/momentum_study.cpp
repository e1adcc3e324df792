// granpen analysis: the momentum study of a push's frames (see momentum_study.h).
#include "momentum_study.h"

#include "rod_frame.h"
#include "scaling_laws.h"

#include <cmath>

namespace granpen {

MomentumFrameRecord momentum_frame(const MomentumStudyParams &p, const TraceColumns &trace, const MomentumFrameInput &f)
{
  MomentumFrameRecord r;
  r.timestep = f.timestep;
  r.where = f.where;
  r.tip = f.tip;
  r.z_tip = p.z_s - f.tip;
  r.t_tilde = t_tilde(r.z_tip, p.v0, p.g, p.D);
  r.tally = tally_momentum(p.classes, f.x, f.y, f.vz, f.mass, f.n, f.axis_x, f.axis_y, 0.5 * p.D, f.period_x, f.period_y);
  r.mu_g_M = p.mu * p.g * r.tally.M_move;
  double pos;
  if (p.by_time) {
    r.t = (double) (f.timestep - p.push_step) * p.dt;
    pos = locate_first(trace.t, r.t);
  } else {
    pos = locate_first(trace.z, r.z_tip);
    r.t = value_at(trace.t, pos);
  }
  r.F = value_at(trace.F, pos);
  r.matched = std::isfinite(r.F);
  return r;
}

DragComparison drag_over_frames(const std::vector<MomentumFrameRecord> &frames)
{
  std::vector<double> x, y;
  for (const auto &r : frames)
    if (r.matched && r.z_tip > 0.0) x.push_back(r.mu_g_M), y.push_back(r.F);
  return compare_drag(x, y);
}

}    // namespace granpen
