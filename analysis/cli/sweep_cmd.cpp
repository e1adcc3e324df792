// granpen sweep SPEC [options]: run a sweep of pours and pushes (see sweep/sweep_spec.h).
#include "atomic_file.h"
#include "sweep_options.h"
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


}    // namespace

int granpen::cli::run_sweep_command(const SweepOptions &o)
{
  RunnerOptions opt = o.runner;    // --slurm makes its paths absolute
  const std::string &spec_path = o.spec, &slurm = o.slurm;
  const bool plan_only = o.plan_only;
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
  } catch (InputError &e) {    // bad input (the sweep file, lmp_granpen, inputs/): 1, as every subcommand
    std::fprintf(stderr, "granpen sweep: %s\n", e.what());
    return EXIT_FAILED;
  }
}

int granpen::cli::sweep(int argc, char **argv) { return run_parsed(parse_sweep_command, run_sweep_command, argc, argv); }
