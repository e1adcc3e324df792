// Sweep files: parsing, the plan, the resume decision, hostile input in every field, and
// the progress lines' durations and a push's own ETA.
#include "json_text.h"
#include "sweep_runner.h"
#include "sweep_spec.h"
#include "errors.h"

#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <string>

using namespace granpen;

namespace {

bool known_preset(const std::string &n) { return n == "tiny" || n == "bench"; }
bool known_observe(const std::string &n) { return n == "none" || n == "flow"; }

SweepSpec parse(const std::string &text)
{
  return parse_sweep(text, "s.sweep", known_preset, known_observe);
}

void expect_rejected(const std::string &text, const std::string &pattern)
{
  try {
    parse(text);
    FAIL() << "accepted:\n" << text;
  } catch (InputError &e) {
    EXPECT_TRUE(std::regex_search(e.what(), std::regex(pattern))) << e.what();
  }
}

const std::string BASE = "name = s\npreset = tiny\nv0 = 100\n";

}    // namespace

TEST(SweepSpec, PlanPoursEachBedOnceAndBranchesPushes)
{
  auto spec = parse("# a sweep\nname = calib\npreset = bench\nmu = 0.1 0.3\nseeds = 1 2\nv0 = 50 100 200\n"
                    "g = 981 490.5\nD = 2.0\ndepth = 4.0\nobserve = flow\n");
  auto plan = plan_sweep(spec);
  ASSERT_EQ(plan.size(), 4u + 4u * 3u * 2u);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(plan[i].kind, PlannedRun::POUR);
  EXPECT_EQ(plan[0].id, "bed_bench_mu0.1_s1");
  EXPECT_EQ(plan[4].kind, PlannedRun::PUSH);
  EXPECT_EQ(plan[4].bed, "bed_bench_mu0.1_s1");
  EXPECT_EQ(plan[4].id, "bench_mu0.1_s1_v50_g981_D2.0");
  EXPECT_EQ(plan.back().id, "bench_mu0.3_s2_v200_g490.5_D2.0");
  EXPECT_EQ(spec.observe, "flow");
}

TEST(SweepSpec, RaisingMuInAPouredBedIsAPushDimension)
{
  auto plan = plan_sweep(parse(BASE + "mu = 0.1\nmu_push = 0.2 0.5\n"));
  ASSERT_EQ(plan.size(), 3u);
  EXPECT_EQ(plan[1].id, "tiny_mu0.1_s1_v100_mp0.2");
  EXPECT_EQ(plan[2].mu_push, "0.5");
  EXPECT_EQ(plan[2].bed, "bed_tiny_mu0.1_s1");
}

TEST(SweepSpec, DefaultsAndOptionalKeys)
{
  auto spec = parse(BASE);
  auto plan = plan_sweep(spec);
  ASSERT_EQ(plan.size(), 2u);
  EXPECT_EQ(plan[0].id, "bed_tiny_s1");
  EXPECT_EQ(plan[1].id, "tiny_s1_v100");
  EXPECT_EQ(plan[1].g, "");    // the preset's
}

TEST(SweepSpec, RejectsShellMetacharactersAndPathTricksInEveryField)
{
  const char *hostile[] = {"x; touch /tmp/granpen_pwned", "$(touch /tmp/granpen_pwned)",
                           "`touch /tmp/granpen_pwned`", "a|b", "a&&b", "../../etc", "/etc/passwd",
                           "..", ".hidden", "a b>c", "'quoted'", "\"dq\"", "a\\b", "-rf", "x*"};
  for (const char *h : hostile) {
    const std::string v = h;
    expect_rejected("name = " + v + "\npreset = tiny\nv0 = 100\n", "s\\.sweep:1: name|s\\.sweep:1: 'name' takes one value");
    expect_rejected("name = s\npreset = " + v + "\nv0 = 100\n", "s\\.sweep:2: (preset|unknown preset)");
    expect_rejected(BASE + "mu = " + v + "\n", "s\\.sweep:4: 'mu' value");
    expect_rejected(BASE + "seeds = " + v + "\n", "s\\.sweep:4: seed");
    expect_rejected("name = s\npreset = tiny\nv0 = " + v + "\n", "s\\.sweep:3: 'v0' value");
    expect_rejected(BASE + "g = " + v + "\n", "s\\.sweep:4: 'g' value");
    expect_rejected(BASE + "D = " + v + "\n", "s\\.sweep:4: 'D' value");
    expect_rejected(BASE + "depth = " + v + "\n", "s\\.sweep:4: (depth|'depth' takes one)");
    expect_rejected(BASE + "observe = " + v + "\n", "s\\.sweep:4: (observe|'observe' takes one)");
    expect_rejected(BASE + "set = poly=" + v + "\n", "s\\.sweep:4: 'set' (value|item)");
    expect_rejected(BASE + "push_set = " + v + "=1\n", "s\\.sweep:4: 'push_set' (value|item)");
  }
}

TEST(SweepSpec, DeckVariablesForTheModelAndTheMeasurementChain)
{
  auto spec = parse(BASE + "set = poly=0.1 walls=1 granular=yes kn=2.5e8 shift=-0.5 zero=0\npush_set = ramp=0.3\n");
  ASSERT_EQ(spec.set.size(), 6u);
  EXPECT_EQ(spec.set[0], std::make_pair(std::string("poly"), std::string("0.1")));
  EXPECT_EQ(spec.set[2].second, "yes");
  EXPECT_EQ(spec.set[4].second, "-0.5");
  ASSERT_EQ(spec.push_set.size(), 1u);
  EXPECT_EQ(spec.push_set[0].first, "ramp");
  // variables the runner sets itself, malformed items, values that are neither
  expect_rejected(BASE + "set = v0=3\n", "'set' item 'v0=3' is not NAME=VALUE");
  expect_rejected(BASE + "set = trace=x\n", "'set' item");
  expect_rejected(BASE + "set = poly\n", "'set' item 'poly' is not NAME=VALUE");
  expect_rejected(BASE + "set = 1poly=2\n", "'set' item");
  expect_rejected(BASE + "set = poly=nan\n", "neither a number nor a name");
  expect_rejected(BASE + "set = poly=1e999\n", "neither a number nor a name");
  expect_rejected(BASE + "set = poly=\n", "neither a number nor a name");
  expect_rejected(BASE + "set = poly=0.1\npush_set = poly=0.2\n", "s\\.sweep:5: deck variable poly set twice");
}

TEST(SweepSpec, RejectsMalformedFiles)
{
  expect_rejected("name = s\npreset = tiny\n", "missing 'v0'");
  expect_rejected("preset = tiny\nv0 = 1\n", "missing 'name'");
  expect_rejected(BASE + "v1 = 3\n", "s\\.sweep:4: unknown key 'v1'");
  expect_rejected(BASE + "speed\n", "s\\.sweep:4: expected 'key = value'");
  expect_rejected(BASE + "v0 = 200\n", "s\\.sweep:4: key 'v0' given again \\(first on line 3\\)");
  expect_rejected(BASE + "mu = 0.3 0.3\n", "lists 0.3 twice");
  expect_rejected(BASE + "mu = -0.3\n", "'mu' value '-0.3' is not a positive number");
  expect_rejected(BASE + "mu = 0\n", "is not a positive number");
  expect_rejected(BASE + "mu = nan\n", "is not a positive number");
  expect_rejected(BASE + "mu = 1e999\n", "is not a positive number");
  expect_rejected(BASE + "seeds = 1.5\n", "seed '1.5' is not a positive integer");
  expect_rejected(BASE + "seeds = 0\n", "seed '0' is not a positive integer");
  expect_rejected("name = s\npreset = huge\nv0 = 1\n", "unknown preset 'huge'");
  expect_rejected(BASE + "observe = everything\n", "unknown observe set 'everything'");
  expect_rejected("name =\npreset = tiny\nv0 = 1\n", "s\\.sweep:1: key .name. has no value");
}

TEST(SweepSpec, ResumeDecision)
{
  EXPECT_EQ(push_action(true, true, true), PushAction::SKIP_DONE);
  EXPECT_EQ(push_action(false, true, true), PushAction::RESUME);
  EXPECT_EQ(push_action(false, true, false), PushAction::RESTART_FRESH);
  EXPECT_EQ(push_action(false, false, false), PushAction::START);
  EXPECT_EQ(push_action(false, false, true), PushAction::START);     // a checkpoint without its trace
  EXPECT_EQ(push_action(true, false, false), PushAction::START);     // a marker without its trace
}

TEST(SweepSpec, JsonStringsAreEscaped)
{
  EXPECT_EQ(json_string("a\"b\\c\nd\x01"), "\"a\\\"b\\\\c\\nd\\u0001\"");
  EXPECT_EQ(json_number("%.3g", 1.0 / 0.0), "0");
}

// Progress lines: seconds that round up to a full minute carry into the minutes (a run
// once printed "30m60s"); each case is an exact string, so any carry or rounding slip fails.
TEST(FormatDuration, RoundsBeforeSplitting)
{
  EXPECT_EQ(format_duration(45.2), "45s");
  EXPECT_EQ(format_duration(119.4), "119s");
  EXPECT_EQ(format_duration(119.6), "2m00s");
  EXPECT_EQ(format_duration(1859.7), "31m00s");
  EXPECT_EQ(format_duration(1807.0), "30m07s");
  EXPECT_EQ(format_duration(7199.4), "119m59s");
  EXPECT_EQ(format_duration(9000.0), "2.5h");
  EXPECT_EQ(format_duration(-1.0), "?");
}

// A long push's own ETA: the rate since it was first seen, carried to the target. Exact
// arithmetic cases (0.1 cm in 600 s, 0.9 cm to go: 5400 s), so any slip in the rate or the
// distance left fails; and the cases where no rate exists yet give no number, not 0 or inf.
TEST(PushSecondsLeft, ItsOwnRateToTheTarget)
{
  EXPECT_DOUBLE_EQ(push_seconds_left(0.5, 0.6, 600.0, 1.5), 5400.0);
  EXPECT_DOUBLE_EQ(push_seconds_left(0.0, 0.75, 30.0, 1.5), 30.0);
  EXPECT_EQ(push_seconds_left(0.5, 1.5, 600.0, 1.5), 0.0);     // at the target
  EXPECT_EQ(push_seconds_left(0.5, 1.6, 600.0, 1.5), 0.0);     // past it (the last row overshoots)
  EXPECT_TRUE(std::isnan(push_seconds_left(0.6, 0.6, 600.0, 1.5)));     // not moved yet
  EXPECT_TRUE(std::isnan(push_seconds_left(0.6, 0.5, 600.0, 1.5)));     // rows written again after a resume
  EXPECT_TRUE(std::isnan(push_seconds_left(0.5, 0.6, 0.0, 1.5)));       // no time between the readings
  EXPECT_TRUE(std::isnan(push_seconds_left(0.5, 0.6, 600.0, 0.0)));     // the deck's default depth
  EXPECT_TRUE(std::isnan(push_seconds_left(NAN, 0.6, 600.0, 1.5)));
  EXPECT_TRUE(std::isnan(push_seconds_left(0.5, 0.6, INFINITY, 1.5)));
}
