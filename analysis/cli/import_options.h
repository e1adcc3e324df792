// granpen import: its command line as a typed struct and its parse function, words ->
// options (pure: no file read, nothing written or printed, nothing thrown but UsageError,
// subcommand.h), and its run function (import_cmd.cpp: calls the library and writes; the
// process exit status). What the parse accepts satisfies the checks listed with the
// struct (tests/fuzz/fuzz_cli_body.h asserts them on every accepted parse).
#ifndef GRANPEN_CLI_IMPORT_OPTIONS_H
#define GRANPEN_CLI_IMPORT_OPTIONS_H

#include "subcommand.h"

#include <string>
#include <vector>

namespace granpen {
namespace cli {

// granpen import FILE-OR-FOLDER... --mapping MAP --out DIR --D D --g G. Checks: at least
// one input; mapping, out_dir not empty; D, g > 0 and finite; v0 0 (not given) or > 0;
// window 0 (the mapping's) or > 0; first_run >= 1; d_g, rho_g, mu empty or a number > 0.
struct ImportOptions : ParsedCommand {
  std::vector<std::string> inputs;
  std::string mapping, out_dir;
  bool si = false;
  double D = 0.0, g = 0.0, v0 = 0.0, window = 0.0;
  std::string v0_table;                                // file -> nominal v0 ("" none)
  double speed_tolerance = 0.0, end_tolerance = 0.0;   // 0: the mapping's
  std::string d_g, rho_g, mu;
  int first_run = 1;
  bool dry_run = false;
};
ImportOptions parse_import(int argc, char **argv);
int run_import(const ImportOptions &o);

}    // namespace cli
}    // namespace granpen

#endif
