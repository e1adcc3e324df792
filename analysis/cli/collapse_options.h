// granpen collapse: its command line as a typed struct and its parse function, words ->
// options (pure: no file read, nothing written or printed, nothing thrown but UsageError,
// subcommand.h), and its run function (collapse_cmd.cpp: calls the library and writes; the
// process exit status). What the parse accepts satisfies the checks listed with the
// struct (tests/fuzz/fuzz_cli_body.h asserts them on every accepted parse).
#ifndef GRANPEN_CLI_COLLAPSE_OPTIONS_H
#define GRANPEN_CLI_COLLAPSE_OPTIONS_H

#include "collapse_tables.h"    // DepthTerm, CollapseParams
#include "ensemble_args.h"    // EnsembleOptions
#include "subcommand.h"

#include <string>
#include <vector>

namespace granpen {
namespace cli {

// granpen collapse TRACE-OR-FOLDER... Checks: at least one trace; depth.kz_zmin <
// kz_zmax (kz_zmax may be +inf, kz_zmin finite); depth.alpha, mu, rho_g 0 (not given) or
// > 0; params.band, tbin > 0 and finite, params.zmin finite; csv, json empty or a name;
// ensemble as EnsembleOptions (ensemble_args.h).
struct CollapseOptions : ParsedCommand {
  std::vector<std::string> traces;
  DepthTerm depth;
  CollapseParams params;
  std::string csv, json;
  EnsembleOptions ensemble;
};
CollapseOptions parse_collapse(int argc, char **argv);
int run_collapse(const CollapseOptions &o);

}    // namespace cli
}    // namespace granpen

#endif
