// granpen analysis: the mapping file of `granpen import` (see import_mapping.h).
#include "import_mapping.h"

#include "text_util.h"
#include "trace_reader.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

namespace granpen {

namespace {

// "PATH:LINE: what", or "PATH: what" for the file as a whole (line 0)
[[noreturn]] void fail_line(const std::string &path, long line, const std::string &what)
{
  if (line > 0) fail_at(path, line, what);
  throw InputError(path + ": " + what);
}

struct Entry {
  std::string value;
  long line;
};

// the keys a mapping may hold; the aliases say the same as the key they name
const std::set<std::string> KEYS = {
    "delimiter", "decimal", "header_lines", "column_names", "lines_after_names", "time", "time_unit", "sample_rate", "force",
    "force_unit", "area", "area_unit", "force_sign", "displacement", "depth", "position_unit", "position_sign",
    "speed", "speed_unit", "speed_sign", "v0", "v0_unit", "tare_rows", "onset_force", "surface", "position_noise",
    "end_time", "speed_rows", "speed_tolerance", "end_tolerance", "window"};
const std::map<std::string, std::string> ALIASES = {{"displacement_unit", "position_unit"},
                                                     {"depth_unit", "position_unit"},
                                                     {"displacement_sign", "position_sign"},
                                                     {"depth_sign", "position_sign"}};

class Mapping {
 public:
  Mapping(const std::string &with_bom, const std::string &path) : path_(path)
  {
    const std::string text = without_bom(with_bom);
    long n = 0;
    std::size_t pos = 0;
    while (pos <= text.size()) {
      const std::size_t nl = text.find('\n', pos);
      std::string line = text.substr(pos, nl == std::string::npos ? std::string::npos : nl - pos);
      pos = nl == std::string::npos ? text.size() + 1 : nl + 1;
      ++n;
      const std::size_t hash = line.find('#');
      // '#' starts a comment unless it is a column index ("force = #2")
      if (hash != std::string::npos && (hash == 0 || line.find('=') == std::string::npos || hash < line.find('=') ||
                                        (hash + 1 < line.size() && !std::isdigit((unsigned char) line[hash + 1]))))
        line = line.substr(0, hash);
      line = trim(line);
      if (line.empty()) continue;
      const std::size_t eq = line.find('=');
      if (eq == std::string::npos) fail_line(path, n, "expected 'key = value', got '" + line + "'");
      std::string key = trim(line.substr(0, eq)), value = trim(line.substr(eq + 1));
      if (ALIASES.count(key)) key = ALIASES.at(key);
      if (!KEYS.count(key)) fail_line(path, n, "unknown key '" + key + "' (the keys are in docs/measurements.md)");
      if (value.empty()) fail_line(path, n, "key '" + key + "' has no value");
      if (entries_.count(key)) fail_line(path, n, "key '" + key + "' given twice (first at line " +
                                                    std::to_string(entries_[key].line) + ")");
      entries_[key] = {value, n};
    }
  }

  bool has(const std::string &key) const { return entries_.count(key) > 0; }
  long line(const std::string &key) const { return has(key) ? entries_.at(key).line : 0; }
  std::string text(const std::string &key, const std::string &fallback) const
  {
    return has(key) ? entries_.at(key).value : fallback;
  }
  double number(const std::string &key, double fallback) const
  {
    if (!has(key)) return fallback;
    const std::string &s = entries_.at(key).value;
    errno = 0;
    char *end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (end == s.c_str() || *end || errno == ERANGE || !std::isfinite(v))
      fail_line(path_, line(key), key + " needs a number, got '" + s + "'");
    return v;
  }
  double positive(const std::string &key, double fallback) const
  {
    const double v = number(key, fallback);
    if (has(key) && !(v > 0.0)) fail_line(path_, line(key), key + " must be > 0, got '" + text(key, "") + "'");
    return v;
  }
  double sign(const std::string &key) const
  {
    const double v = number(key, 1.0);
    if (v != 1.0 && v != -1.0) fail_line(path_, line(key), key + " must be 1 or -1, got '" + text(key, "") + "'");
    return v;
  }
  std::size_t count(const std::string &key, std::size_t fallback, std::size_t least) const
  {
    const double v = number(key, (double) fallback);
    if (v != std::floor(v) || v < (double) least || v > 1e9)
      fail_line(path_, line(key), key + " must be a whole number >= " + std::to_string(least) + ", got '" +
                                    text(key, "") + "'");
    return (std::size_t) v;
  }
  ColumnRef column(const std::string &key) const
  {
    ColumnRef c;
    if (!has(key)) return c;
    const std::string &s = entries_.at(key).value;
    if (s.size() > 1 && s[0] == '#') {
      char *end = nullptr;
      const long i = std::strtol(s.c_str() + 1, &end, 10);
      if (*end || i < 1 || i > 100000) fail_line(path_, line(key), key + " column index must be #1, #2, ..., got '" + s + "'");
      c.index = (int) i;
    } else {
      c.name = s;
    }
    return c;
  }
  [[noreturn]] void unknown_unit(const std::string &key, const std::string &known) const
  {
    fail_line(path_, line(key), "unknown " + key.substr(0, key.find('_')) + " unit '" + text(key, "") + "' (" + known + ")");
  }

 private:
  std::string path_;
  std::map<std::string, Entry> entries_;
};

}    // namespace

ImportMapping parse_import_mapping(const std::string &text, const std::string &path, bool si)
{
  const Mapping m(text, path);
  ImportMapping out;
  out.path = path;

  // layout
  out.delimiter = m.text("delimiter", "auto");
  static const std::set<std::string> delimiters = {"auto", "comma", "semicolon", "tab", "whitespace", "keyvalue"};
  if (!delimiters.count(out.delimiter))
    fail_line(path, m.line("delimiter"), "unknown delimiter '" + out.delimiter +
                                           "' (auto, comma, semicolon, tab, whitespace, keyvalue)");
  const std::string decimal = m.text("decimal", "point");
  if (decimal != "point" && decimal != "." && decimal != "comma" && decimal != ",")
    fail_line(path, m.line("decimal"), "decimal must be point or comma, got '" + decimal + "'");
  out.decimal_comma = decimal == "comma" || decimal == ",";
  if (out.decimal_comma && out.delimiter == "comma")
    fail_line(path, m.line("decimal"), "a decimal comma needs another delimiter than comma");
  if (m.text("header_lines", "auto") != "auto") out.header_lines = (int) m.count("header_lines", 0, 0);
  out.lines_after_names = (int) m.count("lines_after_names", 0, 0);
  const std::string names = m.text("column_names", "yes");
  if (names != "yes" && names != "no") fail_line(path, m.line("column_names"), "column_names must be yes or no, got '" + names + "'");
  out.column_names = names == "yes" && out.delimiter != "keyvalue";

  // columns
  out.time = m.column("time");
  out.force = m.column("force");
  out.speed = m.column("speed");
  if (m.has("displacement") && m.has("depth"))
    fail_line(path, m.line("depth"), "both displacement and depth given: one position column");
  out.position_is_depth = m.has("depth");
  out.position = m.column(out.position_is_depth ? "depth" : "displacement");
  if (!out.force.given()) fail_line(path, 0, "no force column (force = NAME or force = #N)");
  // one column, one role: `speed = F` beside `force = F` would read the force as the speed
  // (a name and an index naming one column are caught where the columns are located)
  const char *position_key = out.position_is_depth ? "depth" : "displacement";
  for (const char *a : {"time", "force", position_key, "speed"})
    for (const char *b : {"time", "force", position_key, "speed"}) {
      const ColumnRef ca = m.column(a), cb = m.column(b);
      if (std::string(a) >= std::string(b) || !ca.given() || !cb.given() || ca.text() != cb.text()) continue;
      const bool a_first = m.line(a) < m.line(b);
      fail_line(path, std::max(m.line(a), m.line(b)), std::string(a_first ? b : a) + " = " + m.text(a, "") +
                                                          " is the column of " + (a_first ? a : b) + " (line " +
                                                          std::to_string(std::min(m.line(a), m.line(b))) +
                                                          "): one column, one role");
    }
  for (const auto *key : {"time", "force", "displacement", "depth", "speed"}) {
    const ColumnRef c = m.column(key);
    if (!c.name.empty() && !out.column_names && out.delimiter != "keyvalue")
      fail_line(path, m.line(key), std::string(key) + " by name needs column_names = yes, or give #N");
  }
  if (out.time.given() && m.has("sample_rate"))
    fail_line(path, m.line("sample_rate"), "both a time column and a sample_rate: one of them");
  if (!out.time.given() && !m.has("sample_rate") && !out.position.given())
    fail_line(path, 0, "neither a time column nor a sample_rate (nor a depth or displacement column: a depth-sampled "
                       "log, whose t is the integral of dz / v with a speed column)");
  out.sample_rate = m.positive("sample_rate", 0.0);
  using TS = ImportMapping::TimeSource;
  out.time_source = out.time.given()        ? TS::column
                    : m.has("sample_rate")  ? TS::sample_rate
                    : out.speed.given()     ? TS::depth_over_speed
                                            : TS::none;
  // without a time every rule in time is meaningless: refused, not silently ignored
  if (out.time_source == TS::none)
    for (const char *key : {"window", "end_time", "time_unit"})
      if (m.has(key))
        fail_line(path, m.line(key), std::string(key) + " needs a time: no time column, sample_rate or speed column");

  // units and signs
  out.time_unit = m.text("time_unit", "s");
  if (!time_unit_factor(out.time_unit, out.time_factor)) m.unknown_unit("time_unit", "s, ms, us, min");
  out.force_unit = m.text("force_unit", "N");
  if (out.force_unit == "kPa" || out.force_unit == "MPa" || out.force_unit == "Pa") {
    if (!m.has("area")) fail_line(path, m.line("force_unit"), "a stress unit (" + out.force_unit + ") needs area = A");
    double area_factor;
    const std::string area_unit = m.text("area_unit", "m2");
    if (!area_unit_factor_m2(area_unit, area_factor)) m.unknown_unit("area_unit", "m2, cm2, mm2, in2");
    stress_unit_factor(out.force_unit, m.positive("area", 0.0) * area_factor, si, out.force_factor);
  } else if (!force_unit_factor(out.force_unit, si, out.force_factor)) {
    m.unknown_unit("force_unit", "N, kN, mN, lbf, dyne, or a stress Pa, kPa, MPa with area = A");
  } else if (m.has("area")) {
    fail_line(path, m.line("area"), "area is for a stress force_unit (kPa, MPa), not " + out.force_unit);
  }
  out.force_factor *= m.sign("force_sign");
  out.position_unit = m.text("position_unit", "mm");
  if (!length_unit_factor(out.position_unit, si, out.position_factor)) m.unknown_unit("position_unit", "m, cm, mm, um, in");
  out.position_factor *= m.sign("position_sign");
  out.speed_unit = m.text("speed_unit", out.position_unit + "/s");
  if (!speed_unit_factor(out.speed_unit, si, out.speed_factor))
    m.unknown_unit("speed_unit", "LENGTH/TIME: m, cm, mm, um, in over s, ms, min");
  out.speed_factor *= m.sign("speed_sign");
  if ((m.has("position_unit") || m.has("position_sign")) && !out.position.given())
    fail_line(path, m.line("position_unit") ? m.line("position_unit") : m.line("position_sign"), "a position unit or sign without a position column");

  // how a push is read
  ImportRules &r = out.rules;
  r.has_position = out.position.given();
  r.has_speed = out.speed.given();
  r.has_time = out.time_source != TS::none;
  r.tare_rows = m.count("tare_rows", 50, 0);
  if (m.has("onset_force")) r.onset_force = m.positive("onset_force", 0.0) * std::fabs(out.force_factor);
  const std::string surface = m.text("surface", out.position_is_depth ? "0" : "threshold");
  if (surface != "threshold") {
    r.surface_given = true;
    const double raw = m.has("surface") ? m.number("surface", 0.0) : 0.0;
    r.surface = r.has_position ? raw * out.position_factor : raw * out.time_factor;
  } else if (!m.has("onset_force")) {
    fail_line(path, m.line("surface"), "surface = threshold needs onset_force = F (the tared force at contact)");
  }
  r.position_noise = m.number("position_noise", 0.0) * std::fabs(out.position_factor);
  if (r.position_noise < 0.0) fail_line(path, m.line("position_noise"), "position_noise must be >= 0");
  if (m.has("end_time")) r.end_time = m.number("end_time", 0.0) * out.time_factor;
  r.speed_rows = m.count("speed_rows", 50, 2);
  r.speed_tolerance = m.positive("speed_tolerance", 0.05);
  r.end_tolerance = m.positive("end_tolerance", 0.15);
  if (!(r.end_tolerance < 1.0)) fail_line(path, m.line("end_tolerance"), "end_tolerance must be below 1 (a fraction of the mean speed)");
  r.window = m.positive("window", 0.0);
  if (m.has("v0")) {
    double f;
    const std::string unit = m.text("v0_unit", out.position_unit + "/s");
    if (!speed_unit_factor(unit, si, f)) m.unknown_unit("v0_unit", "LENGTH/TIME: m, cm, mm, um, in over s, ms, min");
    out.v0 = m.positive("v0", 0.0) * f;
  }
  return out;
}

std::map<std::string, double> read_v0_table(const std::string &path, bool si)
{
  std::string text;
  if (!read_text_file(path, text)) throw InputError(path + ": cannot read the v0 table: " + std::strerror(errno));
  std::map<std::string, double> table;
  std::map<std::string, long> first;
  long n = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    const std::size_t nl = text.find('\n', pos);
    std::string line = text.substr(pos, nl == std::string::npos ? std::string::npos : nl - pos);
    pos = nl == std::string::npos ? text.size() : nl + 1;
    ++n;
    line = line.substr(0, line.find('#'));
    for (auto &c : line)
      if (c == ',' || c == ';' || c == '\t' || c == '\r') c = ' ';
    const auto w = words(line);
    if (w.empty()) continue;
    if (w.size() < 2 || w.size() > 3) fail_at(path, n, "expected 'FILE V0 [UNIT]', got '" + trim(line) + "'");
    char *end = nullptr;
    errno = 0;
    const double v = std::strtod(w[1].c_str(), &end);
    if (*end || errno == ERANGE || !(v > 0.0) || !std::isfinite(v))
      fail_at(path, n, "v0 of " + w[0] + " must be a number > 0, got '" + w[1] + "'");
    double f = 1.0;
    if (w.size() == 3 && !speed_unit_factor(w[2], si, f))
      fail_at(path, n, "unknown speed unit '" + w[2] + "' (LENGTH/TIME: m, cm, mm, um, in over s, ms, min)");
    if (first.count(w[0])) fail_at(path, n, w[0] + " given twice (first at line " + std::to_string(first[w[0]]) + ")");
    first[w[0]] = n;
    table[w[0]] = v * f;
  }
  if (table.empty()) throw InputError(path + ": no 'FILE V0' line in the v0 table");
  return table;
}

std::string gef_mapping_text(const std::string &path)
{
  require_regular_file(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot read: " + std::strerror(errno));
  std::map<int, std::pair<int, std::string>> by_quantity;    // quantity -> (column, unit)
  std::string separator = "whitespace", area, area_unit, line;
  long n = 0, eoh = 0;
  std::vector<char> buf(64 * 1024);
  while (eoh == 0 && n < 10000 && read_bounded_line(in, buf, line, path, n, 1 << 20, "not a GEF header")) {
    if (++n == 1) line = without_bom(line);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const auto eq = line.find('=');
    if (line.empty() || line[0] != '#' || eq == std::string::npos) continue;
    const std::string key = trim(line.substr(1, eq - 1));
    std::vector<std::string> v = split(line.substr(eq + 1), ',');
    for (auto &f : v) f = trim(f);
    if (key == "EOH") eoh = n;
    else if (key == "COLUMNSEPARATOR" && !v.empty())
      separator = v[0] == ";" ? "semicolon" : v[0] == "," ? "comma" : v[0] == "\t" || v[0].empty() ? "tab" : "whitespace";
    else if (key == "COLUMNINFO" && v.size() >= 4)
      by_quantity[std::atoi(v[3].c_str())] = {std::atoi(v[0].c_str()), v[1]};
    else if (key == "MEASUREMENTVAR" && v.size() >= 3 && std::atoi(v[0].c_str()) == 1)
      area = v[1], area_unit = v[2];
  }
  if (!eoh) throw InputError(path + ": GEF: no '#EOH=' line ending the header (in the first 10000 lines)");
  const int depth_q = by_quantity.count(11) ? 11 : 1;
  if (!by_quantity.count(depth_q)) throw InputError(path + ": GEF: no column of quantity 1 (penetration length) or 11 (corrected depth)");
  if (!by_quantity.count(2)) throw InputError(path + ": GEF: no column of quantity 2 (cone resistance)");
  if (area.empty()) throw InputError(path + ": GEF: no #MEASUREMENTVAR= 1 (the cone's area): the force is the cone resistance times it");
  std::string t = "# implied by the GEF header of " + path + "\ndelimiter = " + separator + "\nheader_lines = " +
                  std::to_string(eoh) + "\ncolumn_names = no\ndepth = #" + std::to_string(by_quantity[depth_q].first) +
                  "\nposition_unit = " + by_quantity[depth_q].second + "\nforce = #" + std::to_string(by_quantity[2].first) +
                  "\nforce_unit = " + by_quantity[2].second + "\narea = " + area + "\narea_unit = " + area_unit +
                  "\ntare_rows = 0\n";
  if (by_quantity.count(12))
    t += "time = #" + std::to_string(by_quantity[12].first) + "\ntime_unit = " + by_quantity[12].second + "\n";
  return t;
}

double nominal_v0(const std::map<std::string, double> &table, const std::string &file)
{
  const std::filesystem::path p(file);
  for (const std::string &key : {p.filename().string(), p.stem().string()}) {
    const auto it = table.find(key);
    if (it != table.end()) return it->second;
  }
  return NAN;
}

std::string ImportMapping::time_from() const
{
  switch (time_source) {
    case TimeSource::column: return "time";
    case TimeSource::sample_rate: return "sample_rate";
    case TimeSource::depth_over_speed: return "dz/v";
    case TimeSource::none: break;
  }
  return "none";
}

ImportMapping read_import_mapping(const std::string &path, bool si)
{
  std::string text;
  if (!read_text_file(path, text)) throw InputError(path + ": cannot read the mapping: " + std::strerror(errno));
  return parse_import_mapping(text, path, si);
}

}    // namespace granpen
