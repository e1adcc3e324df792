// The collapse study's stages (core/collapse_study.h) on synthetic traces of known answer:
// F = K z gives k_z = K and F/F_z = 1 in every bin; a peak c v0^2 gives the peak law's
// exponent 2; runs F = K_r z give an ensemble k_z of mean(K_r) and a per-bin standard
// error of F/F_z over runs computed here by hand from the K_r alone.
#include "collapse_study.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

using namespace granpen;

namespace {

// z = z0 + 0.01 i up to zmax, F = K z plus a spike of height `peak` at i = 30 (z = 0.3 cm
// for z0 = 0: inside the peak regime 0 < z < 0.7 R of D = 2 cm, above the k_z window)
CollapseTrace line_trace(const std::string &name, double v0, double K, double peak = 0.0, double zmax = 6.0,
                         double z0 = 0.0)
{
  CollapseTrace t;
  t.name = name, t.v0 = v0, t.D = 2.0, t.g = 981.0;
  for (int i = 0; i <= (int) std::lround(zmax / 0.01); ++i) {
    const double z = z0 + 0.01 * i;
    t.z.push_back(z);
    t.F.push_back(K * z + (i == 30 ? peak : 0.0));
  }
  return t;
}

// an ensemble of runs F = K_r z, sampled at the centres of the 0.01 cm bins (z = 0.005 +
// 0.01 i), so that each bin's value is K_r times its centre; no alignment
CollapseEnsemble line_ensemble(const std::string &name, double v0, const std::vector<double> &K)
{
  std::vector<std::vector<double>> zs, Fs;
  for (double k : K) {
    const CollapseTrace t = line_trace(name, v0, k, 0.0, 6.0, 0.005);
    zs.push_back(t.z), Fs.push_back(t.F);
  }
  EnsembleParams ep;
  ep.align = false;
  ep.bin = 0.01;
  CollapseEnsemble e;
  e.name = name, e.v0 = v0, e.D = 2.0, e.g = 981.0;
  e.mean = ensemble_mean(zs, Fs, ep);
  return e;
}

}    // namespace

// Stage 1: a fitted line gives its slope; a given depth term is taken as it is; a falling
// trace is left out with its negative k_z; a window beyond the data is shortened, with a note.
TEST(CollapseStudy, DepthTermsKnownAnswer)
{
  std::vector<CollapseTrace> t = {line_trace("fit", 100, 2.5e4), line_trace("given", 100, 2.5e4),
                                  line_trace("falling", 100, -1e3), line_trace("short", 100, 3e4, 0.0, 2.0)};
  t[1].k_z_given = true, t[1].k_z_fixed = 7.0;
  const auto d = collapse_depth_terms(t, CollapseStudyParams{});
  ASSERT_EQ(d.size(), 4u);
  // an exact line: the least-squares slope is K to rounding (1e-9 relative)
  EXPECT_TRUE(d[0].ok && d[0].fitted);
  EXPECT_NEAR(d[0].k_z, 2.5e4, 2.5e4 * 1e-9);
  EXPECT_DOUBLE_EQ(d[0].zlo, 3.0);
  EXPECT_DOUBLE_EQ(d[0].zhi, 6.0);    // the infinite end is the data's end
  EXPECT_TRUE(d[1].ok && !d[1].fitted);
  EXPECT_EQ(d[1].k_z, 7.0);
  EXPECT_FALSE(d[2].ok);
  EXPECT_NEAR(d[2].k_z, -1e3, 1e3 * 1e-9);
  EXPECT_TRUE(d[3].ok && d[3].window_shortened);
  EXPECT_FALSE(d[3].window_note.empty());
  EXPECT_NEAR(d[3].k_z, 3e4, 3e4 * 1e-9);
  const auto in = collapse_inputs(t, d);
  ASSERT_EQ(in.size(), 3u);    // the falling trace left out
  EXPECT_EQ(in[1].name, "given");
  EXPECT_EQ(in[1].k_z, 7.0);
}

// Stages 2 and 3 through run_collapse_study: lines with spikes c v0^2 collapse to F/F_z = 1
// below and above the spike (so every curve crosses, the spread after the collapse is 0),
// and the peaks of stage 3 (k_z = 1) follow v0^2 exactly.
TEST(CollapseStudy, CollapseAndPeakLawKnownAnswer)
{
  const double c = 10.0;    // c v0^2 + K 0.3 above K 0.7 (the line's largest F in the peak regime) at v0 = 50
  std::vector<CollapseTrace> t;
  for (double v0 : {50.0, 100.0, 200.0}) t.push_back(line_trace("v" + std::to_string((int) v0), v0, 2e4, c * v0 * v0));
  CollapseStages st;
  st.peaks = true;
  std::vector<std::string> order;
  const CollapseStudy s = run_collapse_study(t, {}, CollapseStudyParams{}, st,
                                             [&](CollapseStage x) { order.push_back(collapse_stage_name(x)); });
  EXPECT_EQ(order, (std::vector<std::string>{"depth terms", "collapse", "peaks"}));
  ASSERT_TRUE(s.collapsed && s.peaks_done);
  EXPECT_FALSE(s.ensembles_done);
  ASSERT_EQ(s.result.curves.size(), 3u);
  EXPECT_EQ(s.result.n_crossed, 3);
  for (const auto &cv : s.result.curves) EXPECT_NEAR(cv.k_z, 2e4, 2e4 * 1e-9);    // the spike is outside z >= 3
  // the peaks are K 0.3 + c v0^2 at z = 0.3; the law is the least-squares slope of ln peak on
  // ln v0, computed here by hand on those known peaks
  ASSERT_TRUE(s.peaks.peak_law.ok);
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (double v0 : {50.0, 100.0, 200.0}) {
    const double x = std::log(v0), y = std::log(2e4 * 0.3 + c * v0 * v0);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  const double slope = (3 * sxy - sx * sy) / (3 * sxx - sx * sx);
  // the same least squares on the same three points: equal to rounding (1e-9)
  EXPECT_NEAR(s.peaks.peak_law.exponent, slope, 1e-9);
  for (const auto &cv : s.peaks.curves) EXPECT_NEAR(cv.peak_z, 0.3, 1e-12);
}

// Nothing collapsed (every trace falls): the peaks that go with the collapse are not run,
// but they are when asked for alone.
TEST(CollapseStudy, PeaksGoWithTheCollapse)
{
  const std::vector<CollapseTrace> t = {line_trace("a", 50, -10.0, 5.0), line_trace("b", 100, -10.0, 20.0)};
  CollapseStages st;
  st.peaks = true;
  const CollapseStudy s = run_collapse_study(t, {}, CollapseStudyParams{}, st);
  EXPECT_FALSE(s.collapsed);
  EXPECT_FALSE(s.peaks_done);
  st.collapse = false;
  const CollapseStudy p = run_collapse_study(t, {}, CollapseStudyParams{}, st);
  EXPECT_TRUE(p.peaks_done);
  EXPECT_EQ(p.peaks.curves.size(), 2u);
}

// Stage 4: runs F = K_r z. The ensemble mean is (mean K) z, so k_z = mean K; each run's
// F/F_z in a bin is K_r / mean K, whose standard error over the runs is
// sd(K_r) / mean(K) / sqrt(n), the same in every bin. An ensemble with a given depth term
// that is not positive is left out.
TEST(CollapseStudy, EnsembleRatioErrorKnownAnswer)
{
  const std::vector<double> K = {1.8e4, 2.0e4, 2.3e4};
  const double mean = (1.8e4 + 2.0e4 + 2.3e4) / 3.0;
  double s2 = 0;
  for (double k : K) s2 += (k / mean - 1.0) * (k / mean - 1.0);
  const double se = std::sqrt(s2 / 2.0 / 3.0);
  std::vector<CollapseEnsemble> e = {line_ensemble("slow", 50, K), line_ensemble("fast", 100, K),
                                     line_ensemble("given", 200, K)};
  e[2].k_z_given = true, e[2].k_z_fixed = -1.0;
  CollapseStudyParams p;
  p.boot.resamples = 50;    // the errors over runs are not checked here: few resamples suffice
  EnsembleCollapseStudy s;
  collapse_ensemble_means(e, p, s);
  EXPECT_EQ(s.kept, (std::vector<std::size_t>{0, 1}));
  EXPECT_EQ(s.left_out, (std::vector<std::size_t>{2}));
  ASSERT_EQ(s.collapse.result.curves.size(), 2u);
  ASSERT_EQ(s.ratio_se.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_NEAR(s.collapse.result.curves[i].k_z, mean, mean * 1e-9);    // an exact line: rounding
    ASSERT_EQ(s.ratio_se[i].size(), s.collapse.result.curves[i].t.size());
    ASSERT_FALSE(s.ratio_se[i].empty());
    // ratios of exact lines: only rounding in the per-bin sums (1e-9 of the se)
    for (double x : s.ratio_se[i]) EXPECT_NEAR(x, se, se * 1e-9);
  }
}

// Stage 5 (k_z = 1 for every ensemble, the one left out in stage 4 included): the peaks of
// the means are those of the runs' mean.
TEST(CollapseStudy, EnsemblePeaksEveryEnsemble)
{
  std::vector<CollapseEnsemble> e = {line_ensemble("a", 50, {1e4, 1.2e4}), line_ensemble("b", 100, {1e4, 1.2e4}),
                                     line_ensemble("c", 200, {1e4, 1.2e4})};
  e[2].k_z_given = true, e[2].k_z_fixed = -1.0;
  CollapseStudyParams p;
  p.boot.resamples = 50;
  CollapseStages st;
  st.collapse = false, st.ensembles = true, st.ensemble_peaks = true;
  std::vector<std::string> order;
  const CollapseStudy s = run_collapse_study({}, e, p, st, [&](CollapseStage x) { order.push_back(collapse_stage_name(x)); });
  EXPECT_EQ(order, (std::vector<std::string>{"ensembles", "ensemble peaks"}));    // no collapse: no depth terms
  ASSERT_TRUE(s.ensemble_peaks_done);
  ASSERT_EQ(s.ensemble_peaks.result.curves.size(), 3u);
  // the largest F over 0 < z < 0.7 R = 0.7 cm of (mean K) z on the 0.01 cm bins: the last
  // bin centre below 0.7 cm (0.695), so mean K times that centre (to rounding, 1e-9)
  for (const auto &cv : s.ensemble_peaks.result.curves) {
    EXPECT_NEAR(cv.peak, 1.1e4 * cv.peak_z, 1.1e4 * 1e-9);
    EXPECT_LT(cv.peak_z, 0.7);
    EXPECT_GT(cv.peak_z, 0.68);
  }
}

// A collapse the kernel refuses (v0 = 0): the stage function throws its
// std::invalid_argument; the study stops there with the message, the depth terms kept.
TEST(CollapseStudy, RefusedInputStopsTheStudy)
{
  std::vector<CollapseTrace> t = {line_trace("zero", 0.0, 2e4)};
  const auto d = collapse_depth_terms(t, CollapseStudyParams{});
  EXPECT_THROW(collapse(collapse_inputs(t, d), CollapseParams{}), std::invalid_argument);
  CollapseStages st;
  st.peaks = true;
  const CollapseStudy s = run_collapse_study(t, {}, CollapseStudyParams{}, st);
  EXPECT_TRUE(s.refused);
  EXPECT_EQ(s.refused_at, CollapseStage::collapse);
  EXPECT_FALSE(s.refusal.empty());
  EXPECT_EQ(s.depth.size(), 1u);
  EXPECT_FALSE(s.collapsed);
  EXPECT_FALSE(s.peaks_done);
}
