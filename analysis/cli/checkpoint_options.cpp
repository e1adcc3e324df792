// granpen checkpoint: its command line (checkpoint_options.h).
#include "checkpoint_options.h"

#include "args.h"

namespace {

const char *HELP =
    "usage: granpen checkpoint RESTART...\n"
    "Whether each LAMMPS checkpoint (a push's TRACE.a.restart or TRACE.b.restart, a pour's\n"
    "NAME.pour.STEP.restart) was written to its end, by the test the sweep runner resumes by:\n"
    "one cut short by a kill or a full disk, missing or unreadable is incomplete and never\n"
    "resumed from (docs/sweeps.md). Prints one line a file: 'complete FILE' or 'incomplete FILE'.\n"
    "Exit status 0 when every file is complete, 1 otherwise, 2 for a usage error.\n";

}    // namespace

granpen::cli::CheckpointOptions granpen::cli::parse_checkpoint(int argc, char **argv)
{
  Command cmd("checkpoint", HELP);
  CheckpointOptions o;
  cmd.app.add_option("files", o.files, "LAMMPS restart files (checkpoints)")->required()->check(file_name());
  cmd.parse(argc, argv, o.help);
  return o;
}
