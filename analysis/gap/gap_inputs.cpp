// granpen gap, stage 1 (validate): see gap_inputs.h.
#include "gap_inputs.h"

#include "gap_errors.h"
#include "text_util.h"
#include "trace_files.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <system_error>

namespace granpen {

namespace fs = std::filesystem;

namespace {
std::string fmt(double v, const char *f = "%.4g") { return printf_number(f, v); }
}    // namespace

std::vector<const Effect *> choose_effects(const std::optional<std::string> &list)
{
  std::vector<const Effect *> defaults;    // the library but its opt-in effects
  for (const auto &e : effect_library())
    if (!e.opt_in) defaults.push_back(&e);
  if (!list) return defaults;
  std::vector<const Effect *> out;
  std::string known = " default (all but the opt-in ones)";
  for (const auto &x : effect_library()) known += " " + x.name + (x.opt_in ? " (opt-in)" : "");
  std::stringstream in(*list);
  std::string name;
  while (std::getline(in, name, ',')) {
    if (name == "default") {    // the default library, then what else the list names
      for (const Effect *x : defaults) {
        if (std::find(out.begin(), out.end(), x) != out.end()) throw GapRefused("--effects: '" + x->name + "' given twice");
        out.push_back(x);
      }
      continue;
    }
    const Effect *e = find_effect(name);
    if (!e) throw GapRefused("--effects: unknown effect '" + name + "' (known:" + known + ")");
    // a repeat would be simulated, counted and fitted twice
    if (std::find(out.begin(), out.end(), e) != out.end()) throw GapRefused("--effects: '" + name + "' given twice");
    out.push_back(e);
  }
  if (out.empty())
    throw GapRefused("--effects: empty list (name one or more of:" + known + "; without --effects, the default library)");
  return out;
}

std::pair<double, double> runnable_speeds(const Scenario &sc)
{
  const double dt = sc.number("dt_push");
  return {(sc.gap + sc.depth) / (1e6 * dt), 0.01 * sc.d_g / dt};
}

std::vector<std::string> checked_speeds(const std::string &list, const Scenario &sc)
{
  const auto [vmin, vmax] = runnable_speeds(sc);
  std::vector<std::string> out;
  std::stringstream in(list);
  for (std::string v; in >> v;) {
    char *end = nullptr;
    const double x = std::strtod(v.c_str(), &end);
    if (end == v.c_str() || *end || !std::isfinite(x))
      throw GapRefused("--v0: '" + v + "' is not a number (speeds in cm/s, e.g. --v0 \"50 100 200\")");
    if (!(x >= vmin && x <= vmax))
      throw GapRefused("--v0: " + v + " cm/s is outside what scenario '" + sc.name + "' can run (" + fmt(vmin) + " to " +
                       fmt(vmax) + " cm/s: at most 1e6 push steps, at most 0.01 d_g per step)");
    if (std::find(out.begin(), out.end(), v) != out.end()) throw GapRefused("--v0: " + v + " given twice");
    out.push_back(v);
  }
  if (out.empty()) throw GapRefused("--prepare-only and --slurm need --v0 \"SPEEDS\"");
  return out;
}

void check_against_scenario(const Trace &t, const Scenario &sc)
{
  auto differs = [](double a, double b) { return std::abs(a - b) > 0.01 * std::abs(b); };
  const std::string &path = t.path;
  const Trace c = to_cgs(t);
  if (differs(c.D, sc.D))
    throw GapRefused(path + ": header D = " + std::to_string(c.D) + " cm, scenario '" + sc.name + "' has D = " +
                     std::to_string(sc.D) + " cm");
  if (differs(c.g, sc.g))
    throw GapRefused(path + ": header g = " + std::to_string(c.g) + " cm/s^2, scenario '" + sc.name + "' has g = " +
                     std::to_string(sc.g));
  const double dg = c.number("d_g", sc.d_g);
  if (differs(dg, sc.d_g))
    throw GapRefused(path + ": header d_g = " + std::to_string(dg) + " cm, scenario '" + sc.name + "' has d_g = " +
                     std::to_string(sc.d_g) + " cm");
  const double rho = c.number("rho_g", sc.rho_g);
  if (differs(rho, sc.rho_g))
    throw GapRefused(path + ": header rho_g = " + std::to_string(rho) + " g/cm^3, scenario '" + sc.name +
                     "' has rho_g = " + std::to_string(sc.rho_g) + " g/cm^3");
}

namespace {

// the trace files of the folder `real`; refuses anything but a folder holding traces
std::vector<std::string> trace_folder(const std::string &real)
{
  std::error_code ec;
  if (!fs::exists(real, ec)) throw GapRefused("--real " + real + ": no such folder");
  if (!fs::is_directory(real, ec))
    throw GapRefused("--real " + real + ": a file, not a folder: --real takes the folder of the measured traces");
  std::vector<std::string> problems;
  auto files = expand_trace_paths({real}, problems);
  if (!problems.empty()) throw GapRefused(problems[0]);
  return files;
}

}    // namespace

MeasuredData read_measured(const std::string &real, const Scenario &sc)
{
  MeasuredData m;
  m.files = trace_folder(real);
  const auto [vmin, vmax] = runnable_speeds(sc);
  std::string units_file, units;
  for (const auto &p : m.files) {
    const Trace t = read_trace(p);
    check_against_scenario(t, sc);
    if (units_file.empty()) units_file = p, units = t.units;
    else if (t.units != units)
      throw GapRefused(p + ": units = " + t.units + ", but " + units_file + " has units = " + units +
                       ": the traces of one data set must share their unit system");
    TraceRun r = run_of_trace(t);
    if (r.v0 > vmax || r.v0 < vmin)
      throw GapRefused(p + ": v0 = " + fmt(r.v0) + " cm/s is outside what scenario '" + sc.name + "' can run (" +
                       fmt(vmin) + " to " + fmt(vmax) + " cm/s: at most 1e6 push steps, at most 0.01 d_g per step)");
    m.runs[r.v0].push_back(std::move(r));
  }
  if (m.files.size() < 2)
    throw GapRefused("--real " + real + ": a single trace in all (" + m.files[0] +
                     "): a diagnosis compares ensembles and needs at least two measured runs");
  for (const auto &[v, runs] : m.runs) {
    m.v0s.push_back(deck_number(v));
    if (runs.size() == 1)
      m.notes.push_back("v0 = " + fmt(v) + " cm/s has one measured run: its noise is unknown; it is estimated from "
                        "the simulations' run-to-run scatter, scaled by the measured signal's fluctuation level");
  }
  return m;
}

void check_output_path(const std::string &out, const std::string &real, const std::string &cache)
{
  // absolute, symbolic links and .. resolved, no trailing separator
  auto resolved = [](const std::string &p) {
    std::error_code ec;
    fs::path r = fs::weakly_canonical(fs::absolute(p, ec), ec);
    return r.has_filename() ? r : r.parent_path();
  };
  const fs::path o = resolved(out);
  // whether p is o or lies inside it (compared element by element, not as text)
  auto holds = [&](const std::string &p) {
    const fs::path q = resolved(p);
    auto a = o.begin(), b = q.begin();
    for (; a != o.end() && b != q.end() && *a == *b; ++a, ++b) {}
    return a == o.end();
  };
  if (holds(real)) throw GapRefused("--out " + out + ": would replace the measured traces (--real " + real + ")");
  if (holds(cache)) throw GapRefused("--out " + out + ": would replace the simulation cache (--cache " + cache + ")");
}

}    // namespace granpen
