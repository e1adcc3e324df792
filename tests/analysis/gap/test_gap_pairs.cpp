// The pair stage (analysis/gap/gap_pairs.h) alone: which pairs it tries, the joint fit on a
// constructed gap of known magnitudes, a pair that never wins on noise or on one effect, the
// entry rule, and the chain's knot seeded at a residual line's resonance.
#include "effects.h"
#include "gap_pairs.h"
#include "gap_thresholds.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace granpen;

namespace {

constexpr std::size_t SPEEDS = 3, FEATURES = 24, NULLS = 6;
// the variance of every measured and reference mean: signatures of size 1 per feature stand
// 1 / 0.1 = 10 standard deviations out of it, as a gap the omnibus test sees plainly
constexpr double VAR = 1e-2;

// B's size against A's (1: both plain; small: B's part of a gap below what a parameter earns)
double b_size = 1.0;

// a signature per speed: a smooth shape of its own (A rings: alternating; B shifts: a ramp in k)
double shape(char which, std::size_t s, std::size_t k)
{
  return which == 'A' ? (k % 2 ? 1.0 : -0.6) * (1.0 + 0.2 * s) : b_size * 0.8 * std::sin(0.4 * (double) k + 0.3 * s);
}

const double REF = 10.0;

// a push-only effect whose knots 0, 1, 2 are the reference plus that many times its shape
// (linear: any magnitude in the range is exactly its interpolation)
EffectData linear_effect(const std::string &name, char which)
{
  EffectData e;
  e.name = name;
  e.knots = {0.0, 1.0, 2.0};
  e.paired = true;
  e.scale_bound = GapThresholds::calibration_scale_bound;
  for (double a : e.knots) {
    Table m(SPEEDS, std::vector<double>(FEATURES)), v(SPEEDS, std::vector<double>(FEATURES, VAR)),
        d(SPEEDS, std::vector<double>(FEATURES, a == 0.0 ? 0.0 : VAR / 10));
    for (std::size_t s = 0; s < SPEEDS; ++s)
      for (std::size_t k = 0; k < FEATURES; ++k) m[s][k] = REF + a * shape(which, s, k);
    e.mean.push_back(m), e.err.push_back(v), e.diff_err.push_back(d);
  }
  return e;
}

// the reference plus a A + b B plus Gaussian noise of the measured variance
Target measured(double a, double b, unsigned seed)
{
  std::mt19937 rng(seed);
  std::normal_distribution<double> n01(0.0, 1.0);
  Target t;
  t.mean.assign(SPEEDS, std::vector<double>(FEATURES));
  t.err.assign(SPEEDS, std::vector<double>(FEATURES, VAR));
  for (std::size_t s = 0; s < SPEEDS; ++s)
    for (std::size_t k = 0; k < FEATURES; ++k)
      t.mean[s][k] = REF + a * shape('A', s, k) + b * shape('B', s, k) + std::sqrt(VAR) * n01(rng);
  return t;
}

// Features with the target and null replicates only (what the stage reads), and the two
// effects' model data (named as the library's chain and ramp) with their noise residuals
struct World {
  Features f;
  std::map<std::string, EffectData> data;
  FitEvidence evidence;
};

World world(double a, double b, unsigned seed)
{
  World w;
  w.f.speeds = {50, 100, 200};
  w.f.target = measured(a, b, seed);
  for (unsigned i = 0; i < NULLS; ++i) w.f.nulls.push_back(measured(0, 0, 1000 + i));
  std::vector<EffectFit> fits;
  for (auto [name, which] : {std::pair<std::string, char>{"measurement_chain", 'A'}, {"actuator_ramp", 'B'}}) {
    EffectData e = linear_effect(name, which);
    e.noise_r2 = noise_residual(w.f.nulls, e);
    fits.push_back(fit_candidate(e, w.f));
    w.data[name] = std::move(e);
  }
  w.evidence = fit_evidence(true, fits);
  return w;
}

std::vector<const Effect *> library()
{
  std::vector<const Effect *> out;
  for (const auto &e : effect_library()) out.push_back(&e);
  return out;
}

Residual with_line()
{
  Residual r;
  r.moves = "spectrum";
  r.band = "150-450 Hz";
  r.lines.push_back(SpectralLine{200, 428, 3.0, 8.0});
  return r;
}

}    // namespace

// the pairs come from the candidates that cost no pour, a filter with each of the others; the
// force scale (every fit's nuisance) and pour-level effects are never tried
TEST(GapPairs, PairsAreAFilterWithAPushOnlyCandidate)
{
  std::vector<EffectFit> ranking;
  for (const char *n : {"rolling_resistance", "force_scale", "actuator_ramp", "packing", "rod_friction", "measurement_chain"}) {
    EffectFit f;
    f.name = n;
    ranking.push_back(f);
  }
  const auto pairs = pairs_to_try(ranking, library(), true);
  ASSERT_EQ(pairs.size(), 2u);
  EXPECT_EQ(pairs[0].filter, "measurement_chain");
  EXPECT_EQ(pairs[0].other, "actuator_ramp");
  EXPECT_EQ(pairs[1].other, "rod_friction");
  // without the filter among the candidates nothing is a pair of this stage
  std::vector<const Effect *> no_chain;
  for (const Effect *e : library())
    if (e->name != "measurement_chain") no_chain.push_back(e);
  EXPECT_TRUE(pairs_to_try(ranking, no_chain, true).empty());
}

// entered only for an unexplained verdict whose residual carries a line or a band
TEST(GapPairs, EnteredOnlyWhenUnexplainedWithALineOrBand)
{
  std::string why;
  EXPECT_TRUE(pair_stage_entered(Verdict::unexplained, with_line(), why)) << why;
  Residual band_only;
  band_only.band = "450-1350 Hz";
  EXPECT_TRUE(pair_stage_entered(Verdict::unexplained, band_only, why)) << why;
  EXPECT_FALSE(pair_stage_entered(Verdict::unexplained, Residual(), why));
  EXPECT_NE(why.find("no spectral line or band"), std::string::npos) << why;
  EXPECT_FALSE(pair_stage_entered(Verdict::unexplained, std::nullopt, why));
  EXPECT_FALSE(pair_stage_entered(Verdict::explained, with_line(), why));
  EXPECT_FALSE(pair_stage_entered(Verdict::tie, with_line(), why));
}

// a constructed gap of both effects at known magnitudes, with a line: the pair is named at
// them, by a margin beyond its best single member
TEST(GapPairs, AGapOfTwoEffectsNamesThePairAtTheirMagnitudes)
{
  World w = world(1.0, 1.5, 7);
  const PairSearch s = search_pairs_in(library(), w.evidence, w.data, w.f, Verdict::unexplained, with_line());
  ASSERT_TRUE(s.entered) << s.why;
  ASSERT_TRUE(s.named.has_value()) << s.why << (s.tried.empty() ? "" : ": " + s.tried[0].why);
  const PairFit &p = *s.named;
  EXPECT_EQ(p.a, "measurement_chain");
  EXPECT_EQ(p.b, "actuator_ramp");
  // the noise per feature is 0.1 against signatures of about 1 over 72 features: each
  // magnitude's standard error is about 0.1 / sqrt(72 * 0.5) = 0.017; 0.06 is over 3 of them
  EXPECT_NEAR(p.magnitude_a, 1.0, 0.06);
  EXPECT_NEAR(p.magnitude_b, 1.5, 0.06);
  EXPECT_GE(p.margin, GapThresholds::lr_chi2_1_p1e4);
  EXPECT_GT(p.lr, p.lr_threshold);
  EXPECT_GE(p.explained, GapThresholds::explained_min);
  EXPECT_GE(p.heldout_explained, GapThresholds::heldout_explained_min);
  EXPECT_TRUE(p.passes);
}

// noise alone, and one effect alone: no pair (the second member would fit noise, and its
// parameter must earn the single test's threshold on its own)
TEST(GapPairs, NoiseAloneOrOneEffectNamesNoPair)
{
  for (unsigned seed : {11u, 12u, 13u, 14u}) {
    World noise = world(0.0, 0.0, seed);
    const PairSearch s = search_pairs_in(library(), noise.evidence, noise.data, noise.f, Verdict::unexplained, with_line());
    EXPECT_FALSE(s.named.has_value()) << "seed " << seed << ": " << s.why;
  }
  World one = world(1.2, 0.0, 21);
  const PairSearch s = search_pairs_in(library(), one.evidence, one.data, one.f, Verdict::unexplained, with_line());
  ASSERT_FALSE(s.tried.empty());
  EXPECT_FALSE(s.named.has_value()) << s.why;
  EXPECT_FALSE(s.tried[0].passes);
}

// a second member that adds less than a single effect's threshold to its best single member
// (B's signature 0.05 of A's: at 1.2 it adds about 1.2^2 x 72 x (0.04^2 / 2) / 0.01 = 8 to the
// likelihood ratio, under 15.14, while its magnitude stands well away from 0): no pair, by
// the margin rule alone (detected, explaining, inside its range)
TEST(GapPairs, ASecondMemberBelowTheMarginNamesNoPair)
{
  b_size = 0.05;
  World w = world(1.2, 1.2, 31);
  const PairSearch s = search_pairs_in(library(), w.evidence, w.data, w.f, Verdict::unexplained, with_line());
  b_size = 1.0;
  ASSERT_EQ(s.tried.size(), 1u);
  const PairFit &p = s.tried[0];
  EXPECT_FALSE(s.named.has_value()) << s.why;
  EXPECT_TRUE(p.detected);
  EXPECT_LT(p.margin, GapThresholds::lr_chi2_1_p1e4);
  EXPECT_NE(p.why.find("beyond its best single member"), std::string::npos) << p.why;
}

// the pair's threshold: the chi^2(2) quantile of 1e-4 (-2 ln 1e-4), scaled by its null mean
// over the chi^2(2)'s mean 2 when that exceeds 1
TEST(GapPairs, ThresholdIsTheChi2TwoQuantile)
{
  EXPECT_NEAR(GapThresholds::lr_chi2_2_p1e4, -2.0 * std::log(1e-4), 1e-3);
  EXPECT_DOUBLE_EQ(pair_lr_threshold(1.0), GapThresholds::lr_chi2_2_p1e4);
  EXPECT_DOUBLE_EQ(pair_lr_threshold(6.0), 3.0 * GapThresholds::lr_chi2_2_p1e4);
}

// the joint signature as a one-knot effect predicts the pair at knot 1 and the reference at 0
TEST(GapPairs, PairLineIsTheJointPrediction)
{
  World w = world(0, 0, 3);
  const EffectData L = pair_line(w.data.at("measurement_chain"), w.data.at("actuator_ramp"), 0.5, 2.0);
  std::vector<double> m, v;
  effect_predict(L, 1.0, 1, m, v);
  for (std::size_t k = 0; k < FEATURES; ++k) EXPECT_NEAR(m[k], REF + 0.5 * shape('A', 1, k) + 2.0 * shape('B', 1, k), 1e-12);
  effect_predict(L, 0.0, 2, m, v);
  for (std::size_t k = 0; k < FEATURES; ++k) EXPECT_NEAR(m[k], REF, 1e-12);
}

// a line at f seeds the chain at the period whose mount peaks there: the transform's own
// impulse response against the mount's response in closed form, |H|^2 = (1 + (2 zeta r)^2) /
// ((1 - r^2)^2 + (2 zeta r)^2), r = f T, damping ratio 0.2 (docs/gap.md, the mount)
TEST(GapPairs, ALineSeedsTheChainAtItsResonance)
{
  const Effect &chain = *find_effect("measurement_chain");
  const double zeta = 0.2;
  auto h2 = [&](double r) { return (1 + std::pow(2 * zeta * r, 2)) / (std::pow(1 - r * r, 2) + std::pow(2 * zeta * r, 2)); };
  double lo = 0.5, hi = 1.5;
  for (int i = 0; i < 200; ++i) {
    const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
    (h2(m1) > h2(m2) ? hi : lo) = (h2(m1) > h2(m2) ? m2 : m1);
  }
  const double r_peak = 0.5 * (lo + hi);
  for (double f : {428.0, 1000.0}) {
    // ms: T = r_peak / f; the impulse response's DFT bins are 2.4 Hz apart, interpolated:
    // 1% of the period is a quarter of the spacing of the chain's knots' smallest step
    EXPECT_NEAR(resonance_magnitude(chain, f), 1e3 * r_peak / f, 0.01 * 1e3 * r_peak / f) << f;
  }
  // a transform without a resonance (a uniform scale) seeds nothing
  EXPECT_TRUE(std::isnan(resonance_magnitude(*find_effect("force_scale"), 428.0)));
  Residual r = with_line();
  EXPECT_DOUBLE_EQ(seeding_line(r), 428.0);
  r.line_scaling = "scales with v0";    // a wavelength of the bed: no resonance to seed
  EXPECT_TRUE(std::isnan(seeding_line(r)));
}

// without a line the chain's segment holding its own fit is filled, a factor of at most 1.1
// apart: 2 to 4 ms in 8 steps of 2^(1/8) = 1.09 (7 knots between); at a knot, both segments
TEST(GapPairs, SegmentKnotsFillTheSegmentOfTheFit)
{
  const std::vector<double> knots = {0, 0.2, 0.3, 0.45, 0.7, 1, 1.4, 2, 4, 10};
  const auto k = segment_knots(knots, 2.12);
  ASSERT_EQ(k.size(), 7u);
  for (std::size_t i = 0; i < k.size(); ++i) EXPECT_NEAR(k[i], 2.0 * std::pow(2.0, (i + 1) / 8.0), 1e-12);
  // 1.4 to 2 in ceil(ln(2 / 1.4) / ln 1.1) = 4 steps (3 knots), then 2 to 4's 7
  EXPECT_EQ(segment_knots(knots, 2.0).size(), 10u);
  // from 0 (no factor): 4 equal steps
  const auto z = segment_knots(knots, 0.1);
  ASSERT_EQ(z.size(), 3u);
  for (std::size_t i = 0; i < z.size(); ++i) EXPECT_NEAR(z[i], 0.05 * (i + 1), 1e-15);
  EXPECT_TRUE(segment_knots(knots, 12.0).empty());
}
