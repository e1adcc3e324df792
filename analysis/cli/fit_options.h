// granpen fit: its command line as a typed struct and its parse function, words ->
// options (pure: no file read, nothing written or printed, nothing thrown but UsageError,
// subcommand.h), and its run function (fit_cmd.cpp: calls the library and writes; the
// process exit status). What the parse accepts satisfies the checks listed with the
// struct (tests/fuzz/fuzz_cli_body.h asserts them on every accepted parse).
#ifndef GRANPEN_CLI_FIT_OPTIONS_H
#define GRANPEN_CLI_FIT_OPTIONS_H

#include "ensemble_args.h"    // EnsembleOptions
#include "fit_tables.h"    // FitWindow
#include "subcommand.h"

#include <limits>
#include <string>
#include <vector>

namespace granpen {
namespace cli {

// granpen fit TRACE... Checks: at least one trace; window.tmin -1 (not given) or > 0 and
// finite, and then zmin at its default 3 (--zmin and --tmin exclude each other);
// without tmin, zmin < zmax (zmax may be +inf); window.mu, rho_g 0 (from the header) or
// > 0; json, csv empty (not written) or a name; ensemble as EnsembleOptions
// (ensemble_args.h); ensemble_csv empty, or a name and then ensemble.on.
struct FitOptions : ParsedCommand {
  std::vector<std::string> traces;
  FitWindow window = {3.0, std::numeric_limits<double>::infinity(), -1.0, 0.0, 0.0};
  std::string json, csv;
  EnsembleOptions ensemble;
  std::string ensemble_csv;
};
FitOptions parse_fit(int argc, char **argv);
int run_fit(const FitOptions &o);

}    // namespace cli
}    // namespace granpen

#endif
