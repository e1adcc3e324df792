/* -*- c++ -*- ----------------------------------------------------------
   granpen analysis: reader of granpen-trace v1 force traces
   (shared/formats/trace-csv.md). Every rejection names the file and line.
------------------------------------------------------------------------- */

#ifndef GRANPEN_TRACE_READER_H
#define GRANPEN_TRACE_READER_H

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace granpen {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

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
};

// Reads and validates a trace; throws InputError naming path:line.
Trace read_trace(const std::string &path);
Trace parse_trace(const std::string &text, const std::string &name);

// The same trace in cgs (cm, g, s, dyne); a cgs trace comes back unchanged.
Trace to_cgs(const Trace &trace);

}    // namespace granpen

#endif
