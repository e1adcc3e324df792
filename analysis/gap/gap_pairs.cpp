// granpen gap, stage 11b (pairs): see gap_pairs.h.
#include "gap_pairs.h"

#include "gap_plan.h"
#include "text_util.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numeric>

namespace granpen {

namespace {

using TH = GapThresholds;

std::string fmt(double v, const char *f = "%.4g") { return printf_number(f, v); }

std::size_t zero_index(const EffectData &e)
{
  for (std::size_t j = 0; j < e.knots.size(); ++j)
    if (e.knots[j] == 0.0) return j;
  return 0;
}

bool is_filter(const Effect &e) { return pair_filter(e); }
bool costs_no_pour(const Effect &e) { return !e.pour_level && !e.uniform_scale; }

// The joint model at (x, y), speed s: A's prediction plus B's signature (both on the same
// reference), and the variance the two signatures carry (taken as independent).
void pair_model(const EffectData &A, const EffectData &B, double x, double y, std::size_t s, std::vector<double> &m,
                std::vector<double> &U)
{
  std::vector<double> va, ub, vb, ua, uva;
  effect_predict(A, x, s, m, va);
  effect_signature(B, y, s, ub, vb);
  effect_signature(A, x, s, ua, uva);
  U.assign(m.size(), 0.0);
  for (std::size_t k = 0; k < m.size(); ++k) m[k] += ub[k], U[k] = uva[k] + vb[k];
}

// The weighted squared residual at (x, y) over the speeds, with the nuisance scale fitted in
// closed form (fixed weights, as every single fit's); with_signature: the signatures' own
// variance in the weights and its normalization (the likelihood ratio's, gap_fit.cpp).
double pair_residual(const Target &t, const EffectData &A, const EffectData &B, double x, double y,
                     const std::vector<std::size_t> &speeds, bool with_signature, double *scale = nullptr)
{
  const std::size_t j0 = zero_index(A);
  std::vector<std::vector<double>> ms, Us;
  double num = 0.0, den = 0.0;
  for (std::size_t s : speeds) {
    std::vector<double> m, U;
    pair_model(A, B, x, y, s, m, U);
    for (std::size_t k = 0; k < m.size(); ++k) {
      const double V = t.err[s][k] + A.err[j0][s][k];
      num += (t.mean[s][k] - m[k]) * m[k] / V, den += m[k] * m[k] / V;
    }
    ms.push_back(std::move(m)), Us.push_back(std::move(U));
  }
  const double c = A.scale_bound > 0.0 && den > 0.0 ? std::clamp(num / den, -A.scale_bound, A.scale_bound) : 0.0;
  if (scale) *scale = c;
  double r2 = 0.0;
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    const std::size_t s = speeds[i];
    for (std::size_t k = 0; k < ms[i].size(); ++k) {
      const double V = t.err[s][k] + A.err[j0][s][k], U = with_signature ? Us[i][k] : 0.0;
      r2 += std::pow(t.mean[s][k] - (1.0 + c) * ms[i][k], 2) / (V + U) + (with_signature ? std::log1p(U / V) : 0.0);
    }
  }
  return r2;
}

// The best (x, y) over both ranges: a grid, then golden sections along each axis in turn
// within a grid step (fixed weights, as best_magnitude's). edge: the grid's best on a border.
std::pair<double, double> best_pair(const Target &t, const EffectData &A, const EffectData &B,
                                    const std::vector<std::size_t> &speeds, bool *edge)
{
  const auto [alo, ahi] = magnitude_range(A);
  const auto [blo, bhi] = magnitude_range(B);
  const int n = 40;
  int bi = 0, bj = 0;
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const double r = pair_residual(t, A, B, alo + (ahi - alo) * i / n, blo + (bhi - blo) * j / n, speeds, false);
      if (r < best) best = r, bi = i, bj = j;
    }
  if (edge) *edge = bi == 0 || bi == n || bj == 0 || bj == n;
  double x = alo + (ahi - alo) * bi / n, y = blo + (bhi - blo) * bj / n;
  const double hx = (ahi - alo) / n, hy = (bhi - blo) / n;
  for (int round = 0; round < 3; ++round)
    for (int axis = 0; axis < 2; ++axis) {
      const double c = axis == 0 ? x : y, h = axis == 0 ? hx : hy;
      const double lo = std::max(axis == 0 ? alo : blo, c - h), hi = std::min(axis == 0 ? ahi : bhi, c + h);
      auto at = [&](double v) { return axis == 0 ? pair_residual(t, A, B, v, y, speeds, false) : pair_residual(t, A, B, x, v, speeds, false); };
      double x0 = lo, x1 = hi;
      for (int it = 0; it < 30; ++it) {
        const double m1 = x0 + 0.382 * (x1 - x0), m2 = x0 + 0.618 * (x1 - x0);
        if (at(m1) < at(m2)) x1 = m2;
        else x0 = m1;
      }
      const double v = 0.5 * (x0 + x1);
      if (at(v) < at(c)) (axis == 0 ? x : y) = v;
    }
  return {x, y};
}

std::vector<std::size_t> all_speeds(const Target &t)
{
  std::vector<std::size_t> s(t.mean.size());
  std::iota(s.begin(), s.end(), 0);
  return s;
}

}    // namespace

bool pair_filter(const Effect &e) { return e.transform != nullptr && !e.uniform_scale; }
bool pair_partner(const Effect &e) { return !e.pour_level && !e.uniform_scale && !pair_filter(e); }

bool pair_stage_entered(Verdict standing, const std::optional<Residual> &residual, std::string &why)
{
  if (standing != Verdict::unexplained) {
    why = std::string("not tried: the verdict is ") + verdict_name(standing) + ", not unexplained";
    return false;
  }
  if (!residual || (residual->lines.empty() && residual->band.empty())) {
    why = "not tried: the residual carries no spectral line or band (a pair is tried for a gap that moves the spectrum)";
    return false;
  }
  why = "tried: no single candidate explains the gap and the residual carries " +
        std::string(!residual->lines.empty() ? "a narrow line" : "a spectral band (" + residual->band + ")");
  return true;
}

std::vector<PairSpec> pairs_to_try(const std::vector<EffectFit> &ranking, const std::vector<const Effect *> &effects,
                                   bool residual_has_line)
{
  auto effect = [&](const std::string &name) -> const Effect * {
    for (const Effect *e : effects)
      if (e->name == name) return e;
    return nullptr;
  };
  std::vector<const Effect *> nearest;
  for (const EffectFit &r : ranking) {
    const Effect *e = effect(r.name);
    if (e && costs_no_pour(*e) && nearest.size() < PAIR_NEAREST) nearest.push_back(e);
  }
  if (residual_has_line)
    for (const Effect *e : effects)
      if (is_filter(*e) && std::find(nearest.begin(), nearest.end(), e) == nearest.end()) nearest.push_back(e);
  std::vector<PairSpec> out;
  for (const Effect *f : nearest)
    if (is_filter(*f))
      for (const Effect *o : nearest)
        if (!is_filter(*o)) out.push_back({f->name, o->name});
  return out;
}

double resonance_magnitude(const Effect &filter, double f_line)
{
  if (!filter.transform || !(f_line > 0.0)) return NAN;
  const double dt = 1e-4, a0 = reference_magnitude(filter);
  const std::size_t N = 4096;
  // an impulse a quarter in (the kernel holds the record's first value before it and pads
  // with it after: an impulse at the start would be a step down); a shift leaves |H| as it is
  std::vector<double> impulse(N, 0.0);
  impulse[N / 4] = 1.0;
  const std::vector<double> h = filter.transform(impulse, dt, a0);
  std::vector<double> mag(N / 2 + 1, 0.0);
  for (std::size_t j = 0; j < mag.size(); ++j) {
    std::complex<double> sum = 0.0;
    for (std::size_t n = 0; n < h.size() && n < N; ++n) sum += h[n] * std::polar(1.0, -2.0 * M_PI * (double) (j * n % N) / N);
    mag[j] = std::abs(sum);
  }
  const std::size_t jp = (std::size_t) (std::max_element(mag.begin() + 1, mag.end() - 1) - mag.begin());
  if (!(mag[jp] > 1.2 * mag[0])) return NAN;    // no resonance: a peak a fifth above 0 Hz's response
  const double m1 = mag[jp - 1], m0 = mag[jp], p1 = mag[jp + 1], den = m1 - 2.0 * m0 + p1;
  const double f_peak = ((double) jp + (den < 0.0 ? 0.5 * (m1 - p1) / den : 0.0)) / (N * dt);
  // a filter whose magnitude is its time scale peaks at a frequency inverse to it
  return a0 * f_peak / f_line;
}

double seeding_line(const Residual &residual)
{
  if (residual.lines.empty() || residual.line_scaling == "scales with v0") return NAN;
  const auto it = std::max_element(residual.lines.begin(), residual.lines.end(),
                                   [](const SpectralLine &a, const SpectralLine &b) { return a.sigma < b.sigma; });
  return it->freq;
}

PairFit fit_pair(const Target &t, const EffectData &A, const EffectData &B)
{
  PairFit p;
  p.a = A.name, p.b = B.name;
  const std::vector<std::size_t> all = all_speeds(t);
  const auto [x, y] = best_pair(t, A, B, all, &p.at_edge);
  p.magnitude_a = x, p.magnitude_b = y;
  p.chi2_0 = pair_residual(t, A, B, 0.0, 0.0, all, false);
  p.chi2 = pair_residual(t, A, B, x, y, all, false, &p.scale);
  p.explained = explained_fraction(p.chi2_0, p.chi2, noise_of(A, all));
  p.lr = std::max(0.0, p.chi2_0 - pair_residual(t, A, B, x, y, all, true));
  // leave one speed out: fit on the others, predict the one left out (where its gap stands out)
  double sum = 0.0;
  int used = 0;
  for (std::size_t h = 0; h < all.size(); ++h) {
    std::vector<std::size_t> rest;
    for (std::size_t s : all)
      if (s != h) rest.push_back(s);
    const double P = (double) t.mean[h].size();
    if (rest.empty() || !(effect_chi2(t, A, 0.0, {h}) - P > TH::chi2_noise_sigmas * std::sqrt(2.0 * P))) continue;
    const auto [xh, yh] = best_pair(t, A, B, rest, nullptr);
    sum += explained_fraction(pair_residual(t, A, B, 0.0, 0.0, {h}, false), pair_residual(t, A, B, xh, yh, {h}, false),
                              noise_of(A, {h}));
    ++used;
  }
  p.heldout_explained = used ? sum / used : p.explained;
  return p;
}

double pair_lr(const Target &t, const EffectData &A, const EffectData &B)
{
  const std::vector<std::size_t> all = all_speeds(t);
  const auto [x, y] = best_pair(t, A, B, all, nullptr);
  return std::max(0.0, pair_residual(t, A, B, 0.0, 0.0, all, false) - pair_residual(t, A, B, x, y, all, true));
}

double pair_lr_threshold(double lr_null_mean) { return std::max(1.0, lr_null_mean / 2.0) * TH::lr_chi2_2_p1e4; }

namespace {

// the first rule of pair_passes the fit falls short of, in words ("" when none)
std::string pair_shortfall(const PairFit &p, const EffectData &A, const EffectData &B)
{
  if (std::abs(p.magnitude_a) <= same_magnitude_tolerance(A))
    return p.a + " fitted at " + fmt(p.magnitude_a) + ", at 0: the pair is " + p.b + " alone";
  if (std::abs(p.magnitude_b) <= same_magnitude_tolerance(B))
    return p.b + " fitted at " + fmt(p.magnitude_b) + ", at 0: the pair is " + p.a + " alone";
  if (!p.detected)
    return p.at_edge ? "a magnitude at the edge of its range"
                     : "its likelihood ratio " + fmt(p.lr, "%.1f") + " is not above its threshold " + fmt(p.lr_threshold, "%.1f");
  if (p.margin < TH::lr_chi2_1_p1e4)
    return "its evidence " + fmt(p.evidence, "%.1f") + " is beyond its best single member's (" + p.best_single + ", " +
           fmt(p.best_single_evidence, "%.1f") + ") by " + fmt(p.margin, "%.1f") + ", under " + fmt(TH::lr_chi2_1_p1e4, "%.1f");
  if (p.explained < TH::explained_min)
    return "it explains " + fmt(p.explained, "%.2f") + " of the gap, under " + fmt(TH::explained_min, "%.2f");
  if (p.heldout_explained < TH::heldout_explained_min)
    return "it predicts the speeds left out to " + fmt(p.heldout_explained, "%.2f") + ", under " +
           fmt(TH::heldout_explained_min, "%.2f");
  return "";
}

}    // namespace

void judge_pair(PairFit &p, const std::vector<Target> &nulls, const EffectData &A, const EffectData &B,
                double single_evidence_a, double single_evidence_b)
{
  double sum = 0.0;
  for (const Target &t : nulls) sum += pair_lr(t, A, B);
  p.lr_null_mean = nulls.empty() ? 0.0 : sum / nulls.size();
  p.lr_threshold = pair_lr_threshold(p.lr_null_mean);
  p.detected = p.lr > p.lr_threshold && !p.at_edge;
  // the evidence beyond what noise gives along two directions (a chi^2(2) has mean 2)
  p.evidence = p.lr - std::max(0.0, p.lr_null_mean - 2.0);
  const bool a_best = single_evidence_a >= single_evidence_b;
  p.best_single = a_best ? p.a : p.b;
  p.best_single_evidence = a_best ? single_evidence_a : single_evidence_b;
  p.margin = p.evidence - p.best_single_evidence;
  p.why = pair_shortfall(p, A, B);
  p.passes = p.why.empty();
}

EffectData pair_line(const EffectData &A, const EffectData &B, double a, double b)
{
  EffectData L;
  L.name = A.name + "+" + B.name;
  L.knots = {0.0, 1.0};
  L.paired = true;
  L.one_sided = true;
  L.reach = 0.0;
  L.scale_bound = A.scale_bound;
  L.noise_r2 = A.noise_r2;
  const std::size_t j0 = zero_index(A);
  Table m1, d1, zero;
  for (std::size_t s = 0; s < A.mean[0].size(); ++s) {
    std::vector<double> m, U;
    pair_model(A, B, a, b, s, m, U);
    m1.push_back(m), d1.push_back(U), zero.push_back(std::vector<double>(m.size(), 0.0));
  }
  L.mean = {A.mean[j0], m1};
  L.err = {A.err[j0], d1};
  L.diff_err = {zero, d1};
  return L;
}

namespace {

// whether a is a new knot of ed: inside the fit's range and farther from every knot than
// same_magnitude_of_range of the segment of knots it lies in (the chain's knots are spaced by
// factors, 0.2 to 10 ms: a fraction of the whole range would call 2.4 ms the 2 ms knot)
bool new_knot(const std::vector<double> &knots, std::pair<double, double> range, double a)
{
  const auto [lo, hi] = range;
  if (!(std::isfinite(a) && a > lo && a < hi)) return false;
  const auto above = std::upper_bound(knots.begin(), knots.end(), a);
  const double segment = above == knots.begin() || above == knots.end() ? hi - lo : *above - *(above - 1);
  for (double k : knots)
    if (std::abs(a - k) <= TH::same_magnitude_of_range * segment) return false;
  return true;
}
bool new_knot(const EffectData &ed, double a) { return new_knot(ed.knots, magnitude_range(ed), a); }

}    // namespace

EffectData seed_chain_knot(const Effect &chain, const std::vector<double> &at, const SimulatedRuns &sims, const Features &f,
                           const Alignment &al, std::vector<double> &seeded)
{
  EffectData ed = effect_data(chain, f);
  seeded.clear();
  Effect with = chain;
  Features f2 = f;
  const auto range = magnitude_range(ed);
  for (double a : at) {
    std::vector<double> knots = ed.knots;    // the knots so far, seeds included
    knots.insert(knots.end(), seeded.begin(), seeded.end());
    std::sort(knots.begin(), knots.end());
    if (!new_knot(knots, range, a)) continue;
    with.knots.push_back(a);
    RunsBySpeed filtered = transformed_runs(chain, a, sims.base);
    std::vector<Ensemble> ens;
    for (double v : f.speeds) {
      align_runs(filtered[v], al.onset.at(v));
      ens.push_back(ensemble_of(filtered[v], al.grid, v));
    }
    f2.knots[effect_sweep_name(chain, a)] = std::move(ens);
    seeded.push_back(a);
  }
  if (seeded.empty()) return ed;
  std::sort(with.knots.begin(), with.knots.end());
  return effect_data(with, f2);
}

std::vector<double> segment_knots(const std::vector<double> &knots, double a)
{
  std::vector<double> out;
  for (std::size_t i = 0; i + 1 < knots.size(); ++i) {
    const double lo = knots[i], hi = knots[i + 1];
    if (!(a >= lo && a <= hi)) continue;
    const int n = lo > 0.0 ? (int) std::ceil(std::log(hi / lo) / std::log(PAIR_SEED_STEP)) : 4;
    for (int j = 1; j < n; ++j)
      out.push_back(lo > 0.0 ? lo * std::pow(hi / lo, (double) j / n) : hi * j / n);
  }
  return out;
}

PairSearch search_pairs_in(const std::vector<const Effect *> &effects, const FitEvidence &evidence,
                           std::map<std::string, EffectData> data, const Features &f, Verdict standing,
                           const std::optional<Residual> &residual, const EffectFit *seeded_single)
{
  PairSearch out;
  out.entered = pair_stage_entered(standing, residual, out.why);
  if (!out.entered) return out;
  if (seeded_single) out.seeded_single = *seeded_single;
  auto single_evidence = [&](const std::string &name) {
    double e = -std::numeric_limits<double>::infinity();
    for (const EffectFit &r : evidence.ranking)
      if (r.name == name) e = lr_evidence(r);
    if (seeded_single && seeded_single->name == name) e = std::max(e, lr_evidence(*seeded_single));
    return e;
  };
  for (const PairSpec &p : pairs_to_try(evidence.ranking, effects, !residual->lines.empty())) {
    if (!data.count(p.filter) || !data.count(p.other)) continue;
    const EffectData &A = data.at(p.filter), &B = data.at(p.other);
    PairFit fit = fit_pair(f.target, A, B);
    judge_pair(fit, f.nulls, A, B, single_evidence(p.filter), single_evidence(p.other));
    out.tried.push_back(std::move(fit));
  }
  std::sort(out.tried.begin(), out.tried.end(), [](const PairFit &x, const PairFit &y) { return x.evidence > y.evidence; });
  std::vector<const PairFit *> passing;
  for (const PairFit &p : out.tried)
    if (p.passes) passing.push_back(&p);
  if (passing.empty()) out.why += out.tried.empty() ? "; no pair of candidates that cost no pour" : "; no pair passes";
  else if (passing.size() > 1 && passing[0]->evidence - passing[1]->evidence < TH::evidence_margin)
    out.why += "; two pairs pass within the evidence margin of each other: none named";
  else out.named = *passing[0], out.why += "; " + passing[0]->a + " with " + passing[0]->b + " passes";
  for (const PairFit &p : out.tried)
    if (out.named || p.passes) out.data.emplace(p.a, data.at(p.a)), out.data.emplace(p.b, data.at(p.b));
  return out;
}

namespace {

// The search with the filter's knots seeded at the given magnitudes (none seeded: as fitted).
PairSearch search_seeded(const std::vector<const Effect *> &effects, const FittedCandidates &fitted, const Features &f,
                         const SimulatedRuns &sims, const Alignment &al, Verdict standing,
                         const std::optional<Residual> &residual, const Effect *filter, const std::vector<double> &at)
{
  std::map<std::string, EffectData> data = fitted.data;
  std::vector<double> seeded;
  std::optional<EffectFit> seeded_single;
  if (filter && data.count(filter->name)) {
    EffectData ed = seed_chain_knot(*filter, at, sims, f, al, seeded);
    if (!seeded.empty()) seeded_single = fit_candidate(ed, f), data[filter->name] = std::move(ed);
  }
  PairSearch out = search_pairs_in(effects, fitted.evidence, std::move(data), f, standing, residual,
                                   seeded_single ? &*seeded_single : nullptr);
  out.seeded_knots = seeded;
  return out;
}

}    // namespace

PairSearch search_pairs(const std::vector<const Effect *> &effects, const FittedCandidates &fitted, const Features &f,
                        const SimulatedRuns &sims, const Alignment &al, Verdict standing,
                        const std::optional<Residual> &residual)
{
  std::string why;
  if (!pair_stage_entered(standing, residual, why)) return search_pairs_in(effects, fitted.evidence, {}, f, standing, residual);
  const Effect *filter = nullptr;
  for (const Effect *e : effects)
    if (!filter && is_filter(*e)) filter = e;
  // the filter's knot search: a line that does not scale with v0 seeds it at the period that
  // rings there; without one, at the filter's own fitted magnitude (a transform's knot costs
  // nothing, so it is placed where the data put it rather than interpolated)
  const double line = seeding_line(*residual);
  std::vector<double> at;
  if (filter && std::isfinite(line)) at.push_back(resonance_magnitude(*filter, line));
  for (const EffectFit &r : fitted.evidence.ranking)
    if (filter && at.empty() && r.name == filter->name && fitted.data.count(r.name))
      at = segment_knots(fitted.data.at(r.name).knots, r.magnitude);
  PairSearch out = search_seeded(effects, fitted, f, sims, al, standing, residual, filter, at);
  // once more with a knot where the best pair put the filter, when that is a new knot
  if (filter && !out.tried.empty() && out.tried[0].a == filter->name && out.data.count(filter->name) &&
      new_knot(out.data.at(filter->name), out.tried[0].magnitude_a)) {
    at.push_back(out.tried[0].magnitude_a);
    out = search_seeded(effects, fitted, f, sims, al, standing, residual, filter, at);
  }
  out.line_freq = line;
  return out;
}

PairConfirmStep confirm_pair(const PairSearch &search, const WhereResult &where, const Features &f, const Alignment &al,
                             bool fit_only, const StageRuns &given)
{
  PairConfirmStep step;
  PairConfirmation &c = step.done;
  if (!search.named) return step;
  const PairFit &p = *search.named;
  const Effect &filter = *find_effect(p.a), &other = *find_effect(p.b);
  c.filter = p.a, c.other = p.b, c.magnitude_filter = p.magnitude_a, c.magnitude_other = p.magnitude_b;
  c.unit_filter = filter.unit, c.unit_other = other.unit;
  c.outcome.effects = {p.a, p.b};
  c.outcome.gap_before = where.before.gap;
  if (fit_only) return c.outcome.kind = PairOutcome::Kind::fit_only, step;
  if (!given.count("confirm")) {
    step.need = RunsNeeded{other.name, "confirming the pair " + p.a + " + " + p.b, {{"confirm", p.magnitude_b, {}, CONFIRM_SEEDS}}};
    return step;
  }
  RunsBySpeed runs = transformed_runs(filter, p.magnitude_a, given.at("confirm"));
  const EffectData line = pair_line(search.data.at(p.a), search.data.at(p.b), p.magnitude_a, p.magnitude_b);
  c.proj_before = signature_sigma(line, 1.0, f);
  c.after = evaluate_after(runs, 1.0, p.scale, line, f, al);    // compared as fitted: with the pair's nuisance scale
  c.chi2_after = c.after.chi2, c.proj_after = c.after.sigma();
  // like with like: chi^2 before against the baseline within the calibration bound
  c.chi2_before = where.omnibus.chi2_within_bound;
  const double P = (double) where.omnibus.nfeatures, excess0 = c.chi2_before - P;
  c.confirmed_fraction = excess0 > 0 ? 1.0 - std::max(0.0, c.chi2_after - P) / excess0 : 0.0;
  c.outcome.kind = PairOutcome::Kind::simulated;
  c.outcome.confirmed = confirms(!where.omnibus.significant, c.chi2_before, where.omnibus.nfeatures, c.proj_before,
                                 c.chi2_after, c.proj_after);
  c.outcome.gap_after = c.after.all();
  c.corrected_traces = corrected_trace_files(c.after.files, &filter, p.magnitude_a, p.scale);
  return step;
}

}    // namespace granpen
