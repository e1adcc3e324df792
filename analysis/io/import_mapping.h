// granpen analysis: the mapping file of `granpen import`: a small "key = value" file a lab
// writes once for its instrument, saying where force, position, time and speed are in the
// instrument's files, in which units and signs, and how a push is read (tare, onset,
// surface, end, speed checks). docs/measurements.md lists the keys. Every rejection names
// the mapping file and line.
#ifndef GRANPEN_IMPORT_MAPPING_H
#define GRANPEN_IMPORT_MAPPING_H

#include "instrument_import.h"

#include <string>

namespace granpen {

// A column by name (as in the file's column-name line) or by 1-based index ("#3").
struct ColumnRef {
  std::string name;    // "" when by index or absent
  int index = 0;       // 1-based; 0 when by name or absent
  bool given() const { return index > 0 || !name.empty(); }
  std::string text() const { return index > 0 ? "#" + std::to_string(index) : "'" + name + "'"; }
};

struct ImportMapping {
  std::string path;
  // layout
  std::string delimiter = "auto";    // auto, comma, semicolon, tab, whitespace, keyvalue
  bool decimal_comma = false;
  int header_lines = -1;             // lines before the column names (or the data); -1: found
  bool column_names = true;          // a column-name line precedes the data
  int lines_after_names = 0;         // lines between the names and the data (a units line)
  // columns
  ColumnRef time, force, position, speed;
  bool position_is_depth = false;    // "depth = ..." (surface 0 unless given) or "displacement = ..."
  double sample_rate = 0.0;          // Hz, instead of a time column
  // factors to the trace's units (signs included); set by read_import_mapping for `si`
  double time_factor = 1.0, force_factor = 1.0, position_factor = 1.0, speed_factor = 1.0;
  std::string force_unit = "N", position_unit = "mm", time_unit = "s", speed_unit = "mm/s";
  // how a push is read, in the trace's units (surface, end_time: raw, converted)
  ImportRules rules;
  double v0 = 0.0;                   // nominal speed in the trace's units (0: not given)
};

// Reads the mapping at path for traces in si (else cgs) units. Throws InputError
// "PATH:LINE: ..." (unknown key or unit, a bad number, two force columns, no force column,
// neither time nor sample rate, ...).
ImportMapping read_import_mapping(const std::string &path, bool si);
ImportMapping parse_import_mapping(const std::string &text, const std::string &path, bool si);

}    // namespace granpen

#endif
