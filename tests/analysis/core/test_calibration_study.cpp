// The calibration study (core/calibration_study.h) on synthetic pushes of known answer:
// F = K z over the window gives k_z = K and alpha = K / (mu rho_g g D^2) (the definition,
// computed here by hand); a push whose data miss the window is left out with the fit's
// note; arrays the fit refuses are named as refused; the table is core/calibration's.
#include "calibration_study.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

using namespace granpen;

namespace {

// z = 0 .. zmax at 0.01 cm, F = K z (cgs: D = 2 cm, g = 981 cm/s^2, rho_g = 3 g/cm^3)
CalibrationTrace push(const std::string &bed, double mu, double seed, double v0, double K, double zmax = 5.0)
{
  CalibrationTrace t;
  t.push.name = bed + "_v" + std::to_string((int) v0) + ".csv";
  t.push.bed = bed, t.push.mu = mu, t.push.seed = seed, t.push.v0 = v0;
  t.D = 2.0, t.g = 981.0, t.rho_g = 3.0, t.d_g = 0.4;
  for (int i = 0; i <= (int) std::lround(zmax / 0.01); ++i) t.z.push_back(0.01 * i), t.F.push_back(K * 0.01 * i);
  return t;
}

CalibrationBed bed(const std::string &name, double mu, double seed, double phi)
{
  CalibrationBed b;
  b.name = name, b.mu = mu, b.seed = seed, b.phi_0 = phi;
  return b;
}

}    // namespace

TEST(CalibrationStudy, FitsAndTableKnownAnswer)
{
  const std::vector<CalibrationBed> beds = {bed("a", 0.3, 1, 0.58), bed("b", 0.3, 2, 0.60)};
  std::vector<CalibrationTrace> pushes = {push("a", 0.3, 1, 100, 2.0e4), push("b", 0.3, 2, 100, 2.2e4),
                                          push("a", 0.3, 1, 100, 2.0e4, 0.5),    // ends above the window
                                          push("b", 0.3, 2, 100, 2.2e4)};
  pushes[3].F.pop_back();    // z and F differ in length: refused
  std::vector<std::string> seen;
  const CalibrationStudy s = run_calibration_study(beds, pushes, CalibrationStudyParams{},
                                                   [&](CalibrationStage x, std::size_t done, std::size_t of) {
                                                     seen.push_back(std::string(calibration_stage_name(x)) + " " +
                                                                    std::to_string(done) + "/" + std::to_string(of));
                                                   });
  EXPECT_EQ(seen, (std::vector<std::string>{"fits 0/4", "fits 1/4", "fits 2/4", "fits 3/4", "fits 4/4", "table 0/1"}));
  ASSERT_EQ(s.fits.size(), 4u);
  EXPECT_TRUE(s.fits[0].ok && s.fits[0].alpha_ok);
  EXPECT_TRUE(s.fits[1].ok);
  EXPECT_FALSE(s.fits[2].ok);
  EXPECT_FALSE(s.fits[2].refused);
  EXPECT_FALSE(s.fits[2].why.empty());
  EXPECT_FALSE(s.fits[3].ok);
  EXPECT_TRUE(s.fits[3].refused);
  ASSERT_EQ(s.pushes.size(), 2u);
  // exact lines: the least-squares slope is K to rounding (1e-9 relative)
  EXPECT_NEAR(s.pushes[0].k_z, 2.0e4, 2.0e4 * 1e-9);
  EXPECT_NEAR(s.pushes[1].k_z, 2.2e4, 2.2e4 * 1e-9);
  const double scale = 0.3 * 3.0 * 981.0 * 4.0;    // mu rho_g g D^2
  EXPECT_NEAR(s.pushes[0].alpha, 2.0e4 / scale, 2.0e4 / scale * 1e-9);
  // one row (mu 0.3, v0 100): phi_0 0.59 +- sd(0.58, 0.60), k_z 2.1e4 +- sd(2e4, 2.2e4)
  ASSERT_EQ(s.rows.size(), 1u);
  EXPECT_EQ(s.rows[0].k_z.n, 2u);
  EXPECT_NEAR(s.rows[0].k_z.mean, 2.1e4, 2.1e4 * 1e-9);
  EXPECT_NEAR(s.rows[0].k_z.sd, std::sqrt(2.0) * 1e3, 1e-6);    // sd of two values d apart: d / sqrt(2)
  EXPECT_NEAR(s.rows[0].phi_0.mean, 0.59, 1e-12);
}

// The pushes' headers (name, bed, mu, seed, v0) pass through the fit unchanged.
TEST(CalibrationStudy, PushKeepsItsRecord)
{
  CalibrationPush fitted;
  const CalibrationTrace t = push("bed_x", 0.5, 7, 50, 1.5e4);
  const CalibrationFitOutcome o = fit_calibration_push(t, CalibrationStudyParams{}, fitted);
  ASSERT_TRUE(o.ok);
  EXPECT_EQ(fitted.name, t.push.name);
  EXPECT_EQ(fitted.bed, "bed_x");
  EXPECT_EQ(fitted.mu, 0.5);
  EXPECT_EQ(fitted.seed, 7);
  EXPECT_EQ(fitted.v0, 50);
  EXPECT_NEAR(fitted.k_z, 1.5e4, 1.5e4 * 1e-9);    // an exact line: rounding
}
