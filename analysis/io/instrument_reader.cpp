// granpen analysis: instrument files read row by row (see instrument_reader.h).
#include "instrument_reader.h"

#include "text_util.h"
#include "trace_reader.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>

namespace granpen {

namespace {

// lines searched for the column names or the first data row before giving up
constexpr long MAX_HEADER_LINES = 10000;

std::string unquote(const std::string &s)
{
  const std::string t = trim(s);
  if (t.size() >= 2 && (t.front() == '"' || t.front() == '\'') && t.back() == t.front()) return trim(t.substr(1, t.size() - 2));
  return t;
}

std::string lower(std::string s)
{
  for (auto &c : s) c = (char) std::tolower((unsigned char) c);
  return s;
}

}    // namespace

InstrumentReader::InstrumentReader(const std::string &path, const ImportMapping &mapping) : path_(path), m_(mapping)
{
  require_regular_file(path);
  in_.open(path, std::ios::binary);
  if (!in_) throw InputError(path + ": cannot read: " + std::strerror(errno));
  find_layout();
}

bool InstrumentReader::read_line(std::string &line)
{
  if (!read_bounded_line(in_, buf_, line, path_, line_no_, kMaxInstrumentLine, "not a row of delimited text"))
    return false;
  if (++line_no_ == 1) line = without_bom(line);
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return true;
}

std::vector<std::string> InstrumentReader::fields(const std::string &line, Delim d) const
{
  std::vector<std::string> out;
  switch (d) {
    case Delim::comma: out = split(line, ','); break;
    case Delim::semicolon: out = split(line, ';'); break;
    case Delim::tab: out = split(line, '\t'); break;
    case Delim::whitespace: return words(line);
    case Delim::keyvalue: {    // pairs between blanks, semicolons and (with a decimal point) commas
      std::string s = line;
      for (auto &c : s)
        if (c == ';' || c == '\t' || (c == ',' && !m_.decimal_comma)) c = ' ';
      return words(s);
    }
  }
  for (auto &f : out) f = unquote(f);
  return out;
}

bool InstrumentReader::parse_number(const std::string &field, double &v) const
{
  std::string s = unquote(field);
  if (m_.decimal_comma)
    for (auto &c : s)
      if (c == ',') c = '.';
  if (s.empty()) return false;
  errno = 0;
  char *end = nullptr;
  v = std::strtod(s.c_str(), &end);
  return *end == '\0' && errno != ERANGE && std::isfinite(v);
}

bool InstrumentReader::locate(const std::vector<std::string> &names, std::string &missing)
{
  auto find = [&](const ColumnRef &c, int &index) {
    index = -1;
    if (!c.given()) return true;
    if (c.index > 0) {
      index = c.index - 1;
      return true;
    }
    for (std::size_t i = 0; i < names.size(); ++i)
      if (names[i] == c.name) index = (int) i;
    for (std::size_t i = 0; i < names.size() && index < 0; ++i)    // then without regard to case
      if (lower(names[i]) == lower(c.name)) index = (int) i;
    if (index < 0 && missing.empty()) missing = c.name;
    return index >= 0;
  };
  missing.clear();
  bool ok = find(m_.time, i_time_);
  ok = find(m_.force, i_force_) && ok;
  ok = find(m_.position, i_position_) && ok;
  ok = find(m_.speed, i_speed_) && ok;
  return ok;
}

bool InstrumentReader::numeric_row(const std::string &line, Delim d) const
{
  const auto f = fields(line, d);
  double v;
  for (const ColumnRef *c : {&m_.time, &m_.force, &m_.position, &m_.speed})
    if (c->given() && !value_of(f, d, c->index - 1, *c, "", v).empty()) return false;
  if (d == Delim::keyvalue) return true;
  return f.size() >= 2 || (f.size() == 1 && m_.force.index == 1 && !m_.time.given() && !m_.position.given());
}

void InstrumentReader::find_layout()
{
  std::vector<Delim> candidates;
  static const std::pair<const char *, Delim> named[] = {{"comma", Delim::comma}, {"semicolon", Delim::semicolon},
                                                          {"tab", Delim::tab}, {"whitespace", Delim::whitespace},
                                                          {"keyvalue", Delim::keyvalue}};
  if (m_.delimiter == "auto") {
    candidates = {Delim::tab, Delim::semicolon};
    if (!m_.decimal_comma) candidates.push_back(Delim::comma);
    candidates.push_back(Delim::whitespace);
  } else {
    for (const auto &n : named)
      if (m_.delimiter == n.first) candidates = {n.second};
  }
  const bool by_name = m_.column_names && (!m_.time.name.empty() || !m_.force.name.empty() ||
                                           !m_.position.name.empty() || !m_.speed.name.empty());
  std::string line, best_missing, best_names;
  long best_line = 0;
  std::size_t best_found = 0;
  while (read_line(line)) {
    if (m_.header_lines >= 0 && line_no_ <= m_.header_lines) continue;
    if (trim(line).empty()) continue;
    if (line_no_ > MAX_HEADER_LINES) break;
    const bool fixed = m_.header_lines >= 0;
    if (by_name) {
      for (Delim d : candidates) {
        const auto names = fields(line, d);
        std::string missing;
        if (locate(names, missing)) {
          delim_ = d;
          names_line_ = line_no_;
          header_lines_ = line_no_ - 1;
          row_fields_ = names.size();
          refuse_shared_columns();
          return;
        }
        std::size_t found = 0;
        for (const ColumnRef *c : {&m_.time, &m_.force, &m_.position, &m_.speed})
          for (const auto &n : names)
            if (!c->name.empty() && lower(n) == lower(c->name)) ++found;
        if (found > best_found || (fixed && !best_line)) {
          best_found = found;
          best_line = line_no_;
          best_missing = missing;
          best_names.clear();
          for (const auto &n : names) best_names += (best_names.empty() ? "" : ", ") + n;
        }
      }
      if (fixed) break;    // the line after the header lines must be the names
      continue;
    }
    for (Delim d : candidates) {
      if (!numeric_row(line, d)) continue;
      std::string missing;
      if (d != Delim::keyvalue) locate({}, missing);
      delim_ = d;
      header_lines_ = line_no_ - 1;
      names_line_ = 0;
      pending_ = line;
      pending_no_ = line_no_;
      row_fields_ = d == Delim::keyvalue ? 0 : fields(line, d).size();
      if (d != Delim::keyvalue) refuse_shared_columns();
      return;
    }
    if (fixed) fail_at(path_, line_no_, "the first row after header_lines = " + std::to_string(m_.header_lines) +
                                            " has no number in the mapped columns");
  }
  if (best_line)
    fail_at(path_, best_line, "no column '" + best_missing + "' in the column names (" + best_names + ")");
  if (by_name)
    throw InputError(path_ + ": no column-name line holds the mapped columns (in the first " +
                     std::to_string(MAX_HEADER_LINES) + " lines)");
  throw InputError(path_ + ": no data row with numbers in the mapped columns");
}

std::string InstrumentReader::value_of(const std::vector<std::string> &f, Delim d, int index, const ColumnRef &c,
                                       const char *what, double &v) const
{
  if (index < 0) {    // a key=value row's key
    for (const auto &kv : f) {
      const auto eq = kv.find('=');
      if (eq == std::string::npos || kv.substr(0, eq) != c.name) continue;
      if (!parse_number(kv.substr(eq + 1), v))
        return std::string(what) + " key '" + c.name + "' is not a number: '" + kv.substr(eq + 1) + "'";
      return "";
    }
    return "no " + std::string(what) + " key '" + c.name + "=' in the row";
  }
  if (index >= (int) f.size()) return std::to_string(f.size()) + " fields: no " + what + " column " + c.text();
  std::string field = f[index];
  if (d == Delim::keyvalue) {
    // a key=value field by position: its value, or a keyless field after its leading symbols
    const auto eq = field.find('=');
    if (eq != std::string::npos)
      field = field.substr(eq + 1);
    else
      field = field.substr(std::min(field.size(), field.find_first_of("0123456789+-.")));
  }
  if (!parse_number(field, v)) return std::string(what) + " column " + c.text() + " is not a number: '" + unquote(f[index]) + "'";
  return "";
}

void InstrumentReader::refuse_shared_columns() const
{
  const struct {
    const char *role;
    const ColumnRef &c;
    int located;
  } roles[] = {{"time", m_.time, i_time_}, {"force", m_.force, i_force_},
               {m_.position_is_depth ? "depth" : "displacement", m_.position, i_position_}, {"speed", m_.speed, i_speed_}};
  for (const auto &a : roles)
    for (const auto &b : roles) {
      if (&a >= &b || !a.c.given() || !b.c.given() || a.located < 0 || a.located != b.located) continue;
      const std::string where = names_line_ ? file_line(path_, names_line_) : path_;
      throw InputError(where + ": " + a.role + " " + a.c.text() + " and " + b.role + " " + b.c.text() +
                       " are the same column (#" + std::to_string(a.located + 1) + "): one column, one role (mapping " +
                       m_.path + ")");
    }
}

std::string InstrumentReader::field_count_error(const std::vector<std::string> &f) const
{
  std::size_t n = f.size();
  while (n > row_fields_ && trim(f[n - 1]).empty()) --n;    // a trailing delimiter adds an empty field
  if (!row_fields_ || n <= row_fields_) return "";
  const std::string of = names_line_ ? "the column names (line " + std::to_string(names_line_) + ") name "
                                     : "the first data row (line " + std::to_string(first_row_line_) + ") has ";
  return "row has " + std::to_string(n) + " fields, " + of + std::to_string(row_fields_) +
         " (a thousands separator, or a decimal comma, splitting a number? the mapping says decimal " +
         (m_.decimal_comma ? "comma" : "point") + ")";
}

std::string InstrumentReader::parse_fields(const std::string &line, ImportRow &r, std::string *count_error) const
{
  const auto f = fields(line, delim_);
  if (count_error && delim_ != Delim::keyvalue) *count_error = field_count_error(f);
  const bool kv = delim_ == Delim::keyvalue;
  std::string why = value_of(f, delim_, kv ? m_.force.index - 1 : i_force_, m_.force, "force", r.F);
  const struct {
    const ColumnRef &c;
    int located;
    const char *what;
    double &v;
  } others[] = {{m_.time, i_time_, "time", r.t}, {m_.position, i_position_, "position", r.x}, {m_.speed, i_speed_, "speed", r.v}};
  for (const auto &o : others)
    if (why.empty() && o.c.given()) why = value_of(f, delim_, kv ? o.c.index - 1 : o.located, o.c, o.what, o.v);
  return why;
}

ImportRow InstrumentReader::to_row(ImportRow r, long line_no)
{
  r.line = line_no;
  r.F *= m_.force_factor;
  r.x *= m_.position_factor;
  r.v *= m_.speed_factor;
  using TS = ImportMapping::TimeSource;
  switch (m_.time_source) {
    case TS::column: r.t *= m_.time_factor; break;
    case TS::sample_rate: r.t = (double) rows_ / m_.sample_rate; break;
    case TS::none: r.t = (double) rows_; break;    // the order of the rows, not a time
    case TS::depth_over_speed:
      try {
        r.t = clock_.next(r.x, r.v, line_no);
      } catch (const ImportRejected &e) {
        fail_at(path_, line_no, e.what());
      }
      break;
  }
  ++rows_;
  last_data_line_ = line_no;
  return r;
}

bool InstrumentReader::next(std::vector<ImportRow> &rows, std::size_t max_rows)
{
  rows.clear();
  if (!pending_.empty()) {
    ImportRow raw;
    const std::string why = parse_fields(pending_, raw);
    if (!why.empty()) fail_at(path_, pending_no_, why);
    first_row_line_ = pending_no_;
    rows.push_back(to_row(raw, pending_no_));
    pending_.clear();
  }
  std::string line;
  while (rows.size() < max_rows && read_line(line)) {
    if (names_line_ && line_no_ <= names_line_ + m_.lines_after_names) continue;    // a units line
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;    // blank lines and comments between rows
    ImportRow raw;
    std::string count_error;
    const std::string why = parse_fields(line, raw, &count_error);
    // a row that reads as numbers but has more fields than the names: its fields are shifted
    if (why.empty() && !count_error.empty()) fail_at(path_, line_no_, count_error);
    if (trailer_line_) {    // past the data's end: a data row now means the end was not one
      if (why.empty())
        fail_at(path_, trailer_line_, trailer_why_ + " (the data seemed to end at this line, but data rows come back at line " +
                                          std::to_string(line_no_) + ")");
      continue;
    }
    if (!why.empty() && rows_ > 0) {    // the data end here: a trailer or footer
      trailer_line_ = line_no_;
      trailer_why_ = why;
      trailer_text_ = t.substr(0, 60);
      continue;
    }
    if (!why.empty()) fail_at(path_, line_no_, why);    // the first data row
    if (!first_row_line_) first_row_line_ = line_no_;
    rows.push_back(to_row(raw, line_no_));
  }
  return !rows.empty();
}

std::string InstrumentReader::layout() const
{
  static const char *names[] = {"comma", "semicolon", "tab", "white-space", "key=value"};
  std::string s = std::string(names[(int) delim_]) + (delim_ == Delim::keyvalue ? " rows" : "-delimited");
  s += m_.decimal_comma ? ", decimal comma" : ", decimal point";
  s += ", " + std::to_string(header_lines_) + " header line" + (header_lines_ == 1 ? "" : "s");
  if (names_line_) s += ", column names at line " + std::to_string(names_line_);
  return s;
}

}    // namespace granpen
