/* ----------------------------------------------------------------------
   granpen analysis: granpen-trace v1 reader.
------------------------------------------------------------------------- */

#include "trace_reader.h"

#include "text_util.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace granpen {

namespace {

double to_number(const std::string &field, const std::string &name, int line,
                 const std::string &what)
{
  const std::string f = trim(field);
  char *end = nullptr;
  errno = 0;
  double v = std::strtod(f.c_str(), &end);
  if (f.empty() || end != f.c_str() + f.size() || errno == ERANGE)
    fail_at(name, line, what + " '" + f + "' is not a number");
  if (!std::isfinite(v)) fail_at(name, line, what + " '" + f + "' is not finite");
  return v;
}

}    // namespace

double Trace::number(const std::string &key, double fallback) const
{
  auto it = keys.find(key);
  if (it == keys.end()) return fallback;
  char *end = nullptr;
  double v = std::strtod(it->second.c_str(), &end);
  return (end && *end == '\0' && std::isfinite(v)) ? v : fallback;
}

Trace parse_trace(const std::string &text, const std::string &name)
{
  Trace tr;
  tr.path = name;
  std::istringstream in(text);
  std::string line;
  int lineno = 0;

  if (!std::getline(in, line)) fail_at(name, 1, "empty file, expected '# granpen-trace v1'");
  ++lineno;
  if (trim(line) != "# granpen-trace v1")
    fail_at(name, lineno, "first line must be '# granpen-trace v1', found '" + trim(line) + "'");

  // header: '# key = value' lines, then the column-name line
  int colline = 0;
  while (std::getline(in, line)) {
    ++lineno;
    std::string s = trim(line);
    if (s.empty()) continue;
    if (s[0] == '#') {
      auto eq = s.find('=');
      if (eq == std::string::npos) continue;    // a plain comment
      std::string key = trim(s.substr(1, eq - 1));
      std::string val = trim(s.substr(eq + 1));
      if (!key.empty()) tr.keys[key] = val;
      continue;
    }
    for (auto &c : split(s, ',')) tr.columns.push_back(trim(c));
    colline = lineno;
    break;
  }
  if (!colline) fail_at(name, lineno, "no column-name line (t,z,F) after the header");

  for (const char *req : {"units", "v0", "D", "g"})
    if (!tr.keys.count(req)) fail_at(name, colline, std::string("missing required header key '") + req + "'");
  tr.units = tr.keys["units"];
  if (tr.units != "cgs" && tr.units != "si")
    fail_at(name, colline, "unknown unit system '" + tr.units + "' (expected cgs or si)");
  tr.v0 = to_number(tr.keys["v0"], name, colline, "header v0");
  tr.D = to_number(tr.keys["D"], name, colline, "header D");
  tr.g = to_number(tr.keys["g"], name, colline, "header g");

  int it = -1, iz = -1, iF = -1;
  for (int i = 0; i < (int) tr.columns.size(); ++i) {
    const auto &c = tr.columns[i];
    if (c == "t") it = i;
    else if (c == "z") iz = i;
    else if (c == "F") iF = i;
  }
  if (it < 0 || iz < 0 || iF < 0)
    fail_at(name, colline, "column line must name t, z and F");

  const std::size_t ncol = tr.columns.size();
  while (std::getline(in, line)) {
    ++lineno;
    std::string s = trim(line);
    if (s.empty() || s[0] == '#') continue;
    auto fields = split(s, ',');
    if (fields.size() < ncol)
      fail_at(name, lineno, "row has " + std::to_string(fields.size()) + " fields, expected " +
                             std::to_string(ncol));
    for (std::size_t i = 0; i < ncol; ++i) {
      double v = to_number(fields[i], name, lineno, "column " + tr.columns[i] + " value");
      if ((int) i == it) {
        if (!tr.t.empty() && !(v > tr.t.back()))
          fail_at(name, lineno, "t does not increase (" + trim(fields[i]) + " after previous row)");
        tr.t.push_back(v);
      } else if ((int) i == iz) {
        tr.z.push_back(v);
      } else if ((int) i == iF) {
        tr.F.push_back(v);
      } else {
        tr.other[tr.columns[i]].push_back(v);
      }
    }
  }
  if (tr.t.size() < 10)
    fail_at(name, lineno, "only " + std::to_string(tr.t.size()) + " data rows, at least 10 needed");
  return tr;
}

Trace read_trace(const std::string &path)
{
  std::string text;
  if (!read_text_file(path, text)) throw InputError(path + ": cannot open trace file");
  return parse_trace(text, path);
}

Trace parse_ave_time(const std::string &text, const std::string &name, const AveTimeSpec &spec)
{
  if (spec.units != "cgs" && spec.units != "si") throw InputError(name + ": unknown unit system '" + spec.units + "'");
  for (double v : {spec.v0, spec.D, spec.g, spec.dt})
    if (!(v > 0.0) || !std::isfinite(v)) throw InputError(name + ": v0, D, g and dt must be given, positive and finite");
  Trace tr;
  tr.path = name;
  tr.units = spec.units;
  tr.v0 = spec.v0;
  tr.D = spec.D;
  tr.g = spec.g;
  std::istringstream in(text);
  std::string line;
  int lineno = 0;
  if (!std::getline(in, line) || trim(line).rfind("# Time-averaged data for fix", 0) != 0)
    fail_at(name, 1, "not fix ave/time output: the first line must be '# Time-averaged data for fix ID'");
  ++lineno;
  std::vector<std::string> names;
  if (std::getline(in, line)) {
    ++lineno;
    const std::vector<std::string> w = words(line);
    if (w.size() < 2 || w[0] != "#" || w[1] != "TimeStep")
      fail_at(name, lineno, "expected '# TimeStep NAME...', found '" + trim(line) + "'");
    names.assign(w.begin() + 2, w.end());
    if (names.size() == 1 && names[0] == "Number-of-rows")
      fail_at(name, lineno, "fix ave/time in vector mode (blocks of rows) is not a force trace: use scalar mode");
  }
  if (names.empty()) fail_at(name, lineno, "no value columns on the '# TimeStep' line");
  std::size_t col = 0;
  if (!spec.column.empty()) {
    col = names.size();
    for (std::size_t i = 0; i < names.size(); ++i)
      if (names[i] == spec.column) col = i;
    if (col == names.size()) {
      std::string known;
      for (const auto &n : names) known += " " + n;
      fail_at(name, lineno, "no column '" + spec.column + "' (columns:" + known + ")");
    }
  }
  std::vector<double> steps;
  while (std::getline(in, line)) {
    ++lineno;
    const std::string s = trim(line);
    if (s.empty() || s[0] == '#') continue;
    const std::vector<std::string> fields = words(s);
    if (fields.size() != names.size() + 1)
      fail_at(name, lineno, "row has " + std::to_string(fields.size()) + " fields, expected " + std::to_string(names.size() + 1));
    const double step = to_number(fields[0], name, lineno, "TimeStep");
    if (!steps.empty() && !(step > steps.back())) fail_at(name, lineno, "TimeStep does not increase");
    steps.push_back(step);
    tr.F.push_back(spec.sign * to_number(fields[col + 1], name, lineno, "column " + names[col] + " value"));
  }
  if (steps.size() < 10) fail_at(name, lineno, "only " + std::to_string(steps.size()) + " data rows, at least 10 needed");
  const double step0 = std::isnan(spec.step0) ? steps[0] - (steps[1] - steps[0]) : spec.step0;
  for (double st : steps) {
    tr.t.push_back((st - step0) * spec.dt);
    tr.z.push_back(spec.z0 + spec.v0 * tr.t.back());
  }
  tr.columns = {"t", "z", "F"};
  auto num = [](double v) {
    std::ostringstream o;
    o.precision(10);
    o << v;
    return o.str();
  };
  tr.keys = {{"units", spec.units}, {"v0", num(spec.v0)}, {"D", num(spec.D)}, {"g", num(spec.g)},
             {"source", "fix ave/time " + name + " column " + names[col]}};
  return tr;
}

Trace read_ave_time(const std::string &path, const AveTimeSpec &spec)
{
  std::string text;
  if (!read_text_file(path, text)) throw InputError(path + ": cannot open fix ave/time file");
  return parse_ave_time(text, path, spec);
}

Trace to_cgs(const Trace &in)
{
  if (in.units == "cgs") return in;
  Trace t = in;
  const double L = 100.0, F = 1.0e5, RHO = 1.0e-3;    // m -> cm, N -> dyne, kg/m^3 -> g/cm^3
  t.units = "cgs";
  t.v0 *= L;
  t.D *= L;
  t.g *= L;
  for (auto &z : t.z) z *= L;
  for (auto &f : t.F) f *= F;
  auto scale_key = [&](const char *key, double s) {
    auto it = t.keys.find(key);
    if (it == t.keys.end()) return;
    char *end = nullptr;
    double v = std::strtod(it->second.c_str(), &end);
    if (end && *end == '\0') {
      std::ostringstream o;
      o.precision(12);
      o << v * s;
      it->second = o.str();
    }
  };
  t.keys["units"] = "cgs";
  scale_key("v0", L);
  scale_key("D", L);
  scale_key("g", L);
  scale_key("d_g", L);
  scale_key("rho_g", RHO);
  return t;
}

}    // namespace granpen
