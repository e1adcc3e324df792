// The studies granpen fit and granpen plot take their numbers from (core/fit_study.h,
// core/flow_table_study.h) and the averaging of ensembles before them
// (core/ensemble_averaging.h), on arrays of known answer: straight lines
// F = K z give k_z = K, the runs' own k_z on the mean's bins average to the mean's (the fit
// is linear in F: two routes to one number), an exact exponential gives its lambda, an exact
// line phi(I) its intercept and slope; refusals and left-out ensembles are named, stages
// reported in order.
#include "ensemble_averaging.h"
#include "fit_study.h"
#include "flow_table_study.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

using namespace granpen;

namespace {

// z = 0 .. zmax at dz, F = K z
void line(double K, double zmax, std::vector<double> &z, std::vector<double> &F, double dz = 0.01)
{
  z.clear(), F.clear();
  for (int i = 0; i <= (int) std::lround(zmax / dz); ++i) z.push_back(dz * i), F.push_back(K * dz * i);
}

FitStudyTrace trace(const std::string &name, double K, double zmax)
{
  FitStudyTrace t;
  t.name = name;
  line(K, zmax, t.z, t.F);
  t.params.zlo = 1.0, t.params.v0 = 100, t.params.D = 2, t.params.g = 981;
  return t;
}

// runs F = K_i z sampled at z = 0.01, 0.03, ... up to zmax: the centres of the 0.02 cm bins
// of unaligned() (the bins are [k w, (k + 1) w)), so that each bin holds one sample at its
// centre and the mean's bins lie on the mean's line exactly
EnsembleRuns runs(const std::string &name, const std::vector<double> &K, double zmax)
{
  EnsembleRuns e;
  e.name = name;
  for (double k : K) {
    std::vector<double> z, F;
    for (int i = 0; 0.01 + 0.02 * i <= zmax + 1e-9; ++i) z.push_back(0.01 + 0.02 * i), F.push_back(k * z.back());
    e.z.push_back(z), e.F.push_back(F);
  }
  return e;
}

EnsembleParams unaligned()
{
  EnsembleParams p;
  p.align = false;    // the onsets are not the subject here
  p.bin = 0.02;
  return p;
}

}    // namespace

TEST(FitStudy, TracesAndEnsemblesKnownAnswer)
{
  std::vector<FitStudyTrace> traces = {trace("a", 2.0e4, 5.0), trace("b", 3.0e4, 5.0), trace("c", 1.0e4, 5.0)};
  traces[2].F.pop_back();    // z and F differ in length: refused, the others fitted
  const EnsembleAveraging avg = average_ensembles({runs("e", {1.8e4, 2.0e4, 2.4e4}, 5.0), runs("shallow", {2e4, 2e4}, 0.5)},
                                                  unaligned());
  ASSERT_EQ(avg.ensembles.size(), 2u);
  ASSERT_TRUE(avg.ensembles[0].ok && avg.ensembles[1].ok);
  std::vector<FitStudyEnsemble> ens(2);
  ens[0].name = "e", ens[0].mean = avg.ensembles[0].mean, ens[0].params = traces[0].params;
  ens[1].name = "shallow", ens[1].mean = avg.ensembles[1].mean, ens[1].params = traces[0].params;    // ends above z = 1
  FitStages st;
  st.ensemble_fits = st.run_fits = true;
  FitStudyParams p;
  p.boot.resamples = 50;    // the errors are not checked here; a few resamples keep it quick
  std::vector<std::string> seen;
  const FitStudy s = run_fit_study(traces, ens, p, st, [&](FitStage x, std::size_t done, std::size_t of) {
    seen.push_back(std::string(fit_stage_name(x)) + " " + std::to_string(done) + "/" + std::to_string(of));
  });
  EXPECT_EQ(seen, (std::vector<std::string>{"fits 0/3", "fits 1/3", "fits 2/3", "fits 3/3", "ensemble fits 0/2",
                                            "ensemble fits 1/2", "ensemble fits 2/2", "run fits 0/2", "run fits 1/2",
                                            "run fits 2/2"}));
  ASSERT_EQ(s.fits.size(), 3u);
  // exact lines: the least-squares slope is K to rounding (1e-9 relative)
  EXPECT_FALSE(s.fits[0].refused);
  EXPECT_NEAR(s.fits[0].fit.k_z, 2.0e4, 2.0e4 * 1e-9);
  EXPECT_NEAR(s.fits[1].fit.k_z, 3.0e4, 3.0e4 * 1e-9);
  EXPECT_TRUE(s.fits[2].refused);
  EXPECT_FALSE(s.fits[2].why.empty());
  ASSERT_EQ(s.ensembles.size(), 2u);
  ASSERT_TRUE(s.ensembles[0].k_z.ok);
  // the mean of three lines is the line of their mean slope (each bin at its sample)
  const double K = (1.8e4 + 2.0e4 + 2.4e4) / 3;
  EXPECT_NEAR(s.ensembles[0].k_z.value, K, K * 1e-9);
  ASSERT_EQ(s.run_fits.size(), 2u);
  ASSERT_EQ(s.run_fits[0].size(), 3u);
  double sum = 0;
  for (const TraceFit &f : s.run_fits[0]) sum += f.k_z;
  EXPECT_NEAR(s.run_fits[0][2].k_z, 2.4e4, 2.4e4 * 1e-9);
  EXPECT_NEAR(sum / 3, s.ensembles[0].k_z.value, K * 1e-9);    // linear in F: the runs' mean is the mean's
  EXPECT_FALSE(s.ensembles[1].k_z.ok);    // no depth in the window
  EXPECT_TRUE(s.run_fits[1].empty());     // and so no run fits
}

TEST(FitStudy, StagesRunOnlyWhenAsked)
{
  const FitStudy s = run_fit_study({trace("a", 2.0e4, 5.0)}, {}, FitStudyParams{}, FitStages{});
  EXPECT_EQ(s.fits.size(), 1u);
  EXPECT_TRUE(s.ensembles.empty());
  EXPECT_TRUE(s.run_fits.empty());
  FitStages none;
  none.fits = false;
  EXPECT_TRUE(run_fit_study({trace("a", 2.0e4, 5.0)}, {}, FitStudyParams{}, none).fits.empty());
}

TEST(AverageEnsembles, LeftOutAndTooFineBinNamed)
{
  // runs that share no depth (not aligned: 0..1 and 2..3 cm) cannot be averaged: its
  // reason without the kernel's name; the others are
  EnsembleRuns apart = runs("apart", {1e4, 1e4}, 1.0);
  for (double &z : apart.z[1]) z += 2.0;
  const EnsembleAveraging a = average_ensembles({runs("one", {1e4, 2e4}, 2.0), apart, runs("two", {1e4}, 2.0)}, unaligned());
  ASSERT_FALSE(a.bin_too_fine);
  ASSERT_EQ(a.ensembles.size(), 3u);
  EXPECT_TRUE(a.ensembles[0].ok);
  EXPECT_EQ(a.ensembles[0].mean.runs, 2u);
  EXPECT_FALSE(a.ensembles[1].ok);
  EXPECT_EQ(a.ensembles[1].why.find("ensemble_mean"), std::string::npos) << a.ensembles[1].why;
  EXPECT_FALSE(a.ensembles[1].why.empty());
  EXPECT_TRUE(a.ensembles[2].ok);
  // a given bin making more than kMaxEnsembleBins bins over the second's depths (0.01..3.99
  // cm) but not over the first's (0.01..0.09 cm): refused there, with the depths, before
  // averaging it or any after it
  EnsembleParams fine = unaligned();
  fine.bin = 4.0 / (double) kMaxEnsembleBins / 2;    // about twice the most bins over 4 cm
  const EnsembleAveraging b = average_ensembles({runs("short", {1e4}, 0.1), runs("deep", {1e4}, 4.0),
                                                 runs("after", {1e4}, 1.0)}, fine);
  ASSERT_TRUE(b.bin_too_fine);
  EXPECT_EQ(b.too_fine, 1u);
  EXPECT_EQ(b.ensembles.size(), 1u);
  EXPECT_NEAR(b.z_lo, 0.01, 1e-12);
  EXPECT_NEAR(b.z_hi, 3.99, 1e-9);
}

TEST(FlowTableStudy, ProfileAndEdgeKnownAnswer)
{
  FlowTableColumns c;
  c.has_profile = c.has_edge = true;
  const double A = 30.0, lambda = 1.9;    // |v_z| = A exp(z / lambda) below the face (z < 0)
  for (int i = 0; i < 12; ++i) {
    const double z = -4.0 + 0.3 * i;
    c.z.push_back(z), c.vz.push_back(-A * std::exp(z / lambda)), c.vz_se.push_back(0.0);
  }
  // phi = 0.57 - 0.35 I at the edge, with rows where one of the two is unknown
  c.I = {0.01, NAN, 0.05, 0.1, 0.2, 0.3, INFINITY};
  for (double I : c.I) c.phi.push_back(0.57 - 0.35 * I);
  c.phi[3] = NAN;
  std::vector<std::string> seen;
  const FlowTableStudy s = run_flow_table_study(c, [&](FlowTableStage x) { seen.push_back(flow_table_stage_name(x)); });
  EXPECT_EQ(seen, (std::vector<std::string>{"profile", "edge"}));
  ASSERT_TRUE(s.profile_done && s.profile.ok) << s.profile.note;
  EXPECT_NEAR(s.profile.lambda, lambda, 1e-9 * lambda);    // exact points: to rounding
  ASSERT_TRUE(s.edge_done);
  EXPECT_EQ(s.edge.I, (std::vector<double>{0.01, 0.05, 0.2, 0.3}));    // the finite pairs, in order
  ASSERT_TRUE(s.edge.ok);
  EXPECT_NEAR(s.edge.fit.a, 0.57, 1e-12);
  EXPECT_NEAR(s.edge.fit.b, -0.35, 1e-12);
  // fewer than 3 pairs, or one I (to 1e-9 of the spread): the pairs without a line
  EXPECT_FALSE(fit_edge_line({0.1, 0.2}, {0.5, 0.4}).ok);
  const EdgeLine one = fit_edge_line({0.1, 0.1, 0.1 + 1e-12}, {0.5, 0.4, 0.45});
  EXPECT_FALSE(one.ok);
  EXPECT_EQ(one.I.size(), 3u);
  // stage 2 with windows of 1 cm: one exponential, one lambda in every window (4 points each)
  c.local_width = 0.9;
  seen.clear();
  const FlowTableStudy l = run_flow_table_study(c, [&](FlowTableStage x) { seen.push_back(flow_table_stage_name(x)); });
  EXPECT_EQ(seen, (std::vector<std::string>{"profile", "local", "edge"}));
  ASSERT_TRUE(l.local_done);
  ASSERT_EQ(l.local.size(), 9u);    // starts -4.0 ... -1.6: z_lo + 0.9 <= -0.7
  for (const auto &w : l.local) {
    ASSERT_TRUE(w.fit.ok) << w.fit.note;
    EXPECT_NEAR(w.fit.lambda, lambda, 1e-9 * lambda);
  }
  EXPECT_FALSE(s.local_done);    // width 0: not run
  // a table not read: its stage does not run
  FlowTableColumns none;
  const FlowTableStudy n = run_flow_table_study(none);
  EXPECT_FALSE(n.profile_done || n.edge_done);
}
