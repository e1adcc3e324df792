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
