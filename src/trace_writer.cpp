/* ----------------------------------------------------------------------
   GRANPEN package: granpen-trace v1 writer.
------------------------------------------------------------------------- */

#include "trace_writer.h"

#include <cstdio>
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
