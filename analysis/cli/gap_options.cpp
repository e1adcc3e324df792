// granpen gap: its command line (gap_options.h).
#include "gap_options.h"

#include "args.h"
#include "gap_plan.h"    // SIGNATURE_SEEDS, REFERENCE_SEEDS

#include <algorithm>
#include <cstdlib>
#include <thread>

namespace {

const char *HELP =
    "usage: granpen gap --real DIR --scenario NAME --out DIR [--effects LIST] [--jobs N] [--cache DIR]\n"
    "       granpen gap --prepare-only --scenario NAME --v0 \"50 100 200\" [--effects LIST] [--jobs N] [--cache DIR]\n"
    "       granpen gap --write-prior FILE --scenario NAME --v0 \"50 100 200\" [--prior-seeds \"41 42\"] [--cache DIR]\n"
    "       granpen gap --slurm FILE --scenario paper --v0 \"40 80 160\" [--jobs N --ranks R] [--cache DIR]\n"
    "Where do measured force traces (DIR: granpen-trace v1 files, one or more runs per speed,\n"
    "cgs or SI) and the simulation of the same set-up (the preset NAME, or your preset FILE) differ, which\n"
    "unmodelled effect causes it, and how far the gap shrinks once it is added.\n"
    "  1. simulates (or takes from the cache) the baseline and every candidate effect at its\n"
    "     reference magnitudes, at the measured speeds, two seeds each;\n"
    "  2. aligns every run's depth origin by its force onset, bins F on a common grid and\n"
    "     compares ensembles: observables per regime (peak, transient, linear) with z-scores,\n"
    "     the gap curve with its noise band, the overall gap G_all (shared/formats/gap-metric.md\n"
    "     v2: bin means and fluctuation spectrum);\n"
    "  3. fits each effect's magnitude to the gap, scores how much it explains, checks it by\n"
    "     leaving one speed out, and decides: none, explained (top effect), tie (two look-alikes)\n"
    "     or unexplained; with every effect's detection limit and the next measurement;\n"
    "  4. simulates the top effect at its fitted magnitude on fresh seeds and reports the gap\n"
    "     before and after, overall, per regime and at the held-out speed, and what is left.\n"
    "Output (written to OUT.partial, then moved to OUT): diagnosis.json, report.md with\n"
    "figures, baseline/ and corrected/ (the simulated traces used, trace CSV v1).\n"
    "Before anything is simulated it prints the plan: pours, pushes, atom-steps, and the estimate\n"
    "in probe pours (bench/common.sh) and core-hours.\n"
    "Exit status: 0 diagnosis written, 1 simulations failed or input unreadable, 2 usage,\n"
    "3 the plan exceeds --budget (nothing started, nothing written in OUT).\n";

}    // namespace

granpen::cli::GapCommandOptions granpen::cli::parse_gap(int argc, char **argv)
{
  Command cmd("gap", HELP);
  GapCommandOptions go;
  GapOptions &opt = go.gap;
  const char *env;
  opt.runner.lmp = (env = std::getenv("GRANPEN_LMP")) ? env : "lmp_granpen";
  opt.runner.inputs = (env = std::getenv("GRANPEN_INPUTS")) ? env : "inputs";
  opt.cache = std::string((env = std::getenv("GRANPEN_RUNS")) ? env : "runs") + "/gap_cache";
  opt.runner.jobs = (int) std::max(1u, std::thread::hardware_concurrency());
  bool sweep_by_sweep = false;
  auto &app = cmd.app;
  app.add_option("--real", opt.real, "the measured traces' folder")->type_name("DIR");
  app.add_option("--scenario", opt.scenario, "the set-up: a preset of inputs/presets (NAME), or a preset file of\n"
                                             "your own (a path, or a name ending in .lmp: docs/gap.md)")->type_name("NAME|FILE");
  app.add_option("--out", opt.out, "the diagnosis folder")->type_name("DIR");
  app.add_option("--cache", opt.cache, "simulation cache (default $GRANPEN_RUNS/gap_cache); interrupted, a\n"
                                     "diagnosis resumes from it; a finished one reruns without simulating")
      ->check(file_name())->type_name("DIR");
  app.add_option("--lmp", opt.runner.lmp, "lmp_granpen (default: as ./granpen sets it)")->check(file_name())->type_name("PATH");
  app.add_option("--inputs", opt.runner.inputs, "the decks (default: as ./granpen sets them)")->check(file_name())->type_name("DIR");
  app.add_flag("--prepare-only", opt.prepare_only, "only run the simulations the cache needs for --v0 speeds");
  app.add_flag("--local", opt.local, "run here a diagnosis whose simulations would take more than 8\n"
                                      "core-hours (the paper scenario), instead of asking for --slurm");
  app.add_flag("--fit-only", opt.fit_only, "stop before step 4: the verdict is provisional (diagnosis.json:\n"
                                            "\"confirmed\": false; nothing simulated on fresh seeds), G after = before");
  app.add_flag("--sweep-by-sweep", sweep_by_sweep, "run the sweeps one after another, each with its own N (the\n"
                                                     "runner's old way: for bench/pool_vs_sweeps.sh)");
  app.add_option("--slurm", opt.slurm, "write a SLURM script preparing the cache on a cluster as two job\n"
                                     "arrays (the pours, then the pushes after them; one run per task,\n"
                                     "R ranks each) and stop")
      ->check(file_name())->type_name("FILE");
  app.add_option("--only", opt.only_task, "with --prepare-only: run task K of the --slurm job arrays alone (what\n"
                                         "each array task does)")
      ->check(whole_number(0, 100000000))->type_name("K");
  app.add_option("--budget", opt.budget, "core-hours: print the plan and stop (exit 3, nothing started) when its\n"
                                        "estimate exceeds them")
      ->check(non_negative_number())->type_name("CORE_HOURS");
  app.add_option("--mpirun", opt.runner.mpirun, "run each simulation through PROG (mpirun, srun, ...)")->type_name("PROG");
  app.add_option("--ranks", opt.runner.ranks, "MPI ranks per simulation (with --mpirun)")->check(whole_number(1, 1000000))
      ->type_name("R");
  app.add_option("--v0", opt.v0, "speeds for --prepare-only and --slurm, e.g. \"50 100 200\"")->type_name("LIST");
  app.add_option("--effects", opt.effects, "comma-separated candidates; default: the library but its opt-in ones (`default` in the list stands for those, e.g. default,cohesion_dmt)")->type_name("LIST");
  app.add_option("--jobs", opt.runner.jobs, "simulations at once, 1 to 1024 (default: the number of cores), every\n"
                                                   "sweep's runs in one pool")
      ->check(whole_number(1, 1024))->type_name("N");
  std::string prior_seeds;
  app.add_option("--prior", opt.prior, "the signature prior the adaptive plan bounds pour-level candidates with\n"
                                      "(default: INPUTS/priors/SCENARIO.json when it exists; none: no prior)")
      ->type_name("FILE|none");
  app.add_option("--write-prior", opt.write_prior, "prepare the pour-level knots and the baseline (--v0, --prior-seeds)\n"
                                                  "in the cache and write their signatures as a prior, and stop")
      ->check(file_name())->type_name("FILE");
  app.add_option("--prior-seeds", prior_seeds, "with --write-prior: the prior's beds (default \"1 2\", the cache's own\n"
                                              "signature sweeps; others: sweeps of their own; \"1 2 41 42\": both, pooled)")->type_name("LIST");
  app.add_flag("--list-effects", go.list_effects, "the candidate effects, their magnitudes and reference values");
  if (!cmd.parse(argc, argv, go.help)) return go;
  if (sweep_by_sweep) opt.runner.pool = false;
  for (std::size_t i = 0, j; i < prior_seeds.size(); i = j + 1) {
    j = std::min(prior_seeds.find(' ', i), prior_seeds.size());
    const std::string seed = prior_seeds.substr(i, j - i);
    if (seed.empty()) continue;
    if (seed.find_first_not_of("0123456789") != std::string::npos || seed.size() > 9)
      throw UsageError("--prior-seeds: '" + seed + "' is not a whole number");
    if (std::find(opt.prior_seeds.begin(), opt.prior_seeds.end(), seed) != opt.prior_seeds.end())
      throw UsageError("--prior-seeds: seed " + seed + " is given twice");
    // the gap is measured against the reference beds: a prior on them would share their noise
    if (std::find(REFERENCE_SEEDS.begin(), REFERENCE_SEEDS.end(), seed) != REFERENCE_SEEDS.end())
      throw UsageError("--prior-seeds: seed " + seed + " is a reference bed's (the gap is measured against them)");
    opt.prior_seeds.push_back(seed);
  }
  {
    const auto n = std::count_if(SIGNATURE_SEEDS.begin(), SIGNATURE_SEEDS.end(), [&](const std::string &s) {
      return std::find(opt.prior_seeds.begin(), opt.prior_seeds.end(), s) != opt.prior_seeds.end();
    });
    if (n != 0 && n != (long) SIGNATURE_SEEDS.size())
      throw UsageError("--prior-seeds: the signature seeds 1 2 (the cache's own sweeps) come both or neither");
  }
  if (go.list_effects) return go;
  const bool prepares = opt.prepare_only || !opt.slurm.empty() || !opt.write_prior.empty();
  if (opt.scenario.empty() || (!prepares && (opt.real.empty() || opt.out.empty())) || (prepares && opt.v0.empty()))
    throw UsageError("needs --scenario and either --real and --out, or --prepare-only (or --slurm, or --write-prior) and --v0");
  if (opt.only_task >= 0 && !opt.prepare_only) throw UsageError("--only K needs --prepare-only (it is what a --slurm array task runs)");
  if (!opt.prior_seeds.empty() && opt.write_prior.empty()) throw UsageError("--prior-seeds needs --write-prior");
  return go;
}
