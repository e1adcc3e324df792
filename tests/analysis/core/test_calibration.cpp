// The friction-calibration kernel on hand-made records (two mu values, two seeds
// each) against hand-computed means and sample standard deviations (the bed .info
// reader: tests/analysis/io/test_bed_info.cpp).
#include "calibration.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace granpen;

namespace {

CalibrationBed bed(const char *name, double mu, double seed, double phi)
{
  CalibrationBed b;
  b.name = name;
  b.mu = mu;
  b.seed = seed;
  b.phi_0 = phi;
  return b;
}

CalibrationPush push(const char *bedname, double mu, double seed, double v0, double k, double alpha)
{
  CalibrationPush p;
  p.name = std::string(bedname) + ".csv";
  p.bed = bedname;
  p.mu = mu;
  p.seed = seed;
  p.v0 = v0;
  p.k_z = k;
  p.alpha = alpha;
  return p;
}

}    // namespace

TEST(Calibration, MeanAndSampleSd)
{
  const Stat s = mean_sd({1.0, 2.0, 4.0});
  EXPECT_EQ(s.n, 3u);
  EXPECT_NEAR(s.mean, 7.0 / 3.0, 1e-12);
  EXPECT_NEAR(s.sd, std::sqrt((16.0 / 9 + 1.0 / 9 + 25.0 / 9) / 2.0), 1e-12);
  EXPECT_EQ(mean_sd({5.0}).sd, 0.0);
  EXPECT_EQ(mean_sd({5.0}).mean, 5.0);
  EXPECT_EQ(mean_sd({}).n, 0u);
}

TEST(Calibration, TwoMuTwoSeeds)
{
  // given out of order; the second mu differs from 0.4 by rounding only
  const std::vector<CalibrationBed> beds = {bed("b4s2", 0.4, 2, 0.57), bed("b2s1", 0.2, 1, 0.60),
                                            bed("b4s1", 0.4000000000001, 1, 0.56), bed("b2s2", 0.2, 2, 0.62)};
  const std::vector<CalibrationPush> pushes = {push("b2s1", 0.2, 1, 100, 1000, 10), push("b4s1", 0.4, 1, 100, 2000, 20),
                                               push("b2s2", 0.2, 2, 100, 1200, 12), push("b4s2", 0.4, 2, 100, 2600, 26)};
  const auto rows = calibration_table(beds, pushes);
  ASSERT_EQ(rows.size(), 2u);

  // mu = 0.2: phi_0 0.60, 0.62 -> 0.61 +- sqrt(2 * 0.01^2 / 1); k_z 1000, 1200 -> 1100 +- 141.42
  EXPECT_NEAR(rows[0].mu, 0.2, 1e-12);
  EXPECT_EQ(rows[0].v0, 100.0);
  EXPECT_EQ(rows[0].phi_0.n, 2u);
  EXPECT_NEAR(rows[0].phi_0.mean, 0.61, 1e-12);
  EXPECT_NEAR(rows[0].phi_0.sd, 0.01 * std::sqrt(2.0), 1e-12);
  EXPECT_EQ(rows[0].k_z.n, 2u);
  EXPECT_NEAR(rows[0].k_z.mean, 1100.0, 1e-9);
  EXPECT_NEAR(rows[0].k_z.sd, 100.0 * std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(rows[0].alpha.mean, 11.0, 1e-12);
  EXPECT_NEAR(rows[0].alpha.sd, std::sqrt(2.0), 1e-12);

  // mu = 0.4: phi_0 0.56, 0.57 -> 0.565 +- 0.0070711; k_z 2000, 2600 -> 2300 +- 424.26
  EXPECT_NEAR(rows[1].mu, 0.4, 1e-9);
  EXPECT_EQ(rows[1].phi_0.n, 2u);
  EXPECT_NEAR(rows[1].phi_0.mean, 0.565, 1e-12);
  EXPECT_NEAR(rows[1].phi_0.sd, 0.005 * std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(rows[1].k_z.mean, 2300.0, 1e-9);
  EXPECT_NEAR(rows[1].k_z.sd, 300.0 * std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(rows[1].alpha.mean, 23.0, 1e-12);
  EXPECT_EQ(rows[1].beds.size(), 2u);
  EXPECT_EQ(rows[1].pushes.size(), 2u);
}

TEST(Calibration, SeveralSpeedsAndMissingPushes)
{
  const std::vector<CalibrationBed> beds = {bed("a", 0.1, 1, 0.62), bed("b", 0.5, 1, 0.55)};
  const std::vector<CalibrationPush> pushes = {push("a", 0.1, 1, 200, 900, 9), push("a", 0.1, 1, 50, 800, 8)};
  const auto rows = calibration_table(beds, pushes);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].v0, 50.0);    // sorted by mu then v0
  EXPECT_EQ(rows[1].v0, 200.0);
  EXPECT_EQ(rows[0].phi_0.n, 1u);
  EXPECT_EQ(rows[0].phi_0.sd, 0.0);
  EXPECT_NEAR(rows[2].mu, 0.5, 1e-12);    // a mu without pushes
  EXPECT_EQ(rows[2].k_z.n, 0u);
  EXPECT_EQ(rows[2].v0, 0.0);
  EXPECT_TRUE(calibration_table({}, {}).empty());
}

TEST(Calibration, MuRaisedInPouredBedsTakesTheirPhi0)
{
  // beds poured at mu = 0.1, pushed at mu = 0.1 and (raised) 0.3
  const std::vector<CalibrationBed> beds = {bed("a", 0.1, 1, 0.60), bed("b", 0.1, 2, 0.58)};
  const std::vector<CalibrationPush> pushes = {push("a", 0.3, 1, 56, 900, 9), push("b", 0.3, 2, 56, 700, 7),
                                               push("a", 0.1, 1, 56, 300, 3)};
  const auto rows = calibration_table(beds, pushes);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_NEAR(rows[1].mu, 0.3, 1e-12);
  EXPECT_EQ(rows[1].phi_0.n, 2u);
  EXPECT_NEAR(rows[1].phi_0.mean, 0.59, 1e-12);
  EXPECT_NEAR(rows[1].k_z.mean, 800.0, 1e-9);
}
