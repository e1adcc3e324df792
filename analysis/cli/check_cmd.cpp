// granpen check TRACE...: validate traces the way every granpen tool reads them.
#include "subcommands.h"
#include "trace_files.h"
#include "trace_reader.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

int granpen::cli::check(int argc, char **argv)
{
  if (argc < 1 || !std::strcmp(argv[0], "--help")) {
    std::puts("usage: granpen check TRACE-OR-FOLDER...\n"
              "A folder stands for every *.csv in it (as for fit, collapse and gap).\n"
              "Reads each trace as every granpen tool does, rejecting malformed input with the\n"
              "file and line, and prints: units, v0, D, g, rows, depth range and largest F (cgs).\n"
              "Exit status 0 when every file is valid, 1 otherwise.");
    return argc < 1 ? 2 : 0;
  }
  std::vector<std::string> problems;
  const auto files = expand_trace_paths(std::vector<std::string>(argv, argv + argc), problems);
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
