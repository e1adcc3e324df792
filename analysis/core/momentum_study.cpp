// granpen analysis: the momentum study of a push's frames (see momentum_study.h).
#include "momentum_study.h"

#include "rod_frame.h"
#include "scaling_laws.h"

#include <cmath>
#include <stdexcept>

namespace granpen {

MomentumStudyParams momentum_study_params(const MomentumParamSources &s, MomentumParamOrigins &from)
{
  MomentumStudyParams p;
  p.classes = momentum_classes(s.v0, s.thresholds, s.mthreshold);
  from.classes = s.thresholds ? "option" : "paper (v0/10, v0/80, v0/320, v0/640)";
  p.v0 = s.v0, p.g = s.g;
  p.mu = resolve(s.mu, DEFAULT_MU, "default", from.mu);
  p.D = resolve(s.D, s.D_trace, "trace", from.D);
  p.by_time = s.by_time;
  if (p.by_time) {
    p.push_step = s.push_step;
    p.dt = resolve(s.dt, std::nan(""), "none", from.dt);
    if (!std::isfinite(p.dt)) throw std::invalid_argument("--push-step needs --dt (the trace has no dt key)");
  }
  return p;
}

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
