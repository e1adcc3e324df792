// granpen sweep: the runs' locks (sweep_lock.h).
#include "sweep_lock.h"

#include "errors.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace granpen {
namespace sweep_run {

// The lock of one run, DIR/locks/ID.lock: an flock the runner holds from before the run's
// files are looked at until the run ends (its process dies with the runner); the file
// names the runner's pid. Returns the descriptor (close-on-exec), or -1 with holder set to the text
// of the file (the holder's pid) when another process holds it.
int lock_run(const std::string &path, std::string &holder)
{
  const int fd = open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) throw InputError("cannot open lock file " + path + ": " + std::strerror(errno));
  if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
    char buf[64] = {0};
    const ssize_t n = pread(fd, buf, sizeof buf - 1, 0);
    holder = n > 0 ? std::string(buf, (std::size_t) n) : std::string("?");
    while (!holder.empty() && (holder.back() == '\n' || holder.back() == ' ')) holder.pop_back();
    close(fd);
    return -1;
  }
  const std::string pid = std::to_string(getpid()) + "\n";
  if (ftruncate(fd, 0) != 0 || pwrite(fd, pid.data(), pid.size(), 0) != (ssize_t) pid.size()) {
    const std::string e = std::strerror(errno);
    close(fd);
    throw InputError("cannot write lock file " + path + ": " + e);
  }
  return fd;
}

void release_lock(int &fd)
{
  if (fd >= 0) close(fd);
  fd = -1;
}


}    // namespace sweep_run
}    // namespace granpen
