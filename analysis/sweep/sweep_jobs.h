// granpen sweep, a sweep's runs (sweep_runner.cpp): each planned run as a Job (its
// command line, files, status and lock), a sweep as its jobs and folder, what a run's
// files say on resume. Internal to the sweep library.
#ifndef GRANPEN_SWEEP_JOBS_H
#define GRANPEN_SWEEP_JOBS_H

#include "json_writer.h"    // Json
#include "sweep_runner.h"
#include "sweep_spec.h"

#include <chrono>
#include <cmath>
#include <map>
#include <string>
#include <sys/types.h>
#include <vector>

namespace granpen {
namespace sweep_run {

using Clock = std::chrono::steady_clock;

// One planned run.
struct Job {
  PlannedRun run;
  std::vector<std::string> argv;
  std::string log, out, trace, info, done;
  std::string pour_checkpoints;      // a checkpointed pour's NAME.pour (pour_checkpoint = yes)
  std::string status = "pending";    // pending, running, done, skipped, failed
  std::string action;                // what was done: started, resumed, restarted, already done
  std::string error;
  int exit_code = 0;
  pid_t pid = -1;
  Clock::time_point start;
  double wall = 0.0;
  double target_depth = 0.0;
  double z_seen = NAN;               // a running push's depth when this runner first read it
  Clock::time_point z_seen_at;       // ... and when (its own rate: push_seconds_left)
  int lock_fd = -1;                  // the run's lock while this runner holds it
};

// releases the run's lock (sweep_lock.h) when this runner holds it
void unlock(Job &j);

// One sweep of a pool: its runs, its folder and what its manifest keeps.
struct Sweep {
  SweepSpec spec;
  std::string dir;
  std::string label;                       // "NAME/" before run ids when a pool has several sweeps
  std::vector<Job> jobs;
  std::vector<Json> other_runs;            // manifest records of other sweep files of this name
  std::map<std::string, Json> held_runs;   // manifest records of runs another process holds
  std::string lammps_version;
  bool reported = false;                   // its closing line printed
};

inline bool finished(const Job &j) { return j.status == "done" || j.status == "skipped"; }
inline bool terminal(const Job &j) { return finished(j) || j.status == "failed"; }

// the command line of one planned run
Job make_job(const PlannedRun &r, const Sweep &sw, const RunnerOptions &opt);

// What a run's files say: a finished run is skipped, an interrupted push resumed from its
// newest complete checkpoint. `own`: this runner holds the run's lock and may move files.
void inspect_job(Job &j, bool own);

// The sweep's folder made, its runs planned; those this runner runs (opt.only_index, or
// all) locked before their files are looked at (one another process holds is refused,
// its files untouched), then inspected; the manifest's other records kept.
Sweep setup_sweep(const SweepTask &task, const RunnerOptions &opt);

}    // namespace sweep_run
}    // namespace granpen

#endif
