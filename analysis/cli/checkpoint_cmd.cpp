// granpen checkpoint RESTART...: the sweep runner's own test (sweep_runner.h,
// complete_checkpoint), one line a file, for scripts (validation/campaign.sh --status).
#include "checkpoint_options.h"
#include "subcommand.h"
#include "subcommands.h"
#include "sweep_runner.h"

#include <cstdio>

int granpen::cli::run_checkpoint(const CheckpointOptions &o)
{
  int status = EXIT_OK;
  for (const std::string &f : o.files) {
    const bool complete = complete_checkpoint(f);
    std::printf("%s %s\n", complete ? "complete" : "incomplete", f.c_str());
    if (!complete) status = EXIT_FAILED;
  }
  return status;
}
int granpen::cli::checkpoint(int argc, char **argv) { return run_parsed(parse_checkpoint, run_checkpoint, argc, argv); }
