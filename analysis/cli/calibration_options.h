// granpen calibration: its command line as a typed struct and its parse function, words ->
// options (pure: no file read, nothing written or printed, nothing thrown but UsageError,
// subcommand.h), and its run function (calibration_cmd.cpp: calls the library and writes; the
// process exit status). What the parse accepts satisfies the checks listed with the
// struct (tests/fuzz/fuzz_cli_body.h asserts them on every accepted parse).
#ifndef GRANPEN_CLI_CALIBRATION_OPTIONS_H
#define GRANPEN_CLI_CALIBRATION_OPTIONS_H

#include "subcommand.h"

#include <string>
#include <vector>

namespace granpen {
namespace cli {

// granpen calibration SWEEP_DIR. Checks: sweep not empty; zmin < zmax, both finite; out
// not empty (SWEEP_DIR when not given).
struct CalibrationOptions : ParsedCommand {
  std::string sweep, out;
  double zmin = 1.0, zmax = 3.0;
};
CalibrationOptions parse_calibration(int argc, char **argv);
int run_calibration(const CalibrationOptions &o);

}    // namespace cli
}    // namespace granpen

#endif
