// granpen gap: the false-alarm rate measured at a scenario's scale (see gap_bench_rate.h).
#include "gap_bench_rate.h"

#include "errors.h"
#include "text_util.h"

#include <filesystem>
#include <map>

namespace granpen {

namespace {

// a whole number of at most 9 digits (a count of data sets), else InputError at `where`
int count_of(const std::string &v, const std::string &where)
{
  if (v.empty() || v.size() > 9 || v.find_first_not_of("0123456789") != std::string::npos)
    throw InputError(where + " is '" + v + "', not a whole number");
  return std::stoi(v);
}

std::string trimmed(const std::string &s)
{
  const auto a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

}    // namespace

MeasuredFalseAlarms parse_false_alarm_figure(const std::string &text, const std::string &file)
{
  std::map<std::string, std::string> kv;
  int line_no = 0;
  for (const std::string &raw : split(text, '\n')) {
    ++line_no;
    const std::string line = trimmed(raw);
    if (line.empty() || line[0] == '#') continue;
    const std::string at = file + ":" + std::to_string(line_no);
    const auto eq = line.find('=');
    if (eq == std::string::npos) throw InputError(at + ": not 'key = value'");
    const std::string key = trimmed(line.substr(0, eq));
    if (key != "sets" && key != "alarms" && key != "source" && key != "scenario" && key != "rate" && key != "low95" &&
        key != "high95")
      throw InputError(at + ": unknown key '" + key + "' (sets, alarms, source)");
    if (kv.count(key)) throw InputError(at + ": key '" + key + "' given twice");
    kv[key] = trimmed(line.substr(eq + 1));
  }
  for (const char *k : {"sets", "alarms"})
    if (!kv.count(k)) throw InputError(file + ": no '" + k + " = N' line");
  MeasuredFalseAlarms m;
  m.file = file;
  m.source = kv.count("source") ? kv["source"] : "";
  m.sets = count_of(kv["sets"], file + ": sets");
  m.alarms = count_of(kv["alarms"], file + ": alarms");
  if (m.sets < 1) throw InputError(file + ": sets = 0: no data set, no rate");
  if (m.alarms > m.sets) throw InputError(file + ": alarms = " + kv["alarms"] + " exceeds sets = " + kv["sets"]);
  m.interval = clopper_pearson(m.alarms, m.sets, 0.95);
  return m;
}

std::optional<MeasuredFalseAlarms> measured_false_alarms(const std::string &inputs, const std::string &scenario)
{
  const std::string file = inputs + "/false_alarms/" + scenario + ".txt";
  if (!std::filesystem::exists(file)) return std::nullopt;
  std::string text;
  if (!read_text_file(file, text)) throw InputError(file + ": cannot be read");
  return parse_false_alarm_figure(text, file);
}

}    // namespace granpen
