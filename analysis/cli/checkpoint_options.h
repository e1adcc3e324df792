// granpen checkpoint: its command line as a typed struct and its parse function, words ->
// options (pure: no file read, nothing written or printed, nothing thrown but UsageError,
// subcommand.h), and its run function (checkpoint_cmd.cpp: asks the sweep runner's test and
// prints; the process exit status). What the parse accepts satisfies the checks listed with
// the struct (tests/fuzz/fuzz_cli_body.h asserts them on every accepted parse).
#ifndef GRANPEN_CLI_CHECKPOINT_OPTIONS_H
#define GRANPEN_CLI_CHECKPOINT_OPTIONS_H

#include "subcommand.h"

#include <string>
#include <vector>

namespace granpen {
namespace cli {

// granpen checkpoint RESTART...    Checks: at least one file.
struct CheckpointOptions : ParsedCommand {
  std::vector<std::string> files;
};
CheckpointOptions parse_checkpoint(int argc, char **argv);
int run_checkpoint(const CheckpointOptions &o);

}    // namespace cli
}    // namespace granpen

#endif
