// granpen gap: runs, grouped by speed and aligned (see gap_runs.h).
#include "gap_runs.h"

#include "gap_data.h"

#include <algorithm>

namespace granpen {

double speed_key(double v0) { return std::round(v0 * 1e6) / 1e6; }

TraceRun run_of_trace(const Trace &trace)
{
  const Trace t = to_cgs(trace);
  TraceRun r;
  r.path = trace.path;
  r.v0 = speed_key(t.v0);
  r.t = t.t;
  r.z = t.z;
  r.F = t.F;
  r.onset = force_onset(r.z, r.F);
  if (!std::isfinite(r.onset)) throw InputError(trace.path + ": no force onset (F never rises above zero)");
  return r;
}

void align_runs(std::vector<TraceRun> &runs, double onset)
{
  for (auto &r : runs) {
    const double d = onset - r.onset;
    for (auto &z : r.z) z += d;
    r.onset = onset;
  }
}

double deepest_common(const std::vector<TraceRun> &runs)
{
  double m = INFINITY;
  for (const auto &r : runs) m = std::min(m, r.z.empty() ? -INFINITY : *std::max_element(r.z.begin(), r.z.end()));
  return m;
}

}    // namespace granpen
