// granpen gap, stage 8 (verdict): the one owner of the verdict. decide_verdict holds every
// rule, from two typed inputs: the fits' evidence (stage 7, which) and, once there is one,
// the confirmation's result (stage 9, confirm). The diagnosis calls it twice: on the fits
// alone (what the confirmation then simulates) and with the confirmation (the verdict that
// stands); the null replicates call it on their fits alone. No other file sets a verdict.
//
// The fits' rules. Two routes to a finding: the omnibus chi^2 over every feature
// (FitEvidence::omnibus: a gap spread over many features), or one candidate's likelihood
// ratio above its null-calibrated threshold (EffectFit::detected: a gap too small for the
// omnibus test that lies along an effect's signature). Candidates are compared best first
// (rank_by_evidence: by the likelihood ratio beyond the noise's, lr_evidence). A tie names
// the candidates that explain the gap within the evidence margin of the top's, or whose
// fitted predictions lie within their knots' noise of the top's (two or more, best first).
// separation2 to the top, when given (gap_limits.h, prediction_separation2: squared
// standard deviations, the knots' noise subtracted): under the evidence margin the top and
// such a candidate are not told apart, whatever their likelihood ratios say, so one that
// explains the gap as well makes a tie, wherever it ranks. Without it (the null replicates,
// unit tests) only the evidence margin tells them apart. On either route an effect is named
// (or half of a tie) only when detected. An unexplained verdict whose top candidate falls
// short only in what its interpolated signature explains (detected, inside its range,
// alone, explaining at least between_knots_min_explained) is between_knots: the
// confirmation simulates it at its fitted magnitude before the verdict stands.
//
// A uniform force scale (EffectFit::is_scale: a sensor's gain, the grains' density) is a
// nuisance, not a cause: every candidate is fitted with a scale free within the lab's
// calibration bound (gap_fit.h), and when the scale candidate is what explains the gap the
// verdict is scale_only, never explained: "the force is X% high at every depth and speed",
// with what can do that (gap_limits.h, ScaleFinding). It is confirmed on fresh runs as an
// explained verdict is (the baseline's runs there, scaled), and unexplained when they fail.
//
// The confirmation's rules. An explained verdict stands when its fresh runs confirm it
// (gap_confirm.h, confirms) and halve G_all; between knots, when they confirm it and halve
// G_all both over all speeds and at the held-out speed; with --fit-only an explained verdict
// is provisional. The thresholds: gap_thresholds.h. docs/gap.md, "Verdict".
#ifndef GRANPEN_GAP_VERDICT_H
#define GRANPEN_GAP_VERDICT_H

#include "gap_fit.h"
#include "gap_thresholds.h"

#include <cstddef>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace granpen {

// pair: two effects at once, both named (the pair stage, gap_pairs.h: tried only when the single
// candidates leave the gap unexplained and the residual carries a spectral line or band)
enum class Verdict { none, explained, tie, unexplained, scale_only, pair };

// "none", "explained", "tie", "unexplained", "scale_only", "pair": as diagnosis.json and the report write it
const char *verdict_name(Verdict v);

using Separation2 = std::function<double(const EffectFit &, const EffectFit &)>;
// The top (first) against an undetected candidate (second): the squared standard deviations
// between the top's fitted prediction and the nearest the other makes below its detection
// limit, and that magnitude (gap_limits.h, below_limit_mimic); NaN: none
using Mimic2 = std::function<std::pair<double, double>(const EffectFit &, const EffectFit &)>;

// Sorts the candidates best first: by the likelihood ratio beyond the noise's (lr_evidence).
void rank_by_evidence(std::vector<EffectFit> &ranking);

// What the fits found, as the verdict reads it.
struct FitEvidence {
  bool omnibus = false;                  // the omnibus chi^2's p below significance_p
  double chi2_0 = 0, p_value = 1;        // the omnibus test, for the verdict's sentences
  std::size_t nfeatures = 0;
  int n_null = 0;                        // null replicates behind the thresholds
  std::vector<EffectFit> ranking;        // best first (rank_by_evidence)
  // per candidate of the ranking, its fitted prediction's separation from the top's
  // (separation2), where that can decide (the candidate explains the gap); NaN: not known
  std::vector<double> separation2_to_top;
  // per candidate of the ranking that is not detected, the squared standard deviations between
  // the top's fitted prediction and the nearest one it makes at a magnitude below its detection
  // limit, and that magnitude (Mimic2); NaN: not known, or the candidate is detected
  std::vector<double> mimic2_of_top, mimic_magnitude;
};

// The evidence of a ranking (sorted here), with the separations taken from separation2
// and the below-limit mimics of the top from mimic2 (none when they are not given).
FitEvidence fit_evidence(bool omnibus, std::vector<EffectFit> ranking, const Separation2 &separation2 = {},
                         const Mimic2 &mimic2 = {});

// Whether G_all shrank from `before` to at most gap_shrink_explained of it.
bool gap_shrinks(double before, double after);

// Whether fresh runs between knots explain the gap: confirmed, and G_all halved both over all
// speeds and at the held-out speed (the confirmation asks it too: short of it, it refits).
bool between_knots_explains(bool confirmed, double gap_before, double gap_after, double heldout_before,
                            double heldout_after);

// What the confirmation found (gap_confirm.h makes it), as the verdict reads it.
struct ConfirmationResult {
  enum class Kind {
    none,         // nothing to confirm (no explained verdict, not between knots)
    at_knot,      // between knots, but the fitted magnitude is at a knot: nothing to check
    fit_only,     // --fit-only: nothing simulated
    simulated     // fresh runs of the top candidate decided
  };
  Kind kind = Kind::none;
  double magnitude = 0;                  // where the deciding runs were simulated
  bool confirmed = false;                // by chi^2 or along the signature (gap_confirm.h, confirms)
  // chi^2 over every feature before (against the baseline within the calibration bound, as
  // the runs after are compared times 1 + their fitted scale) and after
  double chi2_before = 0, chi2_after = 0, proj_before = 0, proj_after = 0;
  // G_all before (gap-metric.md: the data against the baseline) and after (against the runs
  // as compared, OUT/corrected/)
  double gap_before = 0, gap_after = 0, heldout_before = 0, heldout_after = 0;
};

// What the pair stage found (gap_pairs.h makes it), as the verdict reads it: the pair its fits
// name (two effects, or none), and what their runs on fresh beds said.
struct PairOutcome {
  std::vector<std::string> effects;      // the pair the fits name (two: the filter, then the other); empty: none
  enum class Kind { none, fit_only, simulated } kind = Kind::none;
  bool confirmed = false;                // the fresh runs pass the singles' confirmation test (gap_confirm.h, confirms)
  double gap_before = 0, gap_after = 0;  // G_all
};

// How the pair stage changed an unexplained verdict.
enum class PairRule {
  none,            // no pair named by the fits (or the verdict was not unexplained): the verdict stands
  explained,       // the pair's fresh runs confirm it and halve G_all: pair
  provisional,     // --fit-only: pair, provisional
  not_confirmed,   // its fresh runs do not confirm it: unexplained
  not_halved       // confirmed by chi^2, G_all not halved: unexplained
};

// Which rule decided, for the sentences that say why.
enum class VerdictRule {
  within_noise,            // none: nothing significant, nothing detected
  no_candidates,           // unexplained: no candidate effects
  look_alike,              // tie: the top and one whose prediction lies within the knots' noise
  tie_by_margin,           // tie: the top two explain the gap and their evidence is within the margin
  targeted_explained,      // explained on the targeted route
  targeted_weak,           // unexplained: detected alone, but explains too little
  targeted_close,          // unexplained: two detected, too close to tell apart, not both explaining
  omnibus_explained,       // explained on the omnibus route
  explains_too_little,     // unexplained: the top explains less than explained_min
  heldout_too_little,      // unexplained: the top does not predict the speeds left out
  at_edge,                 // unexplained: the top needs a magnitude beyond its range
  not_detected,            // unexplained: the top's likelihood ratio is below its threshold
  too_close,               // unexplained: the top two explain the gap about equally well
  scale_explains,          // scale_only: the one candidate that explains the gap is a uniform force scale
  below_limit_look_alike   // tie: the top explains (and is confirmed), but an undetected candidate at a magnitude below its
                           // detection limit makes a prediction within the evidence margin of the top's (issue 37, section 0)
};

// How the confirmation changed the fits' verdict.
enum class ConfirmationRule {
  none,                    // nothing confirmed: the fits' verdict stands
  provisional,             // --fit-only, explained: provisional
  between_knots_fit_only,  // --fit-only, between knots: stays unexplained
  confirmed,               // explained, confirmed and halved: stands
  not_halved,              // explained, confirmed by chi^2 but G_all not halved: unexplained
  not_confirmed,           // explained, not confirmed: unexplained
  between_knots_explained, // between knots: explained
  between_knots_short      // between knots: the runs did not explain it: unexplained
};

// A candidate in a tie, and why it is there (for the sentences).
struct TieMember {
  std::string name;
  double evidence_gap = 0;    // lr_evidence(top) - lr_evidence(this)
  double separation2 = -1;    // >= 0: within the margin by its fitted prediction
};

// One rule a candidate fell short of, as the verdict checked it: the number measured and the
// one the rule asks (the sentences that say why a candidate was not the answer are made from
// these alone, so a reason cannot contradict its numbers).
struct Shortfall {
  enum class Kind {
    not_detected,          // value: its likelihood ratio, threshold: its threshold (value <= threshold)
    at_edge,               // value: its fitted magnitude (beyond its simulated range)
    explains_too_little,   // value: explained, threshold: explained_min (value < threshold)
    heldout_too_little,    // value: held-out explained, threshold: heldout_explained_min (value < threshold)
    less_evidence,         // value: evidence below `other`'s, threshold: the evidence margin
    not_confirmed          // value: G_all after on fresh runs, threshold: what it had to reach (gap_shrink_explained of before)
  };
  Kind kind = Kind::not_detected;
  double value = 0, threshold = 0;
  std::string other;       // less_evidence: the candidate ahead
  bool confirmed_by_chi2 = false;    // not_confirmed: the fresh runs passed the chi^2 test (G_all did not halve)
};

// The sentence of one shortfall, from its numbers.
std::string shortfall_text(const Shortfall &s);

// Every candidate's shortfalls (ranking order): why it is not the answer on its own.
struct CandidateRecord {
  std::string name;
  std::vector<Shortfall> shortfalls;
};

// The decision and its record.
struct VerdictDecision {
  Verdict verdict = Verdict::none;
  std::string top_effect;                // explained: the effect named; else ""
  std::string scale_effect;              // scale_only: the scale candidate that explains the gap; else ""
  std::vector<std::string> tie;          // tie: the candidates, best first
  std::vector<std::string> pair;         // pair: the two effects (PairOutcome::effects)
  PairRule pair_rule = PairRule::none;
  bool significant = false;              // on either route
  bool targeted = false;                 // by one effect's likelihood ratio, not the omnibus chi^2
  bool between_knots = false;            // the fits' unexplained that fresh runs between knots decide
  bool provisional = false;              // --fit-only: explained, not confirmed
  VerdictRule rule = VerdictRule::within_noise;
  ConfirmationRule confirmation = ConfirmationRule::none;
  std::vector<TieMember> tie_record;     // [0], [1]: the pair that made the tie; then those that joined
  std::vector<CandidateRecord> candidates;    // per candidate of the ranking, the rules it fell short of
};

// The verdict: every rule, from the fits' evidence and (when given) the confirmation's result
// and the pair stage's (an unexplained verdict becomes pair when its pair is confirmed and
// halves G_all, as an explained one must).
VerdictDecision decide_verdict(const FitEvidence &fits, const ConfirmationResult *confirmation = nullptr,
                               const PairOutcome *pair = nullptr);

// The sentences that say why (the report's notes), made from the decision's record: those of
// the fits' rules, and those of the confirmation's.
std::vector<std::string> fits_verdict_notes(const VerdictDecision &v, const FitEvidence &fits);
std::vector<std::string> confirmation_verdict_notes(const VerdictDecision &v, const FitEvidence &fits,
                                                    const ConfirmationResult &c);
// ... and the pair stage's (empty when it changed nothing and named no pair).
std::vector<std::string> pair_verdict_notes(const VerdictDecision &v, const PairOutcome &p);

// (The decision into the record, record_verdict, is declared with the record, gap_result.h.)

}    // namespace granpen

#endif
