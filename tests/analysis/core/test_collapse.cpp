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

}    // namespace

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
  ASSERT_TRUE(r.peak_ok);
  EXPECT_NEAR(r.peak_exponent, 2.0, 0.05);
}

TEST(Collapse, NoCrossoverWhenTheExcessNeverFades)
{
  std::vector<CollapseInput> in = {synthetic(100, 2.0, 1e9, 0)};
  auto r = collapse(in, CollapseParams{});
  EXPECT_EQ(r.n_crossed, 0);
  EXPECT_FALSE(r.curves[0].crossed);
  EXPECT_FALSE(r.peak_ok);    // one trace: no law
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
