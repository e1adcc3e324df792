// granpen gap: what a scenario (a preset, inputs/presets/NAME.lmp) says about the set-up,
// and whether measured traces match it. Pure except for reading the preset file.
#ifndef GRANPEN_GAP_SCENARIO_H
#define GRANPEN_GAP_SCENARIO_H

#include <map>
#include <string>
#include <vector>

namespace granpen {

struct Scenario {
  std::string name, path;
  std::map<std::string, std::string> vars;    // every "variable NAME index VALUE"
  double D = 0, d_g = 0, g = 0, rho_g = 0, mu = 0, depth = 0, gap = 0;    // cgs
  double number(const std::string &key) const;    // throws InputError naming the preset
};

// Reads inputs/presets/NAME.lmp; throws InputError when it is missing or lacks a value.
Scenario read_scenario(const std::string &inputs, const std::string &name);

// Whether --scenario names a preset file of the user's own (a path: it holds a '/' or ends
// in .lmp) rather than a preset of inputs/presets.
bool scenario_is_file(const std::string &arg);

// The variables a preset must set: those every preset of inputs/presets sets (what the
// decks read from a preset, without a second list to keep in step with them).
std::vector<std::string> preset_variables(const std::string &inputs);

// A preset file of the user's own. Its name is the file's stem and a hash of its text
// (an edited file gets a cache of its own). Throws GapRefused (a usage error) naming the
// file when it is unreadable, misses a variable of preset_variables or has a value that is
// not a number where the diagnosis needs one.
Scenario read_scenario_file(const std::string &inputs, const std::string &file);

// The inputs folder the decks run a user's scenario from, made under dir: dir/NAME/ with a
// link to every entry of `inputs` but presets/, and presets/ with links to the presets
// plus a copy of the user's file as NAME.lmp; the decks stay as they are. Returns its path.
std::string stage_scenario_inputs(const Scenario &sc, const std::string &inputs, const std::string &dir);

}    // namespace granpen

#endif
