// granpen sweep: its command line (sweep_options.h).
#include "sweep_options.h"

#include "args.h"

#include <algorithm>
#include <cstdlib>
#include <thread>

namespace {

const char *HELP =
    "usage: granpen sweep SPEC [--jobs N] [--out DIR] [--checkpoint STEPS] [--mpirun PROG --ranks N]\n"
    "                          [--only K] [--slurm FILE] [--plan] [--lmp PATH] [--inputs DIR]\n"
    "                          [--progress SECONDS]\n"
    "Runs the pours and pushes a sweep file asks for: each distinct bed (preset, mu, seed) is\n"
    "poured once, every push (v0, g, D) branches from its saved bed, up to N runs at once\n"
    "(default: the number of cores). Output in DIR/NAME (default runs/NAME): beds/, traces/\n"
    "(granpen-trace v1), logs/ and manifest.json (every parameter, seed, versions, wall time,\n"
    "phi_0, z_s, status). Rerunning skips finished runs and resumes interrupted pushes from\n"
    "their checkpoints (every STEPS steps, default 5000). --slurm writes a job-array script\n"
    "for a cluster instead of running; --only K runs planned run K alone (what each array task\n"
    "does); --plan lists the planned runs. A progress line every SECONDS (default 5): runs done,\n"
    "each running push's depth and, once it has moved, its own time left at its rate, and an\n"
    "ETA. Sweep file format: analysis/sweep/sweep_spec.h,\n"
    "example: inputs/sweeps/v0_bench.sweep. lmp_granpen and inputs/ come from the environment\n"
    "that ./granpen sets (GRANPEN_LMP, GRANPEN_INPUTS) unless given.\n"
    "Exit status: 0 when every run is done (or the script or plan is written), 1 when a run\n"
    "failed or an input (the sweep file, lmp_granpen, inputs/) or output is bad, 2 for a\n"
    "usage error.\n";

}    // namespace

granpen::cli::SweepOptions granpen::cli::parse_sweep_command(int argc, char **argv)
{
  Command cmd("sweep", HELP);
  SweepOptions o;
  RunnerOptions &opt = o.runner;
  const char *env;
  opt.lmp = (env = std::getenv("GRANPEN_LMP")) ? env : "lmp_granpen";
  opt.inputs = (env = std::getenv("GRANPEN_INPUTS")) ? env : "inputs";
  opt.out_root = (env = std::getenv("GRANPEN_RUNS")) && *env ? env : "runs";
  opt.jobs = (int) std::max(1u, std::thread::hardware_concurrency());
  auto &app = cmd.app;
  app.add_option("spec", o.spec, "the sweep file")->required()->check(file_name());
  app.add_option("--jobs", opt.jobs, "runs at once, 1 or more (default: the number of cores)")->check(whole_number(1, 1000000))->type_name("N");
  app.add_option("--out", opt.out_root, "output root: DIR/NAME (default runs)")->check(file_name())->type_name("DIR");
  app.add_option("--checkpoint", opt.checkpoint, "push checkpoint every STEPS steps (default 5000)")->check(whole_number(1, 1000000))
      ->type_name("STEPS");
  app.add_option("--mpirun", opt.mpirun, "run each simulation through this MPI launcher")->type_name("PROG");
  app.add_option("--ranks", opt.ranks, "MPI ranks per run (with --mpirun)")->check(whole_number(1, 1000000))->type_name("N");
  app.add_option("--only", opt.only_index, "run planned run K alone (what each SLURM array task does)")
      ->check(whole_number(0, 1000000))->type_name("K");
  app.add_option("--slurm", o.slurm, "write a SLURM job-array script instead of running")->check(file_name())
      ->type_name("FILE");
  app.add_option("--lmp", opt.lmp, "lmp_granpen (default $GRANPEN_LMP)")->check(file_name())->type_name("PATH");
  app.add_option("--inputs", opt.inputs, "the decks' folder (default $GRANPEN_INPUTS)")->check(file_name())->type_name("DIR");
  app.add_flag("--plan", o.plan_only, "list the planned runs");
  int progress = 5;
  app.add_option("--progress", progress, "a progress line every SECONDS, 1 to 86400 (default 5)")
      ->check(whole_number(1, 86400))->type_name("SECONDS");
  cmd.parse(argc, argv, o.help);
  opt.progress_seconds = progress;
  return o;
}
