// granpen gap --real DIR --scenario NAME --out DIR: the sim-to-real gap diagnosis
// (gap/gap_diagnosis.h); --prepare-only runs (or resumes) the cache's simulations.
#include "args.h"
#include "effects.h"
#include "gap_diagnosis.h"
#include "gap_errors.h"
#include "subcommands.h"
#include "errors.h"

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

// The diagnosis's progress, as lines: steps and facts on stdout, warnings on stderr, the
// ensembles' numbers on stderr with GRANPEN_GAP_DEBUG set.
void render_progress(const granpen::GapProgress &p)
{
  using granpen::GapProgress;
  switch (p.kind) {
    case GapProgress::STEP: std::printf("granpen gap: [%d/%d] %s\n", p.done, p.total, p.message.c_str()); break;
    case GapProgress::INFO: std::printf("granpen gap: %s\n", p.message.c_str()); break;
    case GapProgress::DETAIL: std::printf("  %s\n", p.message.c_str()); break;
    case GapProgress::WARNING: std::fprintf(stderr, "granpen gap: warning: %s\n", p.message.c_str()); break;
    case GapProgress::DEBUG:
      if (std::getenv("GRANPEN_GAP_DEBUG")) std::fprintf(stderr, "%s\n", p.message.c_str());
      break;
  }
  std::fflush(stdout);
}

}    // namespace

int granpen::cli::gap(int argc, char **argv)
{
  const Usage usage{"gap", HELP};
  if (argc < 1) return usage.no_arguments();
  if (!std::strcmp(argv[0], "--help")) return usage.help_asked();
  GapOptions opt;
  const char *env;
  opt.runner.lmp = (env = std::getenv("GRANPEN_LMP")) ? env : "lmp_granpen";
  opt.runner.inputs = (env = std::getenv("GRANPEN_INPUTS")) ? env : "inputs";
  opt.cache = std::string((env = std::getenv("GRANPEN_RUNS")) ? env : "runs") + "/gap_cache";
  opt.runner.jobs = (int) std::max(1u, std::thread::hardware_concurrency());
  for (int i = 0; i < argc; ++i) {
    const std::string a = argv[i];
    std::string v;
    auto value = [&]() -> std::string {
      if (!next_value(argc, argv, i, v)) std::exit(usage.bare(needs_value(a)));
      return v;
    };
    if (a == "--real") opt.real = value();
    else if (a == "--scenario") opt.scenario = value();
    else if (a == "--out") opt.out = value();
    else if (a == "--cache") opt.cache = value();
    else if (a == "--lmp") opt.runner.lmp = value();
    else if (a == "--inputs") opt.runner.inputs = value();
    else if (a == "--prepare-only") opt.prepare_only = true;
    else if (a == "--local") opt.local = true;
    else if (a == "--fit-only") opt.fit_only = true;
    else if (a == "--sweep-by-sweep") opt.runner.pool = false;
    else if (a == "--slurm") opt.slurm = value();
    else if (a == "--mpirun") opt.runner.mpirun = value();
    else if (a == "--ranks") {
      const std::string r = value();
      if (!integer_arg(r, 1, 1000000, opt.runner.ranks)) return usage.bare(needs_integer("--ranks", 1, r));
    }
    else if (a == "--v0") opt.v0 = value();
    else if (a == "--effects") opt.effects = value();
    else if (a == "--jobs") {
      const std::string j = value();
      if (!integer_arg(j, 1, 1024, opt.runner.jobs)) return usage.bare(needs_integer("--jobs", 1, j));
    } else if (a == "--list-effects") {
      for (const auto &e : effect_library()) {
        std::printf("%-20s %s\n%-20s magnitude: %s; reference values:", e.name.c_str(), e.what.c_str(), "",
                    e.unit.c_str());
        for (double k : e.knots) std::printf(" %s", deck_number(k).c_str());
        std::printf("%s\n", e.pour_level ? " (new beds)" : " (push only: the baseline's beds)");
      }
      return 0;
    } else {
      return usage.with_help(unknown_option(a));
    }
  }
  if (opt.scenario.empty() || (!opt.prepare_only && opt.slurm.empty() && (opt.real.empty() || opt.out.empty())) ||
      ((opt.prepare_only || !opt.slurm.empty()) && opt.v0.empty())) {
    return usage.with_help("needs --scenario and either --real and --out, or --prepare-only (or --slurm) and --v0");
  }
  try {
    return run_gap(opt, render_progress);
  } catch (GapRefused &e) {
    std::fprintf(stderr, "granpen gap: %s\n", e.what());
    return 2;
  } catch (InputError &e) {
    std::fprintf(stderr, "granpen gap: %s\n", e.what());
    return 1;
  }
}
