// granpen analysis: plain CSV tables with named columns (see csv_table.h).
#include "csv_table.h"

#include "text_util.h"
#include "errors.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>

namespace granpen {

namespace {

// the cells of a CSV line, trimmed; "..." quotes a cell ("" inside is a quote)
std::vector<std::string> csv_cells(const std::string &line)
{
  std::vector<std::string> out;
  std::string cell;
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') cell += '"', ++i;
      else if (c == '"') quoted = false;
      else cell += c;
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      out.push_back(trim(cell));
      cell.clear();
    } else {
      cell += c;
    }
  }
  out.push_back(trim(cell));
  return out;
}

}    // namespace

bool CsvTable::has(const std::string &column) const { return index(column) >= 0; }

int CsvTable::index(const std::string &column) const
{
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (columns[i] == column) return static_cast<int>(i);
  return -1;
}

std::vector<std::string> CsvTable::text(const std::string &column) const
{
  const int k = index(column);
  if (k < 0) throw InputError(path + ": no column '" + column + "'");
  std::vector<std::string> out;
  out.reserve(rows.size());
  for (const auto &r : rows) out.push_back(r[k]);
  return out;
}

std::vector<double> CsvTable::numbers(const std::string &column, bool allow_nan) const
{
  const int k = index(column);
  if (k < 0) throw InputError(path + ": no column '" + column + "'");
  std::vector<double> out;
  out.reserve(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::string &s = rows[i][k];
    char *end = nullptr;
    errno = 0;
    const double v = std::strtod(s.c_str(), &end);
    const bool parsed = !s.empty() && end && *end == '\0' && errno != ERANGE;
    if (parsed && std::isfinite(v)) {
      out.push_back(v);
      continue;
    }
    if (allow_nan && (s.empty() || (parsed && std::isnan(v)))) {
      out.push_back(NAN);
      continue;
    }
    fail_at(path, lines[i], "column " + column + " value '" + s + "' is not a finite number");
  }
  return out;
}

double CsvTable::key_number(const std::string &key, double fallback) const
{
  const auto it = keys.find(key);
  if (it == keys.end()) return fallback;
  char *end = nullptr;
  const double v = std::strtod(it->second.c_str(), &end);
  if (it->second.empty() || !end || *end != '\0' || !std::isfinite(v))
    throw InputError(path + ": header key " + key + " = '" + it->second + "' is not a number");
  return v;
}

CsvTable parse_csv_table(const std::string &text, const std::string &name, const std::vector<std::string> &required)
{
  CsvTable t;
  t.path = name;
  std::istringstream in(text);
  std::string line;
  int lineno = 0;
  bool header = false;
  while (std::getline(in, line)) {
    ++lineno;
    const std::string s = trim(line);
    if (s.empty()) continue;
    if (s[0] == '#') {
      const auto eq = s.find('=');
      if (eq != std::string::npos) {
        const std::string key = trim(s.substr(1, eq - 1));
        if (!key.empty() && key.find(' ') == std::string::npos) t.keys[key] = trim(s.substr(eq + 1));
      }
      continue;
    }
    auto cells = csv_cells(s);
    if (!header) {
      t.columns = cells;
      header = true;
      continue;
    }
    if (cells.size() != t.columns.size())
      fail_at(name, lineno, "row has " + std::to_string(cells.size()) + " fields, expected " +
                                std::to_string(t.columns.size()) + " (" + std::to_string(t.columns.size()) +
                                " columns in the header)");
    t.rows.push_back(cells);
    t.lines.push_back(lineno);
  }
  if (!header) throw InputError(name + ": no header line of column names");
  std::string missing;
  for (const auto &c : required)
    if (!t.has(c)) missing += (missing.empty() ? "" : ", ") + c;
  if (!missing.empty()) {
    std::string have;
    for (const auto &c : t.columns) have += (have.empty() ? "" : ",") + c;
    throw InputError(name + ": missing column" + (missing.find(',') != std::string::npos ? "s " : " ") + missing +
                     " (the header has " + have + ")");
  }
  return t;
}

CsvTable read_csv_table(const std::string &path, const std::vector<std::string> &required)
{
  std::string text;
  if (!read_text_file(path, text)) throw InputError(path + ": cannot open: " + std::strerror(errno));
  return parse_csv_table(text, path, required);
}

}    // namespace granpen
