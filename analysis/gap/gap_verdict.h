// granpen gap: the verdict from the fitted candidates, before any confirming run.
// Two routes to a finding: the omnibus chi^2 over every feature (d.significant on entry: a
// gap spread over many features), or one candidate's likelihood ratio above its
// null-calibrated threshold (EffectFit::detected: a gap too small for the omnibus test that
// lies along an effect's signature). Sorts d.ranking best first (by the likelihood ratio
// beyond the noise's, lr_evidence) and sets d.targeted, d.significant, d.verdict
// ("none", "explained", "tie", "unexplained"), d.top_effect (explained) or d.tie (the
// candidates that explain the gap within the evidence margin of the top's, or whose fitted
// predictions lie within their knots' noise of the top's: two or more, best first), and a
// note saying why.
// separation2(a, b), when given: the evidence the data would give between a's and b's fitted
// predictions (gap_limits.h, prediction_separation2: squared standard deviations, the knots'
// noise subtracted); under the evidence margin the top and such a candidate are not told
// apart, whatever their likelihood ratios say (the difference is then the knots' noise), so
// one that explains the gap as well makes a tie, wherever it ranks. Without it (the null replicates, unit tests) only
// the evidence margin tells them apart. On either route an effect is named (or half of a
// tie) only when detected: its likelihood ratio above its null-calibrated threshold.
// An unexplained verdict whose top candidate falls short only in what its interpolated
// signature explains (detected, inside its range, alone, explaining at least
// BETWEEN_KNOTS_MIN_EXPLAINED) sets d.between_knots: the confirmation simulates it at its
// fitted magnitude before the verdict stands.
// docs/gap.md, "Verdict".
#ifndef GRANPEN_GAP_VERDICT_H
#define GRANPEN_GAP_VERDICT_H

#include "gap_result.h"

#include <functional>

namespace granpen {

// a quarter: the ramp case of the selftest explains 0.32 from knots 1.6 and 3.2 at its true
// 2.4 cm; below a quarter the candidate is too weak to be worth fresh beds
constexpr double BETWEEN_KNOTS_MIN_EXPLAINED = 0.25;

using Separation2 = std::function<double(const EffectFit &, const EffectFit &)>;

void decide_verdict(Diagnosis &d, const Separation2 &separation2 = {});

}    // namespace granpen

#endif
