// granpen sweep: parsing, validation and planning of sweep files.
#include "sweep_spec.h"

#include "text_util.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <sstream>

namespace granpen {

bool safe_name(const std::string &s)
{
  if (s.empty() || s.size() > 64 || s[0] == '-') return false;
  for (unsigned char c : s)
    if (!(std::isalnum(c) || c == '_' || c == '-')) return false;
  return true;
}

bool positive_number(const std::string &s)
{
  if (s.empty() || s.size() > 32) return false;
  for (unsigned char c : s)
    if (!(std::isdigit(c) || c == '.' || c == 'e' || c == 'E' || c == '-' || c == '+')) return false;
  if (!std::isdigit((unsigned char) s[0]) && s[0] != '.') return false;
  char *end = nullptr;
  double v = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size() && std::isfinite(v) && v > 0.0;
}

SweepSpec parse_sweep(const std::string &text, const std::string &path,
                      bool (*preset_exists)(const std::string &),
                      bool (*observe_exists)(const std::string &))
{
  SweepSpec spec;
  spec.path = path;
  std::istringstream in(text);
  std::string raw;
  int lineno = 0;
  std::map<std::string, int> seen;
  std::map<std::string, int> where;
  while (std::getline(in, raw)) {
    ++lineno;
    std::string line = raw.substr(0, raw.find('#'));
    line = trim(line);
    if (line.empty()) continue;
    auto eq = line.find('=');
    if (eq == std::string::npos) fail_at(path, lineno, "expected 'key = value', found '" + line + "'");
    const std::string key = trim(line.substr(0, eq));
    const std::vector<std::string> vals = words(line.substr(eq + 1));
    if (seen.count(key))
      fail_at(path, lineno, "key '" + key + "' given again (first on line " + std::to_string(seen[key]) + ")");
    seen[key] = lineno;
    if (vals.empty()) fail_at(path, lineno, "key '" + key + "' has no value");

    auto numbers = [&](std::vector<std::string> &dst) {
      std::set<std::string> unique;
      for (const auto &v : vals) {
        if (!positive_number(v))
          fail_at(path, lineno, "'" + key + "' value '" + v + "' is not a positive number");
        if (!unique.insert(v).second) fail_at(path, lineno, "'" + key + "' lists " + v + " twice");
        dst.push_back(v);
      }
    };
    auto one = [&]() -> const std::string & {
      if (vals.size() != 1) fail_at(path, lineno, "'" + key + "' takes one value");
      return vals[0];
    };

    if (key == "name") {
      if (!safe_name(one()))
        fail_at(path, lineno, "name '" + vals[0] + "' may use only letters, digits, _ and - (it names a folder)");
      spec.name = vals[0];
    } else if (key == "preset") {
      for (const auto &v : vals) {
        if (!safe_name(v)) fail_at(path, lineno, "preset '" + v + "' is not a preset name");
        if (preset_exists && !preset_exists(v))
          fail_at(path, lineno, "unknown preset '" + v + "' (no inputs/presets/" + v + ".lmp)");
        spec.presets.push_back(v);
      }
    } else if (key == "mu") {
      numbers(spec.mu);
    } else if (key == "seeds") {
      for (const auto &v : vals) {
        if (v.empty() || v.size() > 9 || v.find_first_not_of("0123456789") != std::string::npos || v[0] == '0')
          fail_at(path, lineno, "seed '" + v + "' is not a positive integer below 1e9");
      }
      numbers(spec.seeds);
    } else if (key == "v0") {
      numbers(spec.v0);
    } else if (key == "g") {
      numbers(spec.g);
    } else if (key == "D") {
      numbers(spec.D);
    } else if (key == "mu_push") {
      numbers(spec.mu_push);
    } else if (key == "depth") {
      if (!positive_number(one())) fail_at(path, lineno, "depth '" + vals[0] + "' is not a positive number");
      spec.depth = vals[0];
    } else if (key == "observe") {
      if (!safe_name(one())) fail_at(path, lineno, "observe '" + vals[0] + "' is not a name");
      if (observe_exists && !observe_exists(vals[0]))
        fail_at(path, lineno, "unknown observe set '" + vals[0] + "' (no inputs/observe/" + vals[0] + ".lmp)");
      spec.observe = vals[0];
    } else if (key == "pour_checkpoint") {
      if (one() != "yes" && vals[0] != "no") fail_at(path, lineno, "pour_checkpoint '" + vals[0] + "' is not yes or no");
      spec.pour_checkpoint = vals[0] == "yes";
    } else if (key == "set" || key == "push_set") {
      auto &dst = key == "set" ? spec.set : spec.push_set;
      for (const auto &v : vals) {
        const auto e = v.find('=');
        const std::string name = v.substr(0, e), value = e == std::string::npos ? "" : v.substr(e + 1);
        if (e == std::string::npos || !settable_variable(name))
          fail_at(path, lineno, "'" + key + "' item '" + v + "' is not NAME=VALUE with a deck variable NAME "
               "(letters, digits, _; not one the runner sets)");
        if (!settable_value(value))
          fail_at(path, lineno, "'" + key + "' value '" + value + "' of " + name + " is neither a number nor a name");
        for (const auto &[n, _] : spec.set)
          if (n == name) fail_at(path, lineno, "deck variable " + name + " set twice");
        for (const auto &[n, _] : spec.push_set)
          if (n == name) fail_at(path, lineno, "deck variable " + name + " set twice");
        dst.emplace_back(name, value);
      }
    } else {
      fail_at(path, lineno, "unknown key '" + key + "' (known: name preset mu seeds v0 g D depth mu_push observe set push_set pour_checkpoint)");
    }
  }
  if (spec.name.empty()) fail_at(path, lineno, "missing 'name'");
  if (spec.presets.empty()) fail_at(path, lineno, "missing 'preset'");
  if (spec.v0.empty()) fail_at(path, lineno, "missing 'v0'");
  if (spec.seeds.empty()) spec.seeds = {"1"};
  return spec;
}

std::vector<PlannedRun> plan_sweep(const SweepSpec &spec)
{
  std::vector<PlannedRun> pours, pushes;
  const std::vector<std::string> mus = spec.mu.empty() ? std::vector<std::string>{""} : spec.mu;
  const std::vector<std::string> gs = spec.g.empty() ? std::vector<std::string>{""} : spec.g;
  const std::vector<std::string> Ds = spec.D.empty() ? std::vector<std::string>{""} : spec.D;
  const std::vector<std::string> mps = spec.mu_push.empty() ? std::vector<std::string>{""} : spec.mu_push;
  for (const auto &p : spec.presets)
    for (const auto &mu : mus)
      for (const auto &seed : spec.seeds) {
        PlannedRun bed{PlannedRun::POUR};
        bed.preset = p;
        bed.mu = mu;
        bed.seed = seed;
        bed.id = "bed_" + p + (mu.empty() ? "" : "_mu" + mu) + "_s" + seed;
        pours.push_back(bed);
        for (const auto &v : spec.v0)
          for (const auto &g : gs)
            for (const auto &D : Ds)
              for (const auto &mp : mps) {
              PlannedRun push = bed;
              push.mu_push = mp;
              push.kind = PlannedRun::PUSH;
              push.bed = bed.id;
              push.v0 = v;
              push.g = g;
              push.D = D;
              push.depth = spec.depth;
              push.id = p + (mu.empty() ? "" : "_mu" + mu) + "_s" + seed + "_v" + v + (g.empty() ? "" : "_g" + g) +
                        (D.empty() ? "" : "_D" + D) + (mp.empty() ? "" : "_mp" + mp);
              pushes.push_back(push);
            }
      }
  pours.insert(pours.end(), pushes.begin(), pushes.end());
  return pours;
}

bool settable_variable(const std::string &name)
{
  static const char *reserved[] = {"inputs", "preset", "mu", "seed", "out", "bed", "v0", "g_push", "D",
                                   "depth", "mu_push", "run", "trace", "checkpoint", "observe",
                                   "drive_extra", "resume", "from", "mu_c", "chain_kw", "roll_kw"};
  if (!safe_name(name) || name.find('-') != std::string::npos || std::isdigit((unsigned char) name[0]))
    return false;
  for (const char *r : reserved)
    if (name == r) return false;
  return true;
}

bool settable_value(const std::string &value)
{
  if (value.empty() || value.size() > 32) return false;
  if (safe_name(value) && std::isalpha((unsigned char) value[0])) {    // yes, no, ...
    std::string low;
    for (unsigned char c : value) low += (char) std::tolower(c);
    return low != "nan" && low.rfind("inf", 0) != 0;    // not a number LAMMPS would read as one
  }
  // a finite number of either sign: the characters positive_number allows, checked the same way
  const std::string mag = (value[0] == '-' || value[0] == '+') ? value.substr(1) : value;
  if (mag.empty() || !(std::isdigit((unsigned char) mag[0]) || mag[0] == '.')) return false;
  for (unsigned char c : mag)
    if (!(std::isdigit(c) || c == '.' || c == 'e' || c == 'E' || c == '-' || c == '+')) return false;
  char *end = nullptr;
  const double v = std::strtod(value.c_str(), &end);
  return end == value.c_str() + value.size() && std::isfinite(v);
}

PushAction push_action(bool done_marker, bool trace_exists, bool checkpoint_exists)
{
  if (done_marker && trace_exists) return PushAction::SKIP_DONE;
  if (checkpoint_exists && trace_exists) return PushAction::RESUME;
  if (trace_exists) return PushAction::RESTART_FRESH;    // the runner keeps the old trace aside
  return PushAction::START;
}

}    // namespace granpen
