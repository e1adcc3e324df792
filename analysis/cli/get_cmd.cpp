// granpen get FILE KEY...: values of a JSON file by key path (io/json_path.h), a record per
// line, the keys' values separated by a tab.
#include "errors.h"
#include "get_options.h"
#include "json_path.h"
#include "subcommand.h"
#include "subcommands.h"

#include <algorithm>
#include <cstdio>

int granpen::cli::run_get(const GetOptions &o)
{
  const Json doc = read_json_file(o.file);
  std::vector<std::vector<std::string>> columns;
  std::size_t rows = 0;
  for (const auto &key : o.keys) {
    const JsonLookup r = json_lookup(doc, key);
    if (!r.complete() && !o.has_missing) throw InputError(o.file + ": " + r.missing);
    std::vector<std::string> column;
    for (const Json *v : r.values) column.push_back(v ? json_value_text(*v) : o.missing);
    rows = std::max(rows, column.size());
    columns.push_back(column);
  }
  // a [*] over an empty array: no records
  for (const auto &c : columns)
    if (c.empty()) rows = 0;
  for (std::size_t k = 0; k < columns.size() && rows > 0; ++k)
    if (columns[k].size() != rows && columns[k].size() != 1)
      throw InputError(o.file + ": key " + o.keys[k] + " gives " + std::to_string(columns[k].size()) + " values where another gives " +
                       std::to_string(rows) + " (keys with [*] must give as many, or one)");
  std::string out;
  for (std::size_t i = 0; i < rows; ++i) {
    for (std::size_t k = 0; k < columns.size(); ++k) {
      out += k ? "\t" : "";
      out += columns[k].size() == 1 ? columns[k][0] : columns[k][i];
    }
    out += '\n';
  }
  std::fputs(out.c_str(), stdout);
  return EXIT_OK;
}
int granpen::cli::get(int argc, char **argv) { return run_parsed(parse_get, run_get, argc, argv); }
