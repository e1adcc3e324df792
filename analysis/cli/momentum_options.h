// granpen momentum: its command line as a typed struct and its parse function, words ->
// options (pure: no file read, nothing written or printed, nothing thrown but UsageError,
// subcommand.h), and its run function (momentum_cmd.cpp: calls the library and writes; the
// process exit status). What the parse accepts satisfies the checks listed with the
// struct (tests/fuzz/fuzz_cli_body.h asserts them on every accepted parse).
#ifndef GRANPEN_CLI_MOMENTUM_OPTIONS_H
#define GRANPEN_CLI_MOMENTUM_OPTIONS_H

#include "dump_options.h"    // RodOptions, NOT_GIVEN, the shared options

#include <string>
#include <vector>

namespace granpen {
namespace cli {

// granpen momentum DUMP... --trace TRACE. Checks: at least one dump; trace not empty;
// out_dir not empty; the numbers finite, or NaN for not given (then the trace header's or
// a default: core/momentum_study.h's momentum_study_params); D, rho_g, dt, mthreshold NaN
// or > 0, mu NaN or >= 0; thresholds empty or F1 > F2 > F3 > F4 > 0; push_step given with
// by_time; rod as finish_rod_options; periodic xy, x, y or none, as px, py.
struct MomentumOptions : ParsedCommand {
  std::vector<std::string> dumps;
  std::string trace, out_dir = ".";
  RodOptions rod;
  double D = NOT_GIVEN, rho_g = NOT_GIVEN, mu = NOT_GIVEN, z_s = NOT_GIVEN, dt = NOT_GIVEN;
  std::vector<double> thresholds;    // --thresholds F1 F2 F3 F4, or empty (the paper's)
  double mthreshold = NOT_GIVEN;
  bool by_time = false;              // --push-step given
  long long push_step = 0;
  std::string periodic = "xy";
  bool px = true, py = true;
};
MomentumOptions parse_momentum(int argc, char **argv);
int run_momentum(const MomentumOptions &o);

}    // namespace cli
}    // namespace granpen

#endif
