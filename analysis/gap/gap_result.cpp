// granpen gap, stage 12 (record): see gap_result.h.
#include "gap_result.h"

#include <utility>

namespace granpen {

namespace {

// The gap before (where): the curves, G and its parts, the omnibus test, the held-out speed;
// the "after" set to the "before" (the corrected curves the baseline's) until a confirmation
// that simulated says otherwise.
void record_where(const WhereResult &w, Diagnosis &d)
{
  d.speeds = w.before.speeds;
  for (auto &c : d.speeds)
    c.corr = c.base, c.corr_se = c.base_se, c.G_after = c.G_before, c.Gs_after = c.Gs_before, c.n_corr = c.n_base;
  d.gap_before = d.gap_after = w.before.gap;
  d.parts_before = d.parts_after = w.before.parts;
  d.n_real_min = w.before.n_real_min;
  d.n_sim = w.before.n_sim;
  d.where = w.findings;
  d.chi2_0 = w.omnibus.chi2_0;
  d.chi2_within_bound = w.omnibus.chi2_within_bound;
  d.gap_within_bound = w.before.gap_within_bound, d.scale_within_bound = w.before.scale_within_bound;
  d.p_value = w.omnibus.p_value;
  d.nfeatures = w.omnibus.nfeatures;
  d.heldout_v0 = w.heldout.v0;
  d.heldout_before = d.heldout_after = w.heldout.gap;
  d.baseline_files = w.baseline_files;
}

// Fresh runs as the "after": the gap after, its parts, the corrected curves and files.
void record_after(const AfterRuns &after, Diagnosis &d)
{
  d.gap_after = after.all();
  d.parts_after = GapParts{after.G, after.G_spec, d.n_real_min, after.runs};
  d.corrected_files = after.files;
  for (std::size_t s = 0; s < d.speeds.size() && s < after.speeds.size(); ++s) {
    auto &curve = d.speeds[s];
    const SpeedAfter &a = after.speeds[s];
    curve.n_corr = a.n;
    for (std::size_t b = 0; b < a.mean.size(); ++b) curve.corr[b] = a.mean[b], curve.corr_se[b] = a.se[b];
    curve.G_after = a.G, curve.Gs_after = a.G_spec;
  }
}

// The pair stage: its record, its verdict's sentences, and after a pair verdict its confirming
// runs as the "after" (the other member's runs filtered: their traces the corrected ones).
void record_pairs(std::optional<PairStage> pairs, const VerdictDecision &verdict, Diagnosis &d)
{
  if (!pairs || !pairs->search.entered) return;
  if (pairs->confirmation) {
    const PairConfirmation &c = *pairs->confirmation;
    const std::vector<std::string> notes = pair_verdict_notes(verdict, c.outcome);
    d.notes.insert(d.notes.end(), notes.begin(), notes.end());
    if (verdict.verdict == Verdict::pair && c.outcome.kind == PairOutcome::Kind::simulated) {
      record_after(c.after, d);
      d.tested_effect = c.filter + "+" + c.other;
      d.chi2_after = c.chi2_after, d.confirmed_fraction = c.confirmed_fraction;
      d.proj_before = c.proj_before, d.proj_after = c.proj_after;
      d.corrected_effect.clear();
      d.corrected_traces = c.corrected_traces;
    }
    if (verdict.verdict == Verdict::pair) d.next.reset();    // as after explained: nothing to measure next
  }
  pairs->search.data.clear();    // the members' model data: the stage's, not the record's
  d.pairs = std::move(pairs);
}

// The confirmation's numbers: the magnitude named, and when it simulated, the gap after, the
// corrected curves and files, the refinement and its note.
void record_confirmation(const Confirmation &c, Diagnosis &d)
{
  if (!c.effect.empty()) d.magnitude = c.magnitude, d.magnitude_unit = c.unit;
  if (c.outcome.kind != ConfirmationResult::Kind::simulated) return;
  d.tested_effect = c.tested_effect;
  d.heldout_magnitude = c.heldout_magnitude;
  d.heldout_after = c.heldout_after;
  d.proj_before = c.outcome.proj_before;
  d.proj_after = c.outcome.proj_after;
  d.chi2_after = c.outcome.chi2_after;
  d.confirmed_fraction = c.confirmed_fraction;
  record_after(c.after, d);
  if (c.second) {
    d.refined = true;
    d.refined_from = c.second->first_magnitude;
    d.gap_after_first = c.second->first_gap;
    d.proj_refined = c.second->second.sigma();
    d.notes.push_back(second_runs_note(*c.second));
  }
  d.corrected_effect = c.corrected_effect;
  d.corrected_magnitude = c.corrected_magnitude;
  d.corrected_traces = c.corrected_traces;
}

void record_blindness(const Blindness &b, Diagnosis &d)
{
  d.limits = b.limits;
  d.look_alikes = b.look_alikes;
  d.knot_bends = b.knot_bends;
  d.next = b.next;
  d.false_alarms = b.false_alarms;
  d.scale_only = b.scale_only;
}

}    // namespace

Diagnosis assemble_diagnosis(const DiagnosisInputs &in, const WhereResult &where, const FittedCandidates &fitted,
                             const VerdictDecision &fits_verdict, const Confirmation &confirmation,
                             const VerdictDecision &verdict, const Blindness &blind, std::optional<Residual> residual,
                             std::optional<PairStage> pairs)
{
  Diagnosis d;
  d.scenario = in.scenario;
  d.real_dir = in.real_dir;
  d.real_files = in.real_files;
  d.grid = in.grid;
  d.peak_end = in.peak_end;
  d.n_reference = in.n_reference;
  d.plan = in.plan;
  d.measured_false_alarms = in.measured_false_alarms;
  // the notes in the order the stages said them: the inputs', where's, the fits' verdict's,
  // a second simulation's, then the confirmation's verdict's (record_verdict)
  d.notes = in.notes;
  d.notes.insert(d.notes.end(), where.notes.begin(), where.notes.end());
  const std::vector<std::string> fits_notes = fits_verdict_notes(fits_verdict, fitted.evidence);
  d.notes.insert(d.notes.end(), fits_notes.begin(), fits_notes.end());
  record_where(where, d);
  d.ranking = fitted.evidence.ranking;
  d.magnitude_note = fitted.magnitude_note;
  d.n_null = fitted.evidence.n_null;
  record_confirmation(confirmation, d);
  record_verdict(verdict, confirmation_verdict_notes(verdict, fitted.evidence, confirmation.outcome), d);
  record_blindness(blind, d);
  record_pairs(std::move(pairs), verdict, d);
  d.residual = std::move(residual);
  d.gap_by_regime = gap_by_regime(d.grid, d.peak_end, d.speeds);
  return d;
}

}    // namespace granpen
