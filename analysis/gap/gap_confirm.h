// granpen gap, stage 8 (confirm): the top effect simulated at its fitted magnitude on
// fresh beds no fit has seen, the gap after, the verdict kept only when those runs remove
// the gap (docs/gap.md, "Verdict", "How far it shrinks"), and the refinement of a
// magnitude the confirming runs show to be off. Without an explained verdict (or with
// --fit-only) the "after" is the "before".
#ifndef GRANPEN_GAP_CONFIRM_H
#define GRANPEN_GAP_CONFIRM_H

#include "effects.h"
#include "gap_align.h"
#include "gap_features.h"
#include "gap_fit.h"
#include "gap_result.h"
#include "gap_sims.h"

#include <map>
#include <string>
#include <vector>

namespace granpen {

// What the confirmation simulates with: the scenario (a preset name), the measured speeds
// as the decks get them, the runner (out_root: the scenario's cache).
struct SimContext {
  std::string scenario;
  std::vector<std::string> v0s;
  RunnerOptions runner;
};

// The "after" set to the "before" (the corrected curves the baseline's, G_all and its parts
// after = before), the reference runs as the baseline files, and the held-out speed: the one
// with the largest G_all.
void after_is_before(const RunsBySpeed &fresh, Diagnosis &d);

// Fresh runs at magnitude a against the measurement: G and G_spec after (means over speeds;
// runs: the fewest per speed), chi^2 over every feature, and the gap along the effect's
// signature u = M(a) - M(0), num / sqrt(uu) standard deviations (num / uu: the leftover's
// coefficient on u).
struct AfterRuns {
  double G = 0, G_spec = 0, chi2 = 0, num = 0, uu = 0;
  int runs = 0;
  double sigma() const;
  double all() const { return gap_all(G, G_spec); }
};

// Aligns the runs (at the measured speeds' onsets), sets the corrected curves, G and G_spec
// after per speed and d.corrected_files; throws InputError when a speed has no runs.
AfterRuns evaluate_after(RunsBySpeed &runs, double a, const EffectData &ed, const Features &f, const Alignment &al,
                         Diagnosis &d);

// The gap along e's signature at magnitude a against the reference, in standard deviations.
double signature_sigma(const EffectData &ed, double a, const Features &f);

// Whether runs with chi^2 chi2a (and proj_a sigma along the signature) confirm the effect:
// omnibus route: chi^2 drops by more than 3 sigma of its noise and by a quarter of the
// excess; targeted route: the squared projection drops by at least 9 and chi^2 does not
// grow beyond its noise.
bool confirms(const Diagnosis &d, double chi2a, double proj_a);

// Whether confirming runs with G_all after `after` shrink the measured gap `before` to at
// most half (issue 21's "how far it shrinks"). A confirmation by chi^2 or along the
// signature whose G_all does not shrink so is the mark of a confident wrong answer (the
// effect's own signature noise fitted, or a look-alike's part of the gap: the synthetic
// friction case named polydispersity, G_all 0.088 -> 0.074), so the stage keeps
// `explained` only when this holds.
constexpr double GAP_SHRINK_EXPLAINED = 0.5;
bool gap_shrinks(double before, double after);

// The stage: for an explained verdict, simulates (through the sweep layer) and judges the
// top effect, refines its magnitude when the runs call for it, and turns the verdict into
// unexplained when they do not confirm it; with fit_only, marks the verdict provisional.
// For an unexplained verdict with d.between_knots (gap_verdict.h) and a fitted magnitude
// away from every knot, it simulates the top candidate there the same way: explained when
// the runs confirm it and halve G_all both over all speeds and at the held-out speed (the
// fits' own test of that speed failed or fell short), else unexplained, as before. When
// those first runs fall short, they become a knot, every speed is fitted again with it, and
// the new magnitude is simulated once more on REFINE_SEEDS; those runs decide.
// Returns the runs that are the "after" (aligned; empty when nothing was simulated).
RunsBySpeed confirm_top_effect(const std::map<std::string, const Effect *> &by_name,
                        const std::map<std::string, EffectData> &data, const Features &f, const Alignment &al,
                        const SimContext &sim, bool fit_only, Diagnosis &d);

}    // namespace granpen

#endif
