// granpen check: its command line (check_options.h).
#include "check_options.h"

#include "args.h"

namespace {

const char *HELP =
    "usage: granpen check TRACE-OR-FOLDER...\n"
    "A folder stands for every *.csv in it (as for fit, collapse and gap).\n"
    "Reads each trace as every granpen tool does, rejecting malformed input with the\n"
    "file and line, and prints: units, v0, D, g, rows, depth range and largest F (cgs).\n"
    "Exit status 0 when every file is valid, 1 otherwise, 2 for a usage error.\n";

}    // namespace

granpen::cli::CheckOptions granpen::cli::parse_check(int argc, char **argv)
{
  Command cmd("check", HELP);
  CheckOptions o;
  cmd.app.add_option("traces", o.traces, "trace files, or folders of them")->required();
  cmd.parse(argc, argv, o.help);
  return o;
}
