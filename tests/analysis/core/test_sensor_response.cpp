// The measurement chain as a filter (core/sensor_response.h), against answers known in
// closed form: the damped oscillator's step and ramp responses (the exact hold
// discretisations), a gain of 1 at DC, the Butterworth's -3 dB point, the impulse the rod's
// momentum balance conserves, the band-limited route's gain exactly H(f) up to the Nyquist
// frequency, and the linear hold's steady-state gain against its exact formula built from the
// continuous gain (so the time-domain kernel and sensor_gain check each other).
#include "sensor_response.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <random>
#include <vector>

using namespace granpen;

namespace {

const double DT = 1e-4;    // a trace's sample interval, s

SensorChain mount(double period, double zeta, bool damper)
{
  SensorChain c;
  c.mount.period = period;
  c.mount.zeta = zeta;
  c.mount.reads_damper = damper;
  return c;
}

SensorChain lowpass(double cutoff, int order)
{
  SensorChain c;
  c.lowpass.cutoff = cutoff;
  c.lowpass.order = order;
  return c;
}

double sinc(double x) { return x == 0.0 ? 1.0 : std::sin(M_PI * x) / (M_PI * x); }

// The steady-state complex gain of the discrete chain at f: a sine sampled every DT from
// rest, the response's sine and cosine parts fitted over the middle third (a whole number of
// periods: f * 0.1 s an integer; clear of the start's transient and the record's end)
std::complex<double> measured_gain(const SensorChain &c, double f, Discretisation how = Discretisation::BandLimited)
{
  std::vector<double> u;
  for (int k = 0; k < 3000; ++k) u.push_back(std::sin(2 * M_PI * f * k * DT));
  const auto y = sensor_response(u, DT, c, how);
  double a = 0, b = 0;
  for (int k = 1000; k < 2000; ++k) {
    a += y[k] * std::sin(2 * M_PI * f * k * DT) / 500.0;
    b += y[k] * std::cos(2 * M_PI * f * k * DT) / 500.0;
  }
  return {a, b};    // y = Re(G) sin + Im(G) cos
}

// What the first-order hold makes of a sampled sine: the samples joined by straight lines
// (the triangle kernel, sinc^2 in frequency) through the continuous chain, sampled again
std::complex<double> foh_gain(const SensorChain &c, double f)
{
  std::complex<double> g = 0.0;
  for (int m = -400; m <= 400; ++m) g += sensor_gain(c, f + m / DT) * std::pow(sinc(f * DT + m), 2);
  return g;
}

}    // namespace

TEST(SensorResponse, ConstantForceReadsTheSameAndGainIsOneAtDc)
{
  for (const SensorChain &c : {mount(1e-3, 0.2, true), mount(1e-2, 0.05, false), lowpass(300, 1), lowpass(300, 2)}) {
    SensorChain both = c;
    both.lowpass = lowpass(500, 2).lowpass;
    for (const SensorChain &x : {c, both}) {
      for (auto how : {Discretisation::BandLimited, Discretisation::LinearHold, Discretisation::ConstantHold}) {
        const auto y = sensor_response(std::vector<double>(300, 1.5e5), DT, x, how);
        ASSERT_EQ(y.size(), 300u);
        for (double v : y) EXPECT_NEAR(v, 1.5e5, 1e-9 * 1.5e5);
      }
      EXPECT_NEAR(std::abs(sensor_gain(x, 0.0) - 1.0), 0.0, 1e-12);
    }
  }
}

TEST(SensorResponse, EmptyChainAndBadInput)
{
  const std::vector<double> F = {0, 1, 3, 2};
  EXPECT_EQ(sensor_response(F, DT, SensorChain{}), F);
  EXPECT_TRUE(sensor_response(F, 0.0, mount(1e-3, 0.2, true)).empty());
  EXPECT_TRUE(sensor_response({}, DT, mount(1e-3, 0.2, true)).empty());
}

TEST(SensorResponse, MountStepResponseIsTheDampedOscillators)
{
  // a step held from the second sample on (zero-order hold: exact for a step at a sample)
  const double T = 1.4e-3, z = 0.2, w = 2 * M_PI / T, wd = w * std::sqrt(1 - z * z);
  std::vector<double> F(400, 1.0);
  F[0] = 0.0;
  for (bool damper : {false, true}) {
    const auto y = sensor_response(F, DT, mount(T, z, damper), Discretisation::ConstantHold);
    double worst = 0;
    for (std::size_t k = 1; k < F.size(); ++k) {
      const double t = (k - 1) * DT, e = std::exp(-z * w * t);
      const double s = 1 - e * (std::cos(wd * t) + z / std::sqrt(1 - z * z) * std::sin(wd * t));
      const double ds = w / std::sqrt(1 - z * z) * e * std::sin(wd * t);    // s'
      worst = std::max(worst, std::abs(y[k] - (damper ? s + 2 * z / w * ds : s)));
    }
    EXPECT_LT(worst, 1e-11) << (damper ? "k x + c x'" : "k x");
    EXPECT_EQ(y[0], 0.0);
  }
  // one sample: the chain at rest with it
  const auto one = sensor_response({2.0}, DT, mount(T, z, false), Discretisation::ConstantHold);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_NEAR(one[0], 2.0, 1e-14);
}

TEST(SensorResponse, RampIsExactWithTheLinearHoldAndTheDamperReadingDoesNotLag)
{
  // F = t from rest: p = t - 2 zeta / w + exp(-zeta w t) (a cos wd t + b sin wd t),
  // a = 2 zeta / w, b = (2 zeta^2 - 1) / wd; the reading k x + c x' = p + (2 zeta / w) p'
  const double T = 4e-3, z = 0.2, w = 2 * M_PI / T, wd = w * std::sqrt(1 - z * z);
  const double a = 2 * z / w, b = (2 * z * z - 1) / wd;
  std::vector<double> F;
  for (int k = 0; k < 600; ++k) F.push_back(k * DT);
  for (bool damper : {false, true}) {
    const auto y = sensor_response(F, DT, mount(T, z, damper), Discretisation::LinearHold);
    double worst = 0;
    for (std::size_t k = 0; k < F.size(); ++k) {
      const double t = k * DT, e = std::exp(-z * w * t), c = std::cos(wd * t), s = std::sin(wd * t);
      const double p = t - a + e * (a * c + b * s);
      const double dp = 1 + e * ((-z * w * a + wd * b) * c + (-z * w * b - wd * a) * s);
      worst = std::max(worst, std::abs(y[k] - (damper ? p + a * dp : p)));
    }
    EXPECT_LT(worst, 1e-12 * F.back() * 1e3) << (damper ? "k x + c x'" : "k x");
    // long after the start: the spring lags by 2 zeta / w, the sensor's damper makes it up
    EXPECT_NEAR(y.back(), damper ? F.back() : F.back() - a, 1e-9);
  }
}

TEST(SensorResponse, ButterworthIsDownThreeDecibelsAtItsCutOff)
{
  for (int order : {1, 2}) {
    const SensorChain c = lowpass(200, order);
    EXPECT_NEAR(std::abs(sensor_gain(c, 200)), 1 / std::sqrt(2.0), 1e-12);
    // |H|^2 = 1 / (1 + (f / fc)^(2 n))
    EXPECT_NEAR(std::abs(sensor_gain(c, 2000)), 1 / std::sqrt(1 + std::pow(10.0, 2 * order)), 1e-12);
    // the discrete chain's sine at the cut-off: band-limited, the continuous gain; with the
    // linear hold, less its sinc^2 (0.13% at 200 Hz and 1e-4 s)
    EXPECT_NEAR(std::abs(measured_gain(c, 200)), 1 / std::sqrt(2.0), 1e-4);
    EXPECT_NEAR(std::abs(measured_gain(c, 200, Discretisation::LinearHold)), 1 / std::sqrt(2.0), 1.5e-3 / std::sqrt(2.0));
  }
}

TEST(SensorResponse, MountResonatesAtItsNaturalFrequency)
{
  // a gauge on the spring: |H| = 1 / (2 zeta) at f_n; the reading k x + c x':
  // sqrt(1 + 4 zeta^2) / (2 zeta); phase -90 degrees for the gauge
  const SensorChain k_x = mount(2e-3, 0.2, false), fix = mount(2e-3, 0.2, true);
  EXPECT_NEAR(std::abs(sensor_gain(k_x, 500)), 2.5, 1e-12);
  EXPECT_NEAR(std::arg(sensor_gain(k_x, 500)), -M_PI / 2, 1e-12);
  EXPECT_NEAR(std::abs(sensor_gain(fix, 500)), std::sqrt(1 + 0.16) / 0.4, 1e-12);
  const MountFilter m = mount_of(9.8696044e6, 1.2566371e4, 100.0);    // 100 g, T = 20 ms, zeta 0.2
  EXPECT_NEAR(m.period, 0.02, 1e-9);
  EXPECT_NEAR(m.zeta, 0.2, 1e-7);
}

TEST(SensorResponse, BandLimitedGainIsTheChainsUpToNyquist)
{
  // the samples as a band-limited signal: a sampled sine at any frequency below Nyquist
  // (5 kHz) comes out as the continuous chain's gain times it, the mount ringing at 4 kHz too
  for (double T : {0.25e-3, 1.4e-3, 10e-3}) {
    SensorChain c = mount(T, 0.2, true);
    c.lowpass = lowpass(2500, 2).lowpass;
    for (double f : {50.0, 450.0, 1430.0, 2500.0, 4000.0, 4900.0}) {
      const std::complex<double> g = measured_gain(c, f), h = sensor_gain(c, f);
      EXPECT_LT(std::abs(g - h), 2e-4 * std::max(1.0, std::abs(h))) << "T " << T << " f " << f;
    }
  }
}

TEST(SensorResponse, NothingIsReadBeforeTheForceFirstChanges)
{
  // a sharp rise at sample 50 (a trace's contact): band-limited, it would ring back into the
  // samples before it; the reading stays the force's first value until the force moves
  std::vector<double> F(400, 0.0);
  for (int k = 50; k < 400; ++k) F[k] = 1e5 * (1 + 0.3 * ((k * 7919) % 13 - 6) / 6.0);
  const auto y = sensor_response(F, DT, mount(0.2e-3, 0.2, true));
  for (int k = 0; k < 50; ++k) EXPECT_EQ(y[k], 0.0) << k;
  EXPECT_NE(y[50], 0.0);
}

TEST(SensorResponse, LinearHoldGainIsTheFirstOrderHoldsExactly)
{
  // the kernel against the hold's formula, for the chain in series, from 50 Hz to Nyquist
  SensorChain c = mount(0.7e-3, 0.2, true);
  c.lowpass = lowpass(2500, 2).lowpass;
  for (double f : {50.0, 450.0, 1430.0, 2500.0, 4000.0}) {
    const std::complex<double> g = measured_gain(c, f, Discretisation::LinearHold), h = foh_gain(c, f);
    EXPECT_LT(std::abs(g - h), 1e-6 * std::abs(h)) << "f = " << f;
  }
  // and what the hold costs against the continuous chain: sinc^2(f dt) at a resonance
  const SensorChain ring = mount(1e-3, 0.2, true);
  EXPECT_NEAR(std::abs(measured_gain(ring, 1000, Discretisation::LinearHold)) / std::abs(sensor_gain(ring, 1000)),
              std::pow(sinc(0.1), 2), 2e-3);
}

TEST(SensorResponse, SmoothForceReadsAlikeEveryWay)
{
  // a force slow against the samples (a raised-cosine rise over 20 ms, then steady): the
  // band-limited route and the exact hold agree, and so does the analytic lag's absence
  std::vector<double> F(1500, 1e5);
  for (int k = 0; k < 200; ++k) F[k] = 0.5e5 * (1 - std::cos(M_PI * k / 200.0));
  const SensorChain c = mount(4e-3, 0.2, true);
  const auto a = sensor_response(F, DT, c), b = sensor_response(F, DT, c, Discretisation::LinearHold);
  double worst = 0;
  for (std::size_t k = 0; k < F.size(); ++k) worst = std::max(worst, std::abs(a[k] - b[k]));
  EXPECT_LT(worst, 1e-4 * 1e5);
}

TEST(SensorResponse, ImpulseIsConservedAsTheRodsMomentumBalanceSays)
{
  // m dV/dt = reading - F: once the rod rests again, the impulse of the reading equals the
  // force's (fix rod/drive mount's momentum balance, tests/inputs/mount_momentum_balance.sh)
  std::mt19937 rng(7);
  std::normal_distribution<double> n01(0.0, 1.0);
  std::vector<double> F(3000, 0.0);
  for (int k = 10; k < 800; ++k) F[k] = 1e5 * (1 + 0.3 * n01(rng));
  for (const SensorChain &c : {mount(1.4e-3, 0.2, true), mount(10e-3, 0.2, false), lowpass(1000, 2)})
    for (auto how : {Discretisation::BandLimited, Discretisation::LinearHold}) {
      const auto y = sensor_response(F, DT, c, how);
      double sF = 0, sy = 0;
      for (std::size_t k = 0; k < F.size(); ++k) sF += F[k], sy += y[k];
      // band-limited: the pulse's sharp edges have sinc tails, a little of which lies past
      // the record's end or before the force's first change, where the reading is held at
      // rest (measured 1.1e-5); the hold is causal and exact
      EXPECT_NEAR(sy / sF, 1.0, how == Discretisation::BandLimited ? 3e-5 : 1e-9);
    }
}
