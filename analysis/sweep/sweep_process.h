// granpen sweep, the runner's processes (sweep_runner.cpp): a run started from its
// argument vector (no shell), and what its end means. Internal to the sweep library.
#ifndef GRANPEN_SWEEP_PROCESS_H
#define GRANPEN_SWEEP_PROCESS_H

#include <string>
#include <sys/types.h>
#include <vector>

namespace granpen {
namespace sweep_run {

// Starts argv with stdout and stderr into out; its pid, or -1 (errno set). The child is a
// process group of its own, dies with the runner, and inherits no lock (sweep_process.cpp).
pid_t spawn(const std::vector<std::string> &argv, const std::string &out);
// "exit code N" or the signal that ended a run, with what it means when it is a known fault
std::string exit_reason(int wstatus);

}    // namespace sweep_run
}    // namespace granpen

#endif
