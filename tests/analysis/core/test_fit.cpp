// The fit kernels on synthetic data of known answers: least squares (slope and
// its standard error), alpha, the transient peak, the fluctuation wavelength,
// and the rejections (too few points, zero spread) and undefined results.
#include "linear_fit.h"
#include "trace_fit.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

using namespace granpen;

namespace {

constexpr double PI = 3.14159265358979323846;

// z from z0 to z1 (inclusive) at spacing dz
std::vector<double> grid(double z0, double z1, double dz)
{
  std::vector<double> z;
  const int n = (int) std::lround((z1 - z0) / dz);
  for (int i = 0; i <= n; ++i) z.push_back(z0 + i * dz);
  return z;
}

void expect_all_finite(const TraceFit &f)
{
  for (double v : {f.zlo, f.zhi, f.z_first, f.z_last, f.k_z, f.k_z_se, f.intercept, f.intercept_se, f.rms,
                   f.alpha, f.alpha_se, f.peak_zmax, f.peak_F, f.peak_z, f.wavelength, f.wavelength_dg,
                   f.spectrum.dz, f.spectrum.length, f.spectrum.power_fraction})
    EXPECT_TRUE(std::isfinite(v));
}

}    // namespace

TEST(LinearFit, ExactLine)
{
  std::vector<double> x = {0, 1, 2, 3, 4}, y;
  for (double v : x) y.push_back(2.5 + 4.0 * v);
  const LinearFit f = linear_fit(x, y);
  EXPECT_NEAR(f.a, 2.5, 1e-12);
  EXPECT_NEAR(f.b, 4.0, 1e-12);
  EXPECT_NEAR(f.se_b, 0.0, 1e-12);
  EXPECT_NEAR(f.rms, 0.0, 1e-12);
  EXPECT_EQ(f.n, 5u);
}

TEST(LinearFit, HandComputedStandardErrors)
{
  // x = 0..3, y = 1, 3, 2, 4: b = 0.8, a = 1.3, residuals -0.3, 0.9, -0.9, 0.3,
  // SSR = 1.8, s^2 = 0.9, Sxx = 5: se_b = sqrt(0.18), se_a = sqrt(0.9 (1/4 + 2.25/5))
  const LinearFit f = linear_fit({0, 1, 2, 3}, {1, 3, 2, 4});
  EXPECT_NEAR(f.b, 0.8, 1e-12);
  EXPECT_NEAR(f.a, 1.3, 1e-12);
  EXPECT_NEAR(f.se_b, std::sqrt(0.18), 1e-12);
  EXPECT_NEAR(f.se_a, std::sqrt(0.9 * (0.25 + 0.45)), 1e-12);
  EXPECT_NEAR(f.rms, std::sqrt(1.8 / 4), 1e-12);
}

TEST(LinearFit, NoisyLineRecoversSlopeAndStandardError)
{
  const double k = 5.0e4, F0 = 1.0e3, sigma = 2.0e3;
  std::mt19937 rng(12345);
  std::normal_distribution<double> noise(0.0, sigma);
  const auto z = grid(3.0, 7.0, 0.01);
  std::vector<double> F;
  for (double v : z) F.push_back(F0 + k * v + noise(rng));
  const LinearFit f = linear_fit(z, F);

  double zbar = 0, sxx = 0;
  for (double v : z) zbar += v;
  zbar /= z.size();
  for (double v : z) sxx += (v - zbar) * (v - zbar);
  const double se_analytic = sigma / std::sqrt(sxx);

  EXPECT_LT(std::fabs(f.b - k), 3.0 * f.se_b) << "b = " << f.b << " +- " << f.se_b;
  EXPECT_NEAR(f.se_b / se_analytic, 1.0, 0.2) << "se_b " << f.se_b << ", analytic " << se_analytic;
  EXPECT_LT(std::fabs(f.a - F0), 3.0 * f.se_a);
  EXPECT_NEAR(f.rms / sigma, 1.0, 0.2);
}

TEST(LinearFit, ThroughOrigin)
{
  const double k = 300.0, sigma = 5.0;
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, sigma);
  const auto x = grid(0.5, 5.0, 0.05);
  std::vector<double> y;
  double sxx = 0;
  for (double v : x) {
    y.push_back(k * v + noise(rng));
    sxx += v * v;
  }
  const LinearFit f = linear_fit_origin(x, y);
  EXPECT_EQ(f.a, 0.0);
  EXPECT_LT(std::fabs(f.b - k), 3.0 * f.se_b);
  EXPECT_NEAR(f.se_b / (sigma / std::sqrt(sxx)), 1.0, 0.2);
  EXPECT_NEAR(linear_fit_origin({1, 2, 3}, {2, 4, 6}).b, 2.0, 1e-12);
}

TEST(LinearFit, RejectsTooFewPointsAndZeroSpread)
{
  EXPECT_THROW(linear_fit({1, 2}, {1, 2}), std::invalid_argument);
  EXPECT_THROW(linear_fit({}, {}), std::invalid_argument);
  EXPECT_THROW(linear_fit({2, 2, 2, 2}, {1, 2, 3, 4}), std::invalid_argument);
  EXPECT_THROW(linear_fit({1, 2, 3}, {1, 2}), std::invalid_argument);
  EXPECT_THROW(linear_fit({1, 2, NAN}, {1, 2, 3}), std::invalid_argument);
  EXPECT_THROW(linear_fit_origin({1, 2}, {1, 2}), std::invalid_argument);
  EXPECT_THROW(linear_fit_origin({0, 0, 0}, {1, 2, 3}), std::invalid_argument);
}

TEST(TraceFit, AlphaOfSyntheticTrace)
{
  // F = alpha mu rho_g g D^2 z with the paper's alpha = 35 at the paper's parameters
  TraceFitParams p;
  p.v0 = 40;
  p.D = 2.0;
  p.g = 981;
  p.mu = 0.3;
  p.rho_g = 3.0;
  p.d_g = 0.2;
  const double alpha = 35.0, kz = alpha * p.mu * p.rho_g * p.g * p.D * p.D;
  std::mt19937 rng(2024);
  std::normal_distribution<double> noise(0.0, 0.02 * kz);
  const auto z = grid(-0.5, 10.0, 0.01);
  std::vector<double> F;
  for (double v : z) F.push_back(v > 0 ? kz * v + noise(rng) : 0.0);

  const TraceFit f = fit_trace(z, F, p);    // default window z >= 3 cm
  ASSERT_TRUE(f.slope_ok);
  ASSERT_TRUE(f.alpha_ok);
  EXPECT_EQ(f.n_window, 701u);
  EXPECT_NEAR(f.z_first, 3.0, 1e-9);
  EXPECT_NEAR(f.zhi, 10.0, 1e-9);
  EXPECT_LT(std::fabs(f.k_z - kz), 3.0 * f.k_z_se);
  EXPECT_LT(std::fabs(f.alpha - alpha), 3.0 * f.alpha_se) << f.alpha << " +- " << f.alpha_se;
  EXPECT_NEAR(f.alpha_se / f.alpha, f.k_z_se / f.k_z, 1e-12);
  expect_all_finite(f);
}

TEST(TraceFit, DepthTermThroughTheOrigin)
{
  // F = b + k z over z 3..6: the line's slope is k; through the origin the least-squares
  // slope is sum F z / sum z^2 = k + b sum z / sum z^2
  TraceFitParams p;
  p.zlo = 3.0, p.mu = 0.3, p.rho_g = 3.0, p.g = 981.0, p.D = 2.0;
  const std::vector<double> z = grid(3.0, 6.0, 0.01);
  const double k = 1.0e5, b = 5.0e4;
  std::vector<double> F;
  double sz = 0, szz = 0;
  for (double v : z) F.push_back(b + k * v), sz += v, szz += v * v;
  const TraceFit f = fit_trace(z, F, p);
  ASSERT_TRUE(f.slope_ok);
  EXPECT_NEAR(f.k_z, k, 1e-6 * k);
  EXPECT_NEAR(f.k_z0, k + b * sz / szz, 1e-9 * k);
  EXPECT_NEAR(f.alpha0 / f.alpha, f.k_z0 / f.k_z, 1e-12);
  EXPECT_GT(f.k_z0_se, 0.0);    // the line does not pass through the origin
  // a proportional trace: both agree, and the origin fit is exact
  for (std::size_t i = 0; i < z.size(); ++i) F[i] = k * z[i];
  const TraceFit g = fit_trace(z, F, p);
  EXPECT_NEAR(g.k_z0, k, 1e-9 * k);
  EXPECT_NEAR(g.k_z0_se, 0.0, 1e-6);
}

TEST(QuadraticFit, ExactQuadraticAndHandComputedStandardErrors)
{
  // y = 3 x + 2 x^2 exactly: the parameters to round-off, no residual
  const std::vector<double> x = {1, 2, 3, 4, 5};
  std::vector<double> y;
  for (double v : x) y.push_back(3 * v + 2 * v * v);
  const QuadraticFit f = quadratic_fit_origin(x, y);
  EXPECT_NEAR(f.a, 3.0, 1e-12);
  EXPECT_NEAR(f.b, 2.0, 1e-12);
  EXPECT_NEAR(f.rms, 0.0, 1e-11);
  // by hand for x = 1, 2, 3 and y = 1, 2, 4: sums x^2 = 14, x^3 = 36, x^4 = 98, xy = 17,
  // x^2 y = 45; det = 14 98 - 36^2 = 76; a = (98 17 - 36 45) / 76 = 46/76,
  // b = (14 45 - 36 17) / 76 = 18/76; residuals 1 - 64/76, 2 - 164/76, 4 - 300/76
  const QuadraticFit h = quadratic_fit_origin({1, 2, 3}, {1, 2, 4});
  EXPECT_NEAR(h.a, 46.0 / 76.0, 1e-12);
  EXPECT_NEAR(h.b, 18.0 / 76.0, 1e-12);
  const double r1 = 1 - 64.0 / 76, r2 = 2 - 164.0 / 76, r3 = 4 - 300.0 / 76;
  const double s2 = (r1 * r1 + r2 * r2 + r3 * r3) / 1.0;    // n - 2 = 1
  EXPECT_NEAR(h.se_a, std::sqrt(s2 * 98.0 / 76.0), 1e-12);
  EXPECT_NEAR(h.se_b, std::sqrt(s2 * 14.0 / 76.0), 1e-12);
}

TEST(QuadraticFit, AgreesWithTheLineOfYOverXOnExactDataAndRecoversNoisyTerms)
{
  // another route on exact data: y / x = a + b x is a line
  const auto x = grid(0.5, 5.0, 0.05);
  std::vector<double> y, yx;
  for (double v : x) y.push_back(1.0e5 * v + 2.0e4 * v * v), yx.push_back(y.back() / v);
  const QuadraticFit q = quadratic_fit_origin(x, y);
  const LinearFit l = linear_fit(x, yx);
  EXPECT_NEAR(q.a, l.a, 1e-9 * l.a);
  EXPECT_NEAR(q.b, l.b, 1e-9 * l.b);
  // with noise: within 3 standard errors, and the errors of the right size (Monte Carlo
  // over 200 draws: the spread of a over the draws matches the mean se to 20%, the size
  // 200 draws resolve)
  std::mt19937 rng(11);
  std::normal_distribution<double> noise(0.0, 500.0);
  double sa = 0, saa = 0, se = 0;
  const int draws = 200;
  for (int k = 0; k < draws; ++k) {
    std::vector<double> yn;
    for (double v : y) yn.push_back(v + noise(rng));
    const QuadraticFit f = quadratic_fit_origin(x, yn);
    sa += f.a, saa += f.a * f.a, se += f.se_a;
  }
  const double mean = sa / draws, sd = std::sqrt((saa - draws * mean * mean) / (draws - 1));
  EXPECT_LT(std::fabs(mean - 1.0e5), 3.0 * sd / std::sqrt((double) draws));
  EXPECT_NEAR(sd / (se / draws), 1.0, 0.2);
}

TEST(QuadraticFit, RejectsWhatCannotTellTheTermsApart)
{
  EXPECT_THROW(quadratic_fit_origin({1, 2}, {1, 2}), std::invalid_argument);        // 2 points
  EXPECT_THROW(quadratic_fit_origin({2, 2, 2}, {1, 2, 3}), std::invalid_argument);  // one x
  EXPECT_THROW(quadratic_fit_origin({0, 0, 0}, {1, 2, 3}), std::invalid_argument);  // every x 0
  EXPECT_THROW(quadratic_fit_origin({0, 2, 2}, {1, 2, 3}), std::invalid_argument);  // one nonzero x
  EXPECT_THROW(quadratic_fit_origin({1, 2, NAN}, {1, 2, 3}), std::invalid_argument);
}

TEST(TraceFit, DepthLinearAndSquaredTerms)
{
  // F = a z + b z^2 with a the paper's alpha = 35 and b a shaft-like term of beta = 4: the
  // fit gives them back, alpha_a = 35 and beta_b = 4 to round-off
  TraceFitParams p;
  p.zlo = 1.0, p.mu = 0.3, p.rho_g = 3.0, p.g = 981.0, p.D = 2.0;
  const double a = 35.0 * p.mu * p.rho_g * p.g * p.D * p.D, b = 4.0 * p.mu * p.rho_g * p.g * p.D;
  const std::vector<double> z = grid(-0.5, 5.0, 0.01);
  std::vector<double> F;
  for (double v : z) F.push_back(v > 0 ? a * v + b * v * v : 0.0);
  const TraceFit f = fit_trace(z, F, p);
  ASSERT_TRUE(f.quad_ok);
  EXPECT_NEAR(f.quad_a, a, 1e-9 * a);
  EXPECT_NEAR(f.quad_b, b, 1e-9 * b);
  EXPECT_NEAR(f.alpha_a, 35.0, 1e-9);
  EXPECT_NEAR(f.beta_b, 4.0, 1e-9);
  // the line through the origin over z >= 1 takes the z^2 term into a larger alpha0
  EXPECT_GT(f.alpha0, 35.0 + 4.0);
}

TEST(TraceFit, FindsInsertedPeak)
{
  TraceFitParams p;
  p.D = 2.0;    // peak range 0 < z < 0.7 cm
  p.g = 981;
  p.mu = 0.3;
  p.rho_g = 3.0;
  p.d_g = 0.4;
  const double k = 3.0e4, H = 5.0e4, w = 0.05;
  const auto z = grid(-0.5, 5.0, 0.01);
  std::vector<double> F;
  for (double v : z) F.push_back(v > 0 ? k * v + H * std::exp(-0.5 * (v - 0.3) * (v - 0.3) / (w * w)) : 0.0);
  const TraceFit f = fit_trace(z, F, p);
  ASSERT_TRUE(f.peak_ok);
  EXPECT_NEAR(f.peak_zmax, 0.7, 1e-12);
  EXPECT_NEAR(f.peak_z, 0.3, 1e-9);
  EXPECT_NEAR(f.peak_F, k * 0.3 + H, 1e-6 * H);
  EXPECT_GE(f.n_peak, 69u);    // z = 0.01 .. 0.69 (0.70 by rounding)
  EXPECT_LE(f.n_peak, 70u);

  // a deeper maximum (z >= 0.7 R) is not the transient peak
  F.back() = 1e9;
  EXPECT_NEAR(fit_trace(z, F, p).peak_z, 0.3, 1e-9);
}

TEST(TraceFit, RecoversFluctuationWavelength)
{
  TraceFitParams p;
  p.zlo = 3.0;
  p.D = 2.0;
  p.g = 981;
  p.mu = 0.3;
  p.rho_g = 3.0;
  p.d_g = 0.4;
  const double k = 4.0e4, lambda = 0.4, amp = 3.0e3;
  std::mt19937 rng(99);
  std::normal_distribution<double> noise(0.0, 500.0);
  const auto z = grid(-0.5, 7.37, 0.01);    // window length 4.37 cm: not a whole number of periods
  std::vector<double> F;
  for (double v : z) F.push_back(v > 0 ? k * v + amp * std::sin(2 * PI * v / lambda) + noise(rng) : 0.0);
  const TraceFit f = fit_trace(z, F, p);
  ASSERT_TRUE(f.wavelength_ok) << (f.notes.empty() ? "" : f.notes.front());
  EXPECT_NEAR(f.wavelength, lambda, 0.05 * lambda);
  EXPECT_NEAR(f.wavelength_dg, f.wavelength / 0.4, 1e-12);
  EXPECT_NEAR(f.spectrum.dz, 0.01, 1e-9);
  EXPECT_LT(std::fabs(f.k_z - k), 3.0 * f.k_z_se);
}

TEST(TraceFit, WavelengthOnIrregularSamplingWithRepeatedDepths)
{
  // a halted rod repeats depths; samples jitter in z
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> jitter(-0.003, 0.003);
  std::vector<double> z, y;
  for (int i = 0; i <= 600; ++i) {
    const double v = 1.0 + 0.01 * i + jitter(rng);
    z.push_back(v);
    y.push_back(std::sin(2 * PI * v / 0.25));
    if (i % 50 == 0) {    // the same depth twice
      z.push_back(v);
      y.push_back(std::sin(2 * PI * v / 0.25));
    }
  }
  const Wavelength w = dominant_wavelength(z, y);
  ASSERT_TRUE(w.ok) << w.note;
  EXPECT_NEAR(w.wavelength, 0.25, 0.05 * 0.25);
  EXPECT_GT(w.power_fraction, 0.3);
}

TEST(TraceFit, LongWavelengthIsFlaggedAtTheLowestBin)
{
  // a 3 cm wave in a 2 cm record: the power piles up at the lowest bins
  std::vector<double> z, y;
  for (int i = 0; i <= 200; ++i) {
    z.push_back(1.0 + 0.01 * i);
    y.push_back(std::sin(2 * PI * z.back() / 3.0) + 0.3 * std::sin(2 * PI * z.back() / 0.13));
  }
  const Wavelength w = dominant_wavelength(z, y);
  ASSERT_TRUE(w.ok);
  EXPECT_EQ(w.bin, 2u);
  EXPECT_TRUE(w.lowest_bin);
  EXPECT_NEAR(w.wavelength, w.length / 2.0, 1e-12);
}

TEST(TraceFit, TooFewPointsIsUndefinedAndFinite)
{
  TraceFitParams p;
  p.D = 2.0;
  p.g = 981;
  p.mu = 0.3;
  p.rho_g = 3.0;
  p.d_g = 0.4;
  // a tiny-preset trace: to 1 cm only, so nothing at z >= 3
  const auto z = grid(-0.5, 1.0, 0.01);
  std::vector<double> F;
  for (double v : z) F.push_back(v > 0 ? 1e4 * v : 0.0);
  const TraceFit f = fit_trace(z, F, p);
  EXPECT_FALSE(f.slope_ok);
  EXPECT_FALSE(f.alpha_ok);
  EXPECT_FALSE(f.wavelength_ok);
  EXPECT_TRUE(f.peak_ok);
  EXPECT_EQ(f.n_window, 0u);
  EXPECT_EQ(f.k_z, 0.0);
  EXPECT_EQ(f.alpha, 0.0);
  EXPECT_EQ(f.wavelength, 0.0);
  EXPECT_NEAR(f.zhi, 1.0, 1e-9);
  EXPECT_FALSE(f.notes.empty());
  expect_all_finite(f);

  // two points in the window: still undefined
  p.zlo = 0.985;
  const TraceFit g = fit_trace(z, F, p);
  EXPECT_EQ(g.n_window, 2u);
  EXPECT_FALSE(g.slope_ok);
  expect_all_finite(g);

  // a line without fluctuations has no wavelength; no mu means no alpha
  p.zlo = 0.2;
  p.mu = 0.0;
  const TraceFit h = fit_trace(z, F, p);
  EXPECT_TRUE(h.slope_ok);
  EXPECT_NEAR(h.k_z, 1e4, 1e-6);
  EXPECT_FALSE(h.alpha_ok);
  expect_all_finite(h);

  EXPECT_THROW(fit_trace({1, 2, 3}, {1, 2}, p), std::invalid_argument);
  EXPECT_FALSE(dominant_wavelength({1, 2, 3}, {0, 1, 0}).ok);
}

// issue 19: depths repeated with a 1e-7 cm jitter made the median dz 1e-7 cm and the grid
// about 4e7 points (a hang); the grid is now never finer than a quarter of the mean step
TEST(TraceFit, JitteredRepeatedDepthsFinishQuicklyWithTheRightWavelength)
{
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> jitter(-1e-7, 1e-7);
  std::vector<double> z, y;
  for (int i = 0; i <= 400; ++i)
    for (int rep = 0; rep < 3; ++rep) {    // each depth three times: 2/3 of the steps are ~1e-7 cm
      const double v = 3.0 + 0.01 * i + (rep ? jitter(rng) : 0.0);
      z.push_back(v);
      y.push_back(std::sin(2 * PI * v / 0.4));
    }
  const auto t0 = std::chrono::steady_clock::now();
  const Wavelength w = dominant_wavelength(z, y);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_TRUE(w.ok) << w.note;
  EXPECT_TRUE(w.grid_limited);
  // at most 4 grid points per distinct depth step (1202 distinct depths)
  EXPECT_LE(w.n, 4u * 1203u);
  // 5 % of the wavelength: a bin of this 4 cm record is 0.4 / 10 wide, refined by the parabola
  EXPECT_NEAR(w.wavelength, 0.4, 0.05 * 0.4);
  // a few thousand points take milliseconds; the old 4e7-point grid took minutes
  EXPECT_LT(seconds, 5.0);
}

// a grid with a large prime number of points would make kissfft O(n^2): lowered to a
// 5-smooth count, the span kept
TEST(TraceFit, LargePrimeGridIsLoweredToAFastSize)
{
  const std::size_t N = 100003;    // prime: N * N = 1e10 > kMaxFftWork
  std::vector<double> z(N), y(N);
  for (std::size_t i = 0; i < N; ++i) {
    z[i] = 1e-4 * (double) i;
    y[i] = std::sin(2 * PI * z[i] / 0.4);
  }
  const auto t0 = std::chrono::steady_clock::now();
  const Wavelength w = dominant_wavelength(z, y);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_TRUE(w.ok) << w.note;
  EXPECT_TRUE(w.grid_limited);
  EXPECT_LE(w.n, N);
  std::size_t m = w.n;
  for (std::size_t f : {2, 3, 5})
    while (m % f == 0) m /= f;
  EXPECT_EQ(m, 1u) << w.n << " is not 5-smooth";
  EXPECT_GT(w.n, N * 95 / 100);    // 5-smooth numbers near 1e5 are less than 5 % apart
  EXPECT_NEAR(w.dz * (double) (w.n - 1), z.back() - z.front(), 1e-9);    // the whole span
  EXPECT_NEAR(w.wavelength, 0.4, 0.01 * 0.4);    // 25 periods: the bin width is 4 %, refined
  EXPECT_LT(seconds, 5.0);
}

// more distinct depths than kMaxSpectrumPoints: the grid stops at the limit
TEST(TraceFit, GridNeverExceedsItsLimit)
{
  const std::size_t N = kMaxSpectrumPoints + kMaxSpectrumPoints / 4;
  std::vector<double> z(N), y(N);
  for (std::size_t i = 0; i < N; ++i) {
    z[i] = 4.0 * (double) i / (double) (N - 1);
    y[i] = std::sin(2 * PI * z[i] / 0.4);
  }
  const Wavelength w = dominant_wavelength(z, y);
  ASSERT_TRUE(w.ok) << w.note;
  EXPECT_LE(w.n, kMaxSpectrumPoints);
  EXPECT_TRUE(w.grid_limited);
  EXPECT_NEAR(w.wavelength, 0.4, 0.01 * 0.4);
}
