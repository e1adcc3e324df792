// granpen gap, stage 9 (confirm): see gap_confirm.h.
#include "gap_confirm.h"

#include "gap_plan.h"
#include "text_util.h"

#include <algorithm>
#include <cmath>

namespace granpen {

namespace {

using TH = GapThresholds;

std::string fmt(double v, const char *f = "%.4g") { return printf_number(f, v); }

// The runs' force times 1 + scale: the fit's prediction is (1 + c) M(a) (gap_fit.h,
// nuisance_scale), so runs simulated at a are that prediction only with its scale applied.
void scale_runs(std::vector<TraceRun> &runs, double scale)
{
  if (scale == 0.0) return;
  for (auto &r : runs)
    for (double &F : r.F) F *= 1.0 + scale;
}

// The nuisance scale of the prediction at magnitude a for speed hs from the other speeds (as
// the held-out fit has it), or from every speed when there is one
double heldout_scale(const EffectData &ed, double a, std::size_t hs, const Features &f)
{
  std::vector<std::size_t> rest;
  for (std::size_t s = 0; s < f.nspeeds(); ++s)
    if (s != hs || f.nspeeds() == 1) rest.push_back(s);
  return nuisance_scale(f.target, ed, a, rest);
}

// What the confirmation test reads of the stages before: the fits' route (targeted: by one
// effect's likelihood ratio) and the omnibus chi^2 over its features against the baseline
// within the calibration bound (the runs after are compared times 1 + their fitted scale:
// like with like, a scale a calibration allows is no effect's confirmation).
struct Before {
  bool targeted = false;
  double chi2_0 = 0;
  std::size_t nfeatures = 0;
};

// the fraction of the gap's chi^2 excess that fresh runs with chi^2 chi2a remove
double excess_removed(const Before &d, double chi2a)
{
  const double P = (double) d.nfeatures, excess0 = d.chi2_0 - P;
  return excess0 > 0 ? 1.0 - std::max(0.0, chi2a - P) / excess0 : 0.0;
}

// G_all at the held-out speed hs of the runs given (aligned to the real onset), their force
// times 1 + scale (the nuisance scale of the fit that predicts that speed)
double heldout_gap(RunsBySpeed runs, std::size_t hs, double scale, const Features &f, const Alignment &al)
{
  const double v = f.speeds[hs];
  align_runs(runs[v], al.onset.at(v));
  scale_runs(runs[v], scale);
  return gap_all(gap_metric(f.real[hs], ensemble_of(runs[v], al.grid, v), 0, al.grid.nbins()),
                 hs < f.spec_real.size() ? debiased_gap(f.spec_real[hs], spectrum_moments(runs[v], al.grid)) : 0.0);
}

// The runs that decide the confirmation: their chi^2, excess removed and projection are
// the confirmation's numbers; returns whether they confirm.
bool decide_by(const AfterRuns &runs, const Before &d, Confirmation &c)
{
  c.outcome.chi2_after = runs.chi2;
  c.confirmed_fraction = excess_removed(d, runs.chi2);
  c.outcome.proj_after = runs.sigma();
  return confirms(d.targeted, d.chi2_0, d.nfeatures, c.outcome.proj_before, runs.chi2, c.outcome.proj_after);
}

// The "after": these runs (gap, corrected curves, files)
void adopt(AfterRuns runs, RunsBySpeed &&aligned, Confirmation &c)
{
  c.outcome.gap_after = runs.all();
  c.after = std::move(runs);
  c.after_runs = std::move(aligned);
}

// The second simulation's chain, written once for refine and refit: its runs asked for
// (tag refine, REFINE_SEEDS), evaluated, deciding the confirmation when rec.decides, adopted
// as the "after" (the first runs' magnitude kept as the record's). False: the runs are
// needed first (step.need says which).
bool second_runs(SecondRuns rec, const std::string &what, const EffectData &ed, const Features &f, const Alignment &al,
                 const Before &d, const StageRuns &given, ConfirmStep &step, bool &confirmed)
{
  Confirmation &c = step.done;
  if (!given.count("refine")) {
    step.need = RunsNeeded{c.effect, what, {{"refine", rec.second_magnitude, {}, REFINE_SEEDS}}};
    return false;
  }
  RunsBySpeed runs = given.at("refine");
  rec.second = evaluate_after(runs, rec.second_magnitude, rec.second_scale, ed, f, al);
  if (rec.decides) confirmed = decide_by(rec.second, d, c);
  c.magnitude = rec.second_magnitude;
  c.scale = rec.second_scale;
  adopt(rec.second, std::move(runs), c);
  c.second = std::move(rec);
  return true;
}

// The confirming runs left a significant gap along the signature (refine_projection_sigmas),
// and either confirmed the effect or left more of it (a coefficient > 0: the magnitude fell
// short, as a fit on noisy knots does): the magnitude corrected by linear response, when it
// moves, is simulated on beds no step has seen; those runs are then the "after", and decide
// when the first did not confirm. No refinement: nullopt.
std::optional<SecondRuns> refinement(const EffectData &ed, const AfterRuns &first, bool confirmed, const Confirmation &c,
                                     const Features &f)
{
  const double coef = first.uu > 0 ? first.num / first.uu : 0.0;
  if (!(std::abs(c.outcome.proj_after) >= TH::refine_projection_sigmas && (confirmed || coef > 0.0))) return std::nullopt;
  const double a2 = refined_magnitude(ed, c.magnitude, coef);
  if (std::abs(a2 - c.magnitude) <= same_magnitude_tolerance(ed)) return std::nullopt;
  SecondRuns rec{SecondRuns::Why::refine, c.magnitude, a2, c.outcome.proj_after, c.outcome.chi2_after, first.all(), confirmed,
                 !confirmed, {}};
  // the refined magnitude's prediction carries its own nuisance scale, as a fit there would
  std::vector<std::size_t> all(f.nspeeds());
  for (std::size_t s = 0; s < all.size(); ++s) all[s] = s;
  rec.second_scale = nuisance_scale(f.target, ed, a2, all);
  return rec;
}

// The first runs between knots are the model at magnitude a, simulated: a knot where the
// interpolation fell short. Inserted into the effect's knots (their ensemble means, the
// measured noise model's variances; for a paired effect the same as its own noise), the fit
// of every speed gives the magnitude the blend could not. The runs come scaled by 1 + scale
// (evaluate_after): the knot is the model, unscaled (the fit applies its own scale).
EffectData with_runs_as_knot(const EffectData &ed, double a, double scale, RunsBySpeed runs, const Features &f,
                             const GapGrid &grid)
{
  EffectData out = ed;
  const std::size_t j = (std::size_t) (std::upper_bound(out.knots.begin(), out.knots.end(), a) - out.knots.begin());
  Table m, er;
  for (std::size_t s = 0; s < f.nspeeds(); ++s) {
    scale_runs(runs.at(f.speeds[s]), 1.0 / (1.0 + scale) - 1.0);
    const Ensemble en = ensemble_of(runs.at(f.speeds[s]), grid, f.speeds[s]);
    m.push_back(en.mean);
    er.push_back(model_err(en, f.cv2[s]));
  }
  out.knots.insert(out.knots.begin() + (long) j, a);
  out.mean.insert(out.mean.begin() + (long) j, m);
  out.err.insert(out.err.begin() + (long) j, er);
  out.diff_err.insert(out.diff_err.begin() + (long) j, er);
  return out;
}

// Whether the top candidate between knots sits away from every knot (at a knot, the
// interpolated signature is the simulated one: nothing to check).
bool away_from_knots(const EffectFit &top, const EffectData &ed)
{
  const double same = same_magnitude_tolerance(ed);
  bool away = true;
  for (double k : ed.knots) away = away && std::abs(top.magnitude - k) > same;
  return away;
}

// The first runs: the effect at its fitted magnitude on every speed, and at the held-out
// speed at the magnitude fitted without it (when that differs: its own runs).
bool first_runs(const EffectFit &top, std::size_t hs, bool between, const EffectData &ed, const Features &f,
                const Alignment &al, const StageRuns &given, ConfirmStep &step, AfterRuns &first,
                RunsBySpeed &corr)
{
  Confirmation &c = step.done;
  // between knots the held-out fit rests on the interpolation that fell short: the held-out
  // speed is then judged by the runs at the magnitude fitted on every speed
  c.heldout_magnitude = between ? top.magnitude : top.loso_magnitude[hs];
  const bool own_heldout = std::abs(c.heldout_magnitude - c.magnitude) > same_magnitude_tolerance(ed);
  if (!given.count("confirm")) {
    RunsNeeded need{c.effect, "confirming", {{"confirm", c.magnitude, {}, CONFIRM_SEEDS}}};
    if (own_heldout) need.sets.push_back({"heldout", c.heldout_magnitude, {deck_number(f.speeds[hs])}, CONFIRM_SEEDS});
    step.need = std::move(need);
    return false;
  }
  corr = given.at("confirm");
  const RunsBySpeed &held = own_heldout ? given.at("heldout") : corr;
  c.outcome.proj_before = signature_sigma(ed, c.magnitude, f);
  c.heldout_after = heldout_gap(held, hs, heldout_scale(ed, c.heldout_magnitude, hs, f), f, al);
  // the runs at the fitted magnitude, with the scale fitted with it
  c.scale = top.scale;
  first = evaluate_after(corr, c.magnitude, c.scale, ed, f, al);
  c.outcome.gap_after = first.all();
  c.after = first;
  return true;
}

}    // namespace

double AfterRuns::sigma() const { return uu > 0 ? num / std::sqrt(uu) : 0.0; }

AfterRuns evaluate_after(RunsBySpeed &runs, double a, double scale, const EffectData &ed, const Features &f,
                         const Alignment &al)
{
  const GapGrid &grid = al.grid;
  const std::size_t ns = f.nspeeds(), nb = grid.nbins(), P = grid.nfeatures();
  AfterRuns r;
  r.runs = 1 << 30;
  for (std::size_t s = 0; s < ns; ++s) {
    const double v = f.speeds[s];
    if (runs[v].empty()) throw InputError("no confirming runs at v0 = " + fmt(v));
    align_runs(runs[v], al.onset.at(v));
    scale_runs(runs[v], scale);
    for (const auto &x : runs[v]) r.files.push_back(x.path);
    const Ensemble eC = ensemble_of(runs[v], grid, v);
    const auto errC = model_err(eC, f.cv2[s]);
    SpeedAfter c;
    c.n = (int) eC.n();
    for (std::size_t b = 0; b < nb; ++b) c.mean.push_back(eC.mean[b]), c.se.push_back(std::sqrt(errC[b]));
    c.G = gap_metric(f.real[s], eC, 0, nb);
    c.G_spec = s < f.spec_real.size() ? debiased_gap(f.spec_real[s], spectrum_moments(runs[v], grid)) : 0.0;
    r.G += c.G / ns, r.G_spec += c.G_spec / ns;
    r.speeds.push_back(std::move(c));
    r.runs = std::min(r.runs, (int) eC.n());
    std::vector<double> ma, va, m0, v0;
    effect_predict(ed, a, s, ma, va);
    effect_predict(ed, 0.0, s, m0, v0);
    for (std::size_t k = 0; k < P; ++k) {
      const double w1 = f.target.err[s][k] + errC[k], u = ma[k] - m0[k];
      r.chi2 += std::pow(f.real[s].mean[k] - eC.mean[k], 2) / w1;
      r.num += u * (f.real[s].mean[k] - eC.mean[k]) / w1, r.uu += u * u / w1;
    }
  }
  return r;
}

double signature_sigma(const EffectData &ed, double a, const Features &f)
{
  // the gap at magnitude 0 is the baseline's within the calibration bound, as the fit has it
  std::vector<std::size_t> all(f.nspeeds());
  for (std::size_t s = 0; s < all.size(); ++s) all[s] = s;
  const double c0 = nuisance_scale(f.target, ed, 0.0, all);
  double num0 = 0, uu0 = 0;
  for (std::size_t s = 0; s < f.nspeeds(); ++s) {
    std::vector<double> ma, va, m0, v0;
    effect_predict(ed, a, s, ma, va);
    effect_predict(ed, 0.0, s, m0, v0);
    for (std::size_t k = 0; k < ma.size(); ++k) {
      const double u = ma[k] - m0[k], w0 = f.target.err[s][k] + v0[k];
      num0 += u * (f.real[s].mean[k] - (1.0 + c0) * m0[k]) / w0, uu0 += u * u / w0;
    }
  }
  return uu0 > 0 ? num0 / std::sqrt(uu0) : 0.0;
}

bool confirms(bool targeted, double chi2_0, std::size_t nfeatures, double proj_before, double chi2a, double proj_a)
{
  const double P = (double) nfeatures, noise = TH::chi2_noise_sigmas * std::sqrt(2.0 * P);
  const double excess0 = chi2_0 - P, removed = excess0 > 0 ? 1.0 - std::max(0.0, chi2a - P) / excess0 : 0.0;
  return targeted ? proj_before * proj_before - proj_a * proj_a >= TH::confirm_projection_drop2 && chi2a <= chi2_0 + noise
                  : chi2_0 - chi2a > noise && removed >= TH::confirm_excess_removed;
}

ConfirmStep confirm_top_effect(const std::map<std::string, const Effect *> &by_name, const FittedCandidates &fitted,
                               const VerdictDecision &fits_verdict, const WhereResult &where, const Features &f,
                               const Alignment &al, bool fit_only, const StageRuns &given)
{
  ConfirmStep step;
  Confirmation &c = step.done;
  using Kind = ConfirmationResult::Kind;
  const std::vector<EffectFit> &ranking = fitted.evidence.ranking;
  const Verdict verdict = fits_verdict.verdict;
  const bool between = verdict == Verdict::unexplained && fits_verdict.between_knots && !ranking.empty();
  // a scale_only verdict is confirmed as an explained one: its scale on fresh runs
  if (verdict != Verdict::explained && verdict != Verdict::scale_only && !between) return step;
  const Before d{fits_verdict.targeted, where.omnibus.chi2_within_bound, where.omnibus.nfeatures};
  const double gap_before = where.before.gap, heldout_before = where.heldout.gap;
  const EffectFit &top = ranking[0];
  const Effect &e = *by_name.at(top.name);
  const EffectData &ed = fitted.data.at(e.name);
  c.outcome.gap_before = gap_before, c.outcome.heldout_before = heldout_before, c.outcome.chi2_before = d.chi2_0;
  if (between && !away_from_knots(top, ed)) return c.outcome.kind = Kind::at_knot, step;
  if (between && fit_only) return c.outcome.kind = Kind::fit_only, step;
  c.effect = e.name, c.unit = e.unit;
  c.magnitude = c.outcome.magnitude = top.magnitude;
  if (fit_only) return c.outcome.kind = Kind::fit_only, step;
  c.outcome.kind = Kind::simulated;
  std::size_t hs = 0;
  while (hs + 1 < f.nspeeds() && f.speeds[hs] != where.heldout.v0) ++hs;
  c.tested_effect = e.name;
  AfterRuns first;
  RunsBySpeed corr;
  if (!first_runs(top, hs, between, ed, f, al, given, step, first, corr)) return step;
  bool confirmed = decide_by(first, d, c);
  c.after_runs = corr;
  if (const auto refine = refinement(ed, first, confirmed, c, f)) {
    if (!second_runs(*refine, "refining", ed, f, al, d, given, step, confirmed)) return step;
  } else if (between && !between_knots_explains(confirmed, gap_before, first.all(), heldout_before, c.heldout_after)) {
    // between knots and short: refit with the first runs as a knot, and simulate once more
    // where that fit lands (any move: this is the last try before unexplained)
    const EffectFit refit = fit_effect(f.target, with_runs_as_knot(ed, c.magnitude, c.scale, corr, f, al.grid));
    SecondRuns rec{SecondRuns::Why::refit, c.magnitude, refit.magnitude, c.outcome.proj_after, c.outcome.chi2_after,
                   first.all(), confirmed, true, {}};
    rec.second_scale = refit.scale;
    if (refit.magnitude != c.magnitude && !second_runs(rec, "refitting between knots", ed, f, al, d, given, step, confirmed))
      return step;
  }
  if (between && c.second) {
    // the held-out speed judged by the runs that are now the "after"
    // (those runs carry the all-speed scale; the held-out speed's is the other speeds')
    c.heldout_magnitude = c.magnitude;
    c.heldout_after = heldout_gap(c.after_runs, hs, (1.0 + heldout_scale(ed, c.magnitude, hs, f)) / (1.0 + c.scale) - 1.0, f, al);
  }
  // the "after" as compared: a transform effect's traces transformed, and every effect's
  // times 1 + its fitted scale (none written here: the runs as simulated are copied)
  if (by_transform(e, c.magnitude)) c.corrected_effect = e.name, c.corrected_magnitude = c.magnitude;
  const Effect *derived = c.corrected_effect.empty() ? nullptr : find_effect(c.corrected_effect);
  if (derived && !derived->transform) derived = nullptr;
  if ((derived || c.scale != 0.0) && !c.after.files.empty())
    c.corrected_traces = corrected_trace_files(c.after.files, derived, c.corrected_magnitude, c.scale);
  c.outcome.magnitude = c.magnitude;
  c.outcome.confirmed = confirmed;
  c.outcome.heldout_after = c.heldout_after;
  return step;
}

std::string second_runs_note(const SecondRuns &r)
{
  const AfterRuns &s = r.second;
  if (r.why == SecondRuns::Why::refit)
    return "magnitude refitted between knots: the runs at " + fmt(r.first_magnitude) + " (chi^2 " + fmt(r.first_chi2, "%.1f") +
           ", G_all " + fmt(r.first_gap, "%.3f") + ") taken as a knot, the fit gives " + fmt(r.second_magnitude) + ", simulated on " +
           std::to_string(REFINE_SEEDS.size()) + " more fresh beds: chi^2 " + fmt(s.chi2, "%.1f") + ", G_all " + fmt(s.all(), "%.3f") +
           "; they decide, and the gap after and the corrected traces are these";
  return "magnitude refined: the confirming runs at " + fmt(r.first_magnitude) + " left " + fmt(r.first_proj, "%.2f") +
         " sigma along the signature (chi^2 " + fmt(r.first_chi2, "%.1f") + ", G_all " + fmt(r.first_gap, "%.3f") +
         (r.first_confirmed ? "" : ": not confirmed, the magnitude short") + "); linear response gives " + fmt(r.second_magnitude) +
         ", simulated on " + std::to_string(REFINE_SEEDS.size()) + " more fresh beds: chi^2 " + fmt(s.chi2, "%.1f") + ", G_all " +
         fmt(s.all(), "%.3f") + ", " + fmt(s.sigma(), "%.2f") + " sigma; gap after and the corrected traces are these" +
         (r.decides ? "; they decide the confirmation" : "");
}

}    // namespace granpen
