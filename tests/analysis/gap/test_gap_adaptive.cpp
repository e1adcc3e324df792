// The adaptive plan's decision (analysis/gap/gap_adaptive.h), alone: which pour-level
// candidates a diagnosis simulates after its cheap stage, on hand-made what-was-seen.
#include "gap_adaptive.h"
#include "gap_fit.h"
#include "gap_thresholds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

using namespace granpen;

namespace {

constexpr double FLOOR = GapThresholds::lr_chi2_1_p1e4, MARGIN = GapThresholds::evidence_margin;

const PurchaseDecision &decision(const std::vector<PurchaseDecision> &ds, const std::string &effect)
{
  for (const auto &d : ds)
    if (d.effect == effect) return d;
  throw std::runtime_error("no decision for " + effect);
}

}    // namespace

TEST(GapAdaptive, ACheapCandidateThatExplainsSkipsWhatCannotComeWithinTheMargin)
{
  // the mount explains with evidence 70 of a squared gap of 80: a pour-level candidate changes
  // that only by coming within the margin (64); along their signatures the gap holds 10 and 40
  CheapStageSeen seen{80.0, "measurement_chain", 70.0, true, false};
  const auto ds = decide_purchases(seen, {{"rolling_resistance", 6.0, 10.0}, {"packing", 4.0, 40.0}}, FLOOR, MARGIN);
  ASSERT_EQ(ds.size(), 2u);
  for (const auto &d : ds) {
    EXPECT_FALSE(d.simulate) << d.effect << ": " << d.why;
    EXPECT_DOUBLE_EQ(d.needed, 70.0 - MARGIN);
  }
  EXPECT_DOUBLE_EQ(decision(ds, "packing").bound, 40.0);
  EXPECT_NE(decision(ds, "packing").why.find("cannot reach 64.0"), std::string::npos) << decision(ds, "packing").why;
  // nothing pour-level simulated: the record says so with the bound
  PlanRecord r;
  r.decisions = ds;
  EXPECT_NE(plan_record_text(r).find("0 simulated, 2 skipped"), std::string::npos) << plan_record_text(r);
}

TEST(GapAdaptive, ACandidateWhoseDirectionIsUnknownIsBoundedByTheWholeGap)
{
  // no direction: it could take the whole squared gap (80), which reaches the margin of the
  // mount's 70: simulated. A bound never exceeds the whole gap, whatever a projection says
  CheapStageSeen seen{80.0, "measurement_chain", 70.0, true, false};
  const auto ds = decide_purchases(seen, {{"cohesion", 9.0, std::nullopt}, {"packing", 4.0, 500.0}}, FLOOR, MARGIN);
  EXPECT_TRUE(decision(ds, "cohesion").simulate);
  EXPECT_DOUBLE_EQ(decision(ds, "cohesion").bound, 80.0);
  EXPECT_DOUBLE_EQ(decision(ds, "packing").bound, 80.0);
  // bought cheapest first
  EXPECT_EQ(ds[0].effect, "packing");
}

TEST(GapAdaptive, NothingExplainsAndNothingCanPassStopsAfterTheCheapStage)
{
  // a squared gap of 12 at magnitude 0: no candidate's likelihood ratio can reach the least
  // threshold (15.14), whatever its direction
  CheapStageSeen seen{12.0, "rod_friction", 3.0, false, false};
  const auto ds = decide_purchases(seen, {{"cohesion", 9.0, std::nullopt}, {"friction", 5.0, std::nullopt}}, FLOOR, MARGIN);
  for (const auto &d : ds) {
    EXPECT_FALSE(d.simulate) << d.effect;
    EXPECT_DOUBLE_EQ(d.needed, FLOOR);
    EXPECT_NE(d.why.find("its threshold"), std::string::npos) << d.why;
  }
  // one more unit of squared gap above the threshold and the same candidates are bought
  seen.chi2_0 = FLOOR + 1.0;
  for (const auto &d : decide_purchases(seen, {{"cohesion", 9.0, std::nullopt}, {"friction", 5.0, std::nullopt}}, FLOOR, MARGIN))
    EXPECT_TRUE(d.simulate) << d.effect;
}

TEST(GapAdaptive, AScaleThatExplainsStillNeedsItsLookAlikes)
{
  // a uniform scale names no cause: the pour-level signatures near it are what the verdict
  // lists, so the bar is the threshold, not the scale's evidence
  CheapStageSeen seen{200.0, "force_scale", 190.0, true, true};
  const auto ds = decide_purchases(seen, {{"packing", 4.0, 30.0}, {"polydispersity", 4.0, 10.0}}, FLOOR, MARGIN);
  EXPECT_TRUE(decision(ds, "packing").simulate);
  EXPECT_DOUBLE_EQ(decision(ds, "packing").needed, FLOOR);
  EXPECT_FALSE(decision(ds, "polydispersity").simulate);
}

TEST(GapAdaptive, TheRecordSaysTheRangeAndWhatThisRunSpent)
{
  PlanRecord r;
  r.jobs = 2, r.least = 3.5, r.most = 40, r.spent = 12.3, r.wall_least = 1.9, r.wall_most = 21.1, r.wall_spent = 6.45;
  r.decides = "the bound";
  r.confirmation = {"confirm_packing_-0.1"};
  const std::string t = plan_record_text(r);
  EXPECT_NE(t.find("this run 12.3 (6.45 of wall time) within the plan's 3.5 to 40"), std::string::npos) << t;
  EXPECT_NE(t.find("--jobs 2"), std::string::npos) << t;
  EXPECT_NE(t.find("confirm_packing_-0.1"), std::string::npos) << t;
}

TEST(GapAdaptive, ACandidatesCostIsSaidColdAsTheRangeIsAndWithThisCacheBeside)
{
  // a warm cache: the knots cost nothing now, but the range and "this run" count them cold,
  // so the line gives the cold figure first (a bench diagnosis printed "0 probe pours" beside
  // a simulated candidate whose knots are 3.6 of its 24.6 spent)
  CheapStageSeen seen{80.0, "measurement_chain", 10.0, false, false};
  std::vector<PlanCandidate> cands{{"friction", 0.0, 40.0}, {"packing", 1.25, 40.0}};
  cands[0].cold_cost = 3.61, cands[1].cold_cost = 2.5;
  PlanRecord r;
  r.decisions = decide_purchases(seen, cands, FLOOR, MARGIN);
  EXPECT_DOUBLE_EQ(decision(r.decisions, "friction").cold_cost, 3.61);
  const std::string t = plan_record_text(r);
  EXPECT_NE(t.find("friction (3.61 probe pours, 0 with this cache)"), std::string::npos) << t;
  EXPECT_NE(t.find("packing (2.5 probe pours, 1.25 with this cache)"), std::string::npos) << t;
  cands[1].cost = 2.5;    // a cold cache: one figure
  r.decisions = decide_purchases(seen, cands, FLOOR, MARGIN);
  EXPECT_NE(plan_record_text(r).find("packing (2.5 probe pours)"), std::string::npos) << plan_record_text(r);
}

// The bound with a signature prior (prior_bound): known answers first.
namespace {

using Tab = std::vector<std::vector<double>>;

PriorBoundInput one_speed(const std::vector<double> &gap, const std::vector<double> &scale_dir,
                          const std::vector<std::vector<double>> &signatures, double noise, double scale_bound)
{
  PriorBoundInput in;
  in.gap = {gap}, in.var = {std::vector<double>(gap.size(), 1.0)}, in.scale_dir = {scale_dir};
  for (const auto &s : signatures) {
    in.signature.push_back({s});
    in.knot_var.push_back({std::vector<double>(gap.size(), noise)});
    in.prior_var.push_back({std::vector<double>(gap.size(), noise)});
  }
  in.scale_bound = scale_bound;
  return in;
}

}    // namespace

TEST(GapAdaptivePrior, ExactSignaturesBoundByTheProjection)
{
  // noiseless knots, unit variance: the squared gap the fit's path removes, hand-computed (a
  // point of the path at magnitude a is the knots' interpolation, gap_fit.h; it removes
  // 2 y . x - |x|^2). The gap (3, 4, 0), the knot (3, 0, 0) at 1: 9, at the knot
  const std::vector<double> y{3, 4, 0}, none{0, 0, 0};
  EXPECT_NEAR(prior_bound(one_speed(y, none, {{3, 0, 0}}, 0.0, 0.0)).projection2, 9.0, 1e-9);
  // knots (3, 0, 0) at 1 and (3, 4, 0) at 2: the path passes through the gap itself: 25
  EXPECT_NEAR(prior_bound(one_speed(y, none, {{3, 0, 0}, {3, 4, 0}}, 0.0, 0.0)).projection2, 25.0, 1e-9);
  // knots on either side of 0, (3, 0, 0) at +1 and (0, 4, 0) at -1: the path is the two rays,
  // not their span (25): the larger of 9 and 16
  PriorBoundInput two_sides = one_speed(y, none, {{3, 0, 0}, {0, 4, 0}}, 0.0, 0.0);
  two_sides.magnitude = {1, -1};
  EXPECT_NEAR(prior_bound(two_sides).projection2, 16.0, 1e-9);
  // one-sided: a gap against the knot's direction takes nothing; two-sided, the mirror takes it
  PriorBoundInput against = one_speed({-3, 0, 0}, none, {{3, 0, 0}}, 0.0, 0.0);
  against.one_sided = true;
  EXPECT_NEAR(prior_bound(against).bound(), 0.0, 1e-12);
  against.one_sided = false;
  EXPECT_NEAR(prior_bound(against).projection2, 9.0, 1e-9);
  const PriorBound orth = prior_bound(one_speed(y, none, {{0, 0, 1}}, 0.0, 0.0));
  EXPECT_NEAR(orth.bound(), 0.0, 1e-12);    // every point of the path adds to the residual
  EXPECT_EQ(orth.margin_direction, 0.0);    // no knot noise: the prior is the knots
  // a gap the bounded scale takes (y = 0.02 B, the scale within 0.03) leaves nothing; beyond
  // the bound (0.05 B) the excess 0.02 B along a signature parallel to B is the knots'
  const std::vector<double> B{10, 20, 30};
  auto times = [&](double c) {
    std::vector<double> v(B);
    for (double &x : v) x *= c;
    return v;
  };
  EXPECT_NEAR(prior_bound(one_speed(times(0.02), B, {{1, 0, 0}}, 0.0, 0.03)).bound(), 0.0, 1e-12);
  EXPECT_NEAR(prior_bound(one_speed(times(0.05), B, {B}, 0.0, 0.03)).projection2, std::pow(0.02, 2) * (100 + 400 + 900), 1e-9);
  // a knot's own variance (t = 1 per feature, t lambda^2 at lambda times the knot) is paid for
  // in the likelihood, r^2 / (1 + t) + log(1 + t) per feature: along the knot (3, 0, 0) out to
  // the path's end (lambda 1.25, its reach) the most is there, the residual (-0.75, 4, 0) at
  // t = 1.5625: 25 - 16.5625 / 2.5625 - 3 log 2.5625 = 15.71 (at the knot 14.92)
  PriorBoundInput noisy = one_speed(y, none, {{3, 0, 0}}, 1.0, 0.0);
  noisy.prior_var = {{std::vector<double>(3, 0.0)}};
  const PriorBound nb = prior_bound(noisy);
  EXPECT_NEAR(nb.projection2 + nb.margin_noise, 25.0 - 16.5625 / 2.5625 - 3 * std::log(2.5625), 1e-9);
}

// The measurement chain's simulated knots beyond its filter (gap_adaptive.h, PriorBoundInput::
// beyond, own): the filtered knots (1 and 2 ms here) are the diagnosis's own and fitted
// already, so the bound is over the path beyond 2 ms alone, the segment to the prior's knot at
// 4 ms and past it. Noiseless knots, hand-computed: a gap that is the 1 ms signature, each
// knot's signature along an axis of its own, is orthogonal to every point beyond 2 ms (each
// adds |x|^2 to the residual): bound 0, where the whole path's is the gap itself (100)
TEST(GapAdaptivePrior, TheChainBeyondItsFilterIsBoundedByThePathBeyondAlone)
{
  const std::vector<double> none{0, 0, 0};
  PriorBoundInput in = one_speed({10, 0, 0}, none, {{10, 0, 0}, {0, 10, 0}, {0, 0, 10}}, 0.0, 0.0);
  in.magnitude = {1, 2, 4}, in.one_sided = true, in.own = {true, true, false};
  EXPECT_NEAR(prior_bound(in).bound(), 100.0, 1e-9);
  in.beyond = 2.0;
  EXPECT_NEAR(prior_bound(in).bound(), 0.0, 1e-12);
  // the gap half the 2 ms signature and half the 4 ms one ((0, 5, 5), 50): the path beyond 2
  // passes through it at 3 ms, and removes all of it, to the path's grid: its points lie
  // (magnitude_range to at most 5 ms) 5 / PRIOR_PATH_POINTS apart, so one lies within half that,
  // delta <= 0.0031 of the 2 ms segment, of 3 ms, where it leaves 2 (10 delta)^2 <= 0.002
  in.gap = {{0, 5, 5}};
  EXPECT_NEAR(prior_bound(in).projection2, 50.0, 2e-3);
  // the own knots carry no tilt: their noise (1 per feature, the prior's knot noiseless) enters
  // the fit's weights but not the direction's margin, which is then exactly 0; taken as the
  // prior's, the same noise tilts the path and the margin is positive
  PriorBoundInput noisy = one_speed({0, 5, 5}, none, {{10, 0, 0}, {0, 10, 0}, {0, 0, 10}}, 0.0, 0.0);
  noisy.magnitude = {1, 2, 4}, noisy.one_sided = true, noisy.beyond = 2.0;
  noisy.knot_var[0] = noisy.knot_var[1] = noisy.prior_var[0] = noisy.prior_var[1] = {std::vector<double>(3, 1.0)};
  EXPECT_GT(prior_bound(noisy).margin_direction, 0.0);
  noisy.own = {true, true, false};
  EXPECT_EQ(prior_bound(noisy).margin_direction, 0.0);
}

// A push-only candidate is bought like a pour-level one: skipped when its bound cannot reach
// its threshold, simulated when it can, and said so as push-only in the record
TEST(GapAdaptive, APushOnlyCandidateIsBoughtOnlyWhenItsBoundCanReachItsThreshold)
{
  CheapStageSeen seen{60.0, "force_scale", 4.0, false, false};
  std::vector<PlanCandidate> cands{{"actuator_ramp", 4.4, 9.0}, {"rod_friction", 2.9, 30.0}};
  for (auto &c : cands) c.push_only = true, c.cold_cost = c.cost;
  const auto ds = decide_purchases(seen, cands, FLOOR, MARGIN);
  EXPECT_FALSE(decision(ds, "actuator_ramp").simulate) << decision(ds, "actuator_ramp").why;
  EXPECT_NE(decision(ds, "actuator_ramp").why.find("cannot reach 15.1, its threshold"), std::string::npos);
  EXPECT_TRUE(decision(ds, "rod_friction").simulate) << decision(ds, "rod_friction").why;
  EXPECT_TRUE(decision(ds, "rod_friction").push_only);
  EXPECT_EQ(ds[0].effect, "rod_friction");    // the cheaper first
  PlanRecord r;
  r.decisions = ds;
  EXPECT_NE(plan_record_text(r).find("Push-only candidates: 1 simulated, 1 skipped."), std::string::npos) << plan_record_text(r);
  EXPECT_EQ(plan_record_text(r).find("Pour-level candidates"), std::string::npos) << plan_record_text(r);
}

// The pour-level decision sees what the push-only purchase fitted: before it, nothing cheap
// explains and a pour-level candidate whose bound reaches the threshold is bought; once a
// push-only candidate bought explains (the ramp, evidence 300), the same candidate must come
// within the margin of that evidence, and its bound (100) cannot: skipped
TEST(GapAdaptive, APourLevelDecisionSeesABoughtPushOnlyCandidateThatExplains)
{
  const std::vector<PlanCandidate> pour{{"packing", 4.0, 100.0}, {"friction", 3.6, 296.0}};
  const CheapStageSeen cheap{320.0, "force_scale", 40.0, false, false};
  for (const auto &d : decide_purchases(cheap, pour, FLOOR, MARGIN)) EXPECT_TRUE(d.simulate) << d.effect << ": " << d.why;
  const CheapStageSeen with_ramp{320.0, "actuator_ramp", 300.0, true, false};
  const auto ds = decide_purchases(with_ramp, pour, FLOOR, MARGIN);
  EXPECT_FALSE(decision(ds, "packing").simulate) << decision(ds, "packing").why;
  EXPECT_NE(decision(ds, "packing").why.find("within the evidence margin of actuator_ramp's 300.0"), std::string::npos)
      << decision(ds, "packing").why;
  // one that can still tie it (296 within the margin of 300) is bought
  EXPECT_TRUE(decision(ds, "friction").simulate) << decision(ds, "friction").why;
}

// A pair partner (gap_pairs.h: a push-only effect the pair stage pairs with the filter) on a
// cheap stage left unexplained: the explain gate would skip it (its fit alone removes 100 of
// the 500 a quarter of the gap needs), but a pair explains what neither alone does (the
// selftest's chain_ramp: the ramp skipped this way left the pair stage without its partner, a
// right answer turned unexplained), so it is bought
TEST(GapAdaptive, APairPartnerIsBoughtOnAnUnexplainedCheapStageWhateverItExplainsAlone)
{
  CheapStageSeen seen{2000.0, "measurement_chain", 1400.0, false, false, true, true};
  PriorBound b;
  b.projection2 = 900.0, b.gain = 100.0, b.w0 = 2000.0;
  PlanCandidate ramp{"actuator_ramp", 2.4, std::nullopt};
  ramp.prior = b, ramp.push_only = true;
  const auto gated = decide_purchases(seen, {ramp}, FLOOR, MARGIN);
  EXPECT_FALSE(gated[0].simulate) << gated[0].why;
  EXPECT_DOUBLE_EQ(gated[0].gain_needed, 500.0);
  ramp.pair_partner = true;
  const auto bought = decide_purchases(seen, {ramp}, FLOOR, MARGIN);
  EXPECT_TRUE(bought[0].simulate) << bought[0].why;
  EXPECT_NE(bought[0].why.find("the pair stage may pair it with the filter"), std::string::npos) << bought[0].why;
  // on a cheap stage that is not unexplained the partner is bought on its bound alone
  seen.unexplained = seen.unexplained_stands = false;
  b.projection2 = 10.0, ramp.prior = b;
  EXPECT_FALSE(decide_purchases(seen, {ramp}, FLOOR, MARGIN)[0].simulate);
}

namespace {

// A knot geometry of the Monte Carlo: magnitudes, true signatures over P features, the side
struct Geometry {
  std::vector<double> magnitude;
  std::vector<std::vector<double>> truth;
  bool one_sided;
};

std::vector<Geometry> mc_geometries(std::size_t P, double size)
{
  std::vector<double> s1(P), s2(P), s3(P);
  for (std::size_t k = 0; k < P; ++k)
    s1[k] = size * std::sin(0.3 * k), s2[k] = size * (0.5 + 0.02 * k), s3[k] = size * std::cos(0.7 * k + 0.4);
  auto mix = [&](double a, const std::vector<double> &u, double b, const std::vector<double> &v) {
    std::vector<double> w(P);
    for (std::size_t k = 0; k < P; ++k) w[k] = a * u[k] + b * v[k];
    return w;
  };
  return {{{1.0, 3.0}, {s1, mix(2.5, s1, 1.0, s2)}, true},     // one side, bending (rolling resistance, cohesion)
          {{-1.0, 1.0}, {mix(-1.0, s1, 0.6, s3), mix(1.0, s1, 0.4, s2)}, false},    // both sides (packing, stiffness)
          {{1.0}, {s2}, false}};    // one knot, mirrored (friction)
}

// One draw of the Monte Carlo tests below: the diagnosis's knots of geometry g (the truth plus
// noise of variance U per feature, on a reference bed of noise 0.5 about B) as fit_effect reads
// them, the prior's knots (the truth plus noise of variance prior_var) as prior_bound reads
// them, and a measured target: the true path at `at` (interpolated on the noise-free knots, as
// the fit's path does), noise 0.5, and an outside bump of `bump` squared standard deviations
// spread over features 20 to 20 + width - 1
struct McDraw {
  EffectData knots;
  PriorBoundInput prior;
  std::vector<double> target;
};

McDraw mc_draw(std::mt19937 &rng, std::normal_distribution<double> &N, const std::vector<double> &B, const Geometry &g, double U, double prior_var, double at,
               double bump, std::size_t width)
{
  // N is the caller's: libstdc++'s keeps the second value of each pair it draws
  const std::size_t P = B.size(), K = g.truth.size();
  std::vector<double> path_knots{0.0};
  for (double m : g.magnitude) path_knots.push_back(m);
  std::vector<std::size_t> order(K + 1);
  for (std::size_t j = 0; j <= K; ++j) order[j] = j;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return path_knots[a] < path_knots[b]; });
  McDraw out;
  EffectData &d = out.knots;
  PriorBoundInput &in = out.prior;
  d.one_sided = g.one_sided, d.scale_bound = 0.03;
  std::vector<double> ref(P);
  for (std::size_t k = 0; k < P; ++k) ref[k] = B[k] + std::sqrt(0.5) * N(rng);
  in.scale_bound = 0.03, in.one_sided = g.one_sided, in.magnitude = g.magnitude;
  std::vector<std::vector<double>> dmean(K, std::vector<double>(P));
  for (std::size_t j = 0; j < K; ++j) {
    std::vector<double> p(P);
    for (std::size_t k = 0; k < P; ++k)
      p[k] = g.truth[j][k] + std::sqrt(prior_var) * N(rng), dmean[j][k] = ref[k] + g.truth[j][k] + std::sqrt(U) * N(rng);
    in.signature.push_back({p});
    in.knot_var.push_back({std::vector<double>(P, U)});
    in.prior_var.push_back({std::vector<double>(P, prior_var)});
  }
  for (std::size_t i : order) {
    d.knots.push_back(path_knots[i]);
    d.mean.push_back({i == 0 ? ref : dmean[i - 1]});
    d.err.push_back({std::vector<double>(P, i == 0 ? 0.5 : U)});
  }
  EffectData tp = d;
  for (std::size_t i = 0; i < order.size(); ++i) {
    tp.mean[i] = {B};
    for (std::size_t k = 0; order[i] != 0 && k < P; ++k) tp.mean[i][0][k] += g.truth[order[i] - 1][k];
  }
  std::vector<double> m, v;
  effect_predict(tp, at, 0, m, v);
  out.target.resize(P);
  for (std::size_t k = 0; k < P; ++k)
    out.target[k] = m[k] + std::sqrt(0.5) * N(rng) + (k >= 20 && k < 20 + width ? std::sqrt(bump / (double) width) : 0.0);
  in.gap = {std::vector<double>(P)}, in.var = {std::vector<double>(P, 1.0)}, in.scale_dir = {ref};
  for (std::size_t k = 0; k < P; ++k) in.gap[0][k] = out.target[k] - ref[k];
  return out;
}

}    // namespace

TEST(GapAdaptivePrior, TheBoundHoldsWhatTheDiagnosisKnotsEarn)
{
  // Monte Carlo against the fit itself: the diagnosis's knots (the truth plus their own noise,
  // variance U per feature) fitted by fit_effect's likelihood ratio (effect_lr, the scale
  // nuisance within 3% included) must stay under the bound the prior's knots (the truth plus
  // their noise, W) give, in all but 1% of draws (a skipped candidate that could have passed is
  // a miss: 1% is the most a plan may risk per candidate). Three geometries of knots (gap_fit's
  // paths), knot noise as large as the data's (U = W = 1: a pour-level knot on two beds,
  // docs/gap.md) and a third of it, signatures of 100 to 1000 squared standard deviations, and
  // gaps of noise, of the path at 0 to 1.5 of its end knot, and of noise with an effect outside
  // the library (a bump on 4 features, 60 squared standard deviations). Measured on 2026-11-29
  // (PRIOR_BOUND_P 0.01): 20 of 3840 draws beyond the bound, 1 of them with the bound below the
  // least threshold and the fit's ratio above it (a candidate wrongly skipped); with the tilt's
  // two parts each at its own quantile, 7 and 1; at tail 0.05 31 and 2, at 0.1 63 and 7 (over
  // 1%). Without the margins the fixed-weight gain alone is exceeded in 3349. With the prior's
  // noise at half the data's too (W = 0.5, a prior of four beds; 2026-11-30): 33 of 7680 draws
  // beyond the bound (13 of the 3840 new ones), 3 wrongly skipped.
  std::mt19937 rng(37);
  std::normal_distribution<double> N(0.0, 1.0);
  const std::size_t P = 42;
  std::vector<double> B(P);
  for (std::size_t k = 0; k < P; ++k) B[k] = 20.0 + 5.0 * std::sin(0.2 * k);
  int over = 0, over_projection = 0, wrongly_skipped = 0, trials = 0;
  for (double size : {1.6, 5.0})
    for (double U : {1.0, 0.33})
      for (double W : {1.0, 0.5})
      for (const Geometry &g : mc_geometries(P, size))
        for (double alpha : {0.0, 0.3, 0.7, 1.5})
          for (int outside = 0; outside < 2; ++outside)
            for (int t = 0; t < 40; ++t, ++trials) {
              // the prior's knots as noisy as the data (variance 1: two beds, as the diagnosis's)
              // or half that (a prior of four beds, --prior-seeds "1 2 41 42"); the bump: 60
              // on 4 features
              const McDraw dr = mc_draw(rng, N, B, g, U, W, alpha * g.magnitude.back(), outside ? 60.0 : 0.0, 4);
              const EffectData &d = dr.knots;
              const PriorBoundInput &in = dr.prior;
              const std::vector<double> &target = dr.target;
              const PriorBound b = prior_bound(in);
              const double lr = effect_lr(Target{{target}, {std::vector<double>(P, 0.5)}}, d);
              over += lr > b.bound(), over_projection += lr > b.projection2;
              wrongly_skipped += b.bound() < FLOOR && lr >= FLOOR;
            }
  std::printf("the bound exceeded in %d of %d draws (below the least threshold with the fit above it: %d), the fixed-weight gain alone in %d\n",
              over, trials, wrongly_skipped, over_projection);
  EXPECT_LE(over, 0.01 * trials) << over << " of " << trials;
  EXPECT_GE(over_projection, 0.1 * trials) << over_projection << " of " << trials;
}

TEST(GapAdaptivePrior, TheGainBoundHoldsWhatTheFitRemoves)
{
  // The explain gate (gap_adaptive.h, decide_purchases) skips a candidate on an unexplained gap
  // when the most fixed-weight squared gap its fit can remove (PriorBound::gain) is below what a
  // quarter of the gap needs. Monte Carlo against the fit itself (fit_effect: explained, the
  // fraction of the fixed-weight squared gap w0 its point removes): the diagnosis's knots as in
  // the likelihood's test above, with knot noise 2.7 times the data's (a pour-level knot on 2
  // beds against 8 measured and 4 reference, docs/gap.md) and as large, gaps of noise with an
  // outside bump of 60 and 400 squared standard deviations (the layer's gaps, 82 to 490), and
  // of the path at 0 and 0.7 of its end knot with the large bump. The bound must hold in all
  // but 1% of draws (PRIOR_BOUND_P); a wrong skip is the bound below the quarter's need with
  // the fit detected and above it. Measured on 2026-11-29: exceeded in 6 of 1080 draws (the
  // largest ratio of the fit's to the bound 1.56), no wrong skip, 236 draws gated; the
  // likelihood's bound (prior_bound's bound()) exceeded in 6 of the same draws.
  std::mt19937 rng(3737);
  std::normal_distribution<double> N(0.0, 1.0);
  const std::size_t P = 42;
  std::vector<double> B(P);
  for (std::size_t k = 0; k < P; ++k) B[k] = 20.0 + 5.0 * std::sin(0.2 * k);
  int over = 0, wrong_skips = 0, gated = 0, trials = 0, lr_over = 0;
  double worst = 0;
  for (double size : {1.6, 5.0})
    for (double U : {2.7, 1.0})
      for (const Geometry &g : mc_geometries(P, size))
        for (const auto &[alpha, bump] : {std::pair{0.0, 60.0}, std::pair{0.0, 400.0}, std::pair{0.7, 400.0}})
            for (int t = 0; t < 30; ++t, ++trials) {
              // the prior's knots as noisy as the diagnosis's (U); the outside bump on 6
              // features, not the knots' shapes
              const McDraw dr = mc_draw(rng, N, B, g, U, U, alpha * g.magnitude.back(), bump, 6);
              const EffectData &d = dr.knots;
              const PriorBoundInput &in = dr.prior;
              const std::vector<double> &target = dr.target;
              const PriorBound b = prior_bound(in);
              const EffectFit f = fit_effect(Target{{target}, {std::vector<double>(P, 0.5)}}, d);
              const double removed = f.explained * b.w0, need = explain_gain_needed(b.w0, (double) P, 0.25);
              over += removed > b.gain, gated += b.gain < need, lr_over += f.lr > b.bound();
              wrong_skips += b.gain < need && removed >= need && f.lr >= FLOOR;
              worst = std::max(worst, removed / std::max(1e-9, b.gain));
            }
  std::printf("the gain bound exceeded in %d of %d draws (wrong skips %d, gated %d), the largest ratio of the fit's to it %.2f; "
              "the likelihood ratio's bound in %d\n",
              over, trials, wrong_skips, gated, worst, lr_over);
  EXPECT_LE(over, 0.01 * trials) << over << " of " << trials;
  EXPECT_EQ(wrong_skips, 0);
}

TEST(GapAdaptivePrior, OnNoiseAloneTheBoundFallsBelowTheThreshold)
{
  // the point of the prior: a gap of noise alone over 42 features (the tiny selftest's count)
  // has a whole squared gap of about 42, above the least threshold, but along two knots of
  // clear signature (SNR about 3 per knot) their bound stays below it in most draws (mean:
  // projection 2 + the margins); without a prior nothing would be skipped
  std::mt19937 rng(101);
  std::normal_distribution<double> N(0.0, 1.0);
  const std::size_t P = 42;
  double sum = 0;
  int below = 0;
  for (int t = 0; t < 500; ++t) {
    std::vector<double> y(P), p1(P), p2(P), B(P, 0.0);
    for (std::size_t k = 0; k < P; ++k)
      y[k] = N(rng), p1[k] = 2.0 * std::sin(0.3 * k) + 0.7 * N(rng), p2[k] = 1.0 + 0.05 * k + 0.7 * N(rng);
    const double bound = prior_bound(one_speed(y, B, {p1, p2}, 0.5, 0.0)).bound();
    sum += bound, below += bound < FLOOR;
  }
  std::printf("on noise alone the bound is below the least threshold in %d of 500 draws, mean %.1f\n", below, sum / 500);
  EXPECT_LT(sum / 500, FLOOR) << sum / 500;
  // 350 of 500 on 2026-11-29 with the span's bound, 487 (mean 6.4) with the path's: the
  // bound bites on most noise-only data; at least 60% (the binomial's standard deviation at
  // 70% of 500 is 2%: 5 of them)
  EXPECT_GE(below, 300) << below;
}
