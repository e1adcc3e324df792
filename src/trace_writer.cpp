/* ----------------------------------------------------------------------
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
   GRANPEN package: granpen-trace v1 writer.
------------------------------------------------------------------------- */

#include "trace_writer.h"

#include <cstdio>
#include <cstdlib>
#include <sys/stat.h>

namespace granpen {

static std::string num(double v)
{
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.10g", v);
  return buf;
}

std::string format_trace_header(const TraceHeader &h)
{
  std::string s = "# granpen-trace v1\n";
  s += "# units = " + h.units + "\n";
  s += "# v0 = " + num(h.v0) + "\n";
  s += "# D = " + num(h.D) + "\n";
  s += "# g = " + num(h.g) + "\n";
  for (const auto &kv : h.extra) s += "# " + kv.first + " = " + kv.second + "\n";
  for (std::size_t i = 0; i < h.columns.size(); ++i) s += (i ? "," : "") + h.columns[i];
  s += "\n";
  return s;
}

std::string format_trace_row(const std::vector<double> &values)
{
  std::string s;
  for (std::size_t i = 0; i < values.size(); ++i) s += (i ? "," : "") + num(values[i]);
  s += "\n";
  return s;
}

TraceWriter::~TraceWriter() { close(); }

bool TraceWriter::open(const std::string &path, const TraceHeader &h, bool append, int flush_rows)
{
  close();
  struct stat st;
  const bool has_content = (stat(path.c_str(), &st) == 0) && st.st_size > 0;
  fp_ = std::fopen(path.c_str(), append ? "a" : "w");
  if (!fp_) return false;
  flush_rows_ = flush_rows < 1 ? 1 : flush_rows;
  pending_ = 0;
  if (!(append && has_content)) std::fputs(format_trace_header(h).c_str(), fp_);
  std::fflush(fp_);
  return true;
}

bool TraceWriter::open_resume(const std::string &path, const TraceHeader &h, double t_resume,
                              long &dropped, int flush_rows)
{
  dropped = 0;
  std::FILE *in = std::fopen(path.c_str(), "r");
  if (!in) return open(path, h, false, flush_rows);

  // keep comment lines, the column line and rows up to t_resume; t is the column named "t"
  std::string kept, line;
  int tcol = -1;
  char buf[4096];
  const double tol = 1.0e-9 * (t_resume > 0.0 ? t_resume : 1.0);
  while (std::fgets(buf, sizeof(buf), in)) {
    line = buf;
    // a last line without its '\n' was cut short (a kill or a full disk): never kept
    if (!line.empty() && line.back() != '\n' && std::feof(in)) {
      if (tcol >= 0) ++dropped;
      continue;
    }
    if (line.empty() || line[0] == '#' || line == "\n") {
      kept += line;
      continue;
    }
    if (tcol < 0) {    // the column-name line
      int col = 0;
      std::size_t start = 0;
      while (true) {
        std::size_t end = line.find_first_of(",\r\n", start);
        if (line.compare(start, end - start, "t") == 0) tcol = col;
        if (end == std::string::npos || line[end] != ',') break;
        start = end + 1;
        ++col;
      }
      kept += line;
      if (tcol < 0) tcol = 0;
      continue;
    }
    std::size_t start = 0;
    for (int c = 0; c < tcol && start != std::string::npos; ++c) {
      start = line.find(',', start);
      if (start != std::string::npos) ++start;
    }
    const double t = start == std::string::npos ? 0.0 : std::strtod(line.c_str() + start, nullptr);
    if (t <= t_resume + tol) kept += line;
    else ++dropped;
  }
  std::fclose(in);
  if (kept.empty()) return open(path, h, false, flush_rows);

  const std::string tmp = path + ".resume.tmp";
  std::FILE *out = std::fopen(tmp.c_str(), "w");
  if (!out) return false;
  const bool written = std::fputs(kept.c_str(), out) >= 0;
  if (std::fclose(out) != 0 || !written || std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    return false;
  }
  return open(path, h, true, flush_rows);
}

void TraceWriter::row(const std::vector<double> &values)
{
  if (!fp_) return;
  std::fputs(format_trace_row(values).c_str(), fp_);
  if (++pending_ >= flush_rows_) {
    std::fflush(fp_);
    pending_ = 0;
  }
}

void TraceWriter::close()
{
  if (fp_) std::fclose(fp_);
  fp_ = nullptr;
}

}    // namespace granpen
