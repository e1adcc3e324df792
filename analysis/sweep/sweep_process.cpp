// granpen sweep: the runner's processes (sweep_process.h).
#include "sweep_process.h"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace granpen {
namespace sweep_run {

// Starts argv with stdout and stderr into out. The child is a process group of its own and
// dies with the runner (PR_SET_PDEATHSIG): a runner killed with -9 leaves no LAMMPS behind
// writing the trace and checkpoints a resumed runner writes too. The run's lock is not
// inherited (close-on-exec): an MPI program forks helpers (Open MPI's singleton orted)
// that would keep it held long after the run.
pid_t spawn(const std::vector<std::string> &argv, const std::string &out)
{
  std::vector<char *> args;
  for (auto &a : argv) args.push_back(const_cast<char *>(a.c_str()));
  args.push_back(nullptr);
  const pid_t runner = getpid();
  pid_t pid = fork();
  if (pid == 0) {
    setpgid(0, 0);
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != runner) _exit(127);    // the runner died before prctl took effect
    signal(SIGXFSZ, SIG_DFL);                // the runner ignores it; LAMMPS must not write on past the limit
    int fd = open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
      dup2(fd, 1);
      dup2(fd, 2);
      close(fd);
    }
    int devnull = open("/dev/null", O_RDONLY);
    if (devnull >= 0) dup2(devnull, 0);
    execvp(args[0], args.data());
    std::fprintf(stderr, "cannot run %s: %s\n", args[0], std::strerror(errno));
    _exit(127);
  }
  if (pid > 0) setpgid(pid, pid);    // on both sides: whichever runs first
  return pid;
}

// "exit code N" or the signal that ended a run, with what it means when it is a known fault
std::string exit_reason(int wstatus)
{
  if (WIFEXITED(wstatus)) return "exit code " + std::to_string(WEXITSTATUS(wstatus));
  const int sig = WTERMSIG(wstatus);
  if (sig == SIGXFSZ) return "killed by SIGXFSZ: a file reached the file size limit (ulimit -f)";
  return "killed by signal " + std::to_string(sig) + " (" + strsignal(sig) + ")";
}

}    // namespace sweep_run
}    // namespace granpen
