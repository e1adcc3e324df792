// granpen gap, stage 3 (simulate): the simulations a diagnosis needs, as sweeps
// (sweep/sweep_runner.h) in a cache folder that every diagnosis of the same scenario shares:
//   CACHE/SCENARIO/baseline                 the model as calibrated, seeds 1 2
//   CACHE/SCENARIO/EFFECT_MAGNITUDE         each library effect at each knot, seeds 1 2
//   CACHE/SCENARIO/fresh_baseline           the model on the reference beds, seeds 11 to 14
//   CACHE/SCENARIO/confirm_EFFECT_MAGNITUDE the top effect at its fitted magnitude, seeds 21 to 24
//   CACHE/SCENARIO/heldout_EFFECT_MAGNITUDE the same at the held-out speed's own magnitude
//   CACHE/SCENARIO/confirm_beds             beds of seeds 21 to 24 for push-only confirmations
//   CACHE/SCENARIO/confirm_baseline         the baseline pushed into them (a filtered mount's
//                                           confirmation; refine_beds, refine_baseline: 31-34)
// A push-only effect (actuator ramp, rod friction) reuses the beds of the baseline with the
// same seeds (hard links): its signature is then a paired difference, bed noise cancels.
// Where an effect is realised by a transform (effects.h, by_transform: the measurement chain
// up to 2 ms) nothing is simulated: its knots are the baseline's own runs transformed, paired
// on the same beds, and its confirming runs the baseline pushed on the confirmation's beds
// (CACHE/SCENARIO/confirm_baseline), transformed.
// The sweep runner skips what is done and resumes what was interrupted, so a diagnosis
// resumes from the cache and a repeated one costs nothing. What a sweep folder holds is
// the sweep layer's to say (sweep/sweep_cache.h); the gap names sweeps only.
#ifndef GRANPEN_GAP_SIMS_H
#define GRANPEN_GAP_SIMS_H

#include "effects.h"
#include "gap_runs.h"
#include "sweep_runner.h"
#include "sweep_spec.h"

#include <map>
#include <string>
#include <vector>

namespace granpen {

// a sweep, and the sweep (same preset, seeds) whose beds it reuses; "" = pour its own
using SimRequest = SweepTask;

// One sweep of the scenario's model, or of an effect at magnitude a, over speeds v0.
SimRequest baseline_request(const std::string &scenario, const std::vector<std::string> &v0,
                            const std::vector<std::string> &seeds, const std::string &name);
SimRequest effect_request(const std::string &scenario, const Effect &e, double a,
                          const std::vector<std::string> &v0, const std::vector<std::string> &seeds,
                          const std::string &name);

// Runs the requests as one pool of opt.jobs processes (sweep_runner.h: run_sweeps; a
// reused bed linked once poured); returns the number of sweeps with a failed run.
// opt.out_root is the scenario's cache folder.
int run_requests(const std::vector<SimRequest> &requests, const RunnerOptions &opt);

// The finished runs of one sweep of the cache, by speed (throws InputError for a trace
// that cannot be read).
RunsBySpeed load_sweep_runs(const std::string &cache, const std::string &sweep);

// A transform effect's run at magnitude a (Effect::transform): F transformed (sampled at
// the run's mean time step), the onset found anew (throws InputError as run_of_trace).
// The path stays the source's: the run is computed, not a file.
TraceRun transformed_run(const Effect &e, double a, const TraceRun &run);
RunsBySpeed transformed_runs(const Effect &e, double a, const RunsBySpeed &runs);

// The confirming runs as the prediction the verdict compared, as trace files (for
// OUT/corrected/): per file, SWEEP_FILE and the text: the source's header (a line `derived`
// saying what was done), t and z, its F transformed by `transform` at magnitude a (none: as
// simulated) and times 1 + scale, the nuisance force scale fitted with it (gap_fit.h: the
// prediction is (1 + scale) M(a)); in the file's units, both being linear. Throws InputError
// for a trace that cannot be read.
std::vector<std::pair<std::string, std::string>> corrected_trace_files(const std::vector<std::string> &paths,
                                                                      const Effect *transform, double a, double scale);

// What the fits compare against: the baseline on the signature beds, on the reference
// beds, and every effect knot (sweep name -> runs; the knots a transform realises from the
// baseline's runs).
struct SimulatedRuns {
  RunsBySpeed base, fresh;
  std::map<std::string, RunsBySpeed> knots;
};
SimulatedRuns load_simulations(const std::string &cache, const std::vector<const Effect *> &effects);

// The mean phi_0 of a sweep's beds (NaN without any).
double mean_phi0(const std::string &cache, const std::string &sweep);

// What the later stages simulate with: the scenario (a preset name), the measured speeds
// as the decks get them, the runner (out_root: the scenario's cache).
struct SimContext {
  std::string scenario;
  std::vector<std::string> v0s;
  RunnerOptions runner;
};

// Runs a stage asks for (the confirmation, gap_confirm.h): effect runs at a magnitude on
// fresh seeds, under a tag (confirm, heldout, refine); speeds empty: every measured speed.
struct RunSet {
  std::string tag;
  double magnitude = 0;
  std::vector<std::string> speeds;
  std::vector<std::string> seeds;
};
struct RunsNeeded {
  std::string effect;    // the effect simulated
  std::string what;      // what for, as an error says it ("confirming", "refining", ...)
  std::vector<RunSet> sets;
};
// The runs given back, by tag, as loaded (not aligned; a transform effect's transformed).
using StageRuns = std::map<std::string, RunsBySpeed>;

// The sweeps a later stage's request runs (gap_plan.h, confirm_requests; a sweep that an
// earlier set already asks for, as a push-only effect's shared fresh beds, once).
std::vector<SimRequest> needed_requests(const RunsNeeded &need, const Effect &e, const SimContext &sim);

// The simulate stage for a later stage's request: the sets' sweeps (gap_plan.h,
// confirm_requests; a sweep that an earlier set already asks for, as a push-only effect's
// shared fresh beds, once) run as one pool, then loaded into `given` by tag; throws
// InputError when a simulation failed.
void simulate_needed(const RunsNeeded &need, const Effect &e, const SimContext &sim, StageRuns &given);

}    // namespace granpen

#endif
