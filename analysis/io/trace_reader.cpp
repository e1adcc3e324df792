/* ----------------------------------------------------------------------
   granpen analysis: granpen-trace v1 reader.
------------------------------------------------------------------------- */

#include "trace_reader.h"

#include "text_util.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <algorithm>
#include <cctype>
#include <cstring>
#include <fstream>
#include <sstream>

namespace granpen {

namespace {

double to_number(const std::string &field, const std::string &name, long line,
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

bool Trace::has_t() const { return std::find(columns.begin(), columns.end(), "t") != columns.end(); }

void require_t(const Trace &trace, const std::string &who)
{
  if (!trace.has_t())
    throw InputError(trace.path + ": no t column (t_from = none: a depth-sampled import without a time or a speed "
                                  "column): " + who + " needs t");
}

double Trace::number(const std::string &key, double fallback) const
{
  auto it = keys.find(key);
  if (it == keys.end()) return fallback;
  char *end = nullptr;
  double v = std::strtod(it->second.c_str(), &end);
  return (end && *end == '\0' && std::isfinite(v)) ? v : fallback;
}

namespace {

// The next line of in (without its '\n') into line; false at the end of the input.
// A line longer than kMaxTraceLine is an error, not an allocation as large as the file, and
// so is a NUL byte (text_util.h's read_bounded_line, shared with the instrument reader).
bool bounded_getline(std::istream &in, std::vector<char> &buf, std::string &line, const std::string &name,
                     long lineno)
{
  return read_bounded_line(in, buf, line, name, lineno, kMaxTraceLine, "not a trace");
}

// A granpen-trace v1 file read a row at a time: the header on construction, then rows.
class TraceParser {
 public:
  TraceParser(std::istream &in, const std::string &name) : in_(in), name_(name) { read_header(); }

  const Trace &header() const { return tr_; }

  // the next row's values in column order; false at the end of the file
  bool next_row(std::vector<double> &values)
  {
    std::string line;
    while (bounded_getline(in_, buf_, line, name_, lineno_)) {
      ++lineno_;
      const std::string s = trim(line);
      if (s.empty() || s[0] == '#') continue;
      parse_row(s, values);
      if (!rows_) z_first_ = values[iz_], first_line_ = lineno_;
      z_last_ = values[iz_];
      ++rows_;
      return true;
    }
    return false;
  }

  // the checks that need every row: enough rows, depth not decreasing over the push
  void finish() const
  {
    if (rows_ < 10)
      fail_at(name_, lineno_, "only " + std::to_string(rows_) + " data rows, at least 10 needed");
    if (z_last_ < z_first_)
      fail_at(name_, lineno_, "z decreases over the push (" + printf_number("%g", z_first_) + " at line " +
                                  std::to_string(first_line_) + ", " + printf_number("%g", z_last_) +
                                  " at the last row): z is the depth of the tip below the surface and "
                                  "grows as the rod goes in; a height (opposite sign) must be negated");
  }

  long line() const { return lineno_; }
  int t_index() const { return it_; }
  int z_index() const { return iz_; }
  int F_index() const { return iF_; }

 private:
  // every value must stay finite in cgs (to_cgs scales by up to 1e5: N -> dyne)
  static constexpr double kLargestSiFactor = 1.0e5;
  [[noreturn]] void too_large(long line, const std::string &what) const
  {
    fail_at(name_, line, what + " is too large (it must stay finite in cgs units)");
  }

  void read_header();
  void check_header(long colline);
  void parse_row(const std::string &s, std::vector<double> &values);

  std::istream &in_;
  std::vector<char> buf_ = std::vector<char>(4096);
  std::string name_;
  Trace tr_;
  long lineno_ = 0;
  int it_ = -1, iz_ = -1, iF_ = -1;
  std::size_t rows_ = 0;
  double t_prev_ = 0.0, z_first_ = 0.0, z_last_ = 0.0;
  long first_line_ = 0;
};

void TraceParser::read_header()
{
  const std::string &name = name_;
  std::string line;
  if (!bounded_getline(in_, buf_, line, name, 0)) fail_at(name, 1, "empty file, expected '# granpen-trace v1'");
  lineno_ = 1;
  if (trim(line) != "# granpen-trace v1")
    fail_at(name, lineno_, "first line must be '# granpen-trace v1', found '" + trim(line).substr(0, 60) + "'");

  // header: '# key = value' lines, then the column-name line
  std::map<std::string, long> key_line;
  long colline = 0;
  while (bounded_getline(in_, buf_, line, name, lineno_)) {
    ++lineno_;
    std::string s = trim(line);
    if (s.empty()) continue;
    if (s[0] == '#') {
      auto eq = s.find('=');
      if (eq == std::string::npos) continue;    // a plain comment
      std::string key = trim(s.substr(1, eq - 1));
      std::string val = trim(s.substr(eq + 1));
      if (key.empty()) continue;
      // the last one winning would hide a contradiction (two speeds in one file)
      if (key_line.count(key))
        fail_at(name, lineno_, "header key '" + key + "' given twice (first at line " +
                                   std::to_string(key_line[key]) + ")");
      key_line[key] = lineno_;
      tr_.keys[key] = val;
      continue;
    }
    for (auto &c : split(s, ',')) {
      const std::string col = trim(c);
      if (col.empty()) fail_at(name, lineno_, "empty column name in the column line '" + s.substr(0, 60) + "'");
      if (std::find(tr_.columns.begin(), tr_.columns.end(), col) != tr_.columns.end())
        fail_at(name, lineno_, "column '" + col + "' named twice");
      if (tr_.columns.size() == kMaxTraceColumns)
        fail_at(name, lineno_, "more than " + std::to_string(kMaxTraceColumns) + " columns");
      tr_.columns.push_back(col);
    }
    colline = lineno_;
    break;
  }
  if (!colline) fail_at(name, lineno_, "no column-name line (t,z,F) after the header");
  check_header(colline);
}

void TraceParser::check_header(long colline)
{
  const std::string &name = name_;
  Trace &tr = tr_;
  for (const char *req : {"units", "v0", "D", "g"})
    if (!tr.keys.count(req)) fail_at(name, colline, std::string("missing required header key '") + req + "'");
  tr.units = tr.keys["units"];
  if (tr.units != "cgs" && tr.units != "si")
    fail_at(name, colline, "unknown unit system '" + tr.units + "' (expected cgs or si)");
  // every tool divides by v0, D and g (Froude number, alpha = k_z / (mu rho_g g D^2),
  // time from depth): zero or negative is a broken header, not a trace
  auto positive = [&](const char *key, const char *what) {
    const double v = to_number(tr.keys[key], name, colline, std::string("header ") + key);
    if (!(v > 0.0))
      fail_at(name, colline, std::string("header ") + key + " = " + tr.keys[key] + " must be positive (" + what + ")");
    if (!std::isfinite(v * kLargestSiFactor)) too_large(colline, std::string("header ") + key);
    return v;
  };
  tr.v0 = positive("v0", "the push speed");
  tr.D = positive("D", "the rod diameter");
  tr.g = positive("g", "gravity, downwards");
  // optional keys the tools read as numbers: wrong ones are errors, not silent defaults
  for (const char *key : {"d_g", "rho_g", "mu"}) {
    if (!tr.keys.count(key)) continue;
    const double v = to_number(tr.keys[key], name, colline, std::string("header ") + key);
    if (!std::isfinite(v * kLargestSiFactor)) too_large(colline, std::string("header ") + key);
    if (std::string(key) == "mu" ? v < 0.0 : !(v > 0.0))
      fail_at(name, colline, std::string("header ") + key + " = " + tr.keys[key] + " must be " +
                                 (std::string(key) == "mu" ? "zero or positive" : "positive"));
  }

  for (int i = 0; i < (int) tr.columns.size(); ++i) {
    const auto &c = tr.columns[i];
    if (c == "t") it_ = i;
    else if (c == "z") iz_ = i;
    else if (c == "F") iF_ = i;
  }
  // a depth-sampled import without time or speed writes no t and says so (t_from = none)
  const bool untimed = tr.keys.count("t_from") && tr.keys.at("t_from") == "none";
  if (untimed && it_ >= 0) fail_at(name, colline, "header t_from = none, but the column line names t");
  if ((it_ < 0 && !untimed) || iz_ < 0 || iF_ < 0) fail_at(name, colline, "column line must name t, z and F");
}

void TraceParser::parse_row(const std::string &s, std::vector<double> &values)
{
  const std::size_t ncol = tr_.columns.size();
  const auto fields = split(s, ',');
  if (fields.size() != ncol)
    fail_at(name_, lineno_, "row has " + std::to_string(fields.size()) + " fields, expected " + std::to_string(ncol) +
                                (fields.size() > ncol ? " (a comma used as decimal separator? the decimal mark is '.')" : ""));
  values.resize(ncol);
  for (std::size_t i = 0; i < ncol; ++i) {
    // the common case without building a message: a plain finite number
    const char *b = fields[i].c_str();
    char *end = nullptr;
    errno = 0;
    const double v = std::strtod(b, &end);
    if (end != b && *end == '\0' && errno != ERANGE && std::isfinite(v) && !std::isspace((unsigned char) *b))
      values[i] = v;
    else
      values[i] = to_number(fields[i], name_, lineno_, "column " + tr_.columns[i] + " value");
    if (!std::isfinite(values[i] * kLargestSiFactor)) too_large(lineno_, "column " + tr_.columns[i] + " value");
  }
  if (it_ < 0) return;
  const double t = values[it_];
  if (rows_ && !(t > t_prev_))
    fail_at(name_, lineno_, "t does not increase (" + trim(fields[it_]) + " after previous row)");
  t_prev_ = t;
}

Trace parse_stream(std::istream &in, const std::string &name, std::size_t max_rows)
{
  TraceParser p(in, name);
  Trace tr = p.header();
  tr.path = name;
  std::vector<std::vector<double> *> dest;
  for (int i = 0; i < (int) tr.columns.size(); ++i)
    dest.push_back(i == p.t_index() ? &tr.t : i == p.z_index() ? &tr.z : i == p.F_index() ? &tr.F
                                                                                         : &tr.other[tr.columns[i]]);
  std::vector<double> values;
  while (p.next_row(values)) {
    if (tr.z.size() == max_rows)
      fail_at(name, p.line(), "more than " + std::to_string(max_rows) +
                                  " data rows (the limit of a trace read into memory; thin the trace)");
    for (std::size_t i = 0; i < values.size(); ++i) dest[i]->push_back(values[i]);
  }
  p.finish();
  return tr;
}

}    // namespace

Trace parse_trace(const std::string &text, const std::string &name, std::size_t max_rows)
{
  std::istringstream in(text);
  return parse_stream(in, name, max_rows);
}

Trace check_trace_header(const std::string &header_text, const std::string &name)
{
  std::istringstream in(header_text);
  TraceParser p(in, name);
  return p.header();
}

Trace read_trace(const std::string &path)
{
  require_regular_file(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open trace file (" + std::strerror(errno) + ")");
  return parse_stream(in, path, kMaxTraceRows);
}

Trace read_trace_header(const std::string &path)
{
  require_regular_file(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open trace file (" + std::strerror(errno) + ")");
  TraceParser p(in, path);    // reads and checks the header's lines, no row
  Trace tr = p.header();
  tr.path = path;
  return tr;
}

TraceSummary scan_trace(const std::string &path)
{
  require_regular_file(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open trace file (" + std::strerror(errno) + ")");
  TraceParser p(in, path);
  TraceSummary s;
  s.header = p.header();
  s.header.path = path;
  std::vector<double> values;
  while (p.next_row(values)) {
    const double t = p.t_index() < 0 ? NAN : values[p.t_index()];
    if (!s.rows) s.t_first = t, s.z_first = values[p.z_index()];
    s.t_last = t;
    s.z_last = values[p.z_index()];
    s.F_max = std::max(s.F_max, values[p.F_index()]);
    ++s.rows;
  }
  p.finish();
  return s;
}

namespace {
void check_ave_time_spec(const std::string &name, const AveTimeSpec &spec)
{
  if (spec.units != "cgs" && spec.units != "si") throw InputError(name + ": unknown unit system '" + spec.units + "'");
  for (double v : {spec.v0, spec.D, spec.g, spec.dt})
    if (!(v > 0.0) || !std::isfinite(v)) throw InputError(name + ": v0, D, g and dt must be given, positive and finite");
}
}    // namespace

AveTimeTable parse_ave_time_table(const std::string &text, const std::string &name,
                                  const std::vector<std::string> &wanted)
{
  AveTimeTable table;
  table.name = name;
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
  std::vector<std::size_t> kept;    // file column of each wanted one
  for (const std::string &w : wanted) {
    std::size_t col = 0;
    if (!w.empty()) {
      col = std::find(names.begin(), names.end(), w) - names.begin();
      if (col == names.size()) {
        std::string known;
        for (const auto &n : names) known += " " + n;
        fail_at(name, lineno, "no column '" + w + "' (columns:" + known + ")");
      }
    }
    kept.push_back(col);
    table.asked.push_back(w);
    table.names.push_back(names[col]);
  }
  table.columns.resize(kept.size());
  std::vector<double> &steps = table.steps;
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
    for (std::size_t c = 0; c < kept.size(); ++c)
      table.columns[c].push_back(to_number(fields[kept[c] + 1], name, lineno, "column " + names[kept[c]] + " value"));
  }
  if (steps.size() < 10) fail_at(name, lineno, "only " + std::to_string(steps.size()) + " data rows, at least 10 needed");
  return table;
}

Trace ave_time_trace(const AveTimeTable &table, const AveTimeSpec &spec)
{
  const std::string &name = table.name;
  check_ave_time_spec(name, spec);
  // the column asked for under the same name ("" too: the file's first value column)
  const std::size_t col = std::find(table.asked.begin(), table.asked.end(), spec.column) - table.asked.begin();
  if (col >= table.asked.size())
    throw InputError(name + ": column '" + spec.column + "' was not read from the table (a caller's error)");
  Trace tr;
  tr.path = name;
  tr.units = spec.units;
  tr.v0 = spec.v0;
  tr.D = spec.D;
  tr.g = spec.g;
  const std::vector<double> &steps = table.steps;
  const double step0 = std::isnan(spec.step0) ? steps[0] - (steps[1] - steps[0]) : spec.step0;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    tr.t.push_back((steps[i] - step0) * spec.dt);
    tr.z.push_back(spec.z0 + spec.v0 * tr.t.back());
    tr.F.push_back(spec.sign * table.columns[col][i]);
  }
  tr.columns = {"t", "z", "F"};
  auto num = [](double v) {
    std::ostringstream o;
    o.precision(10);
    o << v;
    return o.str();
  };
  tr.keys = {{"units", spec.units}, {"v0", num(spec.v0)}, {"D", num(spec.D)}, {"g", num(spec.g)},
             {"source", "fix ave/time " + name + " column " + table.names[col]}};
  return tr;
}

Trace parse_ave_time(const std::string &text, const std::string &name, const AveTimeSpec &spec)
{
  check_ave_time_spec(name, spec);    // a bad option is named before a bad file
  return ave_time_trace(parse_ave_time_table(text, name, {spec.column}), spec);
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

TraceSummary to_cgs(const TraceSummary &in)
{
  if (in.header.units == "cgs") return in;
  TraceSummary s = in;
  s.header = to_cgs(in.header);
  s.z_first *= 100.0, s.z_last *= 100.0;    // m -> cm
  s.F_max *= 1.0e5;                          // N -> dyne
  return s;
}

}    // namespace granpen
