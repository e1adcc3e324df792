// The t~ collapse on synthetic traces with a known crossover, a known peak law and
// curves that collapse exactly in t~.
#include "collapse.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

using namespace granpen;

namespace {

// F = k z (1 + A exp(-t~/tau)) + c v0^2 exp(-((z - 0.3) / 0.05)^2)
CollapseInput synthetic(double v0, double A, double tau, double c)
{
  CollapseInput in;
  in.name = "v" + std::to_string((int) v0);
  in.v0 = v0, in.D = 2.0, in.g = 981.0, in.k_z = 1.0e5;
  const double s = std::sqrt(in.g / in.D) / v0;
  for (double z = 0.0; z <= 20.0; z += 0.01) {
    in.z.push_back(z);
    const double peak = c * v0 * v0 * std::exp(-std::pow((z - 0.3) / 0.05, 2));
    in.F.push_back(in.k_z * z * (1.0 + A * std::exp(-z * s / tau)) + peak);
  }
  return in;
}

// a trace whose only force inside 0 < z < 0.7 R is a spike of height `peak` at z = 0.3
CollapseInput spike(double v0, double peak)
{
  CollapseInput in;
  in.name = "v" + std::to_string(v0);
  in.v0 = v0, in.D = 2.0, in.g = 981.0, in.k_z = 1.0;
  for (double z = 0.0; z <= 1.0; z += 0.01) {
    in.z.push_back(z);
    in.F.push_back(std::fabs(z - 0.3) < 0.005 ? peak : 0.0);
  }
  return in;
}

}    // namespace

// peak = c1 v0 + c2 v0^2 exactly: the two-term fit gives c1, c2 and v_x = c1 / c2, with
// standard errors of rounding size; the power law over 40 to 200 lies between 1 and 2
TEST(Collapse, TwoTermPeakLawKnownAnswer)
{
  const double c1 = 3400.0, c2 = 61.0;
  std::vector<CollapseInput> in;
  for (double v : {40.0, 80.0, 140.0, 200.0}) in.push_back(spike(v, c1 * v + c2 * v * v));
  const auto r = collapse(in, CollapseParams{});
  ASSERT_TRUE(r.peak_law.two_term_ok);
  ASSERT_TRUE(r.peak_law.crossover_ok);
  EXPECT_NEAR(r.peak_law.linear, c1, 1e-9 * c1);
  EXPECT_NEAR(r.peak_law.quadratic, c2, 1e-9 * c2);
  EXPECT_NEAR(r.peak_law.crossover_speed, c1 / c2, 1e-9 * c1 / c2);
  EXPECT_LT(r.peak_law.crossover_speed_se, 1e-6 * c1 / c2);
  EXPECT_GT(r.peak_law.exponent, 1.0);
  EXPECT_LT(r.peak_law.exponent, 2.0);
  // without the linear term the exponent is 2 and the crossover speed 0
  std::vector<CollapseInput> pure;
  for (double v : {40.0, 80.0, 200.0}) pure.push_back(spike(v, c2 * v * v));
  const auto q = collapse(pure, CollapseParams{});
  EXPECT_NEAR(q.peak_law.exponent, 2.0, 1e-9);
  EXPECT_NEAR(q.peak_law.crossover_speed, 0.0, 1e-6);
}

// The crossover speed's standard error (delta method, the covariance of c1 and c2 included)
// against the spread of v_x over noisy draws: three beds at each of four speeds, 3% noise on
// each peak. 4000 draws give the spread to about 1.1% (sqrt(1/(2 n))); the delta method is
// first order in a noise whose relative size on v_x is about 10%, so it may be off by a few
// percent: agreement within 10% is asked. Without the covariance term it comes out 20% too large.
TEST(Collapse, TwoTermCrossoverErrorMatchesNoisyDraws)
{
  const double c1 = 3400.0, c2 = 61.0;
  unsigned long long state = 12345;
  auto gauss = [&state]() {    // Box-Muller on a 64-bit LCG: deterministic across platforms
    auto uni = [&state]() {
      state = state * 6364136223846793005ULL + 1442695040888963407ULL;
      return ((state >> 11) + 0.5) / 9007199254740992.0;
    };
    const double u = uni(), w = uni();
    return std::sqrt(-2.0 * std::log(u)) * std::cos(6.283185307179586 * w);
  };
  const int draws = 4000;
  double s = 0.0, ss = 0.0, se_sum = 0.0;
  for (int k = 0; k < draws; ++k) {
    std::vector<CollapseInput> in;
    for (double v : {40.0, 80.0, 140.0, 200.0})
      for (int bed = 0; bed < 3; ++bed) in.push_back(spike(v, (c1 * v + c2 * v * v) * (1.0 + 0.03 * gauss())));
    const auto r = collapse(in, CollapseParams{});
    ASSERT_TRUE(r.peak_law.crossover_ok);
    s += r.peak_law.crossover_speed, ss += r.peak_law.crossover_speed * r.peak_law.crossover_speed;
    se_sum += r.peak_law.crossover_speed_se;
  }
  const double mean = s / draws, sd = std::sqrt((ss - draws * mean * mean) / (draws - 1));
  EXPECT_NEAR(mean, c1 / c2, 0.05 * c1 / c2);    // unbiased to first order
  EXPECT_NEAR(se_sum / draws, sd, 0.10 * sd);
}

TEST(Collapse, KnownCrossoverCollapseAndPeakLaw)
{
  const double A = 2.0, tau = 0.3, band = 0.2;
  std::vector<CollapseInput> in = {synthetic(50, A, tau, 1000), synthetic(100, A, tau, 1000),
                                   synthetic(200, A, tau, 1000)};
  CollapseParams p;
  p.band = band;
  p.zmin = 0.6;    // past the peak
  auto r = collapse(in, p);
  ASSERT_EQ(r.curves.size(), 3u);
  const double t_exact = tau * std::log(A / band);    // F/F_z - 1 = A exp(-t~/tau) = band
  EXPECT_EQ(r.n_crossed, 3);
  for (const auto &c : r.curves) EXPECT_NEAR(c.t_star, t_exact, p.tbin) << c.name;
  EXPECT_NEAR(r.t_star_mean, t_exact, p.tbin);
  // the curves are one function of t~: binned against t~ they nearly coincide
  EXPECT_GT(r.spread_z, 0.05);    // most z bins hold curves already near 1
  EXPECT_LT(r.spread_t, 0.1 * r.spread_z);
  ASSERT_TRUE(r.peak_law.ok);
  EXPECT_NEAR(r.peak_law.exponent, 2.0, 0.05);
}

TEST(Collapse, NoCrossoverWhenTheExcessNeverFades)
{
  std::vector<CollapseInput> in = {synthetic(100, 2.0, 1e9, 0)};
  auto r = collapse(in, CollapseParams{});
  EXPECT_EQ(r.n_crossed, 0);
  EXPECT_FALSE(r.curves[0].crossed);
  EXPECT_FALSE(r.peak_law.ok);    // one trace: no law
}

TEST(Collapse, EnsembleCrossoverSeesThroughRunNoise)
{
  // eight runs of one speed with fluctuations of +-50% of F_z (wavelength 1
  // cm, phases evenly spread, so they cancel in the mean): no single run stays in the band,
  // their mean crosses where the noiseless curve does
  const double A = 2.0, tau = 0.3, band = 0.2;
  std::vector<CollapseInput> in;
  for (int k = 0; k < 8; ++k) {
    auto c = synthetic(50, A, tau, 0);
    c.name += "_run" + std::to_string(k);
    for (std::size_t i = 0; i < c.z.size(); ++i)
      c.F[i] += 0.5 * c.k_z * c.z[i] * std::sin(2 * M_PI * c.z[i] / 1.0 + 2 * M_PI * k / 8);
    in.push_back(c);
  }
  CollapseParams p;
  p.band = band;
  p.zmin = 0.6;
  auto r = collapse(in, p);
  EXPECT_EQ(r.n_crossed, 0);
  ASSERT_TRUE(r.ens_crossed);
  EXPECT_NEAR(r.t_star_ensemble, tau * std::log(A / band), p.tbin);
  for (std::size_t k = 0; k < r.ens_n.size(); ++k) EXPECT_EQ(r.ens_n[k], 8);
  // fewer curves than min_curves: bins need all of them
  auto one = collapse({in[0]}, p);
  EXPECT_FALSE(one.ens_crossed);
  EXPECT_EQ(one.ens_t.size(), one.curves[0].t.size());
}

TEST(Collapse, RejectsMissingParameters)
{
  auto bad = synthetic(100, 1.0, 1.0, 0);
  bad.k_z = 0.0;
  EXPECT_THROW(collapse({bad}, CollapseParams{}), std::invalid_argument);
}

TEST(Collapse, StudentQuantiles)
{
  EXPECT_NEAR(t95(1), 12.706, 1e-3);
  EXPECT_NEAR(t95(10), 2.228, 1e-3);
  EXPECT_NEAR(t95(100), 1.96, 1e-9);
}
