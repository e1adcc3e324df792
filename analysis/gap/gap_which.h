// granpen gap, stage 7 (which): every candidate effect's model from its knots' ensembles
// (referenced to the reference beds), fitted to the measured gap, scored by leaving one
// speed out, and calibrated on the null replicates (its likelihood ratio's threshold): the
// fits' evidence, which the verdict (stage 8, gap_verdict.h) reads. docs/gap.md, "Which".
#ifndef GRANPEN_GAP_WHICH_H
#define GRANPEN_GAP_WHICH_H

#include "effects.h"
#include "gap_features.h"
#include "gap_fit.h"
#include "gap_limits.h"
#include "gap_verdict.h"
#include "gap_where.h"

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace granpen {

// Effect e's model data: per knot (0 = the signature baseline, then e's knots, ascending)
// the ensemble means and variances, paired differences for a push-only effect, every knot
// shifted onto the reference beds (knot 0's variance the reference's, the signature
// baseline's in ref_err) and the noise residual of the null replicates.
EffectData effect_data(const Effect &e, const Features &f);

// The fit of e to the target, its likelihood ratio's null mean and threshold, detected.
EffectFit fit_candidate(const EffectData &ed, const Features &f);

// The false-alarm rate on data without any effect: each null replicate taken as the
// measurement, every effect fitted to it (data: the effects' model data, in the order of
// effects) with its threshold calibrated on the other replicates, the omnibus test against
// the reference beds, and the fits' verdict (decide_verdict, no confirmation); counted by
// verdict.
FalseAlarms null_false_alarms(const std::vector<const Effect *> &effects, const std::map<std::string, EffectData> &data,
                              const std::vector<EffectFit> &fits, const Features &f);

// Packing's note for the report: the phi_0 its fitted pour friction (0.3 + magnitude)
// makes, interpolated between the knots' beds (phi0: each knot's mean, knot 0 first),
// against the baseline's.
std::string packing_note(const EffectData &ed, double magnitude, const std::vector<double> &phi0, double phi0_baseline);

// The stage's result: the effects' model data by name (for the confirmation and the
// limits), the fits' evidence the verdict reads (gap_verdict.h), and per effect a note on its
// fitted magnitude for the report (packing: the phi_0 it makes).
struct FittedCandidates {
  std::map<std::string, EffectData> data;
  FitEvidence evidence;
  std::map<std::string, std::string> magnitude_note;    // effect -> e.g. "pour friction 0.120: phi_0 ..."
};

// Fits every effect against the measured gap; omnibus: the where stage's test (the evidence
// carries it). phi0(sweep): the mean phi_0 of a sweep's beds (for packing's note).
FittedCandidates fit_candidates(const std::vector<const Effect *> &effects, const Features &f,
                                const std::function<double(const std::string &)> &phi0, const Significance &omnibus);

}    // namespace granpen

#endif
