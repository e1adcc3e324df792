// granpen momentum: its command line as a typed struct and its parse function, words ->
// options (pure: no file read, nothing written or printed, nothing thrown but UsageError,
// subcommand.h), and its run function (momentum_cmd.cpp: calls the library and writes; the
// process exit status). What the parse accepts satisfies the checks listed with the
// struct (tests/fuzz/fuzz_cli_body.h asserts them on every accepted parse).
#ifndef GRANPEN_CLI_MOMENTUM_OPTIONS_H
#define GRANPEN_CLI_MOMENTUM_OPTIONS_H

#include "dump_options.h"    // RodOptions, periodic_axes

#include <string>
#include <vector>

namespace granpen {
namespace cli {

// granpen momentum DUMP... --trace TRACE. Checks: at least one dump; --trace given;
// out_dir not empty; the numbers given finite, --D, --rho, --dt, --mthreshold > 0, --mu
// >= 0; --thresholds F1 > F2 > F3 > F4 > 0; --push-step a whole number; rod.rod_type
// >= 1; periodic xy, x, y or none, as px, py.
struct MomentumOptions : ParsedCommand {
  ParsedArgs args;
  RodOptions rod;
  std::string out_dir, periodic;
  bool px = true, py = true;
};
MomentumOptions parse_momentum(int argc, char **argv);
int run_momentum(const MomentumOptions &o);

}    // namespace cli
}    // namespace granpen

#endif
