// granpen sweep: a SLURM batch script that runs one command line in one allocation (the
// gap diagnosis's cache: `granpen-cli gap --prepare-only ...`, which runs its sweeps as
// one pool inside the allocation). The per-run job arrays of a single sweep are
// write_slurm_script (sweep_runner.h).
#ifndef GRANPEN_SLURM_SCRIPT_H
#define GRANPEN_SLURM_SCRIPT_H

#include <string>

namespace granpen {

struct SlurmAllocation {
  std::string job_name;
  int ntasks = 1;
  std::string what;        // one line said at the top of the script, after "# "
  std::string command;     // run with `set -e`, as written
};

// Writes the script to file (through a temporary name, renamed when complete); throws
// InputError naming the file when it cannot be written.
void write_slurm_allocation(const SlurmAllocation &job, const std::string &file);

// The running program's own path (/proc/self/exe), or fallback where it cannot be read:
// what a script calls to run this program again on the cluster.
std::string this_executable(const std::string &fallback);

}    // namespace granpen

#endif
