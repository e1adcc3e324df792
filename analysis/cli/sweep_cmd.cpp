// granpen sweep SPEC [options]: run a sweep of pours and pushes (see sweep/sweep_spec.h).
#include "args.h"
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

const granpen::cli::Usage usage{"sweep", HELP};

}    // namespace

int granpen::cli::sweep(int argc, char **argv)
{
  if (argc < 1) return usage.no_arguments();
  if (!std::strcmp(argv[0], "--help")) return usage.help_asked();
  RunnerOptions opt;
  const char *env;
  opt.lmp = (env = std::getenv("GRANPEN_LMP")) ? env : "lmp_granpen";
  opt.inputs = (env = std::getenv("GRANPEN_INPUTS")) ? env : "inputs";
  opt.out_root = (env = std::getenv("GRANPEN_RUNS")) ? env : "runs";
  opt.jobs = (int) std::max(1u, std::thread::hardware_concurrency());
  std::string spec_path = argv[0], slurm;
  bool plan_only = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() {
      std::string v;
      if (!next_value(argc, argv, i, v)) std::exit(usage.bare(needs_value(a)));
      return v;
    };
    auto integer = [&](int lo) {    // lo to 1000000
      const std::string v = value();
      int n;
      if (!integer_arg(v, lo, 1000000, n)) std::exit(usage.bare(needs_integer(a, lo, v)));
      return n;
    };
    if (a == "--jobs") opt.jobs = integer(1);
    else if (a == "--out") opt.out_root = value();
    else if (a == "--checkpoint") opt.checkpoint = integer(1);
    else if (a == "--mpirun") opt.mpirun = value();
    else if (a == "--ranks") opt.ranks = integer(1);
    else if (a == "--only") opt.only_index = integer(0);
    else if (a == "--slurm") slurm = value();
    else if (a == "--lmp") opt.lmp = value();
    else if (a == "--inputs") opt.inputs = value();
    else if (a == "--plan") plan_only = true;
    else return usage.with_help(unknown_option(a));
  }
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
