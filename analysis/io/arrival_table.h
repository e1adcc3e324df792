/* -*- c++ -*- ----------------------------------------------------------
   granpen analysis: reader of what inputs/observe/arrival.lmp writes beside a
   push's trace TRACE: TRACE.arrival.info, the rings ('key = value' lines:
   step0, dt, radii, width, layer; '#' lines are comments), and
   TRACE.arrival.txt, fix ave/time output with the kinetic energy and the
   pressure-volume sum of each ring (columns c_arr_K[1] and c_arr_K[2], K from
   1). Rejections throw InputError naming file:line or the key.
------------------------------------------------------------------------- */

#ifndef GRANPEN_ARRIVAL_TABLE_H
#define GRANPEN_ARRIVAL_TABLE_H

#include "errors.h"

#include <cstddef>
#include <string>
#include <vector>

namespace granpen {

struct ArrivalTable {
  std::string info_path, table_path;
  std::vector<double> radii;                 // ring centres, cm from the axis
  double width = 0, layer = 0;               // ring width and the layer's depth below z_s, cm
  std::vector<double> t;                     // s since the push's first step (the trace's t)
  std::vector<std::vector<double>> ke;       // per ring, erg
  std::vector<std::vector<double>> pv;       // per ring, -(trace of stress/atom) / 3 summed (erg)
};

// What the reader accepts at most: rings, and bytes of the table (a push of 1e6 rows of 7
// columns is about 100 MB; far beyond a push's 50-step samples).
constexpr std::size_t kMaxArrivalRings = 32;
constexpr std::size_t kMaxArrivalTableBytes = std::size_t(256) << 20;

// The rings of the push whose trace is trace_path (v0, D, g from it: the table's times are
// (step - step0) dt). Throws InputError for a missing or malformed file, a key missing or
// not a number, step0 after the table's first row, radii not increasing and positive.
ArrivalTable read_arrival_table(const std::string &trace_path, double v0, double D, double g);

}    // namespace granpen

#endif
