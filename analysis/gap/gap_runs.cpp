// granpen gap: runs, grouped by speed and aligned (see gap_runs.h).
#include "gap_runs.h"

#include "gap_data.h"
#include "onset_alignment.h"

#include <algorithm>

namespace granpen {

double speed_key(double v0) { return std::round(v0 * 1e6) / 1e6; }

TraceRun run_of_trace(const Trace &trace)
{
  require_t(trace, "granpen gap (its fluctuation bands are in time)");
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
  std::vector<double> onsets;
  for (const auto &r : runs) onsets.push_back(r.onset);
  const OnsetAlignment a = align_onsets(onsets, onset);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    shift_depths(runs[i].z, a.shift[i]);
    runs[i].onset += a.shift[i];
  }
}

double deepest_common(const std::vector<TraceRun> &runs)
{
  std::vector<const std::vector<double> *> z;
  for (const auto &r : runs) z.push_back(&r.z);
  return deepest_common(z);
}

}    // namespace granpen
