// granpen gap, stage 1 (validate): the candidate effects named and the measured traces
// read and checked against the scenario, before anything is simulated or written. What
// the diagnosis refuses throws GapRefused (gap_errors.h, exit 2), naming the option or
// file; an unreadable trace throws InputError.
#ifndef GRANPEN_GAP_INPUTS_H
#define GRANPEN_GAP_INPUTS_H

#include "effects.h"
#include "gap_runs.h"
#include "scenario.h"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace granpen {

// --effects LIST (comma-separated): the named effects, in the order given; not given
// (nullopt) = the whole library. Refuses an empty list and an unknown name.
std::vector<const Effect *> choose_effects(const std::optional<std::string> &list);

// The speeds (cm/s) a scenario can push at: at most 1e6 push steps for gap + depth, at
// most 0.01 d_g per step.
std::pair<double, double> runnable_speeds(const Scenario &sc);
// --v0's speeds (cm/s, blank-separated) for --prepare-only and --slurm, each a whole number
// token, finite, within runnable_speeds and given once; GapRefused naming --v0 otherwise,
// before anything is planned, started or written.
std::vector<std::string> checked_speeds(const std::string &list, const Scenario &sc);

// Refuses a trace whose header contradicts the scenario: D, g, and d_g and rho_g when given, each
// within 1%.
void check_against_scenario(const Trace &t, const Scenario &sc);

struct MeasuredData {
  std::vector<std::string> files;       // sorted
  RunsBySpeed runs;                     // cgs, not yet aligned
  std::vector<std::string> v0s;         // the speeds as the decks get them, ascending
  std::vector<std::string> notes;       // warnings (one run at a speed), said in the report
};

// Reads the folder `real` of measured traces. Refuses a path that is not a folder, a folder
// without traces or with a single one in all, traces that mix unit systems, a header that
// contradicts the scenario and a speed the scenario cannot run.
MeasuredData read_measured(const std::string &real, const Scenario &sc);

// Refuses an OUT that would replace an input when moved into place: the --real folder or
// the cache, or a folder holding either.
void check_output_path(const std::string &out, const std::string &real, const std::string &cache);

}    // namespace granpen

#endif
