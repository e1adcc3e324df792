// granpen sweep, the runs' locks (sweep_runner.cpp): DIR/locks/ID.lock, an flock the
// runner holds from before a run's files are looked at until the run ends (its process
// dies with the runner); the file names the runner's pid. Internal to the sweep library.
#ifndef GRANPEN_SWEEP_LOCK_H
#define GRANPEN_SWEEP_LOCK_H

#include <string>

namespace granpen {
namespace sweep_run {

// The lock at path: its descriptor (close-on-exec, so that no child keeps it held), or -1
// with holder set to the text of the file (the holder's pid) when another process holds
// it. InputError naming the file when it cannot be opened or written.
int lock_run(const std::string &path, std::string &holder);
// closes a descriptor of lock_run (-1: none), leaving -1
void release_lock(int &fd);

}    // namespace sweep_run
}    // namespace granpen

#endif
