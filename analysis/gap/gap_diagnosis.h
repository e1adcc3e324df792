// granpen gap: the diagnosis from measured traces and the simulation cache to OUT/
// (diagnosis.json, report.md, baseline/, corrected/). The numerics are in gap_data.h
// and gap_fit.h; this file reads, runs simulations and writes.
#ifndef GRANPEN_GAP_DIAGNOSIS_H
#define GRANPEN_GAP_DIAGNOSIS_H

#include "sweep_runner.h"

#include <string>
#include <vector>

namespace granpen {

struct GapOptions {
  std::string real, scenario, out, cache;
  std::string effects;         // comma-separated; empty = the whole library
  std::string v0;              // --prepare-only: the speeds
  bool prepare_only = false;
  bool local = false;          // run even what the cost estimate sends to a cluster
  bool fit_only = false;       // stop before the confirming simulations (a provisional verdict)
  std::string slurm;           // write a SLURM script that prepares the cache, and stop
  RunnerOptions runner;        // lmp, inputs, jobs (out_root is set per scenario)
};

// Returns the exit status; throws InputError for unreadable or mismatched input.
int run_gap(const GapOptions &opt);

// Core-hours of the runs of the requests not yet done in the cache (1.1e7 atom-steps
// per second per core, docs/presets.md; grains from the preset's lattice, a pour 0.6 s
// of simulated time).
struct Scenario;
struct SweepTask;
using SimRequest = SweepTask;
double estimate_core_hours(const Scenario &sc, const std::vector<SimRequest> &requests, const std::string &cache);

}    // namespace granpen

#endif
