// granpen gap, stage 8 (verdict): every rule of the verdict (see gap_verdict.h).
#include "gap_verdict.h"

#include "gap_result.h"
#include "text_util.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>

namespace granpen {

namespace {

using TH = GapThresholds;

std::string fmt(double v, const char *f = "%.4g") { return printf_number(f, v); }

// a candidate that would be the answer on its own: explains at least half of the gap,
// predicts the speeds left out, fits inside its simulated range, and is detected: its
// likelihood ratio above its null-calibrated threshold, what its signature fits of pure
// noise (on the omnibus route too: a significant gap says something is there, not that a
// noisy signature's fit of it is more than noise)
bool explains(const EffectFit &f)
{
  return f.explained >= TH::explained_min && f.heldout_explained >= TH::heldout_explained_min && !f.at_edge && f.detected;
}

bool in_tie(const VerdictDecision &v, const std::string &name)
{
  return std::find(v.tie.begin(), v.tie.end(), name) != v.tie.end();
}

// the top two both explain the gap and are not told apart: the answer names both. sep2 >= 0:
// their fitted predictions differ by sep2 only (said when their evidence is the margin apart)
void tie(const EffectFit &top, const EffectFit &second, VerdictRule rule, double sep2, VerdictDecision &v)
{
  v.verdict = Verdict::tie;
  v.rule = rule;
  v.tie = {top.name, second.name};
  v.tie_record = {{top.name, 0.0, -1.0}, {second.name, lr_evidence(top) - lr_evidence(second), sep2}};
}

// Once the top ties, every further candidate that the data cannot tell from the top
// either (it explains the gap on its own, and its evidence is within the margin of the
// top's or its fitted prediction within the knots' noise of the top's) joins the tie:
// naming two of three look-alikes would drop one the data allow as much (a noiseless
// transform signature, as force_scale's, outranks two noisy pour-level ones that fit the
// data better).
void widen_tie(const FitEvidence &fits, VerdictDecision &v)
{
  const auto &ranking = fits.ranking;
  const EffectFit &top = ranking[0];
  for (std::size_t i = 0; i < ranking.size(); ++i) {
    const EffectFit &c = ranking[i];
    if (in_tie(v, c.name) || !explains(c)) continue;
    const double gap = lr_evidence(top) - lr_evidence(c);
    const double known = fits.separation2_to_top[i];
    const double sep2 = gap < TH::evidence_margin || std::isnan(known) ? -1 : known;
    if (gap >= TH::evidence_margin && !(sep2 >= 0 && sep2 < TH::evidence_margin)) continue;
    v.tie.push_back(c.name);
    v.tie_record.push_back({c.name, gap, sep2});
  }
  // best first, as the ranking
  std::vector<std::string> ordered;
  for (const auto &c : ranking)
    if (in_tie(v, c.name)) ordered.push_back(c.name);
  v.tie = ordered;
}

// A physical effect is not named alone where the data cannot tell it from another candidate
// at a magnitude below that one's detection limit (issue 37, section 0): its own test could
// not have seen it, so its silence rules nothing out. Every such candidate (its nearest
// prediction within the evidence margin of the top's fitted one) makes a tie with the top,
// whether or not its own fit explains the gap (the rule asks what the top's prediction could
// be, not what the other's fit found in the noise). The confirmation cannot decide it: the
// top's fresh runs reproduce a gap the other makes as well.
void tie_below_limit(const FitEvidence &fits, VerdictDecision &v)
{
  const auto &ranking = fits.ranking;
  std::vector<TieMember> members;
  for (std::size_t i = 1; i < ranking.size() && i < fits.mimic2_of_top.size(); ++i) {
    const double d2 = fits.mimic2_of_top[i];
    if (d2 < TH::evidence_margin) members.push_back({ranking[i].name, lr_evidence(ranking[0]) - lr_evidence(ranking[i]), d2});
  }
  if (members.empty()) return;
  v.verdict = Verdict::tie, v.rule = VerdictRule::below_limit_look_alike;
  v.top_effect.clear();
  v.tie = {ranking[0].name};
  v.tie_record = {{ranking[0].name, 0.0, -1.0}};
  for (const auto &m : members) v.tie.push_back(m.name), v.tie_record.push_back(m);
}

// The fits' rules (gap_verdict.h): the verdict before any confirming run.
VerdictDecision decide_from_fits(const FitEvidence &fits)
{
  VerdictDecision v;
  const auto &ranking = fits.ranking;
  const bool omnibus = fits.omnibus;
  v.targeted = !omnibus && std::any_of(ranking.begin(), ranking.end(), [](const EffectFit &f) { return f.detected; });
  v.significant = omnibus || v.targeted;
  const double margin = TH::evidence_margin;
  const EffectFit *top = ranking.empty() ? nullptr : &ranking[0];
  const EffectFit *second = ranking.size() > 1 ? &ranking[1] : nullptr;
  // a second that would explain the gap on its own, with a fitted prediction within the
  // knots' noise of the top's: the two are not told apart by the evidence margin alone
  // (the first such in the ranking, not only the second: a further candidate ranked in
  // between, as a new effect in the library may be, must not hide a look-alike of the top)
  double sep2 = -1;
  const EffectFit *alike = nullptr;
  for (std::size_t i = 1; top && !alike && i < ranking.size(); ++i) {
    if (!explains(ranking[i]) || std::isnan(fits.separation2_to_top[i])) continue;
    sep2 = fits.separation2_to_top[i];
    if (sep2 >= margin) sep2 = -1;
    else alike = &ranking[i];
  }
  const bool look_alike = sep2 >= 0 && explains(*top);
  const bool top_leads = top && (!second || lr_evidence(*top) - lr_evidence(*second) >= margin);
  if (v.targeted) {
    // one candidate's signature stands out: it must stand out alone (a second detected one
    // at least the margin behind) and, as on the omnibus route, explain at least half of the
    // gap and predict the speeds left out
    const bool alone = (!second || !second->detected || lr_evidence(*top) - lr_evidence(*second) >= margin) && !look_alike;
    if (look_alike) tie(*top, *alike, VerdictRule::look_alike, sep2, v);
    else if (alone && top->detected && top->explained >= TH::explained_min && top->heldout_explained >= TH::heldout_explained_min)
      v.verdict = Verdict::explained, v.rule = VerdictRule::targeted_explained;
    else if (!alone && explains(*top) && explains(*second)) tie(*top, *second, VerdictRule::tie_by_margin, -1, v);
    else v.verdict = Verdict::unexplained, v.rule = alone ? VerdictRule::targeted_weak : VerdictRule::targeted_close;
  } else if (!v.significant) {
    v.verdict = Verdict::none, v.rule = VerdictRule::within_noise;
  } else if (look_alike) {
    tie(*top, *alike, VerdictRule::look_alike, sep2, v);
  } else if (top && explains(*top) && top_leads) {
    v.verdict = Verdict::explained, v.rule = VerdictRule::omnibus_explained;
  } else if (top && second && explains(*top) && explains(*second) && !top_leads) {
    tie(*top, *second, VerdictRule::tie_by_margin, -1, v);
  } else {
    v.verdict = Verdict::unexplained;
    v.rule = !top                                                    ? VerdictRule::no_candidates
             : top->explained < TH::explained_min                    ? VerdictRule::explains_too_little
             : top->heldout_explained < TH::heldout_explained_min    ? VerdictRule::heldout_too_little
             : top->at_edge                                          ? VerdictRule::at_edge
             : !top->detected                                        ? VerdictRule::not_detected
                                                                     : VerdictRule::too_close;
  }
  if (v.verdict == Verdict::explained) v.top_effect = top->name;
  if (v.verdict == Verdict::tie) widen_tie(fits, v);
  // the fits' unexplained, where the top candidate falls short only in what its interpolated
  // signature explains: its own runs at the fitted magnitude decide (the confirmation)
  v.between_knots = v.verdict == Verdict::unexplained && top && top->detected && !top->at_edge && !look_alike &&
                    top->explained >= TH::between_knots_min_explained &&
                    (top->explained < TH::explained_min || top->heldout_explained < TH::heldout_explained_min) && top_leads;
  return v;
}

// Per candidate, the conditions of explains() it fails, with their numbers, and how far
// behind the top it ranks; the top's failed confirmation (fresh runs simulated) too.
std::vector<CandidateRecord> candidate_records(const FitEvidence &fits, const ConfirmationResult *c)
{
  using K = Shortfall::Kind;
  std::vector<CandidateRecord> out;
  const auto &ranking = fits.ranking;
  for (std::size_t i = 0; i < ranking.size(); ++i) {
    const EffectFit &f = ranking[i];
    CandidateRecord r{f.name, {}};
    if (!(f.lr > f.lr_threshold)) r.shortfalls.push_back({K::not_detected, f.lr, f.lr_threshold, "", false});
    if (f.at_edge) r.shortfalls.push_back({K::at_edge, f.magnitude, 0.0, "", false});
    if (f.explained < TH::explained_min) r.shortfalls.push_back({K::explains_too_little, f.explained, TH::explained_min, "", false});
    if (f.heldout_explained < TH::heldout_explained_min)
      r.shortfalls.push_back({K::heldout_too_little, f.heldout_explained, TH::heldout_explained_min, "", false});
    if (i > 0)
      r.shortfalls.push_back({K::less_evidence, lr_evidence(ranking[0]) - lr_evidence(f), TH::evidence_margin, ranking[0].name, false});
    if (i == 0 && c && c->kind == ConfirmationResult::Kind::simulated && !(c->confirmed && gap_shrinks(c->gap_before, c->gap_after)))
      r.shortfalls.push_back({K::not_confirmed, c->gap_after, TH::gap_shrink_explained * c->gap_before, "", c->confirmed});
    out.push_back(r);
  }
  return out;
}

// scale_only's sentence: the scale as a percentage at every depth and speed, against the
// calibration bound, from the scale candidate's fit (magnitude, error, likelihood ratio)
std::string scale_only_note(const EffectFit &top, const FitEvidence &fits)
{
  const double pct = 100.0 * top.magnitude;
  std::string s = "verdict: scale only: the force is " + fmt(std::fabs(pct), "%.1f") + "% " + (pct >= 0 ? "high" : "low") +
                  " at every depth and speed (" + top.name + " " + fmt(top.magnitude, "%+.3f");
  if (std::isfinite(top.magnitude_error)) s += " +- " + fmt(top.magnitude_error, "%.3f");
  s += ", beyond the +-" + fmt(100.0 * TH::calibration_scale_bound, "%g") + "% a lab's calibration allows; likelihood ratio " +
       fmt(top.lr, "%.1f") + " against its threshold " + fmt(top.lr_threshold, "%.1f") + ", explained " + fmt(top.explained, "%.2f") +
       ", held out " + fmt(top.heldout_explained, "%.2f");
  if (fits.omnibus) s += "; chi^2 " + fmt(fits.chi2_0, "%.1f") + " over " + std::to_string(fits.nfeatures) + " features";
  return s + "): a uniform scale names no physical cause. A sensor's calibration, the grains' density, or an effect "
             "whose signature looks like a scale at this noise can do it (scale_only in diagnosis.json lists them, with "
             "the measurement that tells each apart)";
}

// below_limit_look_alike's sentence, from the tie's record: each candidate's nearest prediction
// below its detection limit, and the magnitude that makes it
std::string below_limit_note(const VerdictDecision &v, const FitEvidence &fits)
{
  const EffectFit &top = fits.ranking[0];
  std::string s = "verdict: a tie: " + top.name + " explains the gap (" + fmt(top.explained, "%.2f") + ", held out " +
                  fmt(top.heldout_explained, "%.2f") + "), but the data cannot tell its fitted prediction from that of ";
  for (std::size_t i = 1; i < v.tie_record.size(); ++i) {
    const TieMember &m = v.tie_record[i];
    std::size_t j = 0;
    while (j < fits.ranking.size() && fits.ranking[j].name != m.name) ++j;
    s += (i > 1 ? (i + 1 == v.tie_record.size() ? " or " : ", ") : "") + m.name + " at " +
         fmt(j < fits.mimic_magnitude.size() ? fits.mimic_magnitude[j] : NAN) + " (" + fmt(m.separation2, "%.1f") +
         " squared standard deviations apart)";
  }
  return s + ", each below its own detection limit there (its likelihood ratio would not pass its threshold): less than the "
             "margin of " + fmt(TH::evidence_margin, "%g") + ", so the effect is not named alone (its runs on fresh seeds, "
             "if any, reproduce a gap the others make as well)";
}

}    // namespace

std::string shortfall_text(const Shortfall &s)
{
  using K = Shortfall::Kind;
  switch (s.kind) {
  case K::not_detected:
    return "its likelihood ratio " + fmt(s.value, "%.1f") + " is not above its threshold " + fmt(s.threshold, "%.1f");
  case K::at_edge: return "it needs a magnitude beyond its simulated range (fitted at the edge, " + fmt(s.value) + ")";
  case K::explains_too_little:
    return "it explains " + fmt(s.value, "%.2f") + " of the gap (" + fmt(s.threshold, "%g") + " needed)";
  case K::heldout_too_little:
    return "it does not predict the speeds left out (" + fmt(s.value, "%.2f") + ", " + fmt(s.threshold, "%g") + " needed)";
  case K::less_evidence:
    return s.other + " has " + fmt(s.value, "%.1f") + " more evidence" +
           (s.value >= s.threshold ? "" : " (within the margin of " + fmt(s.threshold, "%g") + ": not told apart by evidence)");
  case K::not_confirmed:
    return "simulated at its fitted magnitude on fresh beds, it did not shrink the gap (G_all after " + fmt(s.value, "%.3f") +
           ", at most " + fmt(s.threshold, "%.3f") + " needed" + (s.confirmed_by_chi2 ? "; the chi^2 test passed" : "") + ")";
  }
  return "";
}

const char *verdict_name(Verdict v)
{
  switch (v) {
  case Verdict::none: return "none";
  case Verdict::explained: return "explained";
  case Verdict::tie: return "tie";
  case Verdict::unexplained: return "unexplained";
  case Verdict::scale_only: return "scale_only";
  case Verdict::pair: return "pair";
  }
  return "none";
}

void rank_by_evidence(std::vector<EffectFit> &ranking)
{
  // candidates compared by their likelihood ratio beyond what noise gives along their
  // signatures (on both routes: the null mean's excess is what a noisier signature fits of
  // any noise, an additive share)
  std::sort(ranking.begin(), ranking.end(), [&](const EffectFit &a, const EffectFit &b) { return lr_evidence(a) > lr_evidence(b); });
}

FitEvidence fit_evidence(bool omnibus, std::vector<EffectFit> ranking, const Separation2 &separation2, const Mimic2 &mimic2)
{
  FitEvidence ev;
  ev.omnibus = omnibus;
  rank_by_evidence(ranking);
  ev.ranking = std::move(ranking);
  // the separation matters only for a candidate that explains the gap on its own
  ev.separation2_to_top.assign(ev.ranking.size(), std::nan(""));
  for (std::size_t i = 1; separation2 && i < ev.ranking.size(); ++i)
    if (explains(ev.ranking[i])) ev.separation2_to_top[i] = separation2(ev.ranking[0], ev.ranking[i]);
  // the mimic matters only for a candidate its own test does not see (a detected one is weighed
  // by the evidence margin and the look-alike rule)
  ev.mimic2_of_top.assign(ev.ranking.size(), std::nan(""));
  ev.mimic_magnitude.assign(ev.ranking.size(), std::nan(""));
  for (std::size_t i = 1; mimic2 && i < ev.ranking.size(); ++i)
    if (!ev.ranking[i].detected) std::tie(ev.mimic2_of_top[i], ev.mimic_magnitude[i]) = mimic2(ev.ranking[0], ev.ranking[i]);
  return ev;
}

bool gap_shrinks(double before, double after) { return std::isfinite(after) && after <= TH::gap_shrink_explained * before; }

bool between_knots_explains(bool confirmed, double gap_before, double gap_after, double heldout_before, double heldout_after)
{
  return confirmed && gap_shrinks(gap_before, gap_after) && gap_shrinks(heldout_before, heldout_after);
}

namespace {

// The confirmation's rules (gap_verdict.h) on the fits' decision v.
void apply_confirmation(const FitEvidence &fits, const ConfirmationResult &c, VerdictDecision &v)
{
  using Kind = ConfirmationResult::Kind;
  if (v.between_knots) {
    // at (or next to) a knot the interpolated signature is the simulated one: the fits' verdict
    if (c.kind == Kind::at_knot) v.between_knots = false;
    else if (c.kind == Kind::fit_only) v.confirmation = ConfirmationRule::between_knots_fit_only;
    else if (c.kind == Kind::simulated) {
      const bool explained = between_knots_explains(c.confirmed, c.gap_before, c.gap_after, c.heldout_before, c.heldout_after);
      v.confirmation = explained ? ConfirmationRule::between_knots_explained : ConfirmationRule::between_knots_short;
      if (explained) v.verdict = Verdict::explained, v.top_effect = fits.ranking[0].name;
    }
  } else if (v.verdict == Verdict::explained && c.kind == Kind::fit_only) {
    v.provisional = true;
    v.confirmation = ConfirmationRule::provisional;
  } else if (v.verdict == Verdict::explained && c.kind == Kind::simulated) {
    // kept only when the fresh runs confirm it and halve G_all
    v.confirmation = !c.confirmed                            ? ConfirmationRule::not_confirmed
                     : !gap_shrinks(c.gap_before, c.gap_after) ? ConfirmationRule::not_halved
                                                             : ConfirmationRule::confirmed;
    if (v.confirmation != ConfirmationRule::confirmed) v.verdict = Verdict::unexplained, v.top_effect.clear();
  }
}

// The pair stage's rules on an unexplained verdict: its pair stands as an explained effect
// does, on fresh runs that confirm it and halve G_all (--fit-only: provisional).
void apply_pair(const PairOutcome &p, VerdictDecision &v)
{
  if (v.verdict != Verdict::unexplained || p.effects.size() != 2 || p.kind == PairOutcome::Kind::none) return;
  if (p.kind == PairOutcome::Kind::fit_only) v.pair_rule = PairRule::provisional, v.provisional = true;
  else v.pair_rule = !p.confirmed                              ? PairRule::not_confirmed
                     : !gap_shrinks(p.gap_before, p.gap_after) ? PairRule::not_halved
                                                               : PairRule::explained;
  if (v.pair_rule == PairRule::explained || v.pair_rule == PairRule::provisional) v.verdict = Verdict::pair, v.pair = p.effects;
}

}    // namespace

VerdictDecision decide_verdict(const FitEvidence &fits, const ConfirmationResult *c, const PairOutcome *pair)
{
  VerdictDecision v = decide_from_fits(fits);
  if (c) apply_confirmation(fits, *c, v);
  if (pair) apply_pair(*pair, v);
  // the verdict that stands (after the confirmation): a physical effect named alone
  if (c && v.verdict == Verdict::explained && !fits.ranking[0].is_scale) tie_below_limit(fits, v);
  v.candidates = candidate_records(fits, c);
  // a uniform scale explains the gap: a finding of its own kind, no physical effect named
  if (v.verdict == Verdict::explained && fits.ranking[0].is_scale) {
    v.verdict = Verdict::scale_only, v.rule = VerdictRule::scale_explains;
    v.scale_effect = v.top_effect, v.top_effect.clear();
  }
  return v;
}

std::vector<std::string> fits_verdict_notes(const VerdictDecision &v, const FitEvidence &fits)
{
  std::vector<std::string> notes;
  const auto &ranking = fits.ranking;
  const EffectFit *top = ranking.empty() ? nullptr : &ranking[0];
  const EffectFit *second = ranking.size() > 1 ? &ranking[1] : nullptr;
  const auto fit_of = [&](const std::string &name) -> const EffectFit & {
    return *std::find_if(ranking.begin(), ranking.end(), [&](const EffectFit &f) { return f.name == name; });
  };
  if (v.verdict == Verdict::tie) {
    const EffectFit &b = fit_of(v.tie_record[1].name);
    const double gap = v.tie_record[1].evidence_gap, sep2 = v.tie_record[1].separation2;
    const bool by_margin = sep2 < 0 || gap < TH::evidence_margin;
    const std::string why =
        by_margin ? "their evidence differs by " + fmt(gap, "%.1f") + ", less than the margin of " + fmt(TH::evidence_margin, "%g")
                  : "their evidence differs by " + fmt(gap, "%.1f") + ", but their fitted predictions only by " + fmt(sep2, "%.1f") +
                        " squared standard deviations beyond their knots' noise, less than the margin of " +
                        fmt(TH::evidence_margin, "%g") + " (the difference in evidence is the knots' noise)";
    notes.push_back("verdict: a tie between " + top->name + " and " + b.name + ": each explains the gap (" +
                    fmt(top->explained, "%.2f") + " and " + fmt(b.explained, "%.2f") + ", held out " +
                    fmt(top->heldout_explained, "%.2f") + " and " + fmt(b.heldout_explained, "%.2f") + ") and " + why +
                    ": at this noise they look alike (next_measurement says what would separate them)");
    for (std::size_t i = 2; i < v.tie_record.size(); ++i) {
      const TieMember &m = v.tie_record[i];
      const EffectFit &c = fit_of(m.name);
      notes.push_back("verdict: " + c.name + " joins the tie: it explains the gap (" + fmt(c.explained, "%.2f") + ", held out " +
                      fmt(c.heldout_explained, "%.2f") + ") and " +
                      (m.evidence_gap < TH::evidence_margin
                           ? "its evidence is " + fmt(m.evidence_gap, "%.1f") + " below " + top->name + "'s, within the margin"
                           : "its fitted prediction lies " + fmt(m.separation2, "%.1f") + " squared standard deviations from " +
                                 top->name + "'s beyond their knots' noise"));
    }
    return notes;
  }
  std::string why;
  switch (v.rule) {
  case VerdictRule::targeted_explained:
    notes.push_back("the gap is within the noise over all features (chi^2 " + fmt(fits.chi2_0, "%.1f") + " over " +
                    std::to_string(fits.nfeatures) + ", p = " + fmt(fits.p_value, "%.2g") + ") but lies along " + top->name +
                    "'s signature: likelihood ratio " + fmt(top->lr, "%.1f") + " against a threshold of " +
                    fmt(top->lr_threshold, "%.1f") + " (" + std::to_string(fits.n_null) + " null replicates on the reference beds)");
    return notes;
  case VerdictRule::omnibus_explained: return notes;
  case VerdictRule::scale_explains:
    notes.push_back(scale_only_note(*top, fits));
    return notes;
  case VerdictRule::targeted_weak:
    why = "a gap along " + top->name + "'s signature (likelihood ratio " + fmt(top->lr, "%.1f") + " against " +
          fmt(top->lr_threshold, "%.1f") + "), but it explains only " + fmt(top->explained, "%.2f") + " of the gap (held out " +
          fmt(top->heldout_explained, "%.2f") + ")";
    break;
  case VerdictRule::targeted_close:
    why = "a gap along the signatures of " + top->name + " and " + second->name + " (likelihood ratios " + fmt(top->lr, "%.1f") +
          " and " + fmt(second->lr, "%.1f") + ", thresholds " + fmt(top->lr_threshold, "%.1f") + " and " +
          fmt(second->lr_threshold, "%.1f") + "): too close to tell apart";
    break;
  case VerdictRule::within_noise:
    why = "the gap is within the noise (chi^2 " + fmt(fits.chi2_0, "%.1f") + " over " + std::to_string(fits.nfeatures) +
          " features, p = " + fmt(fits.p_value, "%.2g") + "; no candidate's likelihood ratio above its threshold)";
    break;
  case VerdictRule::no_candidates: why = "no candidate effects"; break;
  case VerdictRule::explains_too_little:
    why = "the best candidate (" + top->name + ") explains " + fmt(top->explained, "%.2f") + " of the gap";
    break;
  case VerdictRule::heldout_too_little:
    why = top->name + " fits but does not predict the speeds left out (" + fmt(top->heldout_explained, "%.2f") + ")";
    break;
  case VerdictRule::at_edge: why = top->name + " needs a magnitude beyond its simulated range"; break;
  case VerdictRule::not_detected:
    why = "the best candidate (" + top->name + ") explains " + fmt(top->explained, "%.2f") + " of the gap, but its likelihood ratio " +
          fmt(top->lr, "%.1f") + " is below its threshold " + fmt(top->lr_threshold, "%.1f") +
          " (what its signature fits of pure noise): not told from noise fitting";
    break;
  default:
    why = top->name + " and " + second->name + " explain the gap about equally well (likelihood ratios beyond the noise's " +
          fmt(lr_evidence(*top), "%.1f") + " and " + fmt(lr_evidence(*second), "%.1f") + ", chi^2 at the fits " +
          fmt(top->chi2, "%.1f") + " and " + fmt(second->chi2, "%.1f") + ")";
  }
  if (v.between_knots)
    why += " (its signature at that magnitude is interpolated between knots: it is simulated there on fresh beds "
           "before the verdict stands)";
  notes.push_back("verdict: " + why);
  return notes;
}

std::vector<std::string> confirmation_verdict_notes(const VerdictDecision &v, const FitEvidence &fits,
                                                    const ConfirmationResult &c)
{
  if (v.rule == VerdictRule::below_limit_look_alike) return {below_limit_note(v, fits)};
  if (v.confirmation == ConfirmationRule::none || v.confirmation == ConfirmationRule::confirmed) return {};
  const EffectFit &top = fits.ranking[0];
  const std::string gaps = "G_all " + fmt(c.gap_before, "%.3f") + " -> " + fmt(c.gap_after, "%.3f");
  const std::string heldout = ", at the held-out speed " + fmt(c.heldout_before, "%.3f") + " -> " + fmt(c.heldout_after, "%.3f");
  switch (v.confirmation) {
  case ConfirmationRule::between_knots_fit_only:
    return {"verdict provisional (--fit-only): " + top.name + " at " + fmt(top.magnitude) +
            " would be simulated between its knots on fresh seeds; without those runs it stays unexplained"};
  case ConfirmationRule::provisional:
    return {"verdict provisional (--fit-only): " + top.name + " was not simulated on fresh seeds, "
            "so the gap after is the gap before"};
  case ConfirmationRule::between_knots_explained:
    return {"verdict: explained by " + top.name + " simulated between its knots at " + fmt(c.magnitude) +
            " on fresh seeds (its interpolated signature explained " + fmt(top.explained, "%.2f") + ", held out " +
            fmt(top.heldout_explained, "%.2f") + "): chi^2 " + fmt(c.chi2_before, "%.1f") + " -> " + fmt(c.chi2_after, "%.1f") +
            ", " + gaps + heldout + " (the runs at the magnitude fitted on every speed: the held-out fit rests on the interpolation)"};
  case ConfirmationRule::between_knots_short:
    return {"verdict: " + top.name + " simulated between its knots at " + fmt(c.magnitude) + " on fresh seeds did not explain the gap (" +
            (c.confirmed ? "confirmed by chi^2, " : "not confirmed by chi^2, ") + gaps + heldout + "; both must halve): unexplained"};
  case ConfirmationRule::not_halved:
    return {"verdict: " + top.name + " at magnitude " + fmt(c.magnitude) + " passed the chi^2 test on fresh seeds (" +
            fmt(c.chi2_before, "%.1f") + " -> " + fmt(c.chi2_after, "%.1f") + ") but G_all did not shrink to half (" +
            fmt(c.gap_before, "%.3f") + " -> " + fmt(c.gap_after, "%.3f") +
            "): the fit followed noise or a look-alike's part of the gap, not the gap: unexplained"};
  default:    // not_confirmed
    return {"verdict: " + top.name + " at magnitude " + fmt(c.magnitude) + " did not shrink the gap on fresh seeds (chi^2 " +
            fmt(c.chi2_before, "%.1f") + " -> " + fmt(c.chi2_after, "%.1f") + " over " + std::to_string(fits.nfeatures) +
            " features; along its signature " + fmt(c.proj_before, "%.2f") + " -> " + fmt(c.proj_after, "%.2f") + " sigma; " + gaps +
            "): unexplained"};
  }
}

std::vector<std::string> pair_verdict_notes(const VerdictDecision &v, const PairOutcome &p)
{
  if (p.effects.size() != 2) return {};
  const std::string both = p.effects[0] + " and " + p.effects[1];
  const std::string gaps = "G_all " + fmt(p.gap_before, "%.3f") + " -> " + fmt(p.gap_after, "%.3f");
  switch (v.pair_rule) {
  case PairRule::explained: return {"verdict: explained by two effects at once, " + both + ", confirmed on fresh seeds (" + gaps + ")"};
  case PairRule::provisional:
    return {"verdict provisional (--fit-only): the pair " + both + " was not simulated on fresh seeds"};
  case PairRule::not_confirmed:
    return {"verdict: the pair " + both + " did not pass the confirmation test on fresh seeds (" + gaps + "): unexplained"};
  case PairRule::not_halved:
    return {"verdict: the pair " + both + " passed the chi^2 test on fresh seeds but G_all did not shrink to half (" + gaps +
            "): unexplained"};
  case PairRule::none: break;
  }
  return {};
}

void record_verdict(const VerdictDecision &v, const std::vector<std::string> &notes, Diagnosis &d)
{
  d.verdict = v.verdict;
  d.pair = v.pair;
  d.top_effect = v.top_effect;
  d.scale_effect = v.scale_effect;
  d.tie = v.tie;
  d.candidates = v.candidates;
  d.significant = v.significant;
  d.targeted = v.targeted;
  d.between_knots = v.between_knots;
  d.provisional = v.provisional;
  d.notes.insert(d.notes.end(), notes.begin(), notes.end());
}

}    // namespace granpen
