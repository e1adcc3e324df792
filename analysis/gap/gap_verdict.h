// granpen gap: the verdict from the fitted candidates, before any confirming run.
// Two routes to a finding: the omnibus chi^2 over every feature (d.significant on entry: a
// gap spread over many features), or one candidate's likelihood ratio above its
// null-calibrated threshold (EffectFit::detected: a gap too small for the omnibus test that
// lies along an effect's signature). Sorts d.ranking best first (by the likelihood ratio
// beyond the noise's, lr_evidence) and sets d.targeted, d.significant, d.verdict
// ("none", "explained", "tie", "unexplained"), d.top_effect (explained) or d.tie (the two
// candidates that both explain the gap within the evidence margin of each other), and a
// note saying why.
// docs/gap.md, "Verdict".
#ifndef GRANPEN_GAP_VERDICT_H
#define GRANPEN_GAP_VERDICT_H

#include "gap_result.h"

namespace granpen {

void decide_verdict(Diagnosis &d);

}    // namespace granpen

#endif
