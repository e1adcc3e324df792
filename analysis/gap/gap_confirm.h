// granpen gap, stage 9 (confirm): the top effect simulated at its fitted magnitude on fresh
// beds no fit has seen, and what those runs say: the gap after, whether they confirm the
// effect, and the refinement of a magnitude they show to be off. The stage decides no
// verdict (gap_verdict.h reads its ConfirmationResult) and launches no simulation: it
// returns the runs it needs (RunsNeeded) and is called again with them, the simulate stage
// (gap_sims.h, simulate_needed) running them between the calls. docs/gap.md, "Verdict",
// "How far it shrinks".
#ifndef GRANPEN_GAP_CONFIRM_H
#define GRANPEN_GAP_CONFIRM_H

#include "effects.h"
#include "gap_align.h"
#include "gap_features.h"
#include "gap_fit.h"
#include "gap_sims.h"
#include "gap_verdict.h"
#include "gap_where.h"
#include "gap_which.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace granpen {

// Fresh runs at magnitude a against the measurement: G and G_spec after (means over speeds;
// runs: the fewest per speed), chi^2 over every feature, and the gap along the effect's
// signature u = M(a) - M(0), num / sqrt(uu) standard deviations (num / uu: the leftover's
// coefficient on u); per speed the corrected curve on the grid's bins, and the runs' files.
struct SpeedAfter {
  int n = 0;
  std::vector<double> mean, se;     // per bin
  double G = 0, G_spec = 0;
};
struct AfterRuns {
  double G = 0, G_spec = 0, chi2 = 0, num = 0, uu = 0;
  int runs = 0;
  std::vector<SpeedAfter> speeds;
  std::vector<std::string> files;
  double sigma() const;
  double all() const { return gap_all(G, G_spec); }
};

// Aligns the runs (at the measured speeds' onsets), multiplies their force by 1 + scale (the
// nuisance scale fitted with a: the fit's prediction is (1 + scale) M(a), gap_fit.h) and
// evaluates them; on return the runs are that prediction, aligned and scaled. Throws
// InputError when a speed has no runs.
AfterRuns evaluate_after(RunsBySpeed &runs, double a, double scale, const EffectData &ed, const Features &f,
                         const Alignment &al);

// The gap along e's signature at magnitude a against the reference within the calibration
// bound (the nuisance scale at magnitude 0, as the fit's gap before), in standard deviations.
double signature_sigma(const EffectData &ed, double a, const Features &f);

// Whether runs with chi^2 chi2a (and proj_a sigma along the signature) confirm the effect,
// chi2_0 the omnibus chi^2 before against the baseline within the calibration bound
// (Significance::chi2_within_bound: the runs are compared times 1 + their fitted scale):
// omnibus route: chi^2 drops by more than chi2_noise_sigmas of its noise and by
// confirm_excess_removed of the excess; targeted route: the squared projection drops by at
// least confirm_projection_drop2 and chi^2 does not grow beyond its noise (gap_thresholds.h).
// The numbers: the route (targeted), chi^2 before over nfeatures, the projection before.
bool confirms(bool targeted, double chi2_0, std::size_t nfeatures, double proj_before, double chi2a, double proj_a);

// A second simulation after the first runs fell short (the record its note is made from):
// refine (the first runs left a significant part along the signature: linear response) or
// refit (between knots, the first runs taken as a knot).
struct SecondRuns {
  enum class Why { refine, refit } why = Why::refine;
  double first_magnitude = 0, second_magnitude = 0;
  double first_proj = 0, first_chi2 = 0, first_gap = 0;
  bool first_confirmed = false;
  bool decides = false;          // these runs decide the confirmation
  AfterRuns second;
  double second_scale = 0;       // the nuisance scale at second_magnitude (the runs are compared times 1 + it)
};

// The stage's result: what the verdict reads, and the "after" it leaves.
struct Confirmation {
  ConfirmationResult outcome;
  std::string effect, unit;      // the effect named at a magnitude ("" when none is)
  double magnitude = 0;          // final (refined) magnitude
  double scale = 0;              // the nuisance force scale fitted with it: the "after" runs are compared times 1 + scale
  std::string tested_effect;     // simulated on fresh beds
  double heldout_magnitude = 0, heldout_after = 0;
  double confirmed_fraction = 0;
  std::optional<SecondRuns> second;
  AfterRuns after;               // the runs adopted as the "after"
  RunsBySpeed after_runs;        // ... aligned (empty when nothing was simulated)
  std::string corrected_effect;  // a transform effect's "after": the output writes its traces transformed
  double corrected_magnitude = 0;
  // ... and the "after" runs as the verdict compared them (transformed, times 1 + scale) as
  // the files of OUT/corrected/ (name, text), made here so that the report only writes them;
  // empty when they are the runs as simulated (no transform, scale 0: copied)
  std::vector<std::pair<std::string, std::string>> corrected_traces;
  // the magnitude the diagnosis names: this one when an effect was named at one, else 0
  double named_magnitude() const { return effect.empty() ? 0.0 : magnitude; }
};

// One call of the stage: either the runs it needs next, or (need empty) its result.
struct ConfirmStep {
  std::optional<RunsNeeded> need;
  Confirmation done;
};

// For an explained verdict, judges the top effect on its fresh runs (refining its magnitude
// when they call for it); with fit_only, simulates nothing (the verdict is then
// provisional). For the fits' unexplained that is between_knots (gap_verdict.h) at a fitted
// magnitude away from every knot, judges the top candidate there the same way; when those
// first runs do not explain the gap they become a knot, every speed is fitted again with
// them, and the new magnitude is simulated once more on REFINE_SEEDS; those runs decide.
// Reads the fits (ranking, model data, the omnibus test), the fits' verdict (what to
// confirm, by which route) and the where stage (the gap before, the held-out speed); given:
// the runs simulated so far for earlier steps (by tag).
ConfirmStep confirm_top_effect(const std::map<std::string, const Effect *> &by_name, const FittedCandidates &fitted,
                               const VerdictDecision &fits_verdict, const WhereResult &where, const Features &f,
                               const Alignment &al, bool fit_only, const StageRuns &given);

// The note of a second simulation (refined, or refitted between knots), from its record.
std::string second_runs_note(const SecondRuns &r);

}    // namespace granpen

#endif
