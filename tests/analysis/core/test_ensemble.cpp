// granpen --ensemble kernels: the onset alignment (core/onset_alignment.h), the ensemble
// mean with its per-bin standard error (core/ensemble_average.h) and the bootstrap over runs
// that carries the run-to-run scatter into fitted numbers (core/ensemble_fit.h), checked
// against answers known in closed form.
#include "ensemble_average.h"
#include "ensemble_fit.h"
#include "onset_alignment.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

using namespace granpen;

namespace {

std::vector<double> grid(double a, double b, double dz)
{
  std::vector<double> z;
  for (int i = 0; a + i * dz <= b + 1e-9; ++i) z.push_back(a + i * dz);
  return z;
}

}    // namespace

TEST(OnsetAlignment, ShiftsEveryRunToTheMeanOnset)
{
  // a ramp reaching its plateau 0.2 cm after contact: onset (20% of the first cm's largest
  // force) at contact + 0.04 cm; contacts at 0.1, -0.2 and 0.4 cm
  std::vector<double> onsets;
  std::vector<std::vector<double>> zs;
  for (double c : {0.1, -0.2, 0.4}) {
    std::vector<double> z = grid(-1, 3, 0.001), F;
    for (double v : z) F.push_back(v < c ? 0.0 : std::min(1.0, (v - c) / 0.2) * 100.0);
    onsets.push_back(force_onset(z, F));
    zs.push_back(z);
  }
  EXPECT_NEAR(onsets[0], 0.14, 1e-9);
  EXPECT_NEAR(onsets[1], -0.16, 1e-9);
  const OnsetAlignment a = align_onsets(onsets);
  EXPECT_NEAR(a.reference, (0.14 - 0.16 + 0.44) / 3, 1e-9);
  EXPECT_NEAR(a.max_shift, 0.44 - a.reference, 1e-9);
  for (std::size_t i = 0; i < zs.size(); ++i) {
    shift_depths(zs[i], a.shift[i]);
    EXPECT_NEAR(onsets[i] + a.shift[i], a.reference, 1e-12);
  }
  // every run ends at 3 cm before the shift: the deepest common depth is the smallest end
  EXPECT_NEAR(deepest_common({&zs[0], &zs[1], &zs[2]}), 3.0 + a.shift[2], 1e-9);
  // a given reference; a run without contact stays where it was
  const OnsetAlignment b = align_onsets({0.3, NAN}, 0.5);
  EXPECT_NEAR(b.shift[0], 0.2, 1e-12);
  EXPECT_EQ(b.shift[1], 0.0);
  ASSERT_EQ(b.without_onset.size(), 1u);
}

TEST(EnsembleMean, MeanAndStandardErrorOfAlignedRuns)
{
  // F = 2000 and 4000 dyne/cm times the depth after contact, contacts 0.3 cm apart: aligned,
  // every bin holds the mean of the two lines and the se |a - b| / 2 (sd |a - b| / sqrt 2, n = 2)
  std::vector<std::vector<double>> z, F;
  for (auto [k, c] : {std::pair{2000.0, 0.0}, std::pair{4000.0, 0.3}}) {
    z.push_back(grid(-0.5, 4, 0.01));
    F.emplace_back();
    for (double v : z.back()) F.back().push_back(v > c ? k * (v - c) : 0.0);
  }
  const EnsembleMean e = ensemble_mean(z, F);
  ASSERT_EQ(e.runs, 2u);
  EXPECT_NEAR(e.bin, 0.01, 1e-12);
  // the onsets sit about 0.2 cm after contact (20% of the largest F over the first cm after
  // the first touch), so the contacts, moved with the runs, meet to within a step
  const double c1 = 0.0 + e.alignment.shift[0], c2 = 0.3 + e.alignment.shift[1];
  EXPECT_NEAR(c1, c2, 0.005);
  EXPECT_NEAR(e.alignment.max_shift, 0.15, 0.005);
  EXPECT_NEAR(e.alignment.shift[0], -e.alignment.shift[1], 1e-9);    // both to the mean onset
  int checked = 0;
  for (std::size_t k = 0; k < e.z.size(); ++k) {
    EXPECT_EQ(e.n[k], 2);
    // a run's value in a bin is its sample there, anywhere in the 0.01 cm bin: against the
    // lines at the bin centre the mean is off by at most 3000 * 0.005 = 15, and the se
    // |v1 - v2| / 2 by at most (2000 + 4000) * 0.01 / 2 = 30
    if (e.z[k] < 0.2) continue;
    const double a = 2000.0 * (e.z[k] - c1), b = 4000.0 * (e.z[k] - c2);
    EXPECT_NEAR(e.mean[k], (a + b) / 2, 16.0);
    EXPECT_NEAR(e.se[k], std::fabs(b - a) / 2, 31.0);
    ++checked;
  }
  EXPECT_GT(checked, 300);
  // the common range: the second run, moved up, ends first
  EXPECT_NEAR(e.z_last, 4.0 + e.alignment.shift[1], 1e-9);
  // resample_mean of both runs is the mean; of one run twice, that run
  std::vector<double> m;
  resample_mean(e, {0, 1}, m);
  for (std::size_t k = 0; k < m.size(); ++k) EXPECT_NEAR(m[k], e.mean[k], 1e-9);
  resample_mean(e, {1, 1}, m);
  for (std::size_t k = 0; k < m.size(); ++k) EXPECT_NEAR(m[k], e.per_run[1][k], 1e-9);
  EXPECT_THROW(ensemble_mean({}, {}), std::invalid_argument);
  EXPECT_THROW(ensemble_mean({{0, 1}, {5, 6}}, {{1, 2}, {1, 2}}, EnsembleParams{0.0, false}), std::invalid_argument);
}

// Issue 36, class 2: two runs whose depths repeat in pairs 1e-7 cm apart (a logger writing
// each depth twice) made the default bin the median step, 1e-7 cm: 4e7 bins a run, and
// "out of memory". The default bin is now at least the mean step (0.005 cm here: about a
// sample a bin, as the median step gives for evenly sampled runs), and never makes more than
// kMaxEnsembleBins bins; a bin given finer than that is refused.
TEST(EnsembleMean, DepthsRepeatedATinyStepApartKeepTheRunsResolution)
{
  std::vector<std::vector<double>> z(2), F(2);
  for (int r = 0; r < 2; ++r)
    for (int i = 0; i < 2000; ++i) {
      const double depth = -0.5 + 0.01 * (i / 2) + (i % 2) * 1e-7;
      z[r].push_back(depth);
      F[r].push_back(depth > 0 ? 1000.0 * depth * (1.0 + 0.1 * r) : 0.0);
    }
  const EnsembleMean e = ensemble_mean(z, F, EnsembleParams{0.0, false});
  // the mean step: 9.99 cm over 1999 steps, 0.005 cm (the factor: round-off of the steps' sum)
  EXPECT_GE(e.bin, 9.99 / 1999.0 * (1 - 1e-12));
  EXPECT_LE(e.z.size(), 2000u);    // 9.99 cm / 0.005 cm (before: 1e8)
  // a bin of 1e-9 cm over 10 cm: 1e10 bins, refused
  EXPECT_THROW(ensemble_mean(z, F, EnsembleParams{1e-9, false}), std::invalid_argument);
  // a million-sample trace over 1 cm keeps at most kMaxEnsembleBins by default
  std::vector<std::vector<double>> zd(1), Fd(1);
  for (int i = 0; i < 1000000; ++i) zd[0].push_back(i * 1e-6), Fd[0].push_back(i * 1e-3);
  EXPECT_LE(ensemble_mean(zd, Fd, EnsembleParams{0.0, false}).z.size(), kMaxEnsembleBins);
}

// The checkable uncertainty: runs F_i = k z + a_i + b_i z + e_i(z) with run offsets a_i,
// run slopes b_i (a bed's packing) and independent noise e per sample. The slope of the
// ensemble mean over the window has the standard error
//   se^2 = sd_b^2 / n + sd_e^2 / (n Sxx),   Sxx = sum over the window of (z - zbar)^2,
// and the bootstrap over runs must report it.
TEST(EnsembleFit, BootstrapStandardErrorOfKzIsTheKnownOne)
{
  const double k = 20000, sd_a = 300, sd_b = 1500, sd_e = 2000;
  const std::size_t n = 8;
  const std::vector<double> z = grid(0, 4, 0.01);
  double zbar = 0, Sxx = 0;
  int nw = 0;
  for (double v : z)
    if (v >= 1.0 - 1e-9) zbar += v, ++nw;
  zbar /= nw;
  for (double v : z)
    if (v >= 1.0 - 1e-9) Sxx += (v - zbar) * (v - zbar);
  const double se_true = std::sqrt(sd_b * sd_b / n + sd_e * sd_e / (n * Sxx));
  TraceFitParams p;
  p.zlo = 1.0 - 1e-9, p.D = 2, p.g = 981, p.v0 = 100;
  EnsembleParams ep;
  ep.align = false;    // the noise would move the onsets; alignment is checked above
  std::mt19937_64 gen(7);
  std::normal_distribution<double> N01;
  // M independent ensembles: the mean square of the reported se estimates se_true^2 with a
  // relative sd of about sqrt(2 / (M (n - 1))) = 4.4% (M = 150, n = 8), so its root has
  // 2.2%, plus the bootstrap's own 1/sqrt(2B) = 4% per ensemble, averaged down to 0.3%; the
  // spread of the fitted k_z about k estimates se_true with 1/sqrt(2M) = 5.8%.
  const int M = 150;
  double ms_se = 0, ms_err = 0;
  BootstrapParams bp;
  bp.resamples = 300;
  for (int m = 0; m < M; ++m) {
    std::vector<std::vector<double>> zs(n, z), Fs(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double a = sd_a * N01(gen), b = sd_b * N01(gen);
      for (double v : z) Fs[i].push_back(k * v + a + b * v + sd_e * N01(gen));
    }
    const EnsembleFit f = fit_ensemble(ensemble_mean(zs, Fs, ep), p, bp);
    ASSERT_TRUE(f.k_z.ok && f.k_z.se_ok);
    EXPECT_EQ(f.k_z.defined, bp.resamples);
    ms_se += f.k_z.se * f.k_z.se / M;
    ms_err += (f.k_z.value - k) * (f.k_z.value - k) / M;
  }
  // tolerances: about 5 sigma of the 2.2%, and 3.5 sigma of the 5.8%
  std::printf("k_z: se_true %.1f, rms reported se %.1f, rms error %.1f dyne/cm\n", se_true, std::sqrt(ms_se),
              std::sqrt(ms_err));
  EXPECT_NEAR(std::sqrt(ms_se), se_true, 0.125 * se_true) << "se_true " << se_true;
  EXPECT_NEAR(std::sqrt(ms_err), se_true, 0.2 * se_true);
}

TEST(EnsembleFit, OneRunHasNoUncertaintyAndTheSameFitAsTheTrace)
{
  const std::vector<double> z = grid(-0.5, 4, 0.01);
  std::vector<double> F;
  for (double v : z) F.push_back(v > 0 ? 1e4 * v + 50.0 * std::sin(40 * v) : 0.0);
  TraceFitParams p;
  p.zlo = 1, p.D = 2, p.g = 981, p.v0 = 100;
  EnsembleParams ep;
  ep.bin = 0.01;
  const EnsembleFit f = fit_ensemble(ensemble_mean({z}, {F}, ep), p);
  EXPECT_EQ(f.resamples, 0);
  EXPECT_FALSE(f.k_z.se_ok);
  const TraceFit t = fit_trace(z, F, p);
  // one run, unshifted: its bins are its samples (z on the bin grid up to round-off at the
  // bin centres, 0.005 cm off): the slope agrees to the ripple's leverage, 1%
  EXPECT_NEAR(f.k_z.value, t.k_z, 0.01 * t.k_z);
}

// The peak law from ensembles: peaks P_j = c v0_j^2 (1 + eps_i), eps ~ N(0, s), n runs at
// each of 3 speeds a factor 2 apart. ln P_j of the mean has variance s^2 / n, and the
// least-squares slope over x = ln v0 (deviations -ln 2, 0, ln 2) has
//   se^2 = sum_j w_j^2 s^2 / n,  w_j = (x_j - xbar) / Sxx,  Sxx = 2 ln^2 2:  se = s / (ln 2 sqrt(2 n)).
TEST(EnsembleCollapse, PeakExponentAndItsKnownStandardError)
{
  const double c = 2.0, s = 0.1;
  const std::size_t n = 5;
  const double l2 = std::log(2.0);
  const double se_true = std::sqrt(2 * std::pow(l2 / (2 * l2 * l2), 2) * s * s / n);
  const std::vector<double> z = grid(-0.5, 3, 0.005);
  std::mt19937_64 gen(11);
  std::normal_distribution<double> N01;
  BootstrapParams bp;
  bp.resamples = 300;
  // the root mean square of the se: relative sd about sqrt(1 / (2 M (n - 1))) = 3.2%
  // (M = 120, n = 5), plus the bootstrap's 1/sqrt(2B) per ensemble averaged down
  const int M = 120;
  double ms_se = 0, mean_exp = 0;
  for (int m = 0; m < M; ++m) {
    std::vector<EnsembleCase> cases;
    for (double v0 : {50.0, 100.0, 200.0}) {
      std::vector<std::vector<double>> zs(n, z), Fs(n);
      for (std::size_t i = 0; i < n; ++i) {
        const double amp = c * v0 * v0 * (1 + s * N01(gen));
        // a bump at z = 0.3 cm (< 0.7 R = 0.7 cm) on a slow ramp
        for (double v : z) Fs[i].push_back(v > 0 ? 100 * v + amp * std::exp(-std::pow((v - 0.3) / 0.05, 2)) : 0.0);
      }
      EnsembleCase ec;
      ec.name = "v" + std::to_string((int) v0);
      ec.v0 = v0, ec.D = 2, ec.g = 981, ec.k_z_fixed = 1.0;
      ec.mean = ensemble_mean(zs, Fs, EnsembleParams{0.0, false});
      cases.push_back(ec);
    }
    const EnsembleCollapse r = collapse_ensembles(cases, CollapseParams{}, bp);
    ASSERT_TRUE(r.peak_exponent.ok && r.peak_exponent.se_ok);
    ms_se += r.peak_exponent.se * r.peak_exponent.se / M;
    mean_exp += r.peak_exponent.value / M;
  }
  // the ramp adds 30 dyne to peaks of 5000 and more: the exponent is 2 to 0.5%; its mean
  // over M ensembles scatters by se_true / sqrt(M) = 0.004
  EXPECT_NEAR(mean_exp, 2.0, 0.02);
  // the log of a maximum is not linear in the runs, and the se above is its first-order
  // (delta-method) value: 12%, about 4 sigma of the 3.2%
  std::printf("peak exponent: mean %.4f, se_true %.4f, rms reported se %.4f\n", mean_exp, se_true, std::sqrt(ms_se));
  EXPECT_NEAR(std::sqrt(ms_se), se_true, 0.12 * se_true) << "se_true " << se_true;
}
