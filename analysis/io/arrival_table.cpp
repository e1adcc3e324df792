// granpen analysis: reader of observe/arrival.lmp's rings (see arrival_table.h).
#include "arrival_table.h"

#include "text_util.h"
#include "trace_reader.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>

namespace granpen {

namespace {

std::map<std::string, std::string> read_keys(const std::string &path)
{
  require_regular_file(path);
  std::error_code ec;
  const auto bytes = std::filesystem::file_size(path, ec);
  if (!ec && bytes > (std::uintmax_t(1) << 20)) throw InputError(path + ": larger than 1 MiB: not an arrival .info file");
  std::string text;
  if (!read_text_file(path, text)) throw InputError(path + ": cannot open (observe/arrival.lmp writes it beside the trace)");
  std::map<std::string, std::string> keys;
  std::istringstream in(without_bom(text));
  std::string line;
  long lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    const std::string s = trim(line);
    if (s.empty() || s[0] == '#') continue;
    const std::size_t eq = s.find('=');
    if (eq == std::string::npos) fail_at(path, lineno, "expected 'key = value', found '" + s + "'");
    const std::string key = trim(s.substr(0, eq));
    if (key.empty()) fail_at(path, lineno, "a value without a key");
    if (keys.count(key)) fail_at(path, lineno, "key '" + key + "' given twice");
    keys[key] = trim(s.substr(eq + 1));
  }
  return keys;
}

std::vector<double> numbers_of(const std::map<std::string, std::string> &keys, const std::string &key,
                               const std::string &path)
{
  const auto it = keys.find(key);
  if (it == keys.end()) throw InputError(path + ": no key '" + key + "'");
  std::vector<double> out;
  for (const auto &w : words(it->second)) {
    char *end = nullptr;
    const double v = std::strtod(w.c_str(), &end);
    if (w.empty() || *end != '\0' || !std::isfinite(v)) throw InputError(path + ": " + key + ": '" + w + "' is not a number");
    out.push_back(v);
  }
  if (out.empty()) throw InputError(path + ": " + key + ": no value");
  return out;
}

double number_of(const std::map<std::string, std::string> &keys, const std::string &key, const std::string &path)
{
  const auto v = numbers_of(keys, key, path);
  if (v.size() != 1) throw InputError(path + ": " + key + ": one number expected");
  return v[0];
}

}    // namespace

ArrivalTable read_arrival_table(const std::string &trace_path, double v0, double D, double g)
{
  ArrivalTable a;
  a.info_path = trace_path + ".arrival.info";
  a.table_path = trace_path + ".arrival.txt";
  const auto keys = read_keys(a.info_path);
  const double step0 = number_of(keys, "step0", a.info_path), dt = number_of(keys, "dt", a.info_path);
  a.radii = numbers_of(keys, "radii", a.info_path);
  a.width = number_of(keys, "width", a.info_path);
  a.layer = number_of(keys, "layer", a.info_path);
  if (!(dt > 0)) throw InputError(a.info_path + ": dt: must be above 0");
  if (a.radii.size() > kMaxArrivalRings)
    throw InputError(a.info_path + ": radii: " + std::to_string(a.radii.size()) + " rings, at most " + std::to_string(kMaxArrivalRings));
  for (std::size_t k = 0; k < a.radii.size(); ++k)
    if (!(a.radii[k] > 0) || (k && !(a.radii[k] > a.radii[k - 1])))
      throw InputError(a.info_path + ": radii: must be positive and increasing");
  require_regular_file(a.table_path);
  std::error_code ec;
  const auto bytes = std::filesystem::file_size(a.table_path, ec);
  if (!ec && bytes > kMaxArrivalTableBytes) throw InputError(a.table_path + ": larger than 256 MiB: not a push's arrival table");
  std::string text;
  if (!read_text_file(a.table_path, text)) throw InputError(a.table_path + ": cannot open (observe/arrival.lmp writes it beside the trace)");
  // the table read once for every ring's two columns, in the order (ring, 1), (ring, 2)
  std::vector<std::string> wanted;
  for (std::size_t k = 0; k < a.radii.size(); ++k)
    for (int c : {1, 2}) wanted.push_back("c_arr_" + std::to_string(k + 1) + "[" + std::to_string(c) + "]");
  const AveTimeTable table = parse_ave_time_table(text, a.table_path, wanted);
  AveTimeSpec spec;    // for the time axis, (step - step0) dt, once
  spec.v0 = v0, spec.D = D, spec.g = g, spec.dt = dt, spec.step0 = step0, spec.column = wanted.front();
  a.t = ave_time_trace(table, spec).t;
  if (a.t.front() < 0) throw InputError(a.info_path + ": step0 lies after the table's first row: not this push's");
  for (std::size_t k = 0; k < a.radii.size(); ++k) {
    a.ke.push_back(table.columns[2 * k]);
    a.pv.push_back(table.columns[2 * k + 1]);
  }
  return a;
}

}    // namespace granpen
