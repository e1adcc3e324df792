// granpen gap, stage 11b (pairs): two effects at once. A rig can have two of the library's
// effects together (a sensor's filter with an actuator's ramp is the commonest pair), and each
// alone then explains only part of the gap. The stage is entered only when the single
// candidates leave the gap unexplained (from the fits, or when their confirmation failed) and
// the residual (stage 11) carries a spectral line or band: a gap that moves the spectrum is
// the sign of a filter, which the single fits then blend with another effect's part.
//   - Which pairs (pairs_to_try): the residual's nearest directions, i.e. the candidates with
//     the most evidence (each one's evidence is the gap's squared projection on its
//     signature, beyond noise: with an unexplained verdict the residual is the gap), among
//     the candidates that cost no pour: a transform that filters the force (the measurement
//     chain) paired with each push-only candidate among the PAIR_NEAREST with most evidence
//     (the filter always taken when the residual has a line: a line is a resonance, and the
//     chain is the library's one resonance). Pour-level pairs (new beds for each
//     combination) and the force scale (already every fit's nuisance) are not tried.
//   - The chain's knot seeded by the line (seed_chain_knot): a narrow line at f is the
//     resonance of the chain at the period whose filter peaks there; that period is added to
//     the chain's knots (the baseline's runs filtered there, paired on its beds) instead of
//     the fit interpolating between its fixed knots, for the pair and for the chain alone.
//     Without a line, the segment of knots the chain's own single fit lies in is filled with
//     knots a factor PAIR_SEED_STEP apart; and once more a knot where the best pair puts the
//     chain, when that is a new one (a transform's knot costs nothing).
//   - The fit (fit_pair): both magnitudes jointly, their signatures added on the reference
//     beds, M(a, b) = M_A(a) + M_B(b) - M(0), with the nuisance force scale every fit has;
//     its likelihood ratio is calibrated on the null replicates as a single's is, with the
//     chi^2 quantile of two degrees of freedom (GapThresholds::lr_chi2_2_p1e4).
//   - A pair never wins on noise (pair_passes): detected by that threshold, its evidence
//     beyond its best single member's (the chain with the seeded knot included) by
//     GapThresholds::lr_chi2_1_p1e4 (the second member earns its parameter as a single effect
//     earns detection), explaining half the gap, predicting the speeds left out, each
//     magnitude inside its range and away from 0; and alone: a second passing pair within the
//     evidence margin names none.
//   - The confirmation (confirm_pair): the push-only member simulated at its magnitude on the
//     confirmation's fresh beds, filtered by the chain at its own, judged by the singles'
//     test (gap_confirm.h, confirms) along the pair's joint signature; the verdict
//     (gap_verdict.h, PairOutcome) then asks G_all to halve, as for a single effect.
// docs/gap.md, "Two effects at once".
#ifndef GRANPEN_GAP_PAIRS_H
#define GRANPEN_GAP_PAIRS_H

#include "effects.h"
#include "gap_align.h"
#include "gap_confirm.h"
#include "gap_features.h"
#include "gap_fit.h"
#include "gap_residual.h"
#include "gap_sims.h"
#include "gap_verdict.h"
#include "gap_where.h"
#include "gap_which.h"

#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace granpen {

// How many of the candidates with most evidence the pairs are drawn from: the filter and the
// two push-only candidates nearest the gap (a third direction adds pairs whose member explains
// least, each one more test against the pair's threshold).
constexpr std::size_t PAIR_NEAREST = 3;

// Without a line, the filter's knot search fills the segment of knots its own fit lies in with
// knots a factor of at most 1.1 apart (the library's filtered knots are 1.4 to 1.5 apart; a
// tenth of a period moves a 400 Hz resonance by 40 Hz, under the residual's line resolution,
// about 100 Hz over tiny's 2 cm at 200 cm/s).
constexpr double PAIR_SEED_STEP = 1.1;

// The pair stage's members: a filter (a transform of the force that is not a uniform scale:
// the measurement chain) and a partner (a push-only effect that is simulated: no pour, no
// transform). A library with both can have a pair to confirm (gap_plan.h counts its runs).
bool pair_filter(const Effect &e);
bool pair_partner(const Effect &e);

// Whether the stage is entered, and why (or why not) in words.
bool pair_stage_entered(Verdict standing, const std::optional<Residual> &residual, std::string &why);

// A pair to try: a filter (a transform of the force) and another push-only candidate.
struct PairSpec {
  std::string filter, other;
};

// The pairs the rule above draws from the single candidates' ranking (best first).
std::vector<PairSpec> pairs_to_try(const std::vector<EffectFit> &ranking, const std::vector<const Effect *> &effects,
                                   bool residual_has_line);

// The magnitude of a filter effect (a transform whose magnitude is its time scale, as the
// mount's period) whose response peaks at f_line Hz: from the transform's own impulse response
// at its reference magnitude, scaled. NaN when the filter has no resonance (no peak above its
// response at 0 Hz by a fifth).
double resonance_magnitude(const Effect &filter, double f_line);

// Knots filling the segment(s) of knots that hold a (both, when a is a knot), at most
// PAIR_SEED_STEP apart by factor (4 equal steps from 0): where a transform's signature is
// otherwise a blend of two knots' (between 2 and 4 ms the chain's is), filtered knots that
// cost nothing.
std::vector<double> segment_knots(const std::vector<double> &knots, double a);

// The line a seed is taken from: the strongest of the residual's lines when they do not scale
// with v0 (a wavelength of the bed is no resonance); NaN when there is none.
double seeding_line(const Residual &residual);

// The joint fit of two effects to target t (both referenced to the same reference beds).
struct PairFit {
  std::string a, b;                     // a: the filter
  double magnitude_a = 0, magnitude_b = 0, scale = 0;
  bool at_edge = false;
  double chi2_0 = 0, chi2 = 0;          // weighted squared gap at (0, 0) and at the fit
  double explained = 0, heldout_explained = 0;
  double lr = 0, lr_null_mean = 0, lr_threshold = 0, evidence = 0;
  bool detected = false;
  std::string best_single;              // the member with most evidence alone
  double best_single_evidence = 0;
  double margin = 0;                    // evidence - best_single_evidence
  bool passes = false;                  // every rule of pair_passes
  std::string why;                      // the first rule it falls short of ("" when it passes)
};

// Fits magnitudes of A and B jointly (with the nuisance scale) to t; lr, explained and the
// held-out fraction as fit_effect's; not calibrated (lr_null_mean, threshold: calibrate_pair).
PairFit fit_pair(const Target &t, const EffectData &A, const EffectData &B);
// The likelihood ratio of the joint fit alone (for the null replicates).
double pair_lr(const Target &t, const EffectData &A, const EffectData &B);
// The threshold of a pair's likelihood ratio: max(1, null mean / 2) times the chi^2(2)
// quantile of p = 1e-4 (a chi^2 with two degrees of freedom has mean 2).
double pair_lr_threshold(double lr_null_mean);
// Calibrates fit on the null replicates and judges it against its members' single evidence.
void judge_pair(PairFit &fit, const std::vector<Target> &nulls, const EffectData &A, const EffectData &B,
                double single_evidence_a, double single_evidence_b);

// The pair's joint signature as a one-knot effect (knot 1 the pair's prediction at its fit):
// for the confirmation's projection (gap_confirm.h, evaluate_after, signature_sigma).
EffectData pair_line(const EffectData &A, const EffectData &B, double a, double b);

// The chain's model data with knots at the magnitudes at: the baseline's (aligned) runs
// filtered there, aligned to the measured onsets, as every transform knot is; seeded: those
// that became knots (one outside the fit's range, or within same_magnitude_of_range of the
// segment of knots it lies in from a knot or an earlier seed, does not).
EffectData seed_chain_knot(const Effect &chain, const std::vector<double> &at, const SimulatedRuns &sims, const Features &f,
                           const Alignment &al, std::vector<double> &seeded);

// What the stage found.
struct PairSearch {
  bool entered = false;
  std::string why;                        // entered or not, in words
  double line_freq = NAN;                 // the line that seeded the chain (Hz), NaN: none
  std::vector<double> seeded_knots;       // the chain's seeded knots (the line's, or its own fit's; the pair's)
  std::optional<EffectFit> seeded_single; // the chain alone with the seeded knot
  std::vector<PairFit> tried;             // every pair tried, most evidence first
  std::optional<PairFit> named;           // the one pair that passes alone
  std::map<std::string, EffectData> data; // the members' model data as fitted (the chain's seeded)
};

// The stage's search (no simulation): entry, pairs, seeded knot, fits, the pair named.
PairSearch search_pairs(const std::vector<const Effect *> &effects, const FittedCandidates &fitted, const Features &f,
                        const SimulatedRuns &sims, const Alignment &al, Verdict standing,
                        const std::optional<Residual> &residual);
// The same from given model data (tests: no runs; the seed, when any, already in data, and
// seeded_single the filter's single fit with it, which its members' evidence then includes).
PairSearch search_pairs_in(const std::vector<const Effect *> &effects, const FitEvidence &evidence,
                           std::map<std::string, EffectData> data, const Features &f, Verdict standing,
                           const std::optional<Residual> &residual, const EffectFit *seeded_single = nullptr);

// The confirmation's record and the verdict's input.
struct PairConfirmation {
  PairOutcome outcome;
  std::string filter, other;
  double magnitude_filter = 0, magnitude_other = 0;
  std::string unit_filter, unit_other;
  // chi2_before: against the baseline within the calibration bound (the runs after are
  // compared times 1 + the pair's fitted scale), as a single's confirmation
  double chi2_before = 0, chi2_after = 0, proj_before = 0, proj_after = 0, confirmed_fraction = 0;
  AfterRuns after;                        // the runs adopted as the "after" (the other member's, filtered)
  std::vector<std::pair<std::string, std::string>> corrected_traces;    // those runs filtered, times 1 + scale, as files
};
struct PairConfirmStep {
  std::optional<RunsNeeded> need;
  PairConfirmation done;
};

// For a named pair: asks for the push-only member's runs at its magnitude on the
// confirmation's fresh beds (tag "pair"), then filters them by the chain and judges them.
PairConfirmStep confirm_pair(const PairSearch &search, const WhereResult &where,
                             const Features &f, const Alignment &al, bool fit_only, const StageRuns &given);

// The stage's whole record (diagnosis.json "pairs", report.md).
struct PairStage {
  PairSearch search;
  std::optional<PairConfirmation> confirmation;
};

}    // namespace granpen

#endif
