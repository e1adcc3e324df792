// granpen sweep: SLURM scripts (see slurm_script.h).
#include "slurm_script.h"

#include "atomic_file.h"
#include "errors.h"    // InputError

#include <cstdio>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace granpen {

void write_slurm_arrays(const std::vector<std::string> &what, const std::vector<SlurmArray> &arrays, int ntasks,
                        const std::string &file)
{
  std::ostringstream f;
  f << "#!/bin/bash\n";
  for (const auto &line : what) f << "# " << line << "\n";
  f << "set -euo pipefail\n"
    << "SBATCH_OPTS=${SBATCH_OPTS:-}   # e.g. --partition=... --time=...\n";
  std::string before;    // the job id variable of the previous array
  for (const auto &a : arrays) {
    if (a.last < a.first) continue;
    if (a.command.find('"') != std::string::npos)
      throw InputError("a command with a double quote cannot go into a SLURM --wrap: " + a.command);
    f << a.var << "=$(sbatch --parsable $SBATCH_OPTS --job-name=" << a.job_name << " --ntasks=" << ntasks
      << (before.empty() ? "" : " --dependency=afterok:$" + before) << " --array=" << a.first << "-" << a.last
      << " --wrap=\"" << a.command << " \\$SLURM_ARRAY_TASK_ID\")\n"
      << "echo \"" << a.job_name << ": job $" << a.var << " (tasks " << a.first << "-" << a.last << ")\"\n";
    before = a.var;
  }
  write_file_atomic(file, f.str());    // OutputError naming the file
}

std::string this_executable(const std::string &fallback)
{
  char self[4096];
  const ssize_t n = readlink("/proc/self/exe", self, sizeof(self) - 1);
  return n > 0 ? std::string(self, (std::size_t) n) : fallback;
}

}    // namespace granpen
