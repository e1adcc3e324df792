/* -*- c++ -*- ----------------------------------------------------------
   granpen analysis: reader of granpen-trace v1 force traces
   (shared/formats/trace-csv.md). Every rejection names the file and line.
------------------------------------------------------------------------- */

#ifndef GRANPEN_TRACE_READER_H
#define GRANPEN_TRACE_READER_H

#include "errors.h"    // InputError: what read_trace and the others throw

#include <cmath>
#include <cstddef>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace granpen {

struct Trace {
  std::string path;
  std::string units;                          // as written: "cgs" or "si"
  std::map<std::string, std::string> keys;    // every header key, as text
  double v0 = 0.0, D = 0.0, g = 0.0;          // required keys, in the file's units
  std::vector<std::string> columns;           // column names in file order
  std::vector<double> t, z, F;                // the three known columns
  std::map<std::string, std::vector<double>> other;    // any further columns

  // optional numeric key; fallback when absent
  double number(const std::string &key, double fallback) const;
  // false for a trace written without t (header t_from = none: t empty)
  bool has_t() const;
};

// InputError "PATH: no t column (...): WHO needs t" for a trace without t
void require_t(const Trace &trace, const std::string &who);

// What a reader accepts, at most (docs/reliability.md): beyond these it throws a named
// InputError instead of allocating without bound.
constexpr std::size_t kMaxTraceRows = 10000000;    // 240 MB of t, z, F doubles; ~300 MB of text
constexpr std::size_t kMaxTraceColumns = 64;
constexpr std::size_t kMaxTraceLine = std::size_t(1) << 20;    // bytes in one line, 1 MiB

// Reads and validates a trace, streaming the file (no copy of its text); throws InputError
// naming path:line. Validated beyond the format's list: v0 > 0, D > 0, g > 0 (the scalings
// divide by them), d_g > 0, rho_g > 0, mu >= 0 when given, no header key or column given
// twice, exactly as many fields in a row as column names (a comma used as decimal separator
// makes more), z not decreasing from the first row to the last (a height, not a depth), and
// at most kMaxTraceRows rows.
Trace read_trace(const std::string &path);
Trace parse_trace(const std::string &text, const std::string &name, std::size_t max_rows = kMaxTraceRows);

// The same validation with memory independent of the file's size: the header and a summary
// of the rows, none kept (granpen check).
struct TraceSummary {
  Trace header;               // header, keys and columns; t, z, F empty
  std::size_t rows = 0;
  double t_first = 0.0, t_last = 0.0;    // NaN without a t column
  double z_first = 0.0, z_last = 0.0;
  double F_max = -INFINITY;
};
TraceSummary scan_trace(const std::string &path);
TraceSummary to_cgs(const TraceSummary &summary);

// The header checks of read_trace and scan_trace alone, on a header block as
// format_trace_header writes it (the '#' lines and the column line): what a writer of
// traces (import) checks before it writes, so that its output passes `check`. Throws
// InputError "NAME:LINE: ..." naming the key; returns the header (no rows).
Trace check_trace_header(const std::string &header_text, const std::string &name);

// The raw output of `fix ave/time` in scalar mode ("# Time-averaged data for fix ID",
// "# TimeStep NAME...", then rows STEP VALUE...) as a trace: t = (step - step0) dt,
// z = z0 + v0 t, F = sign * the chosen column. LAMMPS writes no units, speed or geometry
// into it, so they come from the caller. Rejections name the file and line.
struct AveTimeSpec {
  std::string column;        // a column name of the "# TimeStep" line; "" = the first value column
  std::string units = "cgs";
  double v0 = 0.0, D = 0.0, g = 0.0;    // > 0, in `units`
  double dt = 0.0;           // timestep, > 0
  double step0 = NAN;        // the push's first step; NaN = first row's step minus the row spacing
  double z0 = -0.5;          // tip depth at step0 (negative above the surface)
  double sign = 1.0;         // -1 when the column is the force on the grains
};
Trace parse_ave_time(const std::string &text, const std::string &name, const AveTimeSpec &spec);
Trace read_ave_time(const std::string &path, const AveTimeSpec &spec);

// The same file read once for several of its columns (a table of many quantities: the
// arrival rings' kinetic energy and pressure): each row's step and the values of the
// columns asked for ("" = the first value column), kept and no others, so that memory
// follows what is asked, not the file's width. ave_time_trace then makes a trace of any
// kept column without reading the text again; parse_ave_time is the two in one.
// Rejections as parse_ave_time's (a column asked for and absent: the "# TimeStep" line).
struct AveTimeTable {
  std::string name;                            // the file, for messages
  std::vector<std::string> asked;              // the columns asked for ("" as given)
  std::vector<std::string> names;              // ... their names in the file
  std::vector<double> steps;                   // increasing
  std::vector<std::vector<double>> columns;    // columns[c][row], c as names
};
AveTimeTable parse_ave_time_table(const std::string &text, const std::string &name,
                                  const std::vector<std::string> &wanted);
Trace ave_time_trace(const AveTimeTable &table, const AveTimeSpec &spec);

// The same trace in cgs (cm, g, s, dyne); a cgs trace comes back unchanged.
Trace to_cgs(const Trace &trace);

}    // namespace granpen

#endif
