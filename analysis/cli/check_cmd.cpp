// granpen check TRACE...: validate traces the way every granpen tool reads them.
#include "check_options.h"
#include "subcommands.h"
#include "trace_files.h"
#include "trace_reader.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

int granpen::cli::run_check(const CheckOptions &o)
{
  const std::vector<std::string> &inputs = o.traces;
  std::vector<std::string> problems;
  const auto files = expand_trace_paths(inputs, problems);
  for (const auto &m : problems) std::fprintf(stderr, "granpen check: %s\n", m.c_str());
  int bad = (int) problems.size();
  for (const auto &file : files) {
    try {
      const auto s = to_cgs(scan_trace(file));    // streamed: memory independent of the file's size
      const double fmax = std::max(0.0, s.F_max);
      std::printf("%s: ok: v0 = %g cm/s, D = %g cm, g = %g cm/s^2, %zu rows, z from %.4g to %.4g cm, "
                  "max F = %.6g dyne\n",
                  file.c_str(), s.header.v0, s.header.D, s.header.g, s.rows, s.z_first, s.z_last, fmax);
    } catch (InputError &e) {
      std::fprintf(stderr, "granpen check: %s\n", e.what());
      ++bad;
    }
  }
  return bad ? 1 : 0;
}

int granpen::cli::check(int argc, char **argv) { return run_parsed(parse_check, run_check, argc, argv); }
