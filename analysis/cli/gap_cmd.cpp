// granpen gap --real DIR --scenario NAME --out DIR: the sim-to-real gap diagnosis
// (gap/gap_diagnosis.h); --prepare-only runs (or resumes) the cache's simulations.
#include "atomic_file.h"
#include "command.h"
#include "effects.h"
#include "gap_diagnosis.h"
#include "subcommands.h"
#include "trace_reader.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>

namespace {

const char *HELP =
    "usage: granpen gap --real DIR --scenario NAME --out DIR [--effects LIST] [--jobs N] [--cache DIR]\n"
    "       granpen gap --prepare-only --scenario NAME --v0 \"50 100 200\" [--effects LIST] [--jobs N] [--cache DIR]\n"
    "       granpen gap --slurm FILE --scenario paper --v0 \"40 80 160\" [--jobs N --ranks R] [--cache DIR]\n"
    "Where do measured force traces (DIR: granpen-trace v1 files, one or more runs per speed,\n"
    "cgs or SI) and the simulation of the same set-up (the preset NAME) differ, which\n"
    "unmodelled effect causes it, and how far the gap shrinks once it is added.\n"
    "  1. simulates (or takes from the cache) the baseline and every candidate effect at its\n"
    "     reference magnitudes, at the measured speeds, two seeds each;\n"
    "  2. aligns every run's depth origin by its force onset, bins F on a common grid and\n"
    "     compares ensembles: observables per regime (peak, transient, linear) with z-scores,\n"
    "     the gap curve with its noise band, the overall gap G (shared/formats/gap-metric.md);\n"
    "  3. fits each effect's magnitude to the gap, scores how much it explains, checks it by\n"
    "     leaving one speed out, and decides: none, explained (top effect) or unexplained;\n"
    "  4. simulates the top effect at its fitted magnitude on fresh seeds and reports the gap\n"
    "     before and after, overall, per regime and at the held-out speed.\n"
    "Output (written to OUT.partial, then moved to OUT): diagnosis.json, report.md with\n"
    "figures, baseline/ and corrected/ (the simulated traces used, trace CSV v1).\n"
    "options:\n"
    "  --effects LIST  comma-separated candidates (default: all of them)\n"
    "  --jobs N        simulations at once (default: the number of cores), every sweep's\n"
    "                  runs in one pool\n"
    "  --sweep-by-sweep  run the sweeps one after another, each with its own N (the\n"
    "                  runner's old way: for bench/pool_vs_sweeps.sh)\n"
    "  --cache DIR     simulation cache (default $GRANPEN_RUNS/gap_cache); interrupted, a\n"
    "                  diagnosis resumes from it; a finished one reruns without simulating\n"
    "  --lmp PATH, --inputs DIR   lmp_granpen and the decks (default: as ./granpen sets them)\n"
    "  --prepare-only  only run the simulations the cache needs for --v0 speeds\n"
    "  --fit-only      stop before step 4: the verdict is provisional (diagnosis.json:\n"
    "                  \"confirmed\": false; nothing simulated on fresh seeds), G after = before\n"
    "  --mpirun PROG --ranks R   run each simulation on R MPI ranks (mpirun, srun, ...)\n"
    "  --slurm FILE    write a SLURM script preparing the cache on a cluster (--jobs runs at\n"
    "                  once, R ranks each) and stop; a diagnosis whose simulations would take\n"
    "                  more than 8 core-hours (the paper scenario) asks for this, or --local\n"
    "  --list-effects  the candidate effects, their magnitudes and reference values\n"
    "Exit status: 0 diagnosis written, 1 simulations failed or input unreadable, 2 usage.\n";

}    // namespace

namespace {

void list_effects()
{
  for (const auto &e : granpen::effect_library()) {
    std::printf("%-20s %s\n%-20s magnitude: %s; reference values:", e.name.c_str(), e.what.c_str(), "", e.unit.c_str());
    for (double k : e.knots) std::printf(" %s", granpen::deck_number(k).c_str());
    std::printf("%s\n", e.pour_level ? " (new beds)" : " (push only: the baseline's beds)");
  }
}

}    // namespace

int granpen::cli::gap(int argc, char **argv)
{
  Command cmd("gap", HELP);
  GapOptions opt;
  const char *env;
  opt.runner.lmp = (env = std::getenv("GRANPEN_LMP")) ? env : "lmp_granpen";
  opt.runner.inputs = (env = std::getenv("GRANPEN_INPUTS")) ? env : "inputs";
  opt.cache = std::string((env = std::getenv("GRANPEN_RUNS")) ? env : "runs") + "/gap_cache";
  opt.runner.jobs = (int) std::max(1u, std::thread::hardware_concurrency());
  bool sweep_by_sweep = false, list = false;
  auto &app = cmd.app;
  app.add_option("--real", opt.real, "the measured traces' folder");
  app.add_option("--scenario", opt.scenario, "the preset of the set-up");
  app.add_option("--out", opt.out, "the diagnosis folder");
  app.add_option("--cache", opt.cache, "simulation cache");
  app.add_option("--lmp", opt.runner.lmp, "lmp_granpen");
  app.add_option("--inputs", opt.runner.inputs, "the decks' folder");
  app.add_flag("--prepare-only", opt.prepare_only, "only run the simulations the cache needs");
  app.add_flag("--local", opt.local, "run a large diagnosis here anyway");
  app.add_flag("--fit-only", opt.fit_only, "stop before the confirmation runs");
  app.add_flag("--sweep-by-sweep", sweep_by_sweep, "run the sweeps one after another");
  app.add_option("--slurm", opt.slurm, "write a SLURM script and stop");
  app.add_option("--mpirun", opt.runner.mpirun, "MPI launcher");
  app.add_option("--ranks", opt.runner.ranks, "MPI ranks per simulation")->check(CLI::Range(1, 1000000));
  app.add_option("--v0", opt.v0, "speeds for --prepare-only and --slurm, e.g. \"50 100 200\"");
  app.add_option("--effects", opt.effects, "comma-separated candidate effects");
  app.add_option("--jobs", opt.runner.jobs, "simulations at once")->check(CLI::Range(1, 1024));
  app.add_flag("--list-effects", list, "the candidate effects and their magnitudes");
  if (!cmd.parse(argc, argv)) return EXIT_OK;
  if (sweep_by_sweep) opt.runner.pool = false;
  if (list) {
    list_effects();
    return EXIT_OK;
  }
  if (opt.scenario.empty() || (!opt.prepare_only && opt.slurm.empty() && (opt.real.empty() || opt.out.empty())) ||
      ((opt.prepare_only || !opt.slurm.empty()) && opt.v0.empty()))
    throw UsageError("needs --scenario and either --real and --out, or --prepare-only (or --slurm) and --v0");
  if (!opt.out.empty() && !opt.real.empty() && same_file(opt.out, opt.real))
    throw UsageError("--out " + opt.out + " is the input --real " + opt.real + ": refusing to overwrite it");
  try {
    return run_gap(opt);
  } catch (InputError &e) {
    std::fprintf(stderr, "granpen gap: %s\n", e.what());
    return 1;
  }
}
