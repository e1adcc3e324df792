// core/wave_arrival.h: the rod's disturbance reaching rings about its axis, on signals of
// known answer (a front at a known speed sampled as observe/arrival.lmp samples it, a jump
// below the factor, a spike before contact, two rings, a front that runs inwards).
#include "wave_arrival.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

using granpen::ArrivalSettings;
using granpen::wave_arrival;
using granpen::WaveArrival;

namespace {

constexpr double SAMPLE = 2e-5;    // 10 steps of 2e-6 s, observe/arrival.lmp's default
constexpr double CONTACT = 2e-3;

struct Rings {
  std::vector<double> t, r;
  std::vector<std::vector<double>> ke;
};
// rings at r, a settled background of 0.01 erg (+-10% in a fixed pattern) and a front that
// leaves r = 1 cm (the rod's edge) at contact at `speed` cm/s, after which the ring's energy
// is `jump` times its background
Rings rings(std::vector<double> r, double speed, double jump = 1e4, double until = 5e-3)
{
  Rings g;
  g.r = r;
  g.ke.assign(r.size(), {});
  for (int i = 0; i * SAMPLE <= until; ++i) {
    const double t = i * SAMPLE;
    g.t.push_back(t);
    for (std::size_t k = 0; k < r.size(); ++k) {
      const double quiet = t == 0 ? 0.0 : 0.01 * (1 + 0.1 * std::sin(7.0 * i + k));
      g.ke[k].push_back(t >= CONTACT + (r[k] - 1) / speed - 1e-12 ? quiet * jump : quiet);
    }
  }
  return g;
}

}    // namespace

TEST(WaveArrival, AFrontAtKnownSpeedIsReadToTheSampling)
{
  const double speed = 3000;    // 30 m/s: 0.333 ms per cm
  const Rings g = rings({1.5, 2.5, 3.5}, speed);
  const WaveArrival w = wave_arrival(g.t, g.ke, g.r, CONTACT);
  ASSERT_EQ(w.arrived, 3u);
  ASSERT_TRUE(w.fitted);
  for (const auto &s : w.stations) {
    // the first sample at or after the arrival: up to one sample late
    const double exact = CONTACT + (s.r - 1) / speed;
    EXPECT_GE(s.t, exact - 1e-12);
    EXPECT_LT(s.t, exact + SAMPLE);
    EXPECT_NEAR(s.background, 0.01, 0.002) << "the mean of the +-10% pattern";
  }
  // two arrivals 2 cm apart each late by less than a sample: the slowness to 2e-5 / 2 s/cm
  EXPECT_NEAR(w.slowness, 1 / speed, SAMPLE / 2);
  EXPECT_NEAR(w.speed, speed, speed * speed * SAMPLE / 2 * 1.01);
  // the front leaves the rod's edge at contact: the fit's r = 0 lies 1 cm before it
  EXPECT_NEAR(w.t_axis, CONTACT - 1 / speed, SAMPLE);
  EXPECT_TRUE(std::isfinite(w.slowness_se));
  EXPECT_NEAR(w.speed_se, w.speed * w.slowness_se / w.slowness, 1e-9 * w.speed);
}

TEST(WaveArrival, AJumpBelowTheFactorIsNoArrival)
{
  const Rings g = rings({1.5, 2.5, 3.5}, 3000, 50);
  const WaveArrival w = wave_arrival(g.t, g.ke, g.r, CONTACT);
  EXPECT_EQ(w.arrived, 0u);
  EXPECT_FALSE(w.fitted);
  ArrivalSettings ten;
  ten.factor = 10;
  EXPECT_EQ(wave_arrival(g.t, g.ke, g.r, CONTACT, ten).arrived, 3u);
}

TEST(WaveArrival, NothingBeforeContactCounts)
{
  Rings g = rings({1.5, 2.5, 3.5}, 3000);
  // one loud sample before contact raises the background (to about 0.11 over ~100 samples)
  // but is no arrival
  g.ke[0][50] = 1.0;
  const WaveArrival w = wave_arrival(g.t, g.ke, g.r, CONTACT);
  ASSERT_TRUE(w.stations[0].arrived);
  EXPECT_GE(w.stations[0].t, CONTACT);
  EXPECT_GT(w.stations[0].background, 0.015);
}

TEST(WaveArrival, TwoRingsFitWithoutAnError)
{
  const Rings g = rings({1.5, 3.5}, 2000);
  const WaveArrival w = wave_arrival(g.t, g.ke, g.r, CONTACT);
  ASSERT_TRUE(w.fitted);
  EXPECT_TRUE(std::isnan(w.slowness_se));
  EXPECT_NEAR(w.speed, 2000, 2000 * 2000 * SAMPLE / 2 * 1.01);
}

TEST(WaveArrival, AFrontRunningInwardsHasNoSpeed)
{
  Rings g = rings({1.5, 2.5, 3.5}, 3000);
  std::swap(g.ke[0], g.ke[2]);    // the outer ring first
  const WaveArrival w = wave_arrival(g.t, g.ke, g.r, CONTACT);
  EXPECT_TRUE(w.fitted);
  EXPECT_LT(w.slowness, 0);
  EXPECT_TRUE(std::isnan(w.speed));
}

TEST(WaveArrival, TooFewSamplesBeforeContactGiveNoBackground)
{
  const Rings g = rings({1.5, 2.5}, 3000);
  const WaveArrival w = wave_arrival(g.t, g.ke, g.r, 2.5 * SAMPLE);    // samples at t = 1, 2 x SAMPLE only
  EXPECT_TRUE(std::isnan(w.stations[0].background));
  EXPECT_EQ(w.arrived, 0u);
}

TEST(WaveArrival, RefusesInputsWithoutMeaning)
{
  const Rings g = rings({1.5, 2.5}, 3000);
  ArrivalSettings s;
  s.factor = 1;
  EXPECT_THROW(wave_arrival(g.t, g.ke, g.r, CONTACT, s), std::invalid_argument);
  EXPECT_THROW(wave_arrival(g.t, g.ke, {1.5}, CONTACT), std::invalid_argument);
  EXPECT_THROW(wave_arrival(g.t, g.ke, g.r, NAN), std::invalid_argument);
  std::vector<std::vector<double>> short_ke = g.ke;
  short_ke[1].pop_back();
  EXPECT_THROW(wave_arrival(g.t, short_ke, g.r, CONTACT), std::invalid_argument);
}
