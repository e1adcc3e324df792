// granpen gap: its command line as a typed struct and its parse function, words ->
// options (pure: no file read, nothing written or printed, nothing thrown but UsageError,
// subcommand.h), and its run function (gap_cmd.cpp: calls the library and writes; the
// process exit status). What the parse accepts satisfies the checks listed with the
// struct (tests/fuzz/fuzz_cli_body.h asserts them on every accepted parse).
#ifndef GRANPEN_CLI_GAP_OPTIONS_H
#define GRANPEN_CLI_GAP_OPTIONS_H

#include "gap_diagnosis.h"    // GapOptions
#include "subcommand.h"

#include <string>
#include <vector>

namespace granpen {
namespace cli {

// granpen gap. Checks, unless list_effects: gap.scenario not empty, and either gap.real
// and gap.out, or (prepare_only or slurm) and v0; gap.runner.jobs 1 to 1024,
// runner.ranks >= 1.
struct GapCommandOptions : ParsedCommand {
  GapOptions gap;
  bool list_effects = false;
};
GapCommandOptions parse_gap(int argc, char **argv);
int run_gap_command(const GapCommandOptions &o);

}    // namespace cli
}    // namespace granpen

#endif
