// granpen sweep SPEC [options]: run a sweep of pours and pushes (see sweep/sweep_spec.h).
#include "atomic_file.h"
#include "subcommand.h"
#include "subcommands.h"
#include "sweep_runner.h"
#include "sweep_spec.h"
#include "text_util.h"
#include "errors.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>
#include <unistd.h>

namespace {

std::string g_inputs;

bool file_exists(const std::string &p) { return access(p.c_str(), R_OK) == 0; }
bool preset_exists(const std::string &name) { return file_exists(g_inputs + "/presets/" + name + ".lmp"); }
bool observe_exists(const std::string &name) { return file_exists(g_inputs + "/observe/" + name + ".lmp"); }

const char *HELP =
    "usage: granpen sweep SPEC [--jobs N] [--out DIR] [--checkpoint STEPS] [--mpirun PROG --ranks N]\n"
    "                          [--only K] [--slurm FILE] [--plan] [--lmp PATH] [--inputs DIR]\n"
    "Runs the pours and pushes a sweep file asks for: each distinct bed (preset, mu, seed) is\n"
    "poured once, every push (v0, g, D) branches from its saved bed, up to N runs at once\n"
    "(default: the number of cores). Output in DIR/NAME (default runs/NAME): beds/, traces/\n"
    "(granpen-trace v1), logs/ and manifest.json (every parameter, seed, versions, wall time,\n"
    "phi_0, z_s, status). Rerunning skips finished runs and resumes interrupted pushes from\n"
    "their checkpoints (every STEPS steps, default 5000). --slurm writes a job-array script\n"
    "for a cluster instead of running; --only K runs planned run K alone (what each array task\n"
    "does); --plan lists the planned runs. Sweep file format: analysis/sweep/sweep_spec.h,\n"
    "example: inputs/sweeps/v0_bench.sweep. lmp_granpen and inputs/ come from the environment\n"
    "that ./granpen sets (GRANPEN_LMP, GRANPEN_INPUTS) unless given.\n";

}    // namespace

int granpen::cli::sweep(int argc, char **argv)
{
  Command cmd("sweep", HELP);
  RunnerOptions opt;
  const char *env;
  opt.lmp = (env = std::getenv("GRANPEN_LMP")) ? env : "lmp_granpen";
  opt.inputs = (env = std::getenv("GRANPEN_INPUTS")) ? env : "inputs";
  opt.out_root = (env = std::getenv("GRANPEN_RUNS")) ? env : "runs";
  opt.jobs = (int) std::max(1u, std::thread::hardware_concurrency());
  std::string spec_path, slurm;
  bool plan_only = false;
  auto &app = cmd.app;
  app.add_option("spec", spec_path, "the sweep file")->required();
  app.add_option("--jobs", opt.jobs, "runs at once, 1 or more (default: the number of cores)")->check(CLI::Range(1, 1000000).description(""))->type_name("N");
  app.add_option("--out", opt.out_root, "output root: DIR/NAME (default runs)")->check(file_name())->type_name("DIR");
  app.add_option("--checkpoint", opt.checkpoint, "push checkpoint every STEPS steps (default 5000)")->check(CLI::Range(1, 1000000).description(""))
      ->type_name("STEPS");
  app.add_option("--mpirun", opt.mpirun, "run each simulation through this MPI launcher")->type_name("PROG");
  app.add_option("--ranks", opt.ranks, "MPI ranks per run (with --mpirun)")->check(CLI::Range(1, 1000000).description(""))->type_name("N");
  app.add_option("--only", opt.only_index, "run planned run K alone (what each SLURM array task does)")
      ->check(CLI::Range(0, 1000000).description(""))->type_name("K");
  app.add_option("--slurm", slurm, "write a SLURM job-array script instead of running")->check(file_name())
      ->type_name("FILE");
  app.add_option("--lmp", opt.lmp, "lmp_granpen (default $GRANPEN_LMP)")->type_name("PATH");
  app.add_option("--inputs", opt.inputs, "the decks' folder (default $GRANPEN_INPUTS)")->type_name("DIR");
  app.add_flag("--plan", plan_only, "list the planned runs");
  if (!cmd.parse(argc, argv)) return EXIT_OK;
  if (!slurm.empty()) refuse_overwriting_inputs(slurm, "--slurm", {spec_path});
  g_inputs = opt.inputs;
  try {
    std::string text;
    if (!read_text_file(spec_path, text)) throw InputError(spec_path + ": cannot open sweep file");
    SweepSpec spec = parse_sweep(text, spec_path, preset_exists, observe_exists);
    if (plan_only) {
      int k = 0;
      for (const auto &r : plan_sweep(spec))
        std::printf("%3d %s %s\n", k++, r.kind == PlannedRun::POUR ? "pour" : "push", r.id.c_str());
      return 0;
    }
    if (!slurm.empty()) {
      char self[4096];
      ssize_t n = readlink("/proc/self/exe", self, sizeof(self) - 1);
      const std::string cli = n > 0 ? std::string(self, n) : "granpen-cli";
      if (opt.mpirun.empty()) opt.mpirun = "srun";
      // the jobs run wherever SLURM starts them: give them absolute paths
      // (lmp_granpen given as a bare name is looked up on the cluster's PATH)
      for (std::string *p : {&opt.out_root, &opt.inputs, &opt.lmp, &spec.path}) {
        if (p->empty() || (*p)[0] == '/' || (p == &opt.lmp && p->find('/') == std::string::npos)) continue;
        char cwd[4096];
        if (getcwd(cwd, sizeof(cwd))) *p = std::string(cwd) + "/" + *p;
      }
      write_slurm_script(spec, opt, cli, slurm);
      std::printf("granpen sweep: wrote %s (submit it on the cluster: bash %s)\n", slurm.c_str(), slurm.c_str());
      return 0;
    }
    return run_sweep(spec, opt);
  } catch (InputError &e) {
    std::fprintf(stderr, "granpen sweep: %s\n", e.what());
    return 2;
  }
}
