// granpen gap: the signature prior (docs/gap.md, "The adaptive plan"): for each candidate
// with simulated knots (pour-level, push-only, the chain beyond its filter), its knots'
// signatures (the knot ensemble's binned features minus the baseline's, physical units, per
// speed and feature, with their variance of the mean) from beds of their own (push-only
// knots pushed into the prior's baseline beds), so that the adaptive plan (gap_adaptive.h) knows a candidate's
// direction before its knots are simulated. Written once per scenario from a cache
// (`granpen gap --write-prior FILE`), read by the diagnosis (inputs/priors/SCENARIO.json, or
// --prior FILE). The features depend on the grid's depth (the windows and the bands span
// it), so the prior holds them for every grid depth from its runs' deepest common one up to
// PRIOR_DEPTHS bins shallower; a diagnosis whose grid is none of them has no prior.
#ifndef GRANPEN_GAP_PRIOR_H
#define GRANPEN_GAP_PRIOR_H

#include "effects.h"
#include "gap_adaptive.h"
#include "gap_data.h"
#include "gap_diagnosis.h"
#include "gap_features.h"
#include "gap_limits.h"
#include "gap_progress.h"
#include "gap_runs.h"
#include "scenario.h"
#include "sweep_runner.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace granpen {

constexpr int PRIOR_FORMAT = 1;
constexpr int PRIOR_DEPTHS = 9;    // grid depths held: the deepest and 8 bins (2 cm) shallower

struct PriorKnot {
  double magnitude = 0;
  std::vector<std::vector<double>> signature, variance;    // [speed][feature]: knot - baseline, its variance of the mean
};
struct PriorGrid {
  double zmax = 0;
  std::map<std::string, std::vector<PriorKnot>> effects;    // effect -> its knots, ascending
};
struct SignaturePrior {
  std::string scenario, source;             // source: the file read, or the cache written from
  std::vector<std::string> seeds;           // the beds its knots and baseline were simulated on
  int beds = 0;                             // beds per knot (the signatures' noise goes as 1 / beds)
  std::vector<double> speeds;               // ascending
  double w = 0.25, window = 1.0;
  std::vector<double> bands;
  std::vector<PriorGrid> grids;             // deepest first
};

// The prior from the baseline's and the simulated knots' runs (a transform's knots are
// skipped: the diagnosis's own), aligned here at the
// baseline's onsets, per grid depth. Throws InputError when a sweep lacks a speed or has
// fewer than 2 runs at one.
SignaturePrior prior_from_runs(const std::string &scenario, const std::vector<std::string> &seeds, const RunsBySpeed &base,
                               const std::map<std::string, RunsBySpeed> &knots, const std::vector<const Effect *> &effects,
                               double max_depth);

void write_prior(const std::string &path, const SignaturePrior &p);    // io/atomic_file: whole or nothing
// Throws GapRefused naming the file and the key for a file that is not a prior of this format.
SignaturePrior read_prior(const std::string &path);

// The prior a diagnosis uses: --prior FILE, none with --prior none, else
// INPUTS/priors/SCENARIO.json when it exists. Throws GapRefused for a file of another
// scenario or one it cannot read.
std::optional<SignaturePrior> find_prior(const std::string &option, const std::string &inputs, const std::string &scenario);

// An effect's knot signatures on the diagnosis's grid and speeds, or a reason why none.
struct PriorSignatures {
  std::vector<PriorKnot> knots;    // speeds in the order of the diagnosis's
  std::string missing;             // why there are none ("" = there are)
};
PriorSignatures prior_signatures(const SignaturePrior &p, const std::string &effect, const GapGrid &grid,
                                 const std::vector<double> &speeds);

// The adaptive plan's bound for effect e from the prior (gap_adaptive.h, prior_bound), on the
// cheap stage's features f and grid: the gap against the reference beds, weighted as the fits
// weigh it, the knots' noise from f's noise model (the diagnosis's knots on its signature
// beds, the prior's on its own). Empty, with the reason in `missing`, when the prior has none.
std::optional<PriorBound> candidate_prior_bound(const SignaturePrior &p, const Effect &e, const Features &f,
                                                const GapGrid &grid, double scale_bound, std::string &missing);

// The detection limits of the candidates the plan skipped, pour-level or push-only (in
// all_effects, no effect of that name in simulated; the chain fitted on its filter alone is
// simulated), from the prior's signatures as their knots (referenced to f's reference beds,
// their noise f's noise model on the prior's beds), with the threshold their null replicates
// give: how blind the diagnosis is to what it did not simulate. Appended to limits.
void add_prior_limits(const SignaturePrior &p, const std::vector<const Effect *> &all_effects,
                      const std::vector<const Effect *> &simulated, const Features &f, const GapGrid &grid,
                      std::vector<DetectionLimit> &limits);

// --write-prior FILE: prepares (or takes from the cache) the baseline and every simulated
// knot (pour-level, and push-only into the baseline's beds) on opt.prior_seeds (the cache's own signature sweeps when they are the signature
// seeds, else sweeps prior_SEEDS_*), and writes the prior. Returns the exit status.
// sc: the scenario as loaded; v0: --v0's speeds; runner: the scenario's cache.
int write_signature_prior(const GapOptions &opt, const Scenario &sc, const std::vector<std::string> &v0,
                          const RunnerOptions &runner, const GapProgressFn &fn);

}    // namespace granpen

#endif
