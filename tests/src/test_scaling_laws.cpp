// The paper's scaling relations (scaling_laws.h) against hand-computed values, and each
// relation against its inverse.
#include "scaling_laws.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace granpen;

TEST(ScalingLaws, TTildeOfTheBenchPush)
{
  // z = 2 cm at v0 = 100 cm/s, g = 981 cm/s^2, D = 2 cm: t~ = 0.02 sqrt(490.5)
  EXPECT_NEAR(t_tilde(2.0, 100.0, 981.0, 2.0), 0.02 * std::sqrt(490.5), 1e-15);
  // t~ = 1 at z = v0 sqrt(D / g): 10 cm/s, g = 1000, D = 10 -> z = 1
  EXPECT_NEAR(t_tilde(1.0, 10.0, 1000.0, 10.0), 1.0, 1e-15);
  for (double bad : {0.0, -1.0, (double) NAN, (double) INFINITY}) {
    EXPECT_TRUE(std::isnan(t_tilde(2.0, bad, 981.0, 2.0))) << bad;
    EXPECT_TRUE(std::isnan(t_tilde(2.0, 100.0, bad, 2.0))) << bad;
    EXPECT_TRUE(std::isnan(t_tilde(2.0, 100.0, 981.0, bad))) << bad;
    EXPECT_TRUE(std::isnan(depth_at_t_tilde(1.0, bad, 981.0, 2.0))) << bad;
  }
}

TEST(ScalingLaws, DepthAtTTildeInvertsTTilde)
{
  EXPECT_NEAR(depth_at_t_tilde(1.0, 10.0, 1000.0, 10.0), 1.0, 1e-15);
  // round trip: a few ulps of a number near 1 (two square roots and two divisions)
  for (double z : {0.1, 1.0, 3.7})
    EXPECT_NEAR(depth_at_t_tilde(t_tilde(z, 40.0, 981.0, 1.0), 40.0, 981.0, 1.0), z, 1e-14 * z);
}

TEST(ScalingLaws, KzOfAlphaIsTheDepthLinearForceSlope)
{
  // alpha 35, mu 0.3, rho_g 3, g 981, D 2: 35 * 0.3 * 3 * 981 * 4 = 123606 dyne/cm
  EXPECT_NEAR(k_z_from_alpha(35.0, 0.3, 3.0, 981.0, 2.0), 123606.0, 1e-9);
  // alpha = 1 is the scale a fitted k_z is divided by
  EXPECT_NEAR(k_z_from_alpha(35.0, 0.3, 3.0, 981.0, 2.0) / k_z_from_alpha(1.0, 0.3, 3.0, 981.0, 2.0), 35.0, 1e-12);
  EXPECT_EQ(k_z_from_alpha(35.0, DEFAULT_MU, DEFAULT_RHO_G, 981.0, 2.0), k_z_from_alpha(35.0, 0.3, 3.0, 981.0, 2.0));
}

TEST(ScalingLaws, PeakRegimeEndsAtSevenTenthsOfTheRadius)
{
  EXPECT_DOUBLE_EQ(peak_regime_end(2.0), 0.7);    // 0.7 R with R = 1
  EXPECT_DOUBLE_EQ(peak_regime_end(1.0), 0.35);
}

TEST(ScalingLaws, PeakRegimeIsOpenAtBothEnds)
{
  // the surface and the end itself are outside: a point at exactly 0.35 D belongs to no peak
  EXPECT_FALSE(in_peak_regime(0.0, 2.0));
  EXPECT_TRUE(in_peak_regime(1e-9, 2.0));
  EXPECT_TRUE(in_peak_regime(std::nextafter(0.7, 0.0), 2.0));
  EXPECT_FALSE(in_peak_regime(peak_regime_end(2.0), 2.0));
  EXPECT_FALSE(in_peak_regime(-0.1, 2.0));
}
