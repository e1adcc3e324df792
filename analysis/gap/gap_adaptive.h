// granpen gap, stage 2b (adaptive plan): which candidates' knots are worth simulating, given
// what the cheap stage saw (the baseline, the reference beds and the transforms, fitted): the
// push-only candidates first (and the measurement chain beyond its filter), then, with what
// they bought fitted in, the pour-level ones; and what the diagnosis cost against its plan's
// range. Pure: typed
// inputs, a typed decision; no files, no simulation (docs/gap.md, "The plan's cost").
//
// A candidate not yet simulated (a push-only one's knots, the measurement chain's simulated
// knots beyond its filter, a pour-level one's) can change the verdict only if its likelihood ratio could
// reach its threshold (lambda x 15.14, lambda >= 1: 15.14 at least) and, when a cheap
// candidate already explains the gap, come within the evidence margin of that candidate's
// evidence. Its likelihood ratio is the squared gap it removes, so it is bounded by the
// squared gap along its signature's direction when that is known (`projection2`; with a
// signature prior, gap_prior.h, prior_bound's), and by the whole squared gap at magnitude 0
// (chi2_0) when it is not: no direction can take more.
// A candidate whose bound falls short is skipped, and said so with its bound. On a gap the
// cheap stage leaves unexplained on the omnibus route (not between knots) the verdict changes
// only for a candidate that explains a quarter of it: with a prior, one whose fit cannot remove
// that much of the squared gap (PriorBound::gain) is skipped too, whatever its likelihood
// ratio could reach (the explain gate; docs/gap.md, "The explain gate").
#ifndef GRANPEN_GAP_ADAPTIVE_H
#define GRANPEN_GAP_ADAPTIVE_H

#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace granpen {

// What the cheap stage saw: the squared gap at magnitude 0 (noise-weighted, against the
// reference beds, within the nuisance scale), and its best candidate.
struct CheapStageSeen {
  double chi2_0 = 0;
  std::string best;                 // the best cheap candidate ("" = none fitted)
  double best_evidence = 0;         // its evidence (likelihood ratio beyond the noise's)
  bool best_explains = false;       // it passes every rule of an explanation (gap_verdict.h, explains)
  bool best_is_scale = false;       // it is a uniform scale: a nuisance, never the cause (its look-alikes are needed)
  // the cheap stage's verdict is unexplained on the omnibus route (the gap significant over
  // every feature) and not between knots: then a pour-level candidate changes the verdict only
  // by explaining at least between_knots_min_explained of the gap (every other verdict, and the
  // runs between knots, need that of some candidate; a tie needs two that explain), whatever
  // its likelihood ratio: the explain gate of decide_purchases
  bool unexplained_stands = false;
  // the cheap stage's verdict is unexplained (on any route): the pair stage (gap_pairs.h) may
  // then pair the filter with a push-only partner, which changes the verdict by what the two
  // explain together, not by what the partner explains alone
  bool unexplained = false;
};

// The bound with a signature prior (gap_prior.h), per speed and feature: the gap y (the
// measurement less the reference beds' baseline), its variance V (the fits' fixed weights,
// the current data's noise model), the force-scale direction B (the reference baseline: the
// prediction is (1 + c) M(a), |c| <= scale_bound), and per knot the prior's signature S_j
// with the variance a diagnosis's own knot signature would carry (U_j) and the prior's (W_j).
struct PriorBoundInput {
  std::vector<std::vector<double>> gap, var, scale_dir;                      // [speed][feature]
  std::vector<std::vector<std::vector<double>>> signature, knot_var, prior_var;    // [knot][speed][feature]
  std::vector<double> magnitude;    // per knot (the baseline, 0, is not one); empty: 1, 2, ...
  bool one_sided = false;           // no magnitude below 0 (Effect::one_sided)
  double reach = 0.25;              // the fit's extrapolation beyond the end knots (EffectData::reach)
  double scale_bound = 0;
  // per knot: its signature is the diagnosis's own (a knot its transform realises, already
  // fitted): exactly known, so no tilt (its prior_var is 0 and its knot_var enters only the
  // fit's weights); empty: none is
  std::vector<bool> own;
  // only the path's points at magnitudes above this (the part the knots bought add: the
  // chain beyond its filter's 2 ms; the filtered part is fitted already)
  double beyond = -INFINITY;
};
// The most likelihood ratio the candidate can earn (docs/gap.md, "The bound with a prior"):
// the largest over the points of the fit's path (each magnitude's interpolation x of the
// knots' signatures, as gap_fit.h predicts: rays from 0, segments between knots on one side,
// the extrapolations, the mirror) that the fit can choose, of the likelihood ratio there:
// projection2, the fixed-weight squared gap the point removes (w0 - |r|^2, r = y - c B - x with
// the bounded scale; negative where the point adds to the residual); margin_noise, what the
// knots' own variance t = U / V changes in the likelihood there (sum r^2 t / (1 + t) - log(1 +
// t), either sign); margin_direction, what the diagnosis's knots, the prior's tilted by d (two
// ensembles' noise, variance (U + W) / V per whitened feature, |c_j|-weighted over the knots)
// add: 2 u - |d|^2_t, u = sum r d / (1 + t) with a coherent part alpha sum W / (V (1 + t)) (the
// signal's part the prior's own noise turned away, alpha the fitted length along x), at sqrt(q)
// of its standard deviation (q the chi^2_K quantile of tail PRIOR_BOUND_P, K knots), at most
// Cauchy-Schwarz's u^2 / |d|^2_t. A point is one the fit can choose unless its fixed-weight
// gain, with the same tilt's at its quantile, stays below 0 (magnitude 0's).
struct PriorBound {
  double projection2 = 0, margin_direction = 0, margin_noise = 0;
  double bound() const { return projection2 + margin_direction + margin_noise; }
  // What `explained` rests on (gap_fit.h, explained_fraction): the most fixed-weight squared gap
  // the fit's point can remove (over the points the fit can choose, the point's projection2 and
  // the tilt's fixed-weight gain at its upper quantile), and the fixed-weight squared gap at
  // magnitude 0 (within the scale) it is a fraction of; noise: that gap's noise share
  // (explained_fraction's n; set by the caller, gap_prior.h, 0 when not known).
  double gain = 0, w0 = 0, noise = 0;
};
// The random part's tail: 0.01 per candidate: in tests/analysis/gap/test_gap_adaptive.cpp's
// Monte Carlo (the fit's own likelihood ratio with the diagnosis's knots, effect_lr, against
// the prior's bound) it is exceeded in 20 of 3840 draws (the test's bound: 1%); at 0.1 in 63.
constexpr double PRIOR_BOUND_P = 0.01;
// Magnitudes on the path's grid (and the knots): the direction between two grid points turns
// by less than 1 / PRIOR_PATH_POINTS of a segment.
constexpr int PRIOR_PATH_POINTS = 400;
PriorBound prior_bound(const PriorBoundInput &in);

// A candidate before its knots are simulated (push-only ones are decided first: their knots
// are pushes into the signature beds, a pour-level candidate's pour beds of their own).
struct PlanCandidate {
  std::string effect;
  double cost = 0;                          // probe pours of core time its knots cost (what the cache lacks)
  std::optional<double> projection2;        // the squared gap along its signature, when a direction is known
  std::optional<PriorBound> prior;          // with a signature prior: its bound (then projection2 is its bound())
  std::string no_prior;                     // why a prior given holds no direction for it ("" = none given, or one used)
  double cold_cost = 0;                     // its knots' cost as a cold cache runs them (the unit of the plan's range)
  bool push_only = false;                   // its knots are pushes only (Effect::pour_level false)
  // a partner the pair stage can pair with the library's filter (gap_pairs.h, pair_partner,
  // with a pair_filter in the library): on an unexplained cheap stage it is bought whatever
  // its own bound, since a pair explains what neither alone does (the selftest's chain_ramp)
  bool pair_partner = false;
};

// The decision on one candidate: simulated or skipped, the bound and what it was held against.
struct PurchaseDecision {
  std::string effect;
  bool push_only = false;  // a push-only candidate's knots (or the chain's beyond its filter)
  bool simulate = true;
  double bound = 0;        // the most its likelihood ratio can reach on this data
  double needed = 0;       // what it would have to reach to change the verdict
  double cost = 0;         // probe pours of core time (what the cache lacked)
  double cold_cost = 0;    // probe pours of core time, as a cold cache runs its knots
  std::string why;         // the rule, with its numbers
  std::optional<PriorBound> prior;    // the prior's bound, when it set `bound`
  // the explain gate (CheapStageSeen::unexplained_stands, with a prior): the most squared gap
  // the candidate's fit can remove (PriorBound::gain) and what explaining
  // between_knots_min_explained of the gap needs (explain_gain_needed); 0 when not applied
  double gain = 0, gain_needed = 0;
};

// The fixed-weight squared gap a fit must remove to explain `fraction` of a gap w0 whose noise
// share is n (the inverse of gap_fit.h's explained_fraction: its excess over n, at least
// chi2_noise_sigmas standard deviations of chi^2_n; of w0 itself when n is not known).
double explain_gain_needed(double w0, double n, double fraction);

// Per candidate (the push-only ones, or the pour-level ones), in the order they are bought (least cost first: the evidence per
// CPU-second a knot buys is its inverse noise over its cost, and the pour-level knots' noise
// is alike, docs/gap.md), whether to simulate it. lr_floor: the least threshold a candidate
// can have (GapThresholds::lr_chi2_1_p1e4); margin: the evidence margin of a tie.
std::vector<PurchaseDecision> decide_purchases(const CheapStageSeen &seen, const std::vector<PlanCandidate> &candidates,
                                               double lr_floor, double margin);

// The plan's record of a diagnosis (diagnosis.json "plan", report.md): its cost range in the
// plan's one unit (probe pours of core time; wall time at --jobs N from it), both as a cold
// cache runs it (the plan printed counts what the cache lacks), what decides
// where in the range a run lands, what this run spent (counted as a cold cache would have
// run it), and every purchase decision.
struct PlanRecord {
  int jobs = 1;
  double least = 0, most = 0, spent = 0;                 // probe pours of core time
  double wall_least = 0, wall_most = 0, wall_spent = 0;  // probe pours of wall time at --jobs
  double core_hours_spent = 0;                           // spent at the probe's 2026-11-22 speed
  std::string decides;                                   // what sets where a run lands
  std::vector<PurchaseDecision> decisions;
  std::vector<std::string> confirmation;                 // the confirmation's sweeps, as run
};

// report.md's sentence on the plan: the range, what this run spent, what it skipped and why.
std::string plan_record_text(const PlanRecord &r);

}    // namespace granpen

#endif
