// granpen-cli: the post-processor's command-line front end (./granpen SUBCOMMAND).
// A thin layer: every subcommand parses its arguments and calls the analysis library.
#include "trace_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

void usage(std::FILE *out)
{
  std::fputs("usage: granpen SUBCOMMAND [ARGS]\n"
             "subcommands:\n"
             "  check TRACE...   validate force traces (granpen-trace v1) and summarise them\n"
             "  help             this text\n"
             "Run `granpen SUBCOMMAND --help` for a subcommand's options.\n",
             out);
}

int check(int argc, char **argv)
{
  if (argc < 1 || !std::strcmp(argv[0], "--help")) {
    std::puts("usage: granpen check TRACE...\n"
              "Reads each trace as every granpen tool does, rejecting malformed input with the\n"
              "file and line, and prints: units, v0, D, g, rows, depth range and largest F (cgs).\n"
              "Exit status 0 when every file is valid, 1 otherwise.");
    return argc < 1 ? 2 : 0;
  }
  int bad = 0;
  for (int i = 0; i < argc; ++i) {
    try {
      auto tr = granpen::to_cgs(granpen::read_trace(argv[i]));
      double fmax = 0.0;
      for (double f : tr.F) fmax = std::max(fmax, f);
      std::printf("%s: ok: v0 = %g cm/s, D = %g cm, g = %g cm/s^2, %zu rows, z from %.4g to %.4g cm, "
                  "max F = %.6g dyne\n",
                  argv[i], tr.v0, tr.D, tr.g, tr.t.size(), tr.z.front(), tr.z.back(), fmax);
    } catch (granpen::InputError &e) {
      std::fprintf(stderr, "granpen check: %s\n", e.what());
      ++bad;
    }
  }
  return bad ? 1 : 0;
}

}    // namespace

int main(int argc, char **argv)
{
  if (argc < 2 || !std::strcmp(argv[1], "help") || !std::strcmp(argv[1], "--help")) {
    usage(stdout);
    return argc < 2 ? 2 : 0;
  }
  const std::string sub = argv[1];
  if (sub == "check") return check(argc - 2, argv + 2);
  std::fprintf(stderr, "granpen: unknown subcommand '%s'\n", sub.c_str());
  usage(stderr);
  return 2;
}
