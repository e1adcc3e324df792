// gap/gap_bench_rate: the false-alarm figure a scenario commits (validation/gap_bench.sh) read
// back with its exact interval, and its refusals named.
#include "errors.h"
#include "gap_bench_rate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

using granpen::parse_false_alarm_figure;

namespace {

std::string error_of(const std::string &text)
{
  try {
    parse_false_alarm_figure(text, "f.txt");
  } catch (const granpen::InputError &e) {
    return e.what();
  }
  return "";
}

}    // namespace

// 0 of 20: the interval's upper end is 1 - 0.025^(1/20) = 0.168 (core/rate_interval.h)
TEST(GapBenchRate, ReadsTheCountsAndGivesTheExactInterval)
{
  const auto m = parse_false_alarm_figure("# the campaign's figure\nscenario = bench\nsets = 20\nalarms = 0\nrate = 0.0000\n"
                                          "source = validation/gap_bench/bench\n",
                                          "f.txt");
  EXPECT_EQ(m.sets, 20);
  EXPECT_EQ(m.alarms, 0);
  EXPECT_EQ(m.source, "validation/gap_bench/bench");
  EXPECT_EQ(m.interval.low, 0.0);
  EXPECT_NEAR(m.interval.high, 1 - std::pow(0.025, 1.0 / 20), 1e-12);    // bisection to double precision
}

TEST(GapBenchRate, RefusalsNameTheFileAndLine)
{
  EXPECT_NE(error_of("sets = 20\n").find("f.txt: no 'alarms = N' line"), std::string::npos);
  EXPECT_NE(error_of("sets = 20\nalarms = 3\nalarms = 2\n").find("f.txt:3: key 'alarms' given twice"), std::string::npos);
  EXPECT_NE(error_of("sets = 20\nalarms 3\n").find("f.txt:2: not 'key = value'"), std::string::npos);
  EXPECT_NE(error_of("sets = 20\nalarms = 3\ncolour = red\n").find("f.txt:3: unknown key 'colour'"), std::string::npos);
  EXPECT_NE(error_of("sets = 2.5\nalarms = 0\n").find("f.txt: sets is '2.5', not a whole number"), std::string::npos);
  EXPECT_NE(error_of("sets = 2\nalarms = 3\n").find("alarms = 3 exceeds sets = 2"), std::string::npos);
  EXPECT_NE(error_of("sets = 0\nalarms = 0\n").find("sets = 0"), std::string::npos);
}

// no committed figure: no measured rate; a committed one is found by the scenario's name
TEST(GapBenchRate, FindsTheScenariosFigureUnderTheInputs)
{
  const auto dir = std::filesystem::temp_directory_path() / "granpen_gap_bench_rate";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "false_alarms");
  EXPECT_FALSE(granpen::measured_false_alarms(dir.string(), "bench").has_value());
  std::ofstream(dir / "false_alarms" / "bench.txt") << "sets = 10\nalarms = 1\n";
  const auto m = granpen::measured_false_alarms(dir.string(), "bench");
  ASSERT_TRUE(m.has_value());
  EXPECT_NEAR(m->interval.rate, 0.1, 1e-15);
  EXPECT_FALSE(granpen::measured_false_alarms(dir.string(), "tiny").has_value());
  std::filesystem::remove_all(dir);
}
