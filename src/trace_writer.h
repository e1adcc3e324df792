/* -*- c++ -*- ----------------------------------------------------------
   LAMMPS - Large-scale Atomic/Molecular Massively Parallel Simulator
   https://www.lammps.org/, Sandia National Laboratories
   Steve Plimpton, sjplimp@sandia.gov

   Copyright (2003) Sandia Corporation.  Under the terms of Contract
   DE-AC04-94AL85000 with Sandia Corporation, the U.S. Government retains
   certain rights in this software.  This software is distributed under
   the GNU General Public License.

   See the README file in the top-level LAMMPS directory.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   Contributing author: granpen developers
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   GRANPEN package: writer of force traces in the granpen-trace v1 CSV
   format (shared/formats/trace-csv.md). Pure C++ and stdio; the caller
   decides which rank writes.
------------------------------------------------------------------------- */

#ifndef LMP_TRACE_WRITER_H
#define LMP_TRACE_WRITER_H

#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace granpen {

struct TraceHeader {
  std::string units;    // "cgs" or "si"
  double v0 = 0.0, D = 0.0, g = 0.0;
  // optional keys, written in this order when set
  std::vector<std::pair<std::string, std::string>> extra;
  std::vector<std::string> columns = {"t", "z", "F"};
};

// The header block (comment lines and the column-name line), newline-terminated.
std::string format_trace_header(const TraceHeader &h);

// One CSV row; values printed with enough digits to round-trip a double's
// first 10 significant figures.
std::string format_trace_row(const std::vector<double> &values);

// Writes a trace, flushing after every `flush_rows` rows so that a killed
// run loses at most that many rows. Appending to an existing trace keeps its
// header and rows.
class TraceWriter {
 public:
  TraceWriter() = default;
  ~TraceWriter();
  TraceWriter(const TraceWriter &) = delete;
  TraceWriter &operator=(const TraceWriter &) = delete;

  // Returns false (errno set) when the file cannot be opened.
  bool open(const std::string &path, const TraceHeader &h, bool append, int flush_rows = 1);

  // Continue a trace from time t_resume: keep the existing header and the rows with
  // t <= t_resume, drop (and count in `dropped`) the rows after it, which the resumed
  // run writes again, then append. A missing or empty file starts afresh with h.
  // The kept part is rewritten through a temporary file and rename, so an interrupted
  // resume never leaves a half-written trace.
  bool open_resume(const std::string &path, const TraceHeader &h, double t_resume, long &dropped,
                   int flush_rows = 1);
  void row(const std::vector<double> &values);
  void close();
  bool is_open() const { return fp_ != nullptr; }

 private:
  std::FILE *fp_ = nullptr;
  int flush_rows_ = 1;
  int pending_ = 0;
};

}    // namespace granpen

#endif
