// granpen sweep: runs a planned sweep with lmp_granpen: pours each bed once, branches
// every push from its saved bed, runs up to `jobs` processes at once, shows progress,
// resumes what an interrupted sweep left (finished runs skipped, pushes continued from
// their checkpoints), and keeps a JSON manifest of every run. Processes are started
// with argument vectors (fork/execv): no value of the sweep file reaches a shell.
#ifndef GRANPEN_SWEEP_RUNNER_H
#define GRANPEN_SWEEP_RUNNER_H

#include "sweep_spec.h"

#include <string>
#include <vector>

namespace granpen {

struct RunnerOptions {
  std::string lmp;         // lmp_granpen
  std::string mpirun;      // empty: run lmp_granpen directly
  int ranks = 1;           // MPI ranks per run (with mpirun)
  std::string inputs;      // the inputs/ folder (decks, presets, observe sets)
  std::string out_root;    // the sweep folder is out_root/NAME
  int jobs = 1;            // runs at once
  bool pool = true;        // run_requests (granpen gap): all sweeps in one pool, or one by one
  int checkpoint = 5000;   // push checkpoint interval (steps)
  int only_index = -1;     // run just this planned run (as a SLURM array task does)
  double progress_seconds = 5.0;
};

// Returns 0 when every run is done, 1 when any failed (all others still run).
int run_sweep(const SweepSpec &spec, const RunnerOptions &opt);

// A wall time for progress lines: "45s", "30m07s", "2.5h"; "?" when negative or not finite.
std::string format_duration(double seconds);

// Seconds left of a push first seen at depth z_then and, `elapsed` seconds later, at z_now
// (cm), if it goes on at that rate to target_depth: a long push's own ETA, before any run
// has finished to give a mean. NaN until it has gone deeper, without a target (the deck's
// default depth) or when an input is not finite; 0 at or past the target.
double push_seconds_left(double z_then, double z_now, double elapsed, double target_depth);

// A sweep of a pool; beds_from names another sweep (same presets, mu and seeds) in
// out_root whose beds it reuses (hard links) instead of pouring its own.
struct SweepTask {
  SweepSpec spec;
  std::string beds_from;
};

// Several sweeps in one pool of opt.jobs processes: every pour first (pushes wait for
// theirs), then the pushes longest first, so that no core idles at the end of one sweep
// while another has runs waiting. Each sweep keeps its folder, manifest and resume; a
// reused bed is linked as soon as its pour is done. Returns the number of sweeps with a
// failed run.
int run_sweeps(const std::vector<SweepTask> &tasks, const RunnerOptions &opt);

// Writes a script that submits the sweep to SLURM as two job arrays, the pours and
// then (after them) the pushes, each task running `granpen-cli sweep SPEC --only K`,
// through io/atomic_file (OutputError naming the file when it cannot be written).
void write_slurm_script(const SweepSpec &spec, const RunnerOptions &opt, const std::string &cli,
                        const std::string &file);

// Whether a LAMMPS checkpoint (a push's TRACE.a/.b.restart, a pour's NAME.pour.STEP.restart)
// was written to its end: the test the runner resumes by (one cut short by a kill or a full
// disk is never resumed from), and what `granpen checkpoint` answers for scripts
// (validation/campaign.sh --status). False for a missing or unreadable file.
bool complete_checkpoint(const std::string &path);

}    // namespace granpen

#endif
