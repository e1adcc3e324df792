// granpen fit, collapse and plot --ensemble: the traces grouped by (v0, g, D)
// (io/ensemble_tables.h) and each group's runs averaged (core/ensemble_averaging.h),
// before the fit or collapse study takes the means.
#ifndef GRANPEN_CLI_ENSEMBLE_GROUPS_H
#define GRANPEN_CLI_ENSEMBLE_GROUPS_H

#include "ensemble_averaging.h"
#include "ensemble_tables.h"

#include <string>
#include <vector>

namespace granpen {
namespace cli {

// The groups with their means; a group that could not be averaged is a line in problems and
// left out. Throws InputError for runs of one case but other grains, or an --ensemble-bin
// too fine (io/ensemble_tables.h).
std::vector<TraceGroup> averaged_groups(const std::vector<Trace> &traces, const EnsembleParams &p,
                                        std::vector<std::string> &problems);

}    // namespace cli
}    // namespace granpen

#endif
