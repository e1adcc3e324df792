// granpen sweep: what a sweep folder holds, for callers that use finished sweeps without
// knowing the runner's layout (OUT_ROOT/NAME/{beds,traces}, markers): the finished traces,
// the beds' info files, and the runs a sweep still has to do.
#ifndef GRANPEN_SWEEP_CACHE_H
#define GRANPEN_SWEEP_CACHE_H

#include "sweep_runner.h"
#include "sweep_spec.h"

#include <string>
#include <vector>

namespace granpen {

// The finished traces (*.csv with a .done marker) of sweep `name` under out_root, sorted;
// empty when the sweep has none (or no folder).
std::vector<std::string> finished_traces(const std::string &out_root, const std::string &name);

// The name of the sweep a trace of finished_traces belongs to.
std::string sweep_of_trace(const std::string &trace_path);

// The bed info files (*.info) of sweep `name` under out_root, sorted; empty without any.
std::vector<std::string> bed_info_files(const std::string &out_root, const std::string &name);

// The planned runs of a task that are not done yet under out_root: a pour whose bed info
// is missing (none when the task reuses another sweep's beds), a push without its .done
// marker.
std::vector<PlannedRun> pending_runs(const SweepTask &task, const std::string &out_root);

}    // namespace granpen

#endif
