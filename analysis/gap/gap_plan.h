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
// The signature beds; the reference beds the fits measure the gap against (and split for the
// null replicates); the confirmation's beds, used by no fit. Inline: the options' parser
// checks --prior-seeds against them without linking this layer (tests/fuzz builds it alone).
inline const std::vector<std::string> SIGNATURE_SEEDS = {"1", "2"}, REFERENCE_SEEDS = {"11", "12", "13", "14"},
                                      CONFIRM_SEEDS = {"21", "22", "23", "24"}, REFINE_SEEDS = {"31", "32", "33", "34"};

// The baseline and every knot of the chosen effects, at the speeds v0 (the cache); knots
// a transform realises (by_transform: the measurement chain up to 2 ms) need nothing
// simulated (gap_sims.h).
std::vector<SimRequest> signature_requests(const std::string &scenario, const std::vector<std::string> &v0,
                                           const std::vector<const Effect *> &effects);
// Effect e's simulated knots alone (signature_requests' for e, without the baseline's): what
// the adaptive plan buys for e. seeds and prefix: the beds and the sweeps' name prefix (the
// signature prior's sweeps, gap_prior.h, are prefix + the usual names); a push-only knot
// pushes into the beds of the sweep prefix + "baseline".
std::vector<SimRequest> knot_requests(const std::string &scenario, const std::vector<std::string> &v0, const Effect &e,
                                      const std::vector<std::string> &seeds = SIGNATURE_SEEDS, const std::string &prefix = "");

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

// The plan's one unit of cost is core time: the seconds the runs take on one core, each
// alone, in probe pours (bench/common.sh's probe_pour: bed 1 of the bench scenario poured
// alone, PROBE_POUR_STEPS steps of its grains, PROBE_POUR_SECONDS on 2026-11-22). A probe
// pour measured on another machine turns it into that machine's seconds; core-hours are the
// same figure at the 2026-11-22 speed (what --budget and --slurm count). Wall time at
// --jobs N follows from it: N runs side by side each go at SIDE_BY_SIDE_SPEED of their speed
// alone (docs/gap.md, "The plan's cost").
constexpr double PROBE_POUR_STEPS = 110000;     // bench bed 1 poured (its .info, 2026-11-22)
constexpr double PROBE_POUR_SECONDS = 69.9;     // ... on one core alone, 2026-11-22
// 16 one-rank pushes side by side on a 16-core node (issue 37); not measured on the 2-core
// development machine, which other work kept at a load of about 7 (docs/gap.md)
constexpr double SIDE_BY_SIDE_SPEED = 0.95;

// A run's cost per atom-step against the bench law's (gran/hertz/history, factor 1): pair
// granular's routes, measured on the bench cold cache of 2026-11-27 (docs/gap.md): the
// knots' CPU seconds over their counted atom-steps, the bench law's own beds taken as 1.
double route_cost_factor(const SimRequest &r);

// What the runs of the requests not yet done in the cache cost, before anything is
// simulated: counted from the preset (grains from its lattice, a pour 0.6 s of simulated
// time, a push gap + depth (+ a ramp's travel) at v0, each at its own time step), in
// atom-steps, and in core time (probe pours: atom-steps times the route's cost factor over
// the probe pour's; probe_grains: the bench preset's grains), also as core-hours. An empty
// cache path: every run, as an empty cache would run them (cold_cost).
struct PlanCost {
  int pours = 0, pushes = 0;
  double atom_steps = 0, core_hours = 0, probe_pours = 0;
  double longest_pour = 0, longest_push = 0;    // probe pours of one run (the wall time's floor)
};
double preset_grains(const Scenario &sc);     // the grains the pour deck creates
PlanCost plan_cost(const Scenario &sc, const std::vector<SimRequest> &requests, const std::string &cache,
                   double probe_grains);
// The same for every run of the requests, as an empty cache would run them (what a
// diagnosis spent, counted cold; a sweep on another's beds pours nothing).
PlanCost cold_cost(const Scenario &sc, const std::vector<SimRequest> &requests, double probe_grains);
// Core-hours of the runs of the requests not yet done in the cache (plan_cost's).
double estimate_core_hours(const Scenario &sc, const std::vector<SimRequest> &requests, const std::string &cache);
// The wall time of a cost run as one pool of `jobs` processes, in probe pours: the core time
// spread over the jobs at their side-by-side speed, and at least the longest pour and push.
double wall_probe_pours(const PlanCost &c, int jobs);
// A cost in the plan's unit: "P probe pours of core time (H core-hours), W of wall time at --jobs N"
std::string cost_phrase(const PlanCost &c, int jobs);
// "N pours, M pushes, A atom-steps: about P probe pours of core time (H core-hours), W of wall time at --jobs N"
std::string plan_summary(const PlanCost &c, int jobs = 1);
// Two costs added (counts, atom-steps, core time; the longest runs of either).
PlanCost operator+(const PlanCost &a, const PlanCost &b);

// The runs a confirmation asks for (docs/gap.md, step 3), of effect e at magnitude a: the
// confirming runs on every speed, the held-out speed's at its own magnitude, and one
// refinement or refit between knots on four more fresh beds. With the slowest speed held
// out and e's outermost knot, the most e's confirmation can cost.
std::vector<SimRequest> largest_confirmation(const std::string &scenario, const Effect &e, double a,
                                             const std::vector<std::string> &v0);
// The runs the pair stage's confirmation asks for (gap_pairs.h, confirm_pair), of the
// push-only member `other` at magnitude b: its pushes into the confirmation's fresh beds at
// every speed (the beds poured once, shared with a single's push-only confirmation).
std::vector<SimRequest> pair_confirmation(const std::string &scenario, const Effect &other, double b,
                                          const std::vector<std::string> &v0);
// The most the confirmations can add to the plan (0 without effects), what the cache lacks:
// the costliest of largest_confirmation over the effects at their outermost knots, and, when
// the library holds a pair the pair stage can try (gap_pairs.h, pair_filter and
// pair_partner), the costliest pair_confirmation over the partners at their outermost knots
// on top (a single's confirmation that fails leaves the pair stage its turn). A pair's
// magnitudes are not refined (docs/gap.md, "Two effects at once"): its one set of runs.
PlanCost confirmation_most(const Scenario &sc, const std::vector<std::string> &v0,
                           const std::vector<const Effect *> &effects, const std::string &cache, double probe_grains);

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
