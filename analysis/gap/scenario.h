// granpen gap: what a scenario (a preset, inputs/presets/NAME.lmp) says about the set-up,
// and whether measured traces match it. Pure except for reading the preset file.
#ifndef GRANPEN_GAP_SCENARIO_H
#define GRANPEN_GAP_SCENARIO_H

#include <map>
#include <string>

namespace granpen {

struct Scenario {
  std::string name, path;
  std::map<std::string, std::string> vars;    // every "variable NAME index VALUE"
  double D = 0, d_g = 0, g = 0, rho_g = 0, mu = 0, depth = 0, gap = 0;    // cgs
  double number(const std::string &key) const;    // throws InputError naming the preset
};

// Reads inputs/presets/NAME.lmp; throws InputError when it is missing or lacks a value.
Scenario read_scenario(const std::string &inputs, const std::string &name);

}    // namespace granpen

#endif
