// granpen analysis: the mapping file of `granpen import`: a small "key = value" file a lab
// writes once for its instrument, saying where force, position, time and speed are in the
// instrument's files, in which units and signs, and how a push is read (tare, onset,
// surface, end, speed checks). docs/measurements.md lists the keys. Every rejection names
// the mapping file and line.
#ifndef GRANPEN_IMPORT_MAPPING_H
#define GRANPEN_IMPORT_MAPPING_H

#include "instrument_import.h"

#include <map>
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
  // where t comes from: a time column, the sample rate, the integral of dz / v over the
  // rows of a depth-sampled log (a position and a speed column, no time), or nowhere (a
  // position alone: the trace is written without t)
  enum class TimeSource { column, sample_rate, depth_over_speed, none };
  TimeSource time_source = TimeSource::column;
  // the header's t_from value for time_source: time, sample_rate, dz/v, none
  std::string time_from() const;
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

// A table of nominal speeds, one run a line: "FILE V0 [UNIT]" (white space, comma, semicolon
// or tab between; '#' starts a comment). FILE: an input's file name, with or without its
// extension; UNIT: LENGTH/TIME, default the traces' (cm/s in cgs, m/s in si). The speeds
// come back in the traces' units. Throws InputError "PATH:LINE: ..." (a bad speed or unit,
// a file given twice, a line of other shape) or "PATH: ..." (unreadable, empty).
std::map<std::string, double> read_v0_table(const std::string &path, bool si);
// GEF (the Geotechnical Exchange Format of cone penetration tests, GEF-CPT): the mapping
// a GEF file's own header implies, as mapping text for parse_import_mapping. Read up to
// "#EOH=": #COLUMNINFO (1 penetration length or 11 corrected depth -> depth, 2 cone
// resistance -> force as a stress on the cone's area, #MEASUREMENTVAR 1 in mm2 or cm2;
// 12 elapsed time -> time, else no time), #COLUMNSEPARATOR (default white space),
// #RECORDSEPARATOR (a trailing field, ignored); tare_rows = 0 (the cone is in the ground
// from the first row). Throws InputError "PATH: ..." (no #EOH=, no depth or cone
// resistance column, no cone area, a unit not known).
std::string gef_mapping_text(const std::string &path);
// the table's speed for an input file (its name, else its stem); NaN when absent
double nominal_v0(const std::map<std::string, double> &table, const std::string &file);

}    // namespace granpen

#endif
