// granpen gap, stage 2 (plan): which simulations a diagnosis needs, as sweep requests over
// the effect library, and what they cost. Pure planning, except that the cost counts only
// the runs the cache does not hold yet (asked of the sweep layer).
#ifndef GRANPEN_GAP_PLAN_H
#define GRANPEN_GAP_PLAN_H

#include "gap_sims.h"
#include "scenario.h"

#include <string>
#include <vector>

namespace granpen {

// Seeds of the signature simulations (baseline and every effect knot) and of the
// confirming runs, which must be beds no fit has seen; the refining runs' beds (the
// magnitude corrected from the confirming runs, which it has seen).
extern const std::vector<std::string> SIGNATURE_SEEDS, REFERENCE_SEEDS, CONFIRM_SEEDS, REFINE_SEEDS;

// The baseline and every knot of the chosen effects, at the speeds v0 (the cache); knots
// a transform realises (by_transform: the measurement chain up to 2 ms) need nothing
// simulated (gap_sims.h).
std::vector<SimRequest> signature_requests(const std::string &scenario, const std::vector<std::string> &v0,
                                           const std::vector<const Effect *> &effects);

// The runs confirming effect e at magnitude a with fresh seeds, at speeds v0; a push-only
// effect pours the fresh beds once (sweep confirm_beds, or refine_beds) and reuses them. At
// a magnitude its transform realises, an effect's are the baseline's pushes on those beds
// (confirm_baseline, refine_baseline), one sweep for every such magnitude and tag:
// transformed when loaded.
std::vector<SimRequest> confirm_requests(const std::string &scenario, const Effect &e, double a,
                                         const std::vector<std::string> &v0, const std::string &tag,
                                         const std::vector<std::string> &seeds = CONFIRM_SEEDS);

// The sweep holding those runs: TAG_EFFECT_MAGNITUDE, or at a magnitude the transform
// realises the baseline's pushes (confirm_baseline for CONFIRM_SEEDS, else refine_baseline).
std::string confirm_sweep(const Effect &e, double a, const std::string &tag,
                          const std::vector<std::string> &seeds = CONFIRM_SEEDS);

// Core-hours of the runs of the requests not yet done in the cache (1.1e7 atom-steps
// per second per core, docs/presets.md; grains from the preset's lattice, a pour 0.6 s
// of simulated time).
double estimate_core_hours(const Scenario &sc, const std::vector<SimRequest> &requests, const std::string &cache);

// What the runs of the requests not yet done in the cache cost, before anything is
// simulated: counted from the preset (grains from its lattice, a pour 0.6 s of simulated
// time, a push gap + depth at v0), in atom-steps; in core-hours at 1.1e7 atom-steps per
// second per core (docs/presets.md); and in probe pours (bench/common.sh: bed 1 of the
// bench scenario, PROBE_POUR_STEPS steps of its grains), the machine unit of issue 21,
// when probe_grains > 0.
struct PlanCost {
  int pours = 0, pushes = 0;
  double atom_steps = 0, core_hours = 0, probe_pours = 0;
};
constexpr double PROBE_POUR_STEPS = 110000;    // bench bed 1 poured (its .info, 2026-11-22)
double preset_grains(const Scenario &sc);     // the grains the pour deck creates
PlanCost plan_cost(const Scenario &sc, const std::vector<SimRequest> &requests, const std::string &cache,
                   double probe_grains);
// "N pours, M pushes, A atom-steps: about P probe pours, H core-hours"
std::string plan_summary(const PlanCost &c);

// The requests' runs as the tasks of SLURM job arrays, in one index space (--slurm, and
// `gap --prepare-only --only K`, which runs task K): every pour of the requests that pour
// their own beds (tasks 0..pours-1), then every push (the next ones), each as (request,
// index of the run in its sweep's plan). Every planned run, done or not: the indices do
// not move as the cache fills, and a task whose run is done does nothing.
struct ArrayTask {
  size_t request = 0;
  int run = 0;
};
struct ArrayTasks {
  std::vector<ArrayTask> pours, pushes;
};
ArrayTasks array_tasks(const std::vector<SimRequest> &requests);

// A diagnosis runs here up to this many core-hours; beyond, it asks for --slurm or --local.
constexpr double LOCAL_CORE_HOURS = 8.0;

struct SimulationPlan {
  std::vector<SimRequest> requests;    // the baseline, the reference beds, every effect knot
  double core_hours = 0;               // of what the cache does not hold yet
};

// The signature simulations at the measured speeds v0s; throws InputError when they would
// cost more than LOCAL_CORE_HOURS and `local` is not set (naming --slurm and --local).
SimulationPlan plan_simulations(const Scenario &sc, const std::vector<std::string> &v0s,
                                const std::vector<const Effect *> &effects, const std::string &cache, bool local);

}    // namespace granpen

#endif
