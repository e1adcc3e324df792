#include "scenario.h"

#include "errors.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace granpen {

double Scenario::number(const std::string &key) const
{
  auto it = vars.find(key);
  if (it == vars.end()) throw InputError(path + ": the preset sets no '" + key + "'");
  char *end = nullptr;
  const double v = std::strtod(it->second.c_str(), &end);
  if (end == it->second.c_str() || !std::isfinite(v))
    throw InputError(path + ": '" + key + "' is not a number: " + it->second);
  return v;
}

Scenario read_scenario(const std::string &inputs, const std::string &name)
{
  Scenario s;
  s.name = name;
  s.path = inputs + "/presets/" + name + ".lmp";
  std::ifstream f(s.path);
  if (!f) throw InputError("unknown scenario '" + name + "': no preset " + s.path);
  std::string line;
  while (std::getline(f, line)) {
    std::istringstream in(line.substr(0, line.find('#')));
    std::string cmd, var, style, value;
    if (in >> cmd >> var >> style >> value && cmd == "variable" && style == "index") s.vars[var] = value;
  }
  s.D = s.number("D");
  s.d_g = s.number("d_g");
  s.g = s.number("g");
  s.rho_g = s.number("rho_g");
  s.mu = s.number("mu");
  s.depth = s.number("depth");
  s.gap = s.number("gap");
  return s;
}

}    // namespace granpen
