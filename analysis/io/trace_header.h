/* -*- c++ -*- ----------------------------------------------------------
   granpen analysis: the header of a granpen-trace v1 file alone (its keys and
   column names), for a trace whose rows do not matter or are too few for
   read_trace (a push of one step, as a style writes it in a test).
------------------------------------------------------------------------- */

#ifndef GRANPEN_TRACE_HEADER_H
#define GRANPEN_TRACE_HEADER_H

#include "trace_reader.h"    // Trace, InputError

#include <string>

namespace granpen {

// The header of the trace at path, checked as read_trace checks it (the first line, the
// keys given once, units, v0, D, g and the columns t, z, F) and read with its bounded lines;
// no row is read. Throws InputError naming path:line. The Trace has path, units, keys, v0,
// D, g and columns; t, z and F empty.
Trace read_trace_header(const std::string &path);

}    // namespace granpen

#endif
