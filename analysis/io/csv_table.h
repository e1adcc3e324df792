/* -*- c++ -*- ----------------------------------------------------------
   granpen analysis: a plain CSV table with named columns, as the post-processor's
   tables are written (granpen flow, granpen momentum): optional `# key = value`
   comment lines (kept as keys; other `#` lines skipped), one header line of column
   names, then rows. Cells are kept as text; numbers() converts a column and names
   file:line of the first cell that is not a finite number. Every rejection names
   the file (and line), as InputError (trace_reader.h).
------------------------------------------------------------------------- */

#ifndef GRANPEN_CSV_TABLE_H
#define GRANPEN_CSV_TABLE_H

#include <map>
#include <string>
#include <vector>

namespace granpen {

struct CsvTable {
  std::string path;
  std::map<std::string, std::string> keys;    // from `# key = value` lines
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> rows;
  std::vector<int> lines;                     // file line of each row

  bool has(const std::string &column) const;
  int index(const std::string &column) const;    // -1 when absent
  // the column as numbers; empty cells and "nan" become NaN when allow_nan, else
  // are rejected. Throws InputError (missing column, bad cell).
  std::vector<double> numbers(const std::string &column, bool allow_nan = true) const;
  std::vector<std::string> text(const std::string &column) const;
  // a key as a number; fallback when absent; throws InputError when not a number
  double key_number(const std::string &key, double fallback) const;
};

// Reads PATH; throws InputError for a missing file, no header line, a row with a
// different number of fields than the header, or (when given) a missing required
// column.
CsvTable read_csv_table(const std::string &path, const std::vector<std::string> &required = {});
CsvTable parse_csv_table(const std::string &text, const std::string &name,
                         const std::vector<std::string> &required = {});

}    // namespace granpen

#endif
