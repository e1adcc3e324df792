// granpen sweep, the runner's files (sweep_runner.cpp): tests on paths, reading the small
// text files runs leave (.info, logs, in.pour's state), the tail of a trace being
// written, LAMMPS checkpoints, beds shared between sweeps. Internal to the sweep library.
#ifndef GRANPEN_SWEEP_FILES_H
#define GRANPEN_SWEEP_FILES_H

#include <map>
#include <string>
#include <utility>

namespace granpen {
namespace sweep_run {

bool exists(const std::string &p);
// modification time in seconds; -1 when p does not exist
double mtime(const std::string &p);
// p and every folder above it (InputError naming the folder that cannot be made)
void mkdirs(const std::string &p);
// the whole file ("" when unreadable)
std::string slurp(const std::string &p);
// the first line of text that starts with prefix, "" when none does
std::string first_line_matching(const std::string &text, const std::string &prefix);
// KEY = VALUE lines of a .info or .done file ('#' lines skipped)
std::map<std::string, std::string> read_info(const std::string &p);
// depth of the last row of a trace being written (z is the second column of our traces)
double last_depth(const std::string &trace);
// an executable path, or a name found on PATH
bool on_path(const std::string &prog);
// the last progress line a pour printed ("granpen pour: chunk 5/60: ..."), shortened
std::string pour_status(const std::string &log);
// (whether a checkpoint is complete: complete_checkpoint, sweep_runner.h, defined here)
// a bed (restart and info) of another sweep, hard-linked (copied across file systems)
void link_bed(const std::string &from_dir, const std::string &to_dir, const std::string &id);
// A finished pour's checkpoints (NAME.pour.state, NAME.pour.STEP.restart): in.pour removes
// the one its state names, but a kill between LAMMPS writing a restart and the deck
// renaming the state leaves that newer restart behind, which only a listing finds.
void remove_pour_checkpoints(const std::string &stem);    // DIR/NAME.pour
// in.pour's NAME.pour.state: LAMMPS variable commands; the phase and the saved step
std::pair<std::string, std::string> read_pour_state(const std::string &path);

}    // namespace sweep_run
}    // namespace granpen

#endif
