// granpen import's kernels (core/instrument_import.h) on arrays, without files: the unit
// table against known conversions; tare, contact and depth; windows that conserve the
// impulse; two speeds and a deceleration; position noise. The round trips through
// granpen-cli: tests/analysis/cli/test_import.cpp.
#include "instrument_import.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

// ---- kernels: the unit table against known conversions
TEST(ImportUnits, KnownFactors)
{
  double f;
  ASSERT_TRUE(granpen::force_unit_factor("kN", false, f));
  EXPECT_DOUBLE_EQ(f, 1e8);    // 1 kN = 1e8 dyne
  ASSERT_TRUE(granpen::force_unit_factor("lbf", true, f));
  EXPECT_DOUBLE_EQ(f, 4.4482216152605);
  ASSERT_TRUE(granpen::stress_unit_factor("kPa", 1e-4, false, f));
  EXPECT_DOUBLE_EQ(f, 1e3 * 1e-4 * 1e5);    // 1 kPa on 1 cm^2 = 0.1 N = 1e4 dyne
  ASSERT_TRUE(granpen::length_unit_factor("in", false, f));
  EXPECT_DOUBLE_EQ(f, 2.54);
  ASSERT_TRUE(granpen::speed_unit_factor("mm/min", true, f));
  EXPECT_DOUBLE_EQ(f, 1e-3 / 60.0);
  EXPECT_FALSE(granpen::force_unit_factor("kip", true, f));
  EXPECT_FALSE(granpen::length_unit_factor("furlong", true, f));
}

// ---- kernels on arrays, without files

namespace {

// the three passes over rows held in memory, in chunks of `chunk` rows
granpen::ImportSummary run_passes(const granpen::ImportRules &rules, const std::vector<granpen::ImportRow> &rows,
                                  std::vector<granpen::TracePoint> &out, std::size_t chunk = 7)
{
  auto feed = [&](const std::function<void(const std::vector<granpen::ImportRow> &)> &f) {
    for (std::size_t i = 0; i < rows.size(); i += chunk)
      f(std::vector<granpen::ImportRow>(rows.begin() + i, rows.begin() + std::min(rows.size(), i + chunk)));
  };
  granpen::PushScan scan(rules);
  feed([&](const auto &c) { scan.add(c); });
  const auto lim = scan.finish();
  granpen::SpeedProfile prof(rules, lim);
  feed([&](const auto &c) { prof.add(c); });
  const auto ramp = prof.finish();
  granpen::TraceBuilder b(rules, lim, ramp);
  feed([&](const auto &c) { b.add(c, out); });
  return b.finish(out);
}

// a push at 100 cm/s sampled at 100 kHz from x = -0.3, F = offset + 1000 z beyond contact,
// speed `v1` from row `change` on
std::vector<granpen::ImportRow> push_rows(int n, double offset, int change = 1 << 30, double v1 = 100.0)
{
  std::vector<granpen::ImportRow> rows;
  double x = -0.3;
  for (int i = 0; i < n; ++i) {
    granpen::ImportRow r;
    r.t = i * 1e-5;
    if (i) x += (i >= change ? v1 : 100.0) * 1e-5;
    r.x = x;
    r.F = offset + (x > 0 ? 1000.0 * x : 0.0);
    r.line = i + 2;
    rows.push_back(r);
  }
  return rows;
}

}    // namespace

// tare, contact and the depth: the offset exactly, the surface at the first row at
// onset_force (x = 0.01 there: F = 1000 x reaches 10 at x = 0.01), the end at the last row
TEST(ImportKernels, TareSurfaceAndEnd)
{
  granpen::ImportRules rules;
  rules.has_position = true;
  rules.tare_rows = 100;
  rules.onset_force = 10.0;
  const auto rows = push_rows(4000, 250.0);
  std::vector<granpen::TracePoint> out;
  const auto s = run_passes(rules, rows, out);
  EXPECT_DOUBLE_EQ(s.limits.tare, 250.0);
  EXPECT_NEAR(s.limits.surface, 0.01, 1e-3 + 1e-9);    // one row's advance (1e-3 cm)
  EXPECT_EQ(s.limits.end_line, rows.back().line);
  EXPECT_EQ(s.rows_cut, 0u);
  ASSERT_EQ(out.size(), rows.size());
  for (std::size_t i = 0; i < out.size(); ++i) {
    ASSERT_NEAR(out[i].z, rows[i].x - s.limits.surface, 1e-12);
    ASSERT_NEAR(out[i].F, rows[i].F - 250.0, 1e-9);
  }
  EXPECT_NEAR(s.speed.mean, 100.0, 1e-6);
  EXPECT_TRUE(s.speed.constant);
}

// windows conserve the impulse: sum F w over the windows written equals sum F dt over
// their rows (two routes to the same integral; rounding only)
TEST(ImportKernels, WindowsConserveImpulse)
{
  granpen::ImportRules rules;
  rules.has_position = true;
  rules.tare_rows = 10;
  rules.onset_force = 10.0;
  rules.window = 1e-4;    // 10 rows a window
  auto rows = push_rows(2001, 0.0);
  for (std::size_t i = 0; i < rows.size(); ++i) rows[i].F += 3.0 * std::sin(0.37 * i) * (rows[i].x > 0);
  std::vector<granpen::TracePoint> out;
  run_passes(rules, rows, out, 13);
  ASSERT_EQ(out.size(), 200u);    // rows 1..2000 in 200 windows; row 0 alone before them
  double by_window = 0.0, by_row = 0.0;
  for (const auto &p : out) by_window += p.F * rules.window;
  for (std::size_t i = 1; i < rows.size(); ++i) by_row += rows[i].F * 1e-5;
  EXPECT_NEAR(by_window, by_row, 1e-9 * std::fabs(by_row));
  for (std::size_t k = 0; k < out.size(); ++k) ASSERT_NEAR(out[k].t, (k + 1) * 1e-4, 1e-15);
}

// two speeds are rejected at the line where the second begins (within a segment of the
// push, 1/16 of it); a change of speed in the last few rows is a deceleration, cut
TEST(ImportKernels, TwoSpeedsAndDeceleration)
{
  granpen::ImportRules rules;
  rules.has_position = true;
  rules.tare_rows = 10;
  rules.onset_force = 10.0;
  rules.speed_rows = 20;
  std::vector<granpen::TracePoint> out;
  try {
    const auto s2 = run_passes(rules, push_rows(6000, 0.0, 3000, 130.0), out);
    FAIL() << "two speeds accepted: ramp " << s2.ramp.ramp_t << " cut " << s2.ramp.cut_line << " mean " << s2.speed.mean
           << " worst " << s2.speed.worst << " lim mean " << s2.limits.mean_speed << " end " << s2.limits.end_line;
  } catch (const granpen::ImportRejected &e) {
    EXPECT_NE(std::string(e.what()).find("two speeds in one file"), std::string::npos);
    EXPECT_NEAR(e.line, 3002, 6000 / 16.0);
  }
  out.clear();
  const auto s = run_passes(rules, push_rows(6000, 0.0, 5970, 30.0), out);
  EXPECT_GE(s.rows_cut, 30u);
  EXPECT_LE(s.rows_cut, 30u + rules.speed_rows);
  EXPECT_TRUE(s.speed.constant);
}

// a sensor's jitter of +-5e-4 cm on the position: a retreat without position_noise, none
// with position_noise above the jitter's full swing (1e-3 cm)
TEST(ImportKernels, PositionNoise)
{
  granpen::ImportRules rules;
  rules.has_position = true;
  rules.tare_rows = 10;
  rules.onset_force = 10.0;
  auto rows = push_rows(3000, 0.0);
  for (std::size_t i = 0; i < 100; ++i) rows[i].x = -0.3 + (i % 2 ? 5e-4 : -5e-4);    // at rest: jitter only
  std::vector<granpen::TracePoint> out;
  EXPECT_THROW(run_passes(rules, rows, out), granpen::ImportRejected);
  rules.position_noise = 1.5e-3;
  out.clear();
  const auto s = run_passes(rules, rows, out);
  EXPECT_EQ(s.limits.end_line, rows.back().line);
}

// t of a depth-sampled log: at a constant speed every step is dz / v exactly; with a speed
// linear in depth, v = v0 (1 + b x), the exact integral is ln(v / v0) / (v0 b), which the
// rule (each step at the mean of its two speeds) meets to second order in the step
TEST(ImportKernels, DepthClockIntegratesDzOverV)
{
  granpen::DepthClock steady;
  for (int i = 0; i <= 100; ++i) ASSERT_NEAR(steady.next(0.05 * i, 2.0, i + 1), 0.025 * i, 1e-12);
  const double v0 = 2.0, b = 0.05, h = 0.05;
  granpen::DepthClock linear;
  double t = 0.0;
  for (int i = 0; i <= 200; ++i) t = linear.next(h * i, v0 * (1.0 + b * h * i), i + 1);
  const double exact = std::log(1.0 + b * h * 200) / (v0 * b);
  // the mean-speed rule's error per step is (b h)^2 / 12 of the step's time (the second
  // derivative of 1/v): 5e-7 of t here; 1e-6 holds it
  EXPECT_NEAR(t, exact, 1e-6 * exact);
  EXPECT_GT(std::fabs(t - exact), 0.0) << "the rule is not exact for a varying speed";
  granpen::DepthClock stuck;
  stuck.next(1.0, 2.0, 5);
  try {
    stuck.next(1.0, 2.0, 6);
    FAIL() << "a depth that does not advance accepted";
  } catch (const granpen::ImportRejected &e) {
    EXPECT_EQ(e.line, 6);
    EXPECT_NE(std::string(e.what()).find("depth does not advance"), std::string::npos);
  }
  granpen::DepthClock halted;
  halted.next(1.0, 0.0, 5);
  EXPECT_THROW(halted.next(1.1, 0.0, 6), granpen::ImportRejected) << "no speed at either end of a step";
}

// The end of the push: a slow drift of the speed (a swing of 8% about the mean, ending
// in a trough) is kept, a deceleration (to 30% and below) is cut
TEST(ImportKernels, EndCutsDecelerationNotDrift)
{
  granpen::ImportRules rules;
  rules.has_position = true;
  rules.tare_rows = 10;
  rules.onset_force = 10.0;
  rules.speed_rows = 20;
  std::vector<granpen::ImportRow> rows;
  double x = -0.3;
  const int n = 6000, stop_from = 5960;
  for (int i = 0; i < n; ++i) {
    // 1.75 periods before the stop: it begins at the mean and ends at the trough
    double v = 100.0 * (1.0 + 0.08 * std::sin(2.0 * M_PI * 1.75 * std::min(i, stop_from) / (double) stop_from));
    if (i >= stop_from) v *= std::max(0.05, 0.3 * (1.0 - (i - stop_from) / 40.0));
    granpen::ImportRow r;
    r.t = i * 1e-5;
    if (i) x += v * 1e-5;
    r.x = x;
    r.F = x > 0 ? 1000.0 * x : 0.0;
    r.line = i + 2;
    rows.push_back(r);
  }
  std::vector<granpen::TracePoint> out;
  const auto s = run_passes(rules, rows, out);
  // the 40 rows of the stop, and at most one block (speed_rows) that holds its start
  EXPECT_GE(s.rows_cut, 40u);
  EXPECT_LE(s.rows_cut, 40u + rules.speed_rows);
  EXPECT_FALSE(s.speed.constant) << "the drift (8% at its end) is reported";
  // the same with a tolerance for the whole run that calls 8% a stop: the drift's end goes too
  rules.end_tolerance = 0.05;
  out.clear();
  const auto tight = run_passes(rules, rows, out);
  EXPECT_GT(tight.rows_cut, 40u + rules.speed_rows);
}

// A slow monotone drift (the speed falls by 8% over the last third of the push, steadily)
// is no second speed: imported, reported as not constant, nothing of it cut; a step of
// the same size is two speeds
TEST(ImportKernels, MonotoneDriftIsNotTwoSpeeds)
{
  granpen::ImportRules rules;
  rules.has_position = true;
  rules.tare_rows = 10;
  rules.onset_force = 10.0;
  rules.speed_rows = 20;
  auto rows_with = [](const std::function<double(int)> &speed) {
    std::vector<granpen::ImportRow> rows;
    double x = -0.3;
    for (int i = 0; i < 6000; ++i) {
      granpen::ImportRow r;
      r.t = i * 1e-5;
      if (i) x += speed(i) * 1e-5;
      r.x = x;
      r.F = x > 0 ? 1000.0 * x : 0.0;
      r.line = i + 2;
      rows.push_back(r);
    }
    return rows;
  };
  std::vector<granpen::TracePoint> out;
  const auto drift = run_passes(rules, rows_with([](int i) { return 100.0 * (1.0 - 0.08 * std::max(0, i - 4000) / 2000.0); }), out);
  EXPECT_FALSE(drift.speed.constant);
  EXPECT_LE(drift.rows_cut, rules.speed_rows) << "at most the last block's rows: the drift is kept";
  out.clear();
  EXPECT_THROW(run_passes(rules, rows_with([](int i) { return i < 4000 ? 100.0 : 92.0; }), out), granpen::ImportRejected);
}
