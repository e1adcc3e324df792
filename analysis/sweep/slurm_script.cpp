// granpen sweep: one SLURM allocation running a command line (see slurm_script.h).
#include "slurm_script.h"

#include "errors.h"    // InputError

#include <cstdio>
#include <fstream>
#include <unistd.h>

namespace granpen {

void write_slurm_allocation(const SlurmAllocation &job, const std::string &file)
{
  const std::string tmp = file + ".tmp";
  {
    std::ofstream f(tmp);
    if (!f) throw InputError(file + ": cannot write");
    f << "#!/bin/bash\n# " << job.what << "\n# Submit with: sbatch [--partition=... --time=...] " << file
      << "\n#SBATCH --job-name=" << job.job_name << "\n#SBATCH --ntasks=" << job.ntasks << "\nset -e\n"
      << job.command << "\n";
    f.close();
    if (!f) {
      std::remove(tmp.c_str());
      throw InputError(file + ": write failed");
    }
  }
  if (std::rename(tmp.c_str(), file.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw InputError(file + ": cannot move the script into place");
  }
}

std::string this_executable(const std::string &fallback)
{
  char self[4096];
  const ssize_t n = readlink("/proc/self/exe", self, sizeof(self) - 1);
  return n > 0 ? std::string(self, (std::size_t) n) : fallback;
}

}    // namespace granpen
