#include "scenario.h"

#include "errors.h"
#include "gap_errors.h"
#include "text_util.h"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <cctype>
#include <cstdio>
#include <iterator>

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
  // the whole value: "2cm" is not 2 (LAMMPS would not read it as a number either)
  if (end == it->second.c_str() || *end != '\0' || !std::isfinite(v))
    throw InputError(path + ": '" + key + "' is not a number: " + it->second);
  return v;
}

namespace fs = std::filesystem;

namespace {

// every "variable NAME index VALUE" of a preset's text
std::map<std::string, std::string> preset_vars(std::istream &f)
{
  std::map<std::string, std::string> vars;
  std::string line;
  while (std::getline(f, line)) {
    std::istringstream in(line.substr(0, line.find('#')));
    std::string cmd, var, style, value;
    if (in >> cmd >> var >> style >> value && cmd == "variable" && style == "index") vars[var] = value;
  }
  return vars;
}

// Every number a gap plan is made of (core-hours, sizes, steps), checked before anything
// starts: a negative lattice or time step made a negative plan that passed --budget 0.
void check_plan_numbers(const Scenario &s)
{
  for (const char *key : {"D", "d_g", "g", "rho_g", "depth", "lat", "box", "dt_pour", "dt_push"})
    if (!(s.number(key) > 0)) throw InputError(s.path + ": '" + key + "' must be > 0, got " + s.vars.at(key));
  for (const char *key : {"mu", "gap"})
    if (!(s.number(key) >= 0)) throw InputError(s.path + ": '" + key + "' must be >= 0, got " + s.vars.at(key));
}

void set_numbers(Scenario &s)
{
  s.D = s.number("D");
  s.d_g = s.number("d_g");
  s.g = s.number("g");
  s.rho_g = s.number("rho_g");
  s.mu = s.number("mu");
  s.depth = s.number("depth");
  s.gap = s.number("gap");
}

// FNV-1a, 32 bits, as 8 hex digits: a name for a file's text, not a security hash
std::string text_hash(const std::string &text)
{
  std::uint32_t h = 2166136261u;
  for (unsigned char c : text) h = (h ^ c) * 16777619u;
  char buf[9];
  std::snprintf(buf, sizeof buf, "%08x", h);
  return buf;
}

}    // namespace

Scenario read_scenario(const std::string &inputs, const std::string &name)
{
  Scenario s;
  s.name = name;
  s.path = inputs + "/presets/" + name + ".lmp";
  std::ifstream f(s.path);
  if (!f) throw InputError("unknown scenario '" + name + "': no preset " + s.path);
  s.vars = preset_vars(f);
  set_numbers(s);
  check_plan_numbers(s);
  return s;
}

bool scenario_is_file(const std::string &arg)
{
  return arg.find('/') != std::string::npos || (arg.size() > 4 && arg.compare(arg.size() - 4, 4, ".lmp") == 0);
}

std::vector<std::string> preset_variables(const std::string &inputs)
{
  std::vector<std::string> common;
  bool first = true;
  std::error_code ec;
  std::vector<fs::path> files;
  for (const auto &e : fs::directory_iterator(inputs + "/presets", ec))
    if (e.path().extension() == ".lmp") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const auto &p : files) {
    std::ifstream f(p);
    std::vector<std::string> keys;
    for (const auto &kv : preset_vars(f)) keys.push_back(kv.first);
    if (first) common = keys, first = false;
    else {
      std::vector<std::string> both;
      std::set_intersection(common.begin(), common.end(), keys.begin(), keys.end(), std::back_inserter(both));
      common = both;
    }
  }
  if (common.empty()) throw InputError(inputs + "/presets: no preset to learn the preset variables from");
  return common;
}

Scenario read_scenario_file(const std::string &inputs, const std::string &file)
{
  try {
    require_regular_file(file);    // a FIFO would block the open
  } catch (InputError &e) {
    throw GapRefused(std::string("--scenario ") + e.what());
  }
  std::ifstream f(file);
  if (!f || fs::is_directory(file)) throw GapRefused("--scenario " + file + ": cannot read this preset file");
  const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  Scenario s;
  s.path = file;
  std::istringstream in(text);
  s.vars = preset_vars(in);
  std::string missing;
  for (const auto &key : preset_variables(inputs))
    if (!s.vars.count(key)) missing += " " + key;
  if (!missing.empty())
    throw GapRefused("--scenario " + file + ": the preset sets no" + missing +
                     " (a preset sets every variable of inputs/presets/*.lmp, as 'variable NAME index VALUE')");
  std::string stem = fs::path(file).stem().string();
  for (char &c : stem)
    if (!std::isalnum((unsigned char) c) && c != '_' && c != '-') c = '_';
  s.name = stem + "-" + text_hash(text);
  try {
    set_numbers(s);
    for (const char *key : {"lat", "box", "fill_lo", "zfill_lo", "zfill_hi", "dt_pour", "dt_push"}) s.number(key);
    check_plan_numbers(s);
  } catch (GapRefused &) {
    throw;
  } catch (InputError &e) {
    throw GapRefused(std::string("--scenario ") + e.what());
  }
  return s;
}

std::string stage_scenario_inputs(const Scenario &sc, const std::string &inputs, const std::string &dir)
{
  const fs::path root = fs::absolute(dir) / sc.name, from = fs::absolute(inputs);
  const fs::path partial = root.string() + ".partial";
  std::error_code ec;
  if (fs::exists(root / "presets" / (sc.name + ".lmp"), ec)) return root.string();
  fs::remove_all(partial, ec);
  fs::create_directories(partial / "presets");
  for (const auto &e : fs::directory_iterator(from))
    if (e.path().filename() != "presets") fs::create_symlink(e.path(), partial / e.path().filename());
  for (const auto &e : fs::directory_iterator(from / "presets"))
    fs::create_symlink(e.path(), partial / "presets" / e.path().filename());
  fs::copy_file(sc.path, partial / "presets" / (sc.name + ".lmp"));
  fs::rename(partial, root);
  return root.string();
}

}    // namespace granpen
