// granpen convert: its command line as a typed struct and its parse function, words ->
// options (pure: no file read, nothing written or printed, nothing thrown but UsageError,
// subcommand.h), and its run function (convert_cmd.cpp: calls the library and writes; the
// process exit status). What the parse accepts satisfies the checks listed with the
// struct (tests/fuzz/fuzz_cli_body.h asserts them on every accepted parse).
#ifndef GRANPEN_CLI_CONVERT_OPTIONS_H
#define GRANPEN_CLI_CONVERT_OPTIONS_H

#include "subcommand.h"
#include "trace_reader.h"    // AveTimeSpec

#include <string>
#include <vector>

namespace granpen {
namespace cli {

// granpen convert FILE --from ave/time --out TRACE ...
// Checks: in, out not empty; spec.v0, dt, D, g > 0 and finite; spec.sign +1 or -1;
// spec.step0 NaN (not given) or a whole number >= 0; spec.z0 finite; spec.units cgs or
// si; extra: mu, d_g, rho_g, each at most once, with a number > 0.
struct ConvertOptions : ParsedCommand {
  std::string in, out, from = "ave/time";
  AveTimeSpec spec;
  std::vector<std::pair<std::string, std::string>> extra;
};
ConvertOptions parse_convert(int argc, char **argv);
int run_convert(const ConvertOptions &o);

}    // namespace cli
}    // namespace granpen

#endif
