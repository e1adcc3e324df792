// granpen gap: the verdict from the fitted candidates (see gap_verdict.h).
#include "gap_verdict.h"

#include "text_util.h"

#include <algorithm>
#include <string>

namespace granpen {

namespace {

std::string fmt(double v, const char *f = "%.4g") { return printf_number(f, v); }

// a candidate that would be the answer on its own: explains at least half of the gap,
// predicts the speeds left out, fits inside its simulated range, and is detected: its
// likelihood ratio above its null-calibrated threshold, what its signature fits of pure
// noise (on the omnibus route too: a significant gap says something is there, not that a
// noisy signature's fit of it is more than noise)
bool explains(const EffectFit &f)
{
  return f.explained >= 0.5 && f.heldout_explained >= 0.3 && !f.at_edge && f.detected;
}

// the top two both explain the gap and are not told apart: the answer names both. sep2 >= 0:
// their fitted predictions differ by sep2 only (said when their evidence is the margin apart)
void tie(const EffectFit &top, const EffectFit &second, Diagnosis &d, double sep2 = -1)
{
  d.verdict = "tie";
  d.tie = {top.name, second.name};
  const bool by_margin = sep2 < 0 || lr_evidence(top) - lr_evidence(second) < EVIDENCE_MARGIN;
  const std::string why =
      by_margin ? "their evidence differs by " + fmt(lr_evidence(top) - lr_evidence(second), "%.1f") +
                     ", less than the margin of " + fmt(EVIDENCE_MARGIN, "%g")
               : "their evidence differs by " + fmt(lr_evidence(top) - lr_evidence(second), "%.1f") +
                     ", but their fitted predictions only by " + fmt(sep2, "%.1f") +
                     " squared standard deviations beyond their knots' noise, less than the margin of " +
                     fmt(EVIDENCE_MARGIN, "%g") + " (the difference in evidence is the knots' noise)";
  d.notes.push_back("verdict: a tie between " + top.name + " and " + second.name + ": each explains the gap (" +
                    fmt(top.explained, "%.2f") + " and " + fmt(second.explained, "%.2f") + ", held out " +
                    fmt(top.heldout_explained, "%.2f") + " and " + fmt(second.heldout_explained, "%.2f") + ") and " + why +
                    ": at this noise they look alike (next_measurement says what would separate them)");
}

// Once the top ties, every further candidate that the data cannot tell from the top
// either (it explains the gap on its own, and its evidence is within the margin of the
// top's or its fitted prediction within the knots' noise of the top's) joins the tie:
// naming two of three look-alikes would drop one the data allow as much (a noiseless
// transform signature, as force_scale's, outranks two noisy pour-level ones that fit the
// data better).
void widen_tie(Diagnosis &d, const Separation2 &separation2)
{
  const EffectFit &top = d.ranking[0];
  for (const auto &c : d.ranking) {
    if (std::find(d.tie.begin(), d.tie.end(), c.name) != d.tie.end() || !explains(c)) continue;
    const double gap = lr_evidence(top) - lr_evidence(c);
    const double sep2 = gap < EVIDENCE_MARGIN || !separation2 ? -1 : separation2(top, c);
    if (gap >= EVIDENCE_MARGIN && !(sep2 >= 0 && sep2 < EVIDENCE_MARGIN)) continue;
    d.tie.push_back(c.name);
    d.notes.push_back("verdict: " + c.name + " joins the tie: it explains the gap (" + fmt(c.explained, "%.2f") + ", held out " +
                      fmt(c.heldout_explained, "%.2f") + ") and " +
                      (gap < EVIDENCE_MARGIN ? "its evidence is " + fmt(gap, "%.1f") + " below " + top.name + "'s, within the margin"
                                             : "its fitted prediction lies " + fmt(sep2, "%.1f") + " squared standard deviations from " +
                                                   top.name + "'s beyond their knots' noise"));
  }
  // best first, as the ranking
  std::vector<std::string> ordered;
  for (const auto &c : d.ranking)
    if (std::find(d.tie.begin(), d.tie.end(), c.name) != d.tie.end()) ordered.push_back(c.name);
  d.tie = ordered;
}

}    // namespace

void decide_verdict(Diagnosis &d, const Separation2 &separation2)
{
  // two routes to a finding: the omnibus chi^2 over every feature (a gap spread over many
  // features), or one candidate's likelihood ratio above its null-calibrated threshold (a
  // gap too small for the omnibus test that lies along an effect's signature)
  const bool omnibus = d.significant;
  d.targeted = !omnibus && std::any_of(d.ranking.begin(), d.ranking.end(), [](const EffectFit &f) { return f.detected; });
  d.significant = omnibus || d.targeted;
  // candidates compared by their likelihood ratio beyond what noise gives along their
  // signatures (on both routes: the null mean's excess is what a noisier signature fits of
  // any noise, an additive share)
  std::sort(d.ranking.begin(), d.ranking.end(),
            [&](const EffectFit &a, const EffectFit &b) { return lr_evidence(a) > lr_evidence(b); });
  const double margin = EVIDENCE_MARGIN;
  const EffectFit *top = d.ranking.empty() ? nullptr : &d.ranking[0];
  const EffectFit *second = d.ranking.size() > 1 ? &d.ranking[1] : nullptr;
  // a second that would explain the gap on its own, with a fitted prediction within the
  // knots' noise of the top's: the two are not told apart by the evidence margin alone
  // (the first such in the ranking, not only the second: a further candidate ranked in
  // between, as a new effect in the library may be, must not hide a look-alike of the top)
  double sep2 = -1;
  const EffectFit *alike = nullptr;
  for (std::size_t i = 1; separation2 && top && !alike && i < d.ranking.size(); ++i) {
    if (!explains(d.ranking[i])) continue;
    sep2 = separation2(*top, d.ranking[i]);
    if (sep2 >= margin) sep2 = -1;
    else alike = &d.ranking[i];
  }
  const bool look_alike = sep2 >= 0 && explains(*top);
  std::string why;
  if (d.targeted) {
    // one candidate's signature stands out: it must stand out alone (a second detected one
    // at least the margin behind) and, as on the omnibus route, explain at least half of the
    // gap and predict the speeds left out
    const bool alone = (!second || !second->detected || lr_evidence(*top) - lr_evidence(*second) >= margin) && !look_alike;
    if (look_alike) {
      tie(*top, *alike, d, sep2);
    } else if (alone && top->detected && top->explained >= 0.5 && top->heldout_explained >= 0.3) {
      d.verdict = "explained";
      d.top_effect = top->name;
      d.notes.push_back("the gap is within the noise over all features (chi^2 " + fmt(d.chi2_0, "%.1f") + " over " +
                        std::to_string(d.nfeatures) + ", p = " + fmt(d.p_value, "%.2g") + ") but lies along " +
                        top->name + "'s signature: likelihood ratio " + fmt(top->lr, "%.1f") + " against a threshold of " +
                        fmt(top->lr_threshold, "%.1f") + " (" + std::to_string(d.n_null) + " null replicates on the reference beds)");
    } else if (!alone && explains(*top) && explains(*second)) {
      tie(*top, *second, d);
    } else if (alone) {
      d.verdict = "unexplained";
      why = "a gap along " + top->name + "'s signature (likelihood ratio " + fmt(top->lr, "%.1f") + " against " +
            fmt(top->lr_threshold, "%.1f") + "), but it explains only " + fmt(top->explained, "%.2f") +
            " of the gap (held out " + fmt(top->heldout_explained, "%.2f") + ")";
    } else {
      d.verdict = "unexplained";
      why = "a gap along the signatures of " + top->name + " and " + second->name + " (likelihood ratios " +
            fmt(top->lr, "%.1f") + " and " + fmt(second->lr, "%.1f") + ", thresholds " + fmt(top->lr_threshold, "%.1f") +
            " and " + fmt(second->lr_threshold, "%.1f") + "): too close to tell apart";
    }
  } else if (!d.significant) {
    d.verdict = "none";
    why = "the gap is within the noise (chi^2 " + fmt(d.chi2_0, "%.1f") + " over " + std::to_string(d.nfeatures) +
          " features, p = " + fmt(d.p_value, "%.2g") + "; no candidate's likelihood ratio above its threshold)";
  } else if (look_alike) {
    tie(*top, *alike, d, sep2);
  } else if (top && explains(*top) && (!second || lr_evidence(*top) - lr_evidence(*second) >= margin)) {
    d.verdict = "explained";
    d.top_effect = top->name;
  } else if (top && second && explains(*top) && explains(*second) && lr_evidence(*top) - lr_evidence(*second) < margin) {
    tie(*top, *second, d);
  } else {
    d.verdict = "unexplained";
    if (!top) why = "no candidate effects";
    else if (top->explained < 0.5) why = "the best candidate (" + top->name + ") explains " + fmt(top->explained, "%.2f") + " of the gap";
    else if (top->heldout_explained < 0.3) why = top->name + " fits but does not predict the speeds left out (" + fmt(top->heldout_explained, "%.2f") + ")";
    else if (top->at_edge) why = top->name + " needs a magnitude beyond its simulated range";
    else if (!top->detected)
      why = "the best candidate (" + top->name + ") explains " + fmt(top->explained, "%.2f") + " of the gap, but its likelihood ratio " +
            fmt(top->lr, "%.1f") + " is below its threshold " + fmt(top->lr_threshold, "%.1f") +
            " (what its signature fits of pure noise): not told from noise fitting";
    else why = top->name + " and " + second->name + " explain the gap about equally well (likelihood ratios beyond the noise's " +
               fmt(lr_evidence(*top), "%.1f") + " and " + fmt(lr_evidence(*second), "%.1f") + ", chi^2 at the fits " +
               fmt(top->chi2, "%.1f") + " and " + fmt(second->chi2, "%.1f") + ")";
  }
  if (d.verdict == "tie") widen_tie(d, separation2);
  // the fits' unexplained, where the top candidate falls short only in what its interpolated
  // signature explains: its own runs at the fitted magnitude decide (confirm_top_effect)
  d.between_knots = d.verdict == "unexplained" && top && top->detected && !top->at_edge && !look_alike &&
                    top->explained >= BETWEEN_KNOTS_MIN_EXPLAINED && (top->explained < 0.5 || top->heldout_explained < 0.3) &&
                    (!second || lr_evidence(*top) - lr_evidence(*second) >= margin);
  if (d.between_knots)
    why += " (its signature at that magnitude is interpolated between knots: it is simulated there on fresh beds "
           "before the verdict stands)";
  if (!why.empty()) d.notes.push_back("verdict: " + why);

}

}    // namespace granpen
