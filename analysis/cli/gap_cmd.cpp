// granpen gap --real DIR --scenario NAME --out DIR: the sim-to-real gap diagnosis
// (gap/gap_diagnosis.h); --prepare-only runs (or resumes) the cache's simulations.
#include "atomic_file.h"
#include "gap_options.h"
#include "effects.h"
#include "gap_diagnosis.h"
#include "subcommands.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>

namespace {


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

namespace {

void list_effects()
{
  for (const auto &e : granpen::effect_library()) {
    // the reference value is what detection limits and look-alikes are stated at; the knots
    // are where the signature is simulated (or transformed)
    std::printf("%-20s %s\n%-20s magnitude: %s; reference value %s; knots:", e.name.c_str(), e.what.c_str(), "",
                e.unit.c_str(), granpen::deck_number(granpen::reference_magnitude(e)).c_str());
    for (double k : e.knots) std::printf(" %s", granpen::deck_number(k).c_str());
    if (e.transform && std::isfinite(e.transform_max))
      std::printf(" (up to %s the baseline's traces transformed, nothing simulated; beyond, push only: the baseline's beds)\n",
                  granpen::deck_number(e.transform_max).c_str());
    else
      std::printf("%s\n", e.transform    ? " (the baseline's traces transformed: nothing simulated)"
                          : e.pour_level ? " (new beds)"
                                         : " (push only: the baseline's beds)");
    if (e.opt_in) std::printf("%-20s opt-in: not in the default library; --effects default,%s adds it\n", "", e.name.c_str());
  }
}

}    // namespace

int granpen::cli::run_gap_command(const GapCommandOptions &go)
{
  const GapOptions &opt = go.gap;
  if (go.list_effects) {
    list_effects();
    return EXIT_OK;
  }
  if (!opt.out.empty() && !opt.real.empty() && same_file(opt.out, opt.real))
    throw UsageError("--out " + opt.out + " is the input --real " + opt.real + ": refusing to overwrite it");
  return run_gap(opt, render_progress);    // its refusals exit 2, its other errors 1: run_subcommand
}

int granpen::cli::gap(int argc, char **argv) { return run_parsed(parse_gap, run_gap_command, argc, argv); }
