// granpen check TRACE...: validate traces the way every granpen tool reads them.
#include "subcommand.h"
#include "subcommands.h"
#include "trace_files.h"
#include "trace_reader.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

namespace {

const char *HELP =
    "usage: granpen check TRACE-OR-FOLDER...\n"
    "A folder stands for every *.csv in it (as for fit, collapse and gap).\n"
    "Reads each trace as every granpen tool does, rejecting malformed input with the\n"
    "file and line, and prints: units, v0, D, g, rows, depth range and largest F (cgs).\n"
    "Exit status 0 when every file is valid, 1 otherwise, 2 for a usage error.\n";

}    // namespace

int granpen::cli::check(int argc, char **argv)
{
  Command cmd("check", HELP);
  std::vector<std::string> inputs;
  cmd.app.add_option("traces", inputs, "trace files, or folders of them")->required();
  if (!cmd.parse(argc, argv)) return EXIT_OK;
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
