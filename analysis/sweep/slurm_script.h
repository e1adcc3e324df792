// granpen sweep: SLURM scripts. A chain of job arrays, each started when the one before
// has succeeded (afterok), one task per planned run: a sweep's pours then its pushes
// (write_slurm_script, sweep_runner.h), the gap diagnosis's cache likewise.
#ifndef GRANPEN_SLURM_SCRIPT_H
#define GRANPEN_SLURM_SCRIPT_H

#include <string>
#include <vector>

namespace granpen {

// One job array of a chain: tasks first..last, each running `command $SLURM_ARRAY_TASK_ID`
// with ntasks SLURM tasks; var names the shell variable that keeps its job id.
struct SlurmArray {
  std::string job_name, var;
  int first = 0, last = -1;    // last < first: an empty stage, left out of the chain
  std::string command;         // the task index is appended; no double quotes in it
};

// Writes a script submitting the arrays in order, each with --dependency=afterok on the
// one before it (the empty ones left out), `what` as comment lines at the top; through
// io/atomic_file (OutputError naming the file). Submit with `bash FILE`; SBATCH_OPTS in
// the environment go to every sbatch.
void write_slurm_arrays(const std::vector<std::string> &what, const std::vector<SlurmArray> &arrays, int ntasks,
                        const std::string &file);

// The running program's own path (/proc/self/exe), or fallback where it cannot be read:
// what a script calls to run this program again on the cluster.
std::string this_executable(const std::string &fallback);

}    // namespace granpen

#endif
