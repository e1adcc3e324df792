// granpen gap, stage 8 (confirm): see gap_confirm.h.
#include "gap_confirm.h"

#include "gap_plan.h"
#include "text_util.h"

#include <algorithm>
#include <cmath>

namespace granpen {

namespace {

std::string fmt(double v, const char *f = "%.4g") { return printf_number(f, v); }

// the fraction of the gap's chi^2 excess that fresh runs with chi^2 chi2a remove
double excess_removed(const Diagnosis &d, double chi2a)
{
  const double P = (double) d.nfeatures, excess0 = d.chi2_0 - P;
  return excess0 > 0 ? 1.0 - std::max(0.0, chi2a - P) / excess0 : 0.0;
}

// the runs of e at magnitude a that confirm_requests(..., tag, seeds) made (a transform
// effect's: the baseline's pushes on those beds, transformed)
RunsBySpeed effect_runs(const SimContext &sim, const Effect &e, double a, const std::string &tag,
                        const std::vector<std::string> &seeds = CONFIRM_SEEDS)
{
  RunsBySpeed runs = load_sweep_runs(sim.runner.out_root, confirm_sweep(e, a, tag, seeds));
  return by_transform(e, a) ? transformed_runs(e, a, runs) : runs;
}

void run_or_throw(const std::vector<SimRequest> &req, const SimContext &sim, const char *what)
{
  if (run_requests(req, sim.runner) != 0)
    throw InputError(std::string(what) + " simulations failed: see the manifests under " + sim.runner.out_root +
                     " (rerun to retry)");
}

// A second simulation of e at magnitude a2 on REFINE_SEEDS's fresh beds, after the first
// runs fell short: its runs (into runs2) and their evaluation against the real traces.
AfterRuns simulate_second_runs(const Effect &e, const EffectData &ed, double a2, const Features &f, const Alignment &al,
                               const SimContext &sim, Diagnosis &d, RunsBySpeed &runs2, const char *what)
{
  run_or_throw(confirm_requests(sim.scenario, e, a2, sim.v0s, "refine", REFINE_SEEDS), sim, what);
  runs2 = effect_runs(sim, e, a2, "refine", REFINE_SEEDS);
  return evaluate_after(runs2, a2, ed, f, al, d);
}

// The second runs decide the confirmation: their chi^2, excess removed and projection
// are the confirmation's numbers.
bool second_runs_decide(const AfterRuns &second, Diagnosis &d)
{
  d.chi2_after = second.chi2;
  d.confirmed_fraction = excess_removed(d, second.chi2);
  d.proj_after = second.sigma();
  return confirms(d, second.chi2, d.proj_after);
}

// The second runs at a2 become the "after" (gap, parts, corrected traces); the first runs'
// magnitude and G_all are kept as refined_from and gap_after_first.
void adopt_second_runs(const AfterRuns &second, RunsBySpeed &&runs2, double a2, double gap_first, Diagnosis &d,
                       RunsBySpeed &after)
{
  d.refined = true;
  d.refined_from = d.magnitude;
  d.gap_after_first = gap_first;
  d.proj_refined = second.sigma();
  d.magnitude = a2;
  d.gap_after = second.all();
  d.parts_after = GapParts{second.G, second.G_spec, d.n_real_min, second.runs};
  after = std::move(runs2);
}

// The confirming runs left a significant gap along the signature (|sigma| >= 3), and
// either confirmed the effect or left more of it (c > 0: the magnitude fell short, as a
// fit on noisy knots does): the magnitude corrected by linear response is simulated on
// beds no step has seen; those runs are then the "after", and decide when the first did
// not confirm. Returns whether the effect stands.
bool refine(const Effect &e, const EffectData &ed, const AfterRuns &first, bool confirmed, const Features &f,
            const Alignment &al, const SimContext &sim, Diagnosis &d, RunsBySpeed &after)
{
  const double c = first.uu > 0 ? first.num / first.uu : 0.0;
  if (!(std::abs(d.proj_after) >= 3.0 && (confirmed || c > 0.0))) return confirmed;
  const auto [alo, ahi] = magnitude_range(ed);
  const double a2 = refined_magnitude(ed, d.magnitude, c);
  if (std::abs(a2 - d.magnitude) <= 0.05 * (ahi - alo)) return confirmed;
  RunsBySpeed runs2;
  const AfterRuns second = simulate_second_runs(e, ed, a2, f, al, sim, d, runs2, "refining");
  std::string how = "the confirming runs at " + fmt(d.magnitude) + " left " + fmt(d.proj_after, "%.2f") +
                    " sigma along the signature (chi^2 " + fmt(d.chi2_after, "%.1f") + ", G_all " + fmt(first.all(), "%.3f") +
                    (confirmed ? "" : ": not confirmed, the magnitude short") + "); linear response gives " + fmt(a2) +
                    ", simulated on " + std::to_string(REFINE_SEEDS.size()) + " more fresh beds: chi^2 " +
                    fmt(second.chi2, "%.1f") + ", G_all " + fmt(second.all(), "%.3f") + ", " + fmt(second.sigma(), "%.2f") +
                    " sigma; gap after and the corrected traces are these";
  if (!confirmed) {
    confirmed = second_runs_decide(second, d);
    how += "; they decide the confirmation";
  }
  d.notes.push_back("magnitude refined: " + how);
  adopt_second_runs(second, std::move(runs2), a2, first.all(), d, after);
  return confirmed;
}

// The first runs between knots are the model at magnitude a, simulated: a knot where the
// interpolation fell short. Inserted into the effect's knots (their ensemble means, the
// measured noise model's variances; for a paired effect the same as its own noise), the fit
// of every speed gives the magnitude the blend could not.
EffectData with_runs_as_knot(const EffectData &ed, double a, const RunsBySpeed &runs, const Features &f, const GapGrid &grid)
{
  EffectData out = ed;
  const std::size_t j = (std::size_t) (std::upper_bound(out.knots.begin(), out.knots.end(), a) - out.knots.begin());
  Table m, er;
  for (std::size_t s = 0; s < f.nspeeds(); ++s) {
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

}    // namespace

double AfterRuns::sigma() const { return uu > 0 ? num / std::sqrt(uu) : 0.0; }

void after_is_before(const RunsBySpeed &fresh, Diagnosis &d)
{
  for (auto &c : d.speeds)
    c.corr = c.base, c.corr_se = c.base_se, c.G_after = c.G_before, c.Gs_after = c.Gs_before, c.n_corr = c.n_base;
  d.gap_after = d.gap_before;
  d.parts_after = d.parts_before;
  for (const auto &r : fresh)
    for (const auto &x : r.second) d.baseline_files.push_back(x.path);
  std::size_t hs = 0;
  for (std::size_t s = 0; s < d.speeds.size(); ++s)
    if (d.speeds[s].all_before() > d.speeds[hs].all_before()) hs = s;
  d.heldout_v0 = d.speeds.empty() ? 0.0 : d.speeds[hs].v0;
  d.heldout_before = d.heldout_after = d.speeds.empty() ? 0.0 : d.speeds[hs].all_before();
}

AfterRuns evaluate_after(RunsBySpeed &runs, double a, const EffectData &ed, const Features &f, const Alignment &al,
                         Diagnosis &d)
{
  const GapGrid &grid = al.grid;
  const std::size_t ns = f.nspeeds(), nb = grid.nbins(), P = grid.nfeatures();
  AfterRuns r;
  r.runs = 1 << 30;
  d.corrected_files.clear();
  for (std::size_t s = 0; s < ns; ++s) {
    const double v = f.speeds[s];
    if (runs[v].empty()) throw InputError("no confirming runs at v0 = " + fmt(v));
    align_runs(runs[v], al.onset.at(v));
    for (const auto &x : runs[v]) d.corrected_files.push_back(x.path);
    const Ensemble eC = ensemble_of(runs[v], grid, v);
    const auto errC = model_err(eC, f.cv2[s]);
    auto &c = d.speeds[s];
    c.n_corr = (int) eC.n();
    for (std::size_t b = 0; b < nb; ++b) c.corr[b] = eC.mean[b], c.corr_se[b] = std::sqrt(errC[b]);
    c.G_after = gap_metric(f.real[s], eC, 0, nb);
    c.Gs_after = s < f.spec_real.size() ? debiased_gap(f.spec_real[s], spectrum_moments(runs[v], grid)) : 0.0;
    r.G += c.G_after / ns, r.G_spec += c.Gs_after / ns;
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
  double num0 = 0, uu0 = 0;
  for (std::size_t s = 0; s < f.nspeeds(); ++s) {
    std::vector<double> ma, va, m0, v0;
    effect_predict(ed, a, s, ma, va);
    effect_predict(ed, 0.0, s, m0, v0);
    for (std::size_t k = 0; k < ma.size(); ++k) {
      const double u = ma[k] - m0[k], w0 = f.target.err[s][k] + v0[k];
      num0 += u * (f.real[s].mean[k] - m0[k]) / w0, uu0 += u * u / w0;
    }
  }
  return uu0 > 0 ? num0 / std::sqrt(uu0) : 0.0;
}

bool confirms(const Diagnosis &d, double chi2a, double proj_a)
{
  const double P = (double) d.nfeatures;
  return d.targeted ? d.proj_before * d.proj_before - proj_a * proj_a >= 9.0 && chi2a <= d.chi2_0 + 3.0 * std::sqrt(2.0 * P)
                    : d.chi2_0 - chi2a > 3.0 * std::sqrt(2.0 * P) && excess_removed(d, chi2a) >= 0.25;
}

bool gap_shrinks(double before, double after) { return std::isfinite(after) && after <= GAP_SHRINK_EXPLAINED * before; }

RunsBySpeed confirm_top_effect(const std::map<std::string, const Effect *> &by_name,
                               const std::map<std::string, EffectData> &data, const Features &f, const Alignment &al,
                               const SimContext &sim, bool fit_only, Diagnosis &d)
{
  bool check = d.verdict == "unexplained" && d.between_knots && !d.ranking.empty();
  if (d.verdict != "explained" && !check) return {};
  const EffectFit &top = d.ranking[0];
  const Effect &e = *by_name.at(top.name);
  const EffectData &ed = data.at(e.name);
  if (check) {
    // at (or next to) a knot the interpolated signature is the simulated one: nothing to check
    const auto [lo, hi] = magnitude_range(ed);
    for (double k : ed.knots) check = check && std::abs(top.magnitude - k) > 0.05 * (hi - lo);
    d.between_knots = check;
    if (!check) return {};
    if (fit_only) {
      d.notes.push_back("verdict provisional (--fit-only): " + top.name + " at " + fmt(top.magnitude) +
                        " would be simulated between its knots on fresh seeds; without those runs it stays unexplained");
      return {};
    }
  }
  d.top_effect = e.name;
  d.magnitude = top.magnitude;
  d.magnitude_unit = e.unit;
  if (fit_only) {
    d.provisional = true;
    d.notes.push_back("verdict provisional (--fit-only): " + d.top_effect + " was not simulated on fresh seeds, "
                      "so the gap after is the gap before");
    return {};
  }
  std::size_t hs = 0;
  while (hs + 1 < f.nspeeds() && f.speeds[hs] != d.heldout_v0) ++hs;
  d.tested_effect = e.name;
  // between knots the held-out fit rests on the interpolation that fell short: the held-out
  // speed is then judged by the runs at the magnitude fitted on every speed
  d.heldout_magnitude = check ? top.magnitude : top.loso_magnitude[hs];
  auto req = confirm_requests(sim.scenario, e, d.magnitude, sim.v0s, "confirm");
  const auto [alo, ahi] = magnitude_range(ed);
  const bool own_heldout = std::abs(d.heldout_magnitude - d.magnitude) > 0.05 * (ahi - alo);
  if (own_heldout)
    for (auto &h : confirm_requests(sim.scenario, e, d.heldout_magnitude, {deck_number(f.speeds[hs])}, "heldout"))
      // a push-only effect's held-out runs push into the same fresh beds (confirm_beds): once
      if (std::none_of(req.begin(), req.end(), [&](const SimRequest &r) { return r.spec.name == h.spec.name; }))
        req.push_back(h);
  run_or_throw(req, sim, "confirming");
  RunsBySpeed corr = effect_runs(sim, e, d.magnitude, "confirm");
  RunsBySpeed held = own_heldout ? effect_runs(sim, e, d.heldout_magnitude, "heldout") : corr;
  d.proj_before = signature_sigma(ed, d.magnitude, f);
  const AfterRuns first = evaluate_after(corr, d.magnitude, ed, f, al, d);
  // G_all at the held-out speed of the runs given (aligned to the real onset)
  const auto heldout_gap = [&](RunsBySpeed &runs) {
    const double v = f.speeds[hs];
    align_runs(runs[v], al.onset.at(v));
    return gap_all(gap_metric(f.real[hs], ensemble_of(runs[v], al.grid, v), 0, al.grid.nbins()),
                   hs < f.spec_real.size() ? debiased_gap(f.spec_real[hs], spectrum_moments(runs[v], al.grid)) : 0.0);
  };
  d.heldout_after = heldout_gap(held);
  d.gap_after = first.all();
  d.parts_after = GapParts{first.G, first.G_spec, d.n_real_min, first.runs};
  d.chi2_after = first.chi2;
  d.confirmed_fraction = excess_removed(d, first.chi2);
  d.proj_after = first.sigma();
  bool confirmed = refine(e, ed, first, confirms(d, first.chi2, d.proj_after), f, al, sim, d, corr);
  if (check && !d.refined && !(confirmed && gap_shrinks(d.gap_before, d.gap_after) && gap_shrinks(d.heldout_before, d.heldout_after))) {
    // between knots and short: refit with the first runs as a knot, and simulate once more
    // where that fit lands (any move: this is the last try before unexplained)
    const EffectFit refit = fit_effect(f.target, with_runs_as_knot(ed, d.magnitude, corr, f, al.grid));
    if (refit.magnitude != d.magnitude) {
      const double a2 = refit.magnitude;
      const double g_first = d.gap_after, chi2_first = d.chi2_after;
      RunsBySpeed runs2;
      const AfterRuns second = simulate_second_runs(e, ed, a2, f, al, sim, d, runs2, "refitting between knots");
      d.notes.push_back("magnitude refitted between knots: the runs at " + fmt(d.magnitude) + " (chi^2 " + fmt(chi2_first, "%.1f") +
                        ", G_all " + fmt(g_first, "%.3f") + ") taken as a knot, the fit gives " + fmt(a2) + ", simulated on " +
                        std::to_string(REFINE_SEEDS.size()) + " more fresh beds: chi^2 " + fmt(second.chi2, "%.1f") + ", G_all " +
                        fmt(second.all(), "%.3f") + "; they decide, and the gap after and the corrected traces are these");
      confirmed = second_runs_decide(second, d);
      adopt_second_runs(second, std::move(runs2), a2, g_first, d, corr);
    }
  }
  if (check && d.refined) {
    // the held-out speed judged by the runs that are now the "after"
    d.heldout_magnitude = d.magnitude;
    d.heldout_after = heldout_gap(corr);
  }
  // a transform effect's "after" is computed: the output writes its traces transformed
  if (by_transform(e, d.magnitude)) d.corrected_effect = e.name, d.corrected_magnitude = d.magnitude;
  if (check && confirmed && gap_shrinks(d.gap_before, d.gap_after) && gap_shrinks(d.heldout_before, d.heldout_after)) {
    d.verdict = "explained";
    d.notes.push_back("verdict: explained by " + d.top_effect + " simulated between its knots at " + fmt(d.magnitude) +
                      " on fresh seeds (its interpolated signature explained " + fmt(top.explained, "%.2f") + ", held out " +
                      fmt(top.heldout_explained, "%.2f") + "): chi^2 " + fmt(d.chi2_0, "%.1f") + " -> " + fmt(d.chi2_after, "%.1f") +
                      ", G_all " + fmt(d.gap_before, "%.3f") + " -> " + fmt(d.gap_after, "%.3f") + ", at the held-out speed " +
                      fmt(d.heldout_before, "%.3f") + " -> " + fmt(d.heldout_after, "%.3f") +
                      " (the runs at the magnitude fitted on every speed: the held-out fit rests on the interpolation)");
  } else if (check) {
    d.notes.push_back("verdict: " + d.top_effect + " simulated between its knots at " + fmt(d.magnitude) +
                      " on fresh seeds did not explain the gap (" + (confirmed ? "confirmed by chi^2, " : "not confirmed by chi^2, ") +
                      "G_all " + fmt(d.gap_before, "%.3f") + " -> " + fmt(d.gap_after, "%.3f") + ", at the held-out speed " +
                      fmt(d.heldout_before, "%.3f") + " -> " + fmt(d.heldout_after, "%.3f") + "; both must halve): unexplained");
    d.top_effect.clear();
  } else if (confirmed && !gap_shrinks(d.gap_before, d.gap_after)) {
    d.notes.push_back("verdict: " + d.top_effect + " at magnitude " + fmt(d.magnitude) + " passed the chi^2 test on fresh seeds (" +
                      fmt(d.chi2_0, "%.1f") + " -> " + fmt(d.chi2_after, "%.1f") + ") but G_all did not shrink to half (" + fmt(d.gap_before, "%.3f") + " -> " + fmt(d.gap_after, "%.3f") +
                      "): the fit followed noise or a look-alike's part of the gap, not the gap: unexplained");
    d.verdict = "unexplained";
    d.top_effect.clear();
  } else if (!confirmed) {
    d.notes.push_back("verdict: " + d.top_effect + " at magnitude " + fmt(d.magnitude) +
                      " did not shrink the gap on fresh seeds (chi^2 " + fmt(d.chi2_0, "%.1f") + " -> " +
                      fmt(d.chi2_after, "%.1f") + " over " + std::to_string(d.nfeatures) + " features; along its signature " +
                      fmt(d.proj_before, "%.2f") + " -> " + fmt(d.proj_after, "%.2f") + " sigma; G_all " +
                      fmt(d.gap_before, "%.3f") + " -> " + fmt(d.gap_after, "%.3f") + "): unexplained");
    d.verdict = "unexplained";
    d.top_effect.clear();
  }
  return corr;
}

}    // namespace granpen
