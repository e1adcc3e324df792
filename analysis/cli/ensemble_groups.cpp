// granpen fit, collapse and plot --ensemble: the groups averaged (see ensemble_groups.h).
#include "ensemble_groups.h"

namespace granpen {
namespace cli {

std::vector<TraceGroup> averaged_groups(const std::vector<Trace> &traces, const EnsembleParams &p,
                                        std::vector<std::string> &problems)
{
  std::vector<TraceGroup> groups = group_traces(traces, p.v0_tolerance);
  keep_averaged(groups, average_ensembles(ensemble_runs(groups), p), p, problems);
  return groups;
}

}    // namespace cli
}    // namespace granpen
