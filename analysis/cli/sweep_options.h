// granpen sweep: its command line as a typed struct and its parse function, words ->
// options (pure: no file read, nothing written or printed, nothing thrown but UsageError,
// subcommand.h), and its run function (sweep_cmd.cpp: calls the library and writes; the
// process exit status). What the parse accepts satisfies the checks listed with the
// struct (tests/fuzz/fuzz_cli_body.h asserts them on every accepted parse).
#ifndef GRANPEN_CLI_SWEEP_OPTIONS_H
#define GRANPEN_CLI_SWEEP_OPTIONS_H

#include "subcommand.h"
#include "sweep_runner.h"    // RunnerOptions

#include <string>
#include <vector>

namespace granpen {
namespace cli {

// granpen sweep SPEC. Checks: spec not empty; runner.jobs, checkpoint, ranks >= 1;
// runner.only_index -1 (all runs) or >= 0; runner.progress_seconds 1 to 86400;
// runner.out_root not empty; slurm empty or a name. Defaults from the environment: GRANPEN_LMP, GRANPEN_INPUTS, GRANPEN_RUNS.
struct SweepOptions : ParsedCommand {
  std::string spec;
  RunnerOptions runner;
  std::string slurm;
  bool plan_only = false;
};
SweepOptions parse_sweep_command(int argc, char **argv);
int run_sweep_command(const SweepOptions &o);

}    // namespace cli
}    // namespace granpen

#endif
