// granpen gap: one force trace as the diagnosis uses it (cgs, with its force onset), runs
// grouped by speed, and the depth alignment of runs by their onsets.
#ifndef GRANPEN_GAP_RUNS_H
#define GRANPEN_GAP_RUNS_H

#include "trace_reader.h"

#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace granpen {

struct TraceRun {
  std::string path;
  double v0 = 0;               // cm/s, rounded (speed_key) so that runs of one speed group
  std::vector<double> t, z, F;    // cgs
  double onset = NAN;          // force_onset (gap_data.h), moved with z by align_runs
};
using RunsBySpeed = std::map<double, std::vector<TraceRun>>;    // v0 -> runs

// A speed as a map key: rounded to 1e-6 cm/s, so that "100" and "1.0 m/s" meet.
double speed_key(double v0);

// The run of a trace already read (converted to cgs); throws InputError naming the file
// when F never rises (no onset).
TraceRun run_of_trace(const Trace &trace);

// Shifts every run's depths so that its onset sits at `onset`.
void align_runs(std::vector<TraceRun> &runs, double onset);

// The deepest depth every run reaches (-inf when a run is empty, +inf without runs).
double deepest_common(const std::vector<TraceRun> &runs);

}    // namespace granpen

#endif
