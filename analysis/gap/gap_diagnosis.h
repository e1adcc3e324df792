// granpen gap: the diagnosis from measured traces and the simulation cache to OUT/
// (diagnosis.json, report.md, baseline/, corrected/), as a sequence of stages with typed
// results, each in its own file, numbered in the order they run (docs/gap.md, "Stages"):
//    1 validate (gap_inputs.h)        2 plan (gap_plan.h)
//    3 simulate (gap_sims.h: through the sweep layer; also the runs later stages ask for)
//    4 align and bin (gap_align.h)    5 features and noise model (gap_features.h)
//    6 where (gap_where.h)            7 which: the fits (gap_which.h)
//    8 verdict (gap_verdict.h: the one owner; on the fits, then with the confirmation)
//    9 confirm (gap_confirm.h: asks 3 for its runs, returns a typed result to 8)
//   10 limits: how blind (gap_limits.h)   11 residual (gap_residual.h)
//   12 record: the Diagnosis, assembled once from the results (gap_result.h)
//   13 report: a pure function of the record (gap_report.h)
// The thresholds are one table (gap_thresholds.h); the numerics are in gap_data.h and
// gap_fit.h. Progress goes through a callback (gap_progress.h): the library prints nothing.
#ifndef GRANPEN_GAP_DIAGNOSIS_H
#define GRANPEN_GAP_DIAGNOSIS_H

#include "gap_progress.h"
#include "sweep_runner.h"

#include <optional>
#include <vector>
#include <string>

namespace granpen {

struct GapOptions {
  std::string real, scenario, out, cache;
  std::optional<std::string> effects;    // comma-separated; not given = the whole library
  std::string v0;              // --prepare-only: the speeds
  bool prepare_only = false;
  bool local = false;          // run even what the cost estimate sends to a cluster
  bool fit_only = false;       // stop before the confirming simulations (a provisional verdict)
  std::string slurm;           // write a SLURM script that prepares the cache, and stop
  int only_task = -1;          // with prepare_only: run task K of the --slurm arrays alone
  double budget = -1;          // core-hours; < 0: none. A plan above it stops before anything starts
  std::string prior;           // the signature prior (gap_prior.h): a file; "" = INPUTS/priors/SCENARIO.json if any; "none"
  std::string write_prior;     // --write-prior FILE: prepare the prior's runs and write it (with --v0), nothing else
  std::vector<std::string> prior_seeds;    // --prior-seeds: its beds (empty: the signature seeds 1 2, the cache's own)
  RunnerOptions runner;        // lmp, inputs, jobs (out_root is set per scenario)
};

// Exit status when the plan's estimate exceeds --budget: the plan printed, nothing started,
// nothing written in OUT (docs/gap.md).
constexpr int GAP_OVER_BUDGET = 3;

// The diagnosis (or, with prepare_only, the cache's simulations; with slurm, the script
// that runs them on a cluster). Returns the exit status (0 done, 1 simulations failed,
// GAP_OVER_BUDGET);
// throws GapRefused (gap_errors.h) for input it refuses before starting anything, and
// InputError for unreadable input or failed simulations.
int run_gap(const GapOptions &opt, const GapProgressFn &progress);

// The diagnosis proper: every stage, from the measured traces to OUT.
int run_gap_diagnosis(const GapOptions &opt, const GapProgressFn &progress);

}    // namespace granpen

#endif
