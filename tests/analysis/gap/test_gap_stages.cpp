// granpen gap: the diagnosis's stages (gap_diagnosis.h) one by one, on small fixtures of
// known answer: validate (the inputs refused), plan (requests and their cost), align and
// bin (a known offset), features (the null replicates), which (the verdict on a hand-made
// feature set), confirm (the signature test), and the sweep layer's side of the cache
// and of the cluster script.
#include "effects.h"
#include "gap_align.h"
#include "gap_confirm.h"
#include "gap_errors.h"
#include "gap_features.h"
#include "gap_inputs.h"
#include "gap_pairs.h"
#include "gap_plan.h"
#include "gap_report.h"
#include "gap_sims.h"
#include "sensor_response.h"
#include "gap_where.h"
#include "scenario.h"
#include "gap_which.h"
#include "slurm_script.h"
#include "sweep_cache.h"
#include "text_util.h"
#include "trace_reader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <unistd.h>

using namespace granpen;
namespace fs = std::filesystem;

namespace {

// a folder of its own per test, removed at the end
struct TempDir {
  fs::path path;
  explicit TempDir(const std::string &name)
      : path(fs::temp_directory_path() / ("granpen_gap_stages_" + std::to_string(getpid()) + "_" + name))
  {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
  std::string operator/(const std::string &f) const { return (path / f).string(); }
};

void write_file(const std::string &path, const std::string &text)
{
  std::ofstream(path) << text;
}

// a trace file: header keys as given, 41 rows of a constant force
std::string trace_text(const std::string &units, const std::string &keys, double F = 5.0)
{
  std::ostringstream s;
  s << "# granpen-trace v1\n# units = " << units << "\n" << keys << "t,z,F\n";
  for (int i = 0; i <= 40; ++i) s << i << "e-4," << (i * 10 - 50) << "e-3," << F << "\n";
  return s.str();
}

const std::string CGS_100 = "# v0 = 100\n# D = 2.0\n# g = 981\n";

// the set-up of the tiny preset, by hand (no preset file: the stage reads only these)
Scenario hand_scenario()
{
  Scenario sc;
  sc.name = "hand";
  sc.path = "(test)";
  sc.D = 2.0, sc.d_g = 0.4, sc.g = 981.0, sc.rho_g = 3.0, sc.mu = 0.3, sc.depth = 2.0, sc.gap = 0.5;
  sc.vars = {{"dt_push", "2e-6"}, {"dt_pour", "5e-6"}, {"lat", "0.5"},       {"box", "4.0"},
             {"fill_lo", "0.25"}, {"zfill_lo", "0.5"}, {"zfill_hi", "2.5"}};
  return sc;
}

// expects f() to throw GapRefused whose message matches the pattern
template <class F>
void expect_refused(F f, const std::string &pattern)
{
  try {
    f();
    ADD_FAILURE() << "not refused; expected: " << pattern;
  } catch (const GapRefused &e) {
    EXPECT_TRUE(std::regex_search(e.what(), std::regex(pattern))) << e.what() << "\n  does not match " << pattern;
  }
}

// F = 0 above z0, then rising with slope 1000 dyne/cm for 0.5 cm, then flat: its onset
// (20% of the largest F in the first cm) is z0 + 0.1. Samples 0.01 cm apart down to zend.
TraceRun ramp_run(const std::string &name, double v0, double z0, double zend)
{
  TraceRun r;
  r.path = name;
  r.v0 = v0;
  for (int i = 0; -0.5 + 0.01 * i <= zend + 1e-9; ++i) {
    const double z = -0.5 + 0.01 * i;
    r.t.push_back((z + 0.5) / v0);
    r.z.push_back(z);
    r.F.push_back(z < z0 ? 0.0 : 1000.0 * std::min(z - z0, 0.5));
  }
  r.onset = force_onset(r.z, r.F);
  return r;
}

}    // namespace

// ---- validate

TEST(GapValidate, EffectsNamedGivenOrAll)
{
  // without a list: the library but its opt-in effects (cohesion_dmt)
  const auto all = choose_effects(std::nullopt);
  std::size_t opt_in = 0;
  for (const auto &e : effect_library()) opt_in += e.opt_in;
  EXPECT_EQ(opt_in, 1u);
  EXPECT_EQ(all.size(), effect_library().size() - opt_in);
  for (const Effect *e : all) EXPECT_FALSE(e->opt_in) << e->name;
  // `default` stands for that library; an opt-in effect is named after it
  const auto more = choose_effects(std::string("default,cohesion_dmt"));
  ASSERT_EQ(more.size(), all.size() + 1);
  EXPECT_EQ(std::vector<const Effect *>(more.begin(), more.end() - 1), all);
  EXPECT_EQ(more.back()->name, "cohesion_dmt");
  expect_refused([] { choose_effects(std::string("default,packing")); }, "'packing' given twice");
  const auto two = choose_effects(std::string("packing,rolling_resistance"));
  ASSERT_EQ(two.size(), 2u);
  EXPECT_EQ(two[0]->name, "packing");
  EXPECT_EQ(two[1]->name, "rolling_resistance");
  // given but empty is not "all": a script that lost its list must not run the whole library
  expect_refused([] { choose_effects(std::string("")); }, "^--effects: empty list");
  expect_refused([] { choose_effects(std::string("packing,magic")); }, "unknown effect 'magic'");
}

TEST(GapValidate, MeasuredFolderReadAndGrouped)
{
  TempDir dir("good");
  write_file(dir / "a.csv", trace_text("cgs", CGS_100));
  write_file(dir / "b.csv", trace_text("cgs", "# v0 = 50\n# D = 2.0\n# g = 981\n"));
  const MeasuredData m = read_measured(dir.path.string(), hand_scenario());
  ASSERT_EQ(m.files.size(), 2u);
  EXPECT_EQ(m.v0s, (std::vector<std::string>{"50", "100"}));
  ASSERT_EQ(m.runs.size(), 2u);
  EXPECT_EQ(m.runs.at(100.0).size(), 1u);
  // one run at each speed: both said, as warnings for the report
  ASSERT_EQ(m.notes.size(), 2u);
  EXPECT_NE(m.notes[0].find("v0 = 50 cm/s has one measured run"), std::string::npos);
}

TEST(GapValidate, InputsRefusedBeforeAnythingStarts)
{
  const Scenario sc = hand_scenario();
  TempDir dir("refused");
  fs::create_directories(dir.path / "single");
  write_file(dir / "single/a.csv", trace_text("cgs", CGS_100));
  expect_refused([&] { read_measured(dir / "single/a.csv", sc); }, "--real .*/single/a.csv: a file, not a folder");
  expect_refused([&] { read_measured(dir / "nowhere", sc); }, "--real .*/nowhere: no such folder");
  expect_refused([&] { read_measured(dir / "single", sc); }, "--real .*/single: a single trace in all");
  fs::create_directories(dir.path / "empty");
  expect_refused([&] { read_measured(dir / "empty", sc); }, "empty: folder holds no \\*\\.csv file");

  fs::create_directories(dir.path / "mixed");
  write_file(dir / "mixed/a.csv", trace_text("cgs", CGS_100));
  write_file(dir / "mixed/b.csv", trace_text("si", "# v0 = 1.0\n# D = 0.02\n# g = 9.81\n", 5e-5));
  expect_refused([&] { read_measured(dir / "mixed", sc); }, "mixed/b.csv: units = si, but .*mixed/a.csv has units = cgs");

  // the scenario pushes at most 0.01 d_g per 2e-6 s step (2000 cm/s) and 1e6 steps over 2.5 cm (1.25 cm/s)
  EXPECT_NEAR(runnable_speeds(sc).first, 1.25, 1e-12);
  EXPECT_NEAR(runnable_speeds(sc).second, 2000.0, 1e-9);
  fs::create_directories(dir.path / "fast");
  write_file(dir / "fast/a.csv", trace_text("cgs", "# v0 = 2100\n# D = 2.0\n# g = 981\n"));
  write_file(dir / "fast/b.csv", trace_text("cgs", CGS_100));
  expect_refused([&] { read_measured(dir / "fast", sc); }, "fast/a.csv: v0 = 2100 cm/s is outside what scenario 'hand' can run");

  // headers that contradict the scenario, each beyond its 1%; 0.5% passes
  const char *contradicting[] = {"# v0 = 100\n# D = 2.1\n# g = 981\n", "# v0 = 100\n# D = 2.0\n# g = 960\n",
                                 "# v0 = 100\n# D = 2.0\n# g = 981\n# d_g = 0.3\n"};
  const char *named[] = {"header D = 2.1", "header g = 960", "header d_g = 0.3"};
  for (int i = 0; i < 3; ++i) {
    const std::string sub = "contra" + std::to_string(i);
    fs::create_directories(dir.path / sub);
    write_file(dir / (sub + "/a.csv"), trace_text("cgs", contradicting[i]));
    write_file(dir / (sub + "/b.csv"), trace_text("cgs", CGS_100));
    expect_refused([&] { read_measured(dir / sub, sc); }, sub + "/a.csv: " + named[i] + ".*scenario 'hand'");
  }
  fs::create_directories(dir.path / "close");
  write_file(dir / "close/a.csv", trace_text("cgs", "# v0 = 100\n# D = 2.01\n# g = 981\n"));
  write_file(dir / "close/b.csv", trace_text("cgs", CGS_100));
  EXPECT_NO_THROW(read_measured(dir / "close", sc));
}

TEST(GapValidate, AnOutputThatWouldReplaceAnInputIsRefused)
{
  TempDir dir("out");
  fs::create_directories(dir.path / "real");
  fs::create_directories(dir.path / "cache");
  const std::string real = dir / "real", cache = dir / "cache";
  expect_refused([&] { check_output_path(real, real, cache); }, "would replace the measured traces");
  expect_refused([&] { check_output_path(real + "/", real, cache); }, "would replace the measured traces");
  expect_refused([&] { check_output_path(dir / "real/../real", real, cache); }, "would replace the measured traces");
  expect_refused([&] { check_output_path(dir.path.string(), real, cache); }, "would replace the measured traces");
  expect_refused([&] { check_output_path(cache, real, dir / "cache/x"); }, "would replace the simulation cache");
  // beside them, or inside the measured folder: nothing of the inputs is replaced
  EXPECT_NO_THROW(check_output_path(dir / "out", real, cache));
  EXPECT_NO_THROW(check_output_path(dir / "real_out", real, cache));
  EXPECT_NO_THROW(check_output_path(dir / "real/out", real, cache));
}

// ---- plan

TEST(GapPlan, RequestsAndTheirCostFromWhatTheCacheLacks)
{
  const Scenario sc = hand_scenario();
  TempDir cache("plan");
  const std::vector<const Effect *> mount{find_effect("measurement_chain")};
  const SimulationPlan p = plan_simulations(sc, {"50", "100"}, mount, cache.path.string(), false);
  // the baseline (seeds 1 2), the reference beds (11-14), the mount's two simulated knots (4
  // and 10 ms) on the baseline's beds; its knots up to 2 ms are the baseline's traces filtered
  ASSERT_EQ(p.requests.size(), 4u);
  EXPECT_EQ(p.requests[2].beds_from, "baseline");
  EXPECT_EQ(p.requests[2].spec.name, "measurement_chain_4");
  EXPECT_EQ(p.requests[3].spec.name, "measurement_chain_10");
  // by hand: grains on the lattice, 8 x 8 across ((4 - 2 x 0.25) / 0.5 + 1) and 5 high;
  // 6 pours of 0.6 s (the knots reuse the baseline's beds), (2 + 4 + 2 x 2) beds pushed
  // 2.5 cm at each speed; a probe pour (6300 grains, 110000 steps) is 69.9 core-seconds
  const double grains = 8 * 8 * 5;
  const double steps = 6 * 0.6 / 5e-6 + 10 * (2.5 / 50 + 2.5 / 100) / 2e-6;
  EXPECT_NEAR(p.core_hours, grains * steps / (6300.0 * 110000) * 69.9 / 3600, 1e-9 * p.core_hours);    // rounding only
  // a done push is not counted again
  const auto pending = pending_runs(p.requests[0], cache.path.string());
  ASSERT_EQ(pending.size(), 6u);    // 2 pours, 4 pushes
  fs::create_directories(cache.path / "baseline" / "traces");
  write_file(cache / ("baseline/traces/" + pending[2].id + ".csv.done"), "");
  EXPECT_EQ(pending_runs(p.requests[0], cache.path.string()).size(), 5u);
  // beyond what a workstation runs: refused with the way out named, unless --local
  Scenario big = sc;
  big.vars["dt_push"] = "2e-10";
  EXPECT_THROW(
      {
        try {
          plan_simulations(big, {"50"}, mount, cache.path.string(), false);
        } catch (const InputError &e) {
          EXPECT_NE(std::string(e.what()).find("--slurm FILE --v0 \"50\""), std::string::npos) << e.what();
          EXPECT_NE(std::string(e.what()).find("--local"), std::string::npos);
          throw;
        }
      },
      InputError);
  EXPECT_GT(plan_simulations(big, {"50"}, mount, cache.path.string(), true).core_hours, LOCAL_CORE_HOURS);
}

// ---- a scenario of the user's own (--scenario FILE)

#ifdef GRANPEN_INPUTS_DIR
namespace {
std::string read_text(const fs::path &p)
{
  std::ifstream f(p);
  return std::string((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
}
}    // namespace

TEST(GapScenarioFile, ReadsAUserPresetAndNamesItByItsText)
{
  TempDir dir("scenario_file");
  const std::string tiny = read_text(std::string(GRANPEN_INPUTS_DIR) + "/presets/tiny.lmp");
  std::ofstream(dir.path / "my rig.lmp") << tiny;
  const Scenario a = read_scenario_file(GRANPEN_INPUTS_DIR, (dir.path / "my rig.lmp").string());
  const Scenario ref = read_scenario(GRANPEN_INPUTS_DIR, "tiny");
  EXPECT_EQ(a.vars, ref.vars);    // the same variables as the preset it copies
  EXPECT_TRUE(std::regex_match(a.name, std::regex("my_rig-[0-9a-f]{8}"))) << a.name;
  // an edited file is another scenario (its own cache), the same text the same one
  std::ofstream(dir.path / "my rig.lmp", std::ios::app) << "variable mu index 0.4\n";
  EXPECT_NE(read_scenario_file(GRANPEN_INPUTS_DIR, (dir.path / "my rig.lmp").string()).name, a.name);
  EXPECT_TRUE(scenario_is_file("mine.lmp"));
  EXPECT_TRUE(scenario_is_file("./mine"));
  EXPECT_FALSE(scenario_is_file("tiny"));
}

TEST(GapScenarioFile, RefusesAPresetMissingWhatTheDecksRead)
{
  TempDir dir("scenario_missing");
  std::string text = read_text(std::string(GRANPEN_INPUTS_DIR) + "/presets/tiny.lmp");
  // every preset sets dt_push and kn: the required list comes from them
  const auto required = preset_variables(GRANPEN_INPUTS_DIR);
  ASSERT_TRUE(std::count(required.begin(), required.end(), "dt_push") && std::count(required.begin(), required.end(), "kn"));
  text = std::regex_replace(text, std::regex("variable dt_push[^\n]*\n|variable kn [^\n]*\n"), "");
  std::ofstream(dir.path / "short.lmp") << text;
  try {
    read_scenario_file(GRANPEN_INPUTS_DIR, (dir.path / "short.lmp").string());
    FAIL() << "a preset without dt_push was read";
  } catch (const GapRefused &e) {
    EXPECT_NE(std::string(e.what()).find("short.lmp: the preset sets no dt_push kn"), std::string::npos) << e.what();
  }
  std::ofstream(dir.path / "nan.lmp") << std::regex_replace(read_text(std::string(GRANPEN_INPUTS_DIR) + "/presets/tiny.lmp"),
                                                             std::regex("variable D  [^\n]*"), "variable D index wide");
  EXPECT_THROW(read_scenario_file(GRANPEN_INPUTS_DIR, (dir.path / "nan.lmp").string()), GapRefused);
  EXPECT_THROW(read_scenario_file(GRANPEN_INPUTS_DIR, (dir.path / "none.lmp").string()), GapRefused);
}

TEST(GapScenarioFile, StagedInputsAreTheDecksWithTheFileAsAPreset)
{
  TempDir dir("scenario_stage");
  const std::string text = read_text(std::string(GRANPEN_INPUTS_DIR) + "/presets/tiny.lmp") + "variable mu index 0.35\n";
  std::ofstream(dir.path / "rig.lmp") << text;
  const Scenario sc = read_scenario_file(GRANPEN_INPUTS_DIR, (dir.path / "rig.lmp").string());
  const fs::path staged = stage_scenario_inputs(sc, GRANPEN_INPUTS_DIR, (dir.path / "cache/_inputs").string());
  EXPECT_EQ(read_text(staged / "presets" / (sc.name + ".lmp")), text);
  // the decks and the other presets, unchanged, through links
  EXPECT_EQ(read_text(staged / "in.pour"), read_text(std::string(GRANPEN_INPUTS_DIR) + "/in.pour"));
  EXPECT_EQ(read_text(staged / "model/contact.lmp"), read_text(std::string(GRANPEN_INPUTS_DIR) + "/model/contact.lmp"));
  EXPECT_EQ(read_text(staged / "presets/bench.lmp"), read_text(std::string(GRANPEN_INPUTS_DIR) + "/presets/bench.lmp"));
  // read back by name, as the decks and the stages do
  EXPECT_EQ(read_scenario(staged.string(), sc.name).vars.at("mu"), "0.35");
  // staging again is a no-op
  EXPECT_EQ(stage_scenario_inputs(sc, GRANPEN_INPUTS_DIR, (dir.path / "cache/_inputs").string()), staged.string());
}

TEST(GapPlan, CostInProbePoursIsAtomStepsOverTheProbePours)
{
  const Scenario sc = hand_scenario();
  TempDir cache("plan_cost");
  const std::vector<const Effect *> mount{find_effect("measurement_chain")};
  const auto req = signature_requests(sc.name, {"50", "100"}, mount);
  const PlanCost c = plan_cost(sc, req, cache.path.string(), 1000.0);
  // as in RequestsAndTheirCostFromWhatTheCacheLacks: 6 pours, 10 beds pushed at 2 speeds
  EXPECT_EQ(c.pours, 6);
  EXPECT_EQ(c.pushes, 20);
  const double steps = 6 * 0.6 / 5e-6 + 10 * (2.5 / 50 + 2.5 / 100) / 2e-6;
  EXPECT_NEAR(c.atom_steps, 320 * steps, 1e-9 * c.atom_steps);
  EXPECT_NEAR(c.probe_pours, c.atom_steps / (1000.0 * PROBE_POUR_STEPS), 1e-12 * c.probe_pours);
  // one unit: core-hours are the probe pours of core time at the probe's 2026-11-22 speed
  EXPECT_NEAR(c.core_hours, c.probe_pours * PROBE_POUR_SECONDS / 3600.0, 1e-12 * c.core_hours);
  // without the bench preset's grains, the probe pour's own (6300, its .info)
  EXPECT_NEAR(estimate_core_hours(sc, req, cache.path.string()), c.atom_steps / (6300.0 * PROBE_POUR_STEPS) * 69.9 / 3600.0,
              1e-12 * c.core_hours);
  EXPECT_NE(plan_summary(c, 2).find("6 pours, 20 pushes"), std::string::npos) << plan_summary(c, 2);
  EXPECT_NE(plan_summary(c, 2).find("probe pours of core time"), std::string::npos) << plan_summary(c, 2);
  // wall time: alone, the core time; side by side, spread over the jobs at 0.95 of their speed
  EXPECT_NEAR(wall_probe_pours(c, 1), c.probe_pours, 1e-12);
  EXPECT_NEAR(wall_probe_pours(c, 2), c.probe_pours / (2 * 0.95), 1e-12);
  // ... never below the longest pour and push one after the other
  EXPECT_NEAR(wall_probe_pours(c, 1000), (c.longest_pour + c.longest_push) / 0.95, 1e-12);
  // as an empty cache runs them: the same (nothing is in this cache)
  const PlanCost cold = cold_cost(sc, req, 1000.0);
  EXPECT_EQ(cold.pours, 6);
  EXPECT_EQ(cold.pushes, 20);
  EXPECT_NEAR(cold.probe_pours, c.probe_pours, 1e-12 * c.probe_pours);
}

TEST(GapPlan, EachRunCountedAtItsOwnTimeStepTravelAndRoute)
{
  // 320 grains (hand_scenario's lattice); a pour 0.6 s, a push gap + depth = 2.5 cm at v0
  const Scenario sc = hand_scenario();
  TempDir cache("plan_routes");
  const double probe = 1000.0 * PROBE_POUR_STEPS;
  auto knot = [&](const char *effect, double a) {
    return plan_cost(sc, {effect_request(sc.name, *find_effect(effect), a, {"100"}, {"1"}, "k")}, cache.path.string(), 1000.0);
  };
  // the bench law: factor 1
  EXPECT_NEAR(knot("polydispersity", 0.25).probe_pours, 320 * (0.6 / 5e-6 + 2.5 / 100 / 2e-6) / probe, 1e-12);
  // pair granular's routes: JKR cohesion 2.1, rolling friction 1.5 (measured, docs/gap.md)
  EXPECT_NEAR(knot("cohesion", 1000).probe_pours, 2.1 * 320 * (0.6 / 5e-6 + 2.5 / 100 / 2e-6) / probe, 1e-12);
  EXPECT_NEAR(knot("rolling_resistance", 0.1).probe_pours, 1.5 * 320 * (0.6 / 5e-6 + 2.5 / 100 / 2e-6) / probe, 1e-12);
  // stiffer contacts at their own, shorter time steps: 10^0.6 stiffer, steps 10^(-0.24) as long
  // (the push's rounded to a whole number of steps per 1e-4 s: 1e-4 / ceil(50 / 0.575))
  const double dt_scale = std::pow(10.0, -0.24), dt_push = 1e-4 / std::ceil(50.0 / dt_scale);
  EXPECT_NEAR(knot("contact_stiffness", 0.6).probe_pours, 320 * (0.6 / (5e-6 * dt_scale) + 2.5 / 100 / dt_push) / probe, 1e-9);
  // a ramp of 1.6 cm: its travel once more at v0 (linear from rest: twice the time over it)
  const PlanCost ramp = plan_cost(sc, {effect_request(sc.name, *find_effect("actuator_ramp"), 1.6, {"100"}, {"1"}, "r")},
                                  cache.path.string(), 1000.0);
  EXPECT_NEAR(ramp.probe_pours, 320 * (0.6 / 5e-6 + (2.5 + 1.6) / 100 / 2e-6) / probe, 1e-12);
}

TEST(GapPlan, TheMostAConfirmationAddsIsTheCostliestEffectsConfirmRefineAndHeldOut)
{
  const Scenario sc = hand_scenario();
  TempDir cache("plan_confirm");
  const std::vector<std::string> v0{"50", "100"};
  const std::vector<const Effect *> lib{find_effect("measurement_chain"), find_effect("cohesion")};
  const PlanCost most = confirmation_most(sc, v0, lib, cache.path.string(), 1000.0);
  // cohesion (pour-level, JKR): 4 fresh beds confirm at both speeds, the slowest held out at its
  // own magnitude on the same seeds (its own sweep: 4 pours, 4 pushes), 4 more refine both
  EXPECT_EQ(most.pours, 12);
  EXPECT_EQ(most.pushes, 8 + 4 + 8);
  const PlanCost cohesion = cold_cost(sc, largest_confirmation(sc.name, *find_effect("cohesion"), 3000, v0), 1000.0);
  EXPECT_NEAR(most.probe_pours, cohesion.probe_pours, 1e-12);
  // the mount's, the baseline pushed into fresh beds, costs less
  const PlanCost mount = cold_cost(sc, largest_confirmation(sc.name, *find_effect("measurement_chain"), 10, v0), 1000.0);
  EXPECT_LT(mount.probe_pours, most.probe_pours);
  EXPECT_EQ(confirmation_most(sc, v0, {}, cache.path.string(), 1000.0).probe_pours, 0.0);
}

// With a filter and a push-only partner in the library the pair stage can confirm a pair after
// a single's confirmation failed (issue 37): the plan's most counts both. The mount and the
// ramp: the single's costliest is the ramp at its outer knot 3.2 (confirm, the slowest held
// out, refine: 8 pours, 20 pushes); the pair's, the ramp at 3.2 pushed into the same fresh
// beds at both speeds (8 pushes more, the beds poured once). Without a partner (the mount and
// cohesion, above) or without a filter, no pair: the single's alone.
TEST(GapPlan, TheMostCountsThePairsConfirmationWhenAPairCanBeTried)
{
  const Scenario sc = hand_scenario();
  TempDir cache("plan_pair");
  const std::vector<std::string> v0{"50", "100"};
  const Effect &ramp = *find_effect("actuator_ramp"), &chain = *find_effect("measurement_chain");
  EXPECT_TRUE(pair_filter(chain) && !pair_partner(chain));
  EXPECT_TRUE(pair_partner(ramp) && !pair_filter(ramp));
  EXPECT_FALSE(pair_filter(*find_effect("force_scale")) || pair_partner(*find_effect("force_scale")));
  EXPECT_FALSE(pair_partner(*find_effect("cohesion")));
  const PlanCost most = confirmation_most(sc, v0, {&chain, &ramp}, cache.path.string(), 1000.0);
  EXPECT_EQ(most.pours, 8);
  EXPECT_EQ(most.pushes, 8 + 4 + 8 + 8);
  std::vector<SimRequest> expect = largest_confirmation(sc.name, ramp, 3.2, v0);
  const std::vector<SimRequest> pair = pair_confirmation(sc.name, ramp, 3.2, v0);
  ASSERT_EQ(pair.size(), 2u);
  EXPECT_EQ(pair[0].spec.name, "confirm_beds");    // shared with the single's: poured once
  expect.push_back(pair[1]);
  EXPECT_NEAR(most.probe_pours, cold_cost(sc, expect, 1000.0).probe_pours, 1e-12);
  // no filter, no pair: the ramp's own confirmation alone
  const PlanCost alone = confirmation_most(sc, v0, {&ramp}, cache.path.string(), 1000.0);
  EXPECT_NEAR(alone.probe_pours, cold_cost(sc, largest_confirmation(sc.name, ramp, 3.2, v0), 1000.0).probe_pours, 1e-12);
  EXPECT_LT(alone.probe_pours, most.probe_pours);
}

#endif

TEST(GapPlan, TransformEffectConfirmsOnTheBaselinePushedIntoFreshBeds)
{
  // the mount's confirming, held-out and refining runs: the baseline pushed into the fresh
  // beds (poured once, shared with every push-only confirmation), one sweep for any magnitude
  const Effect &m = *find_effect("measurement_chain");
  const auto c = confirm_requests("tiny", m, 1.23, {"50", "100"}, "confirm");
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0].spec.name, "confirm_beds");
  EXPECT_TRUE(c[0].spec.v0.empty());
  EXPECT_EQ(c[1].spec.name, "confirm_baseline");
  EXPECT_EQ(c[1].beds_from, "confirm_beds");
  EXPECT_TRUE(c[1].spec.push_set.empty() && c[1].spec.set.empty());
  EXPECT_EQ(confirm_sweep(m, 1.5, "heldout"), "confirm_baseline");
  EXPECT_EQ(confirm_sweep(m, 1.23, "refine", REFINE_SEEDS), "refine_baseline");
  const auto r = confirm_requests("tiny", m, 2.0, {"50"}, "refine", REFINE_SEEDS);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[1].spec.name, "refine_baseline");
  EXPECT_EQ(r[1].beds_from, "refine_beds");
  // beyond 2 ms the mount is simulated: its own sweep, pushed into the same fresh beds
  const auto l = confirm_requests("tiny", m, 4.5, {"50"}, "confirm");
  ASSERT_EQ(l.size(), 2u);
  EXPECT_EQ(l[1].spec.name, "confirm_measurement_chain_4.5");
  EXPECT_EQ(l[1].beds_from, "confirm_beds");
  ASSERT_FALSE(l[1].spec.push_set.empty());
  EXPECT_EQ(l[1].spec.push_set[0].first, "mount_k");
  EXPECT_EQ(confirm_sweep(m, 2.0, "confirm"), "confirm_baseline");
  EXPECT_EQ(confirm_sweep(m, 2.01, "confirm"), "confirm_measurement_chain_2.01");
  // a simulated push-only effect keeps its own sweep on the same beds
  const Effect &ramp = *find_effect("actuator_ramp");
  const auto s = confirm_requests("tiny", ramp, 2.4, {"50"}, "confirm");
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[1].spec.name, "confirm_actuator_ramp_2.4");
  EXPECT_EQ(confirm_sweep(ramp, 2.4, "confirm"), "confirm_actuator_ramp_2.4");
}

// ---- simulate: a transform effect's runs are the baseline's, filtered

TEST(GapSims, ATransformEffectsRunsAreTheBaselinesFiltered)
{
  const Effect &m = *find_effect("measurement_chain");
  ASSERT_NE(m.transform, nullptr);
  const TraceRun base = ramp_run("baseline/traces/b1.csv", 100, 0.2, 3.0);    // 1e-4 s samples
  const TraceRun r = transformed_run(m, 2.0, base);
  SensorChain c;
  c.mount.period = 2e-3;
  c.mount.zeta = 0.2;
  const auto F = sensor_response(base.F, 1e-4, c);
  ASSERT_EQ(r.F.size(), F.size());
  for (std::size_t i = 0; i < F.size(); ++i) EXPECT_NEAR(r.F[i], F[i], 1e-9 * 500.0);
  EXPECT_EQ(r.z, base.z);
  EXPECT_EQ(r.t, base.t);
  EXPECT_EQ(r.path, base.path);
  // the mount's lag moves the onset deeper
  EXPECT_GT(r.onset, base.onset + 0.001);
  EXPECT_NEAR(r.onset, force_onset(r.z, r.F), 1e-12);
  RunsBySpeed by;
  by[100] = {base, ramp_run("baseline/traces/b2.csv", 100, 0.3, 3.0)};
  const RunsBySpeed t = transformed_runs(m, 2.0, by);
  ASSERT_EQ(t.at(100).size(), 2u);
  EXPECT_EQ(t.at(100)[0].F, r.F);
}

// The adaptive plan's split of an effect (effects.h, transform_part; gap_plan.h, knot_requests):
// the measurement chain's part that costs nothing is its filter's knots (up to 2 ms), fitted in
// the cheap stage with nothing simulated beyond the baseline's own sweeps; what the plan can
// buy for it is its two simulated knots, pushes into the signature beds. The force scale is
// its transform whole; an effect without a transform has no free part.
TEST(GapPlan, TheChainSplitsIntoItsFilteredPartAndTheKnotsToBuy)
{
  const Effect &chain = *find_effect("measurement_chain");
  const Effect *part = transform_part(chain);
  ASSERT_NE(part, nullptr);
  EXPECT_NE(part, &chain);
  EXPECT_EQ(part->name, chain.name);
  EXPECT_FALSE(has_simulated_knots(*part));
  EXPECT_TRUE(has_simulated_knots(chain));
  for (double a : part->knots) EXPECT_LE(a, chain.transform_max);
  EXPECT_EQ(part->knots.size() + 2, chain.knots.size());    // all but 4 and 10 ms
  const auto cheap = signature_requests("tiny", {"100"}, {part});
  ASSERT_EQ(cheap.size(), 2u);    // the baseline on the signature beds and on the reference beds
  const auto buy = knot_requests("tiny", {"100"}, chain);
  ASSERT_EQ(buy.size(), 2u);
  EXPECT_EQ(buy[0].spec.name, "measurement_chain_4");
  EXPECT_EQ(buy[1].spec.name, "measurement_chain_10");
  for (const auto &r : buy) EXPECT_EQ(r.beds_from, "baseline");
  const Effect &scale = *find_effect("force_scale");
  EXPECT_EQ(transform_part(scale), &scale);
  EXPECT_TRUE(knot_requests("tiny", {"100"}, scale).empty());
  EXPECT_EQ(transform_part(*find_effect("actuator_ramp")), nullptr);
}

// force_scale: the baseline's traces times (1 + a), at any magnitude; every feature is
// homogeneous of degree one in F, so its signature at a is a / knot times the knot's:
// the interpolation the fit makes between 0 and a knot is exact
TEST(GapSims, ForceScaleScalesTheTraceAndItsSignatureIsLinear)
{
  const Effect &e = *find_effect("force_scale");
  ASSERT_NE(e.transform, nullptr);
  EXPECT_FALSE(e.pour_level);
  EXPECT_FALSE(e.one_sided);
  EXPECT_TRUE(by_transform(e, -0.25) && by_transform(e, 0.25) && by_transform(e, 10.0));
  EXPECT_EQ(reference_magnitude(e), 0.1);
  EXPECT_EQ(confirm_sweep(e, -0.167, "confirm"), "confirm_baseline");
  // nothing to simulate: no sweep of its own in the plan
  for (const auto &r : signature_requests("tiny", {"100"}, {&e})) EXPECT_EQ(r.spec.name.find("force_scale"), std::string::npos);
  // a force with grain-scale wiggles, so the fluctuation levels and bands are not zero
  auto wiggly = [](const std::string &name, double z0, double phase) {
    TraceRun r = ramp_run(name, 100, z0, 3.0);
    for (std::size_t i = 0; i < r.F.size(); ++i)
      if (r.F[i] > 0) r.F[i] += 80.0 * std::sin(0.9 * (double) i + phase) + 30.0 * std::sin(0.23 * (double) i);
    r.onset = force_onset(r.z, r.F);
    return r;
  };
  const TraceRun base = wiggly("baseline/traces/b1.csv", 0.2, 0.0);
  // the known answer: F times 1 + a, sample by sample; t, z and the onset unchanged
  const TraceRun r = transformed_run(e, -1.0 / 6.0, base);
  ASSERT_EQ(r.F.size(), base.F.size());
  for (std::size_t i = 0; i < r.F.size(); ++i) EXPECT_NEAR(r.F[i], base.F[i] * 5.0 / 6.0, 1e-12 * std::abs(base.F[i]));
  EXPECT_EQ(r.z, base.z);
  EXPECT_EQ(r.onset, base.onset);
  // the signature two ways: the transform at a, and a / 0.25 times the knot's
  std::vector<TraceRun> runs{base, wiggly("b2", 0.25, 1.0), wiggly("b3", 0.3, 2.0)};
  GapGrid grid;
  grid.zmax = 2.5;
  auto ens = [&](double a) {
    std::vector<TraceRun> t;
    for (const auto &x : runs) t.push_back(transformed_run(e, a, x));
    return ensemble_of(t, grid, 100);
  };
  const Ensemble e0 = ens(0.0), knot = ens(0.25);
  ASSERT_EQ(e0.mean.size(), grid.nfeatures());
  for (double a : {-0.3, -1.0 / 6.0, 0.05, 0.31}) {
    const Ensemble ea = ens(a);
    for (std::size_t k = 0; k < e0.mean.size(); ++k) {
      const double direct = ea.mean[k] - e0.mean[k], by_knot = a / 0.25 * (knot.mean[k] - e0.mean[k]);
      EXPECT_NEAR(direct, by_knot, 1e-9 * std::abs(e0.mean[k]) + 1e-12) << "a = " << a << ", feature " << k;
    }
  }
  // the features are not all bin means: the fluctuation levels and bands scale too
  EXPECT_GT(e0.mean[grid.nbins()], 1.0);
}

// ---- align and bin

TEST(GapAlign, TwoMeasuredRunsWithAKnownOffset)
{
  // measured onsets 0.2 and 0.4 cm (origins off by -0.1 and +0.1), the baseline's 0.3 cm
  RunsBySpeed real;
  real[100] = {ramp_run("m1", 100, 0.1, 3.0), ramp_run("m2", 100, 0.3, 3.0)};
  SimulatedRuns sims;
  sims.base[100] = {ramp_run("b1", 100, 0.2, 3.0), ramp_run("b2", 100, 0.2, 3.0)};
  sims.fresh[100] = {ramp_run("f1", 100, 0.2, 3.0), ramp_run("f2", 100, 0.2, 3.0), ramp_run("f3", 100, 0.2, 3.0)};
  sims.knots["k_1"][100] = {ramp_run("k1", 100, 0.2, 3.2), ramp_run("k2", 100, 0.2, 3.2)};
  const double z_m1 = real[100][0].z.back();
  const Alignment al = align_and_bin(real, sims, 5.0);
  EXPECT_NEAR(al.onset.at(100), 0.3, 1e-9);
  for (const auto &r : real[100]) EXPECT_NEAR(r.onset, 0.3, 1e-12);
  EXPECT_NEAR(real[100][0].z.back() - z_m1, 0.1, 1e-9);    // moved down by its offset
  // after the move the two measured force curves coincide sample by sample
  EXPECT_NEAR(force_onset(real[100][0].z, real[100][0].F), force_onset(real[100][1].z, real[100][1].F), 1e-9);
  // the deepest common depth is the run moved up: 3.0 - 0.1 = 2.9, on the 0.25 cm grid 2.75
  EXPECT_NEAR(al.grid.zmax, 2.75, 1e-12);
  ASSERT_EQ(al.notes.size(), 1u);
  EXPECT_NE(al.notes[0].find("moved by up to 0.100 cm"), std::string::npos) << al.notes[0];
  // and no deeper than the scenario's push
  RunsBySpeed real2;
  real2[100] = {ramp_run("m1", 100, 0.2, 3.0), ramp_run("m2", 100, 0.2, 3.0)};
  SimulatedRuns sims2 = sims;
  EXPECT_NEAR(align_and_bin(real2, sims2, 1.6).grid.zmax, 1.5, 1e-12);
  // an ensemble of one run cannot be compared
  sims2.knots["k_1"][100].pop_back();
  EXPECT_THROW(align_and_bin(real2, sims2, 5.0), InputError);
}

// ---- features: the null replicates

TEST(GapFeatures, NullReplicatesSplitTheReferenceBeds)
{
  EXPECT_EQ(subsets(4, 2).size(), 6u);
  EXPECT_EQ(subsets(4, 2)[5], (std::vector<std::size_t>{2, 3}));
  EXPECT_TRUE(subsets(2, 3).empty());
  // four reference runs, each scaled by its own factor (run-to-run scatter)
  GapGrid grid;
  grid.zmax = 2.0;
  RunsBySpeed real;
  real[100] = {ramp_run("m1", 100, 0.2, 2.5), ramp_run("m2", 100, 0.2, 2.5)};
  SimulatedRuns sims;
  sims.base[100] = {ramp_run("b1", 100, 0.2, 2.5), ramp_run("b2", 100, 0.2, 2.5)};
  for (int i = 0; i < 4; ++i) {
    TraceRun r = ramp_run("f" + std::to_string(i), 100, 0.2, 2.5);
    for (auto &F : r.F) F *= 1.0 + 0.01 * i;
    sims.fresh[100].push_back(r);
  }
  // two measured runs per speed: subsets of 2 of the 4 reference beds (leaving 2), C(4, 2)
  const Features f = build_features(real, sims, {}, grid, 2);
  EXPECT_EQ(f.n_reference, 4);
  EXPECT_EQ(f.nulls.size(), 6u);
  // one measured run: the 4 single beds, each against the other three. Replicate i's mean is
  // run_i - mean(rest_i) + mean(all); over i the rests average to mean(all), so the
  // replicates' mean is the reference mean itself, feature by feature (a linear identity)
  const Features f1 = build_features(real, sims, {}, grid, 1);
  ASSERT_EQ(f1.nulls.size(), 4u);
  std::vector<double> mean(f1.fresh[0].mean.size(), 0.0);
  for (const auto &t : f1.nulls)
    for (std::size_t k = 0; k < mean.size(); ++k) mean[k] += t.mean[0][k] / f1.nulls.size();
  // rounding only: sums of four numbers
  for (std::size_t k = 0; k < mean.size(); ++k)
    EXPECT_NEAR(mean[k], f1.fresh[0].mean[k], 1e-12 * std::abs(f1.fresh[0].mean[k]) + 1e-12);
  // fewer than 3 reference runs: no null replicate possible
  sims.fresh[100].resize(2);
  EXPECT_THROW(build_features(real, sims, {}, grid, 2), InputError);
}

// ---- which and confirm on a hand-made feature set

namespace {

// Two speeds, six features at 100 (relative run-to-run variance 1e-4), the baseline on its
// signature beds equal to the reference beds; effect "a" adds +10 to features 0-2 per unit
// magnitude, effect "b" +10 to features 3-5, effect "c" +20 to features 0-2 (a's look-alike;
// one knot each, at 1); the measurement is the
// baseline plus `a` units of effect a's signature. Null replicates: the reference moved by
// +-0.5 on alternate features (noise the size of one standard error).
struct HandMade {
  Effect ea, eb, ec;    // ec: a's look-alike, +20 on features 0-2 per unit
  Features f;
  HandMade(double a)
  {
    ea.name = "a", ea.unit = "u", ea.knots = {1.0};
    eb.name = "b", eb.unit = "u", eb.knots = {1.0};
    ec.name = "c", ec.unit = "u", ec.knots = {1.0};
    const std::size_t P = 6;
    auto ens = [&](double v0, std::vector<double> mean) { return make_ensemble(v0, {mean, mean}); };
    for (double v : {50.0, 100.0}) {
      std::vector<double> base(P, 100.0), ka = base, kb = base, kc = base, meas = base;
      for (std::size_t k = 0; k < 3; ++k) ka[k] += 10.0, kb[k + 3] += 10.0, kc[k] += 20.0, meas[k] += 10.0 * a;
      f.speeds.push_back(v);
      f.real.push_back(ens(v, meas));
      f.base.push_back(ens(v, base));
      f.fresh.push_back(ens(v, base));
      f.knots["a_1"].push_back(ens(v, ka));
      f.knots["b_1"].push_back(ens(v, kb));
      f.knots["c_1"].push_back(ens(v, kc));
      f.cv2.push_back(std::vector<double>(P, 1e-4));
      f.fresh_err.push_back(model_err(f.fresh.back(), f.cv2.back()));
      f.target.mean.push_back(meas);
      f.target.err.push_back(model_err(f.real.back(), f.cv2.back()));
      f.target_scale.push_back(1.0);
    }
    for (double sign : {1.0, -1.0}) {
      Target t;
      for (std::size_t s = 0; s < 2; ++s) {
        std::vector<double> m(P, 100.0);
        for (std::size_t k = 0; k < P; ++k) m[k] += (k % 2 ? sign : -sign) * 0.5;
        t.mean.push_back(m);
        t.err.push_back(f.target.err[s]);
      }
      f.nulls.push_back(t);
    }
    f.n_reference = 4;
  }
};

}    // namespace

TEST(GapWhere, CurvesAndSignificanceOnAHandMadeFeatureSet)
{
  HandMade h(0.5);
  // a grid whose features are the hand-made six: 2 bins of 0.25 cm, no fluctuation window
  // (1 cm is deeper than 0.5), the 4 spectral bands
  GapGrid grid;
  grid.zmax = 0.5;
  ASSERT_EQ(grid.nfeatures(), 6u);
  const GapCurves d = gap_curves(h.f, grid);
  ASSERT_EQ(d.speeds.size(), 2u);
  // both bins 5 above a reference of 100, no scatter in either ensemble (two equal runs):
  // G = sqrt(2 x 5^2 / (2 x 105^2)) = 5 / 105 at each speed; rounding only
  EXPECT_NEAR(d.speeds[0].G_before, 5.0 / 105.0, 1e-12);
  EXPECT_NEAR(d.gap, 5.0 / 105.0, 1e-12);
  EXPECT_EQ(d.speeds[1].gap, (std::vector<double>{5.0, 5.0}));
  EXPECT_NEAR(d.speeds[0].band[0], 2.0 * std::sqrt(1e-4 * 105 * 105 / 2 + 0.5), 1e-12);
  EXPECT_EQ(d.n_real_min, 2);
  EXPECT_EQ(d.n_sim, 4);
  const Significance sig = gap_significance(h.f, grid);
  // chi^2 = 2 speeds x 3 features x 5^2 / (1e-4 x 105^2 / 2 + 0.5)
  EXPECT_NEAR(sig.chi2_0, 150.0 / (1e-4 * 105 * 105 / 2 + 0.5), 1e-9);
  EXPECT_EQ(sig.nfeatures, 12u);
  EXPECT_LT(sig.p_value, 1e-20);
  EXPECT_TRUE(sig.significant);
  const Significance sig0 = gap_significance(HandMade(0.0).f, grid);
  EXPECT_EQ(sig0.chi2_0, 0.0);
  EXPECT_FALSE(sig0.significant);
  // the held-out speed: the one with the largest G_all (both alike here: the first)
  const HeldOut held = heldout_speed(d.speeds);
  EXPECT_EQ(held.index, 0u);
  EXPECT_EQ(held.v0, d.speeds[0].v0);
  EXPECT_EQ(held.gap, d.speeds[0].all_before());
}

TEST(GapWhere, AnObservableWithoutScatterGetsANoteNotAZScore)
{
  // runs whose force is one shape times a factor: the forces scatter, but the crossover
  // depth t_star (where the force's shape turns) is the same in every run, as t_star's
  // grid-binned values often are in real ensembles. Its pooled variance is 0: a z-score
  // would divide by 0 (it printed 1e150 before), so t_star gets a note and no finding.
  Scenario sc;
  sc.D = 0.5, sc.d_g = 0.1, sc.g = 981.0;
  const double v = 100.0;
  auto run = [&](double factor) {
    TraceRun r;
    r.v0 = v;
    for (int i = 0; i <= 400; ++i) {
      const double z = 0.0075 * i;
      r.z.push_back(z);
      r.t.push_back(z / v);
      r.F.push_back(factor * (2e4 * z + 6e3 * (1.0 - std::exp(-z / 0.05))));
    }
    r.onset = 0.0;
    return r;
  };
  GapGrid grid;
  grid.zmax = 2.5;
  Features f;
  f.speeds = {v};
  f.target_scale = {1.0};
  RunsBySpeed real{{v, {run(1.3), run(1.35)}}};
  SimulatedRuns sims;
  sims.fresh[v] = {run(0.95), run(1.0), run(1.05)};
  const std::vector<double> ends = transient_ends(f, sims.fresh, sc, grid);
  ASSERT_EQ(ends.size(), 1u);
  const ObservableFindings d = observable_findings(f, real, sims, sc, grid, ends);
  // the independent route: t_star of each simulated run, straight from the kernel
  std::vector<double> ts;
  for (const auto &r : sims.fresh[v]) {
    const auto o = run_observables(r.z, r.F, v, sc.D, sc.g, sc.d_g, grid, ends[0]);
    if (o.crossed) ts.push_back(o.t_star);
  }
  ASSERT_EQ(ts.size(), 3u) << "the shape must cross over, or the test checks nothing";
  ASSERT_EQ(ts[0], ts[1]);
  ASSERT_EQ(ts[1], ts[2]);
  const auto noted = [&](const std::string &name) {
    return std::any_of(d.notes.begin(), d.notes.end(),
                       [&](const std::string &n) { return n.find("where: " + name + " at v0 = 100 has no scatter") == 0; });
  };
  EXPECT_TRUE(noted("t_star"));
  EXPECT_FALSE(noted("peak_F"));
  bool peak_found = false;
  for (const auto &w : d.findings) {
    EXPECT_NE(w.observable, "t_star");
    // every z-score a finite number of standard errors: at most |1.35 - 1| / (0.05 / sqrt 3)
    // ~ 12 for a force, far below the 1e150 a zero variance gave
    EXPECT_TRUE(std::isfinite(w.zscore)) << w.observable;
    EXPECT_LT(std::abs(w.zscore), 1e3) << w.observable;
    if (w.observable == "peak_F") {
      peak_found = true;
      EXPECT_GT(w.zscore, 3.0);
    }
  }
  EXPECT_TRUE(peak_found);
}

TEST(GapWhich, TheVerdictOnAHandMadeFeatureSet)
{
  HandMade h(0.5);
  Significance omnibus;
  omnibus.significant = true;    // the omnibus route: chi^2 about 150 over 12 features (by hand)
  omnibus.nfeatures = 12;
  const FittedCandidates fitted = fit_candidates({&h.ea, &h.eb}, h.f, [](const std::string &) { return NAN; }, omnibus);
  const auto &data = fitted.data;
  const FitEvidence &d = fitted.evidence;
  const VerdictDecision v = decide_verdict(d);
  ASSERT_EQ(d.ranking.size(), 2u);
  EXPECT_EQ(v.verdict, Verdict::explained);
  EXPECT_EQ(v.top_effect, "a");
  // the model is linear between the knots 0 and 1 and the data noise-free: exact
  EXPECT_NEAR(d.ranking[0].magnitude, 0.5, 1e-3);
  EXPECT_GT(d.ranking[0].explained, 0.99);
  EXPECT_TRUE(d.ranking[0].detected);
  // b's signature is orthogonal to the gap: it explains nothing
  EXPECT_EQ(d.ranking[1].name, "b");
  EXPECT_LT(d.ranking[1].explained, 0.01);
  EXPECT_EQ(d.n_null, 2);
  EXPECT_EQ(d.nfeatures, 12u);    // the omnibus test's, carried for the verdict's sentences
  EXPECT_EQ(data.count("a"), 1u);
  EXPECT_EQ(data.count("b"), 1u);
  // each candidate's chi^2 at magnitude 0, raw and within the calibration bound, is the
  // omnibus test's (gap_where: the reference beds as a one-knot model; here each candidate's
  // knot 0, referenced to them): the Which table's references are the verdict's numbers
  GapGrid grid;
  grid.zmax = 0.5;
  const Significance sig = gap_significance(h.f, grid);
  EXPECT_GT(std::abs(sig.scale_within_bound), 1e-3);    // a scale that changes the chi^2
  EXPECT_LT(sig.chi2_within_bound, sig.chi2_0);
  for (const auto &r : d.ranking) {
    EXPECT_NEAR(r.chi2_0, sig.chi2_0, 1e-9 * sig.chi2_0) << r.name;
    EXPECT_NEAR(r.chi2_0_within_bound, sig.chi2_within_bound, 1e-9 * sig.chi2_0) << r.name;
  }

  // no gap at all, and the omnibus test finds none: none
  HandMade z(0.0);
  const VerdictDecision vz =
      decide_verdict(fit_candidates({&z.ea, &z.eb}, z.f, [](const std::string &) { return NAN; }, Significance{}).evidence);
  EXPECT_EQ(vz.verdict, Verdict::none);
  EXPECT_TRUE(vz.top_effect.empty());
}

// "The same magnitude" is measured against the effect's whole range in the library, not the
// range of the knots a plan bought: the chain fitted on its filter's knots alone (0.2 to 2 ms,
// its simulated 4 and 10 ms skipped) has the tolerance of the chain with every knot, so a
// refinement or a held-out run is simulated exactly when it would be with all knots (before
// this, 5% of 0.2-2 ms let a refinement move a fit of 1.05 ms to 0.93 for a truth of 1).
// Flat features (one speed, two features, every knot the baseline): only the knots matter.
TEST(GapPlan, TheSameMagnitudeIsMeasuredOnTheLibrarysWholeRange)
{
  const Effect &chain = *find_effect("measurement_chain");
  const Effect *part = transform_part(chain);
  ASSERT_NE(part, nullptr);
  Features f;
  const std::vector<double> flat(2, 100.0);
  const Ensemble en = make_ensemble(100.0, {flat, flat});
  f.speeds = {100.0};
  f.base = f.fresh = f.real = {en};
  for (double a : chain.knots) f.knots[effect_sweep_name(chain, a)] = {en};
  f.cv2 = {std::vector<double>(2, 1e-4)};
  f.fresh_err = {model_err(en, f.cv2[0])};
  f.target = Target{{flat}, {f.fresh_err[0]}};
  const EffectData whole = effect_data(chain, f), cheap = effect_data(*part, f);
  const auto [wlo, whi] = magnitude_range(whole);
  const auto [clo, chi] = magnitude_range(cheap);
  ASSERT_LT(chi - clo, 0.5 * (whi - wlo));    // the part's own range is much narrower
  EXPECT_DOUBLE_EQ(whole.library_span, whi - wlo);
  EXPECT_DOUBLE_EQ(cheap.library_span, whole.library_span);
  EXPECT_DOUBLE_EQ(same_magnitude_tolerance(cheap), GapThresholds::same_magnitude_of_range * (whi - wlo));
  EXPECT_DOUBLE_EQ(same_magnitude_tolerance(cheap), same_magnitude_tolerance(whole));
  // an effect the library does not hold: its own range
  HandMade h(0.5);
  const EffectData own = effect_data(h.ea, h.f);
  const auto [lo, hi] = magnitude_range(own);
  EXPECT_DOUBLE_EQ(same_magnitude_tolerance(own), GapThresholds::same_magnitude_of_range * (hi - lo));
}

TEST(GapConfirm, TheGapAlongTheSignatureAndTheConfirmationTest)
{
  HandMade h(0.5);
  const EffectData ed = effect_data(h.ea, h.f);
  // by hand: u = 5 on 3 features at 2 speeds, the gap 5 there less the baseline's nuisance
  // scale c0 (100 c0 on every feature: the weighted least squares of the target on the
  // reference 100, weights w on features 0-2 and 0.5 + 0.5 on 3-5), the variance w = 0.5 (the
  // reference's mean) + 1e-4 x 105^2 / 2 (the measured mean's): sum u (g - 100 c0) / w over
  // sqrt(sum u^2 / w) = sqrt(150 / w) (1 - 20 c0); rounding only
  const double w = 0.5 + 1e-4 * 105.0 * 105.0 / 2.0;
  const double c0 = (3 * 5.0 * 100.0 / w) / (3 * 1e4 / w + 3 * 1e4 / 1.0);
  ASSERT_LT(c0, GapThresholds::calibration_scale_bound);    // inside the bound: not clamped
  EXPECT_NEAR(signature_sigma(ed, 0.5, h.f), std::sqrt(150.0 / w) * (1.0 - 20.0 * c0), 1e-9);
  HandMade z(0.0);
  EXPECT_NEAR(signature_sigma(effect_data(z.ea, z.f), 0.5, z.f), 0.0, 1e-12);
  // omnibus route: chi^2 150 over 12 features, noise 3 sqrt(24) = 14.7
  auto omnibus = [](double chi2a) { return confirms(false, 150.0, 12, 0.0, chi2a, 0.0); };
  EXPECT_TRUE(omnibus(20.0));      // excess 138 -> 8: 94% removed
  EXPECT_FALSE(omnibus(140.0));    // within the noise of chi^2
  EXPECT_FALSE(omnibus(120.0));    // beyond the noise, but 22% of the excess removed (< 25%)
  // targeted route: the squared projection must drop by 9 without chi^2 growing beyond its noise
  auto targeted = [](double chi2a, double proj_a) { return confirms(true, 150.0, 12, 4.0, chi2a, proj_a); };
  EXPECT_TRUE(targeted(150.0, 2.0));     // 16 -> 4
  EXPECT_FALSE(targeted(150.0, 3.0));    // 16 -> 9: 7 only
  EXPECT_FALSE(targeted(170.0, 0.0));    // chi^2 up by 20 > 14.7
  // the confirmation is kept only when G_all shrinks to half at most: the side walls case in
  // the faithful synthetic world passed chi^2 with packing while G_all grew 0.118 -> 0.139,
  // the friction case with polydispersity while it went 0.088 -> 0.074 (confident wrong
  // answers); half exactly still counts, a NaN after (no runs) never
  EXPECT_TRUE(gap_shrinks(0.118, 0.039));
  EXPECT_TRUE(gap_shrinks(0.2, 0.1));    // 0.2 is 0.1 doubled in binary too: half exactly
  EXPECT_FALSE(gap_shrinks(0.118, 0.139));
  EXPECT_FALSE(gap_shrinks(0.088, 0.074));
  EXPECT_FALSE(gap_shrinks(0.118, std::nan("")));
}

namespace {

// F = 0 above z0, a ramp of 1000 dyne/cm for 0.5 cm (ramp_run), then rising 300 dyne/cm from
// 1 to 1.5 cm and `extra` dyne/cm from 1.5 to 2 cm; every feature of it nonzero
TraceRun stepped_run(const std::string &name, double z0, double extra = 0.0)
{
  TraceRun r = ramp_run(name, 100, z0, 2.5);
  for (std::size_t i = 0; i < r.F.size(); ++i)
    r.F[i] += 300.0 * std::clamp(r.z[i] - 1.0, 0.0, 0.5) + extra * std::clamp(r.z[i] - 1.5, 0.0, 0.5);
  return r;
}

TraceRun times(TraceRun r, double scale)
{
  for (double &F : r.F) F *= scale;
  return r;
}

// run r written as a trace file at path (cgs, its v0, D 2, g 981; every digit of its numbers),
// and the run pointing at it: the confirmation's corrected traces are read from the files
TraceRun on_file(TraceRun r, const std::string &path)
{
  std::ofstream out(path);
  out << "# granpen-trace v1\n# units = cgs\n# v0 = " << r.v0 << "\n# D = 2.0\n# g = 981\nt,z,F\n";
  out.precision(17);
  for (std::size_t i = 0; i < r.F.size(); ++i) out << r.t[i] << "," << r.z[i] << "," << r.F[i] << "\n";
  r.path = path;
  return r;
}

// confirm_top_effect called until it needs no more runs, each set asked for given as
// runs_at(magnitude) (a transform effect's as loading transforms them, gap_sims.h)
template <class RunsAt>
ConfirmStep confirm_with(const std::map<std::string, const Effect *> &by_name, const FittedCandidates &fitted,
                         const VerdictDecision &v, const WhereResult &where, const Features &f, const Alignment &al,
                         RunsAt runs_at)
{
  StageRuns given;
  ConfirmStep step = confirm_top_effect(by_name, fitted, v, where, f, al, false, given);
  for (int i = 0; i < 4 && step.need; ++i) {
    for (const RunSet &set : step.need->sets) given[set.tag] = runs_at(set.magnitude);
    step = confirm_top_effect(by_name, fitted, v, where, f, al, false, given);
  }
  return step;
}

}    // namespace

TEST(GapConfirm, TheConfirmingRunsAreComparedWithTheFitsScale)
{
  // the measured runs are 1.03 times the effect's knot (magnitude 1: a step of 150 dyne
  // below 1 cm on the ramp), a calibration 3% off: the fit names magnitude 1 with a nuisance
  // scale of 0.03 (the only exact solution: the step and the baseline are independent), so
  // runs simulated at magnitude 1 are the fit's prediction only times 1.03. With that scale
  // the gap after, chi^2 and the held-out speed's gap are 0 (the runs are the knot's shape
  // exactly); compared unscaled they would keep the 3% (G about 0.03)
  auto stepped = [](const std::string &name, double scale) {
    TraceRun r = ramp_run(name, 100, 0.2, 2.5);
    for (std::size_t i = 0; i < r.F.size(); ++i) r.F[i] = scale * (r.F[i] + 300.0 * std::clamp(r.z[i] - 1.0, 0.0, 0.5));
    return r;
  };
  RunsBySpeed real;
  real[100] = {stepped("m1", 1.03), stepped("m2", 1.03)};
  SimulatedRuns sims;
  sims.base[100] = {ramp_run("b1", 100, 0.2, 2.5), ramp_run("b2", 100, 0.2, 2.5)};
  sims.fresh[100] = {ramp_run("f1", 100, 0.2, 2.5), ramp_run("f2", 100, 0.2, 2.5), ramp_run("f3", 100, 0.2, 2.5)};
  Effect ea;
  ea.name = "a", ea.unit = "u", ea.knots = {1.0}, ea.pour_level = true, ea.one_sided = true;
  sims.knots[effect_sweep_name(ea, 1.0)][100] = {stepped("k1", 1.0), stepped("k2", 1.0)};
  const Alignment al = align_and_bin(real, sims, 2.0);
  const Features f = build_features(real, sims, {&ea}, al.grid, 2);
  WhereResult where;
  where.omnibus = gap_significance(f, al.grid);
  where.before.gap = where.heldout.gap = 0.05;
  where.heldout.v0 = 100;
  const FittedCandidates fitted = fit_candidates({&ea}, f, [](const std::string &) { return NAN; }, where.omnibus);
  const EffectFit &top = fitted.evidence.ranking.at(0);
  // the closed-form scale at the grid's magnitude, then golden section: within 1e-6
  ASSERT_NEAR(top.magnitude, 1.0, 1e-5);
  ASSERT_NEAR(top.scale, 0.03, 1e-6);
  VerdictDecision v;
  v.verdict = Verdict::explained, v.top_effect = "a", v.targeted = true, v.significant = true;
  TempDir dir("confirm_scaled");
  const StageRuns given{{"confirm", RunsBySpeed{{100.0, {on_file(stepped("c1", 1.0), dir / "c1.csv"),
                                                         on_file(stepped("c2", 1.0), dir / "c2.csv")}}}}};
  const ConfirmStep step = confirm_top_effect({{"a", &ea}}, fitted, v, where, f, al, false, given);
  ASSERT_FALSE(step.need.has_value());
  const Confirmation &c = step.done;
  EXPECT_NEAR(c.scale, top.scale, 1e-12);
  // OUT/corrected/ holds the runs as compared: the files' force times 1.03 (a simulated
  // effect's runs were copied as simulated before), its `derived` line saying so
  ASSERT_EQ(c.corrected_traces.size(), 2u);
  write_file(dir / "out.csv", c.corrected_traces[0].second);
  const Trace out = read_trace(dir / "out.csv");
  const TraceRun &c1 = given.at("confirm").at(100)[0];
  ASSERT_EQ(out.F.size(), c1.F.size());
  for (std::size_t k = 0; k < out.F.size(); ++k) EXPECT_NEAR(out.F[k], (1.0 + c.scale) * c1.F[k], 1e-9 * 650.0) << k;
  EXPECT_NE(c.corrected_traces[0].second.find("# derived = F times 1 + c = 1.03 (c = 0.03: the force scale fitted with it"), std::string::npos) << c.corrected_traces[0].second.substr(0, 300);
  // exact runs scaled by the fitted scale: rounding only (the scale within 1e-6 of 0.03
  // leaves G of that order)
  EXPECT_LT(c.outcome.gap_after, 1e-5);
  EXPECT_LT(c.outcome.chi2_after, 1e-3);
  EXPECT_LT(c.heldout_after, 1e-5);
  EXPECT_LT(std::abs(c.outcome.proj_after), 1e-2);
}


// OUT/corrected/ holds the "after" as the verdict compared it (issue 37): a transform
// effect's confirming runs filtered and times 1 + the scale fitted with it. The measured runs
// are the mount at 2 ms on the baseline, 1.03 times (a calibration 3% off); the confirming
// runs are the baseline on fresh beds, as files. Each corrected trace must be the compared
// prediction sample by sample: the runs the gap after was computed on (after_runs, filtered
// and scaled), and the file's force filtered at the named magnitude times 1 + scale; its
// `derived` line says so. Unscaled (before): off by the 3%.
TEST(GapConfirm, TheCorrectedTracesOfATransformAreTheComparedPrediction)
{
  TempDir dir("corrected_scaled");
  const Effect &chain = *find_effect("measurement_chain");
  SimulatedRuns sims;
  sims.base[100] = {stepped_run("b1", 0.2), stepped_run("b2", 0.3)};
  sims.fresh[100] = {stepped_run("f1", 0.2), stepped_run("f2", 0.25), stepped_run("f3", 0.3)};
  for (double a : chain.knots)
    sims.knots[effect_sweep_name(chain, a)] = by_transform(chain, a) ? transformed_runs(chain, a, sims.base) : sims.base;
  RunsBySpeed real;
  for (const char *name : {"m1", "m2"}) {
    TraceRun r = transformed_run(chain, 2.0, stepped_run(name, 0.25));
    for (double &F : r.F) F *= 1.03;
    real[100].push_back(r);
  }
  const Alignment al = align_and_bin(real, sims, 2.0);
  const Features f = build_features(real, sims, {&chain}, al.grid, 2);
  WhereResult where;
  where.omnibus = gap_significance(f, al.grid);
  where.before.gap = where.heldout.gap = 0.05;
  where.heldout.v0 = 100;
  const FittedCandidates fitted = fit_candidates({&chain}, f, [](const std::string &) { return NAN; }, where.omnibus);
  VerdictDecision v;
  v.verdict = Verdict::explained, v.top_effect = chain.name, v.targeted = true, v.significant = true;
  const std::vector<TraceRun> fresh = {on_file(stepped_run("c1", 0.2), dir / "c1.csv"),
                                       on_file(stepped_run("c2", 0.3), dir / "c2.csv")};
  const ConfirmStep step = confirm_with({{chain.name, &chain}}, fitted, v, where, f, al, [&](double a) {
    return transformed_runs(chain, a, RunsBySpeed{{100.0, fresh}});
  });
  ASSERT_FALSE(step.need.has_value());
  const Confirmation &c = step.done;
  ASSERT_EQ(c.corrected_effect, chain.name);
  // the fit takes the 3% as its nuisance scale (the filtered knot and the baseline differ in
  // shape: the scale is no part of the filter's signature)
  ASSERT_GT(std::abs(c.scale), 0.02);
  const std::vector<TraceRun> &compared = c.after_runs.at(100);
  ASSERT_EQ(c.corrected_traces.size(), compared.size());
  for (std::size_t i = 0; i < compared.size(); ++i) {
    const std::string path = dir / ("out" + std::to_string(i) + ".csv");
    write_file(path, c.corrected_traces[i].second);
    const Trace t = read_trace(path);
    EXPECT_NE(c.corrected_traces[i].second.find("times 1 + c = " + printf_number("%.6g", 1.0 + c.scale) +
                                                " (c = " + printf_number("%.6g", c.scale)),
              std::string::npos);
    const std::vector<double> expect = transformed_run(chain, c.corrected_magnitude, fresh[i]).F;
    ASSERT_EQ(t.F.size(), compared[i].F.size());
    for (std::size_t k = 0; k < t.F.size(); ++k) {
      // the file's digits (17) and the filter recomputed: rounding only, against forces of 650
      EXPECT_NEAR(t.F[k], compared[i].F[k], 1e-9 * 650.0) << k;
      EXPECT_NEAR(t.F[k], (1.0 + c.scale) * expect[k], 1e-9 * 650.0) << k;
    }
  }
}

// Before and after compare like with like (issue 37): the runs after are compared times
// 1 + their fitted scale, so chi^2 before is the baseline's within the calibration bound. The
// measured runs are the baseline 1.03 times (a calibration 3% off, nothing else): raw, a large
// chi^2 and G_all about 0.04; within the bound, none. A confirmation forced on the omnibus route
// (the candidate at its fit, magnitude 0 and scale 0.03) whose runs are the baseline, the
// prediction exact, removes nothing beyond the scale: not confirmed (against the raw chi^2, as
// before, it was: "chi^2 X -> 0").
TEST(GapConfirm, AGapACalibrationExplainsConfirmsNothing)
{
  RunsBySpeed real;
  real[100] = {times(stepped_run("m1", 0.2), 1.03), times(stepped_run("m2", 0.2), 1.03)};
  SimulatedRuns sims;
  sims.base[100] = {stepped_run("b1", 0.2), stepped_run("b2", 0.2)};
  sims.fresh[100] = {stepped_run("f1", 0.2), stepped_run("f2", 0.2), stepped_run("f3", 0.2)};
  Effect ea;
  ea.name = "a", ea.unit = "u", ea.knots = {1.0}, ea.pour_level = true, ea.one_sided = true;
  sims.knots[effect_sweep_name(ea, 1.0)][100] = {stepped_run("k1", 0.2, 200.0), stepped_run("k2", 0.2, 200.0)};
  const Alignment al = align_and_bin(real, sims, 2.0);
  const Features f = build_features(real, sims, {&ea}, al.grid, 2);
  WhereResult where;
  where.omnibus = gap_significance(f, al.grid);
  where.before = gap_curves(f, al.grid);
  where.heldout.gap = where.before.gap, where.heldout.v0 = 100;
  // the raw gap: chi^2 far beyond its features' noise, G_all of the 3% (G and G_spec each
  // 0.03 / 1.03: identical runs, no noise to subtract)
  const double P = (double) where.omnibus.nfeatures;
  EXPECT_GT(where.omnibus.chi2_0, P + 10.0 * std::sqrt(2.0 * P));
  EXPECT_NEAR(where.before.gap, std::sqrt(2.0) * 0.03 / 1.03, 2e-3);
  // within the bound: the scale found (within rounding) and nothing left
  EXPECT_NEAR(where.omnibus.scale_within_bound, 0.03, 1e-9);
  EXPECT_NEAR(where.before.scale_within_bound, 0.03, 1e-9);
  EXPECT_LT(where.omnibus.chi2_within_bound, 1e-6 * where.omnibus.chi2_0);
  EXPECT_LT(where.before.gap_within_bound, 1e-4);
  const FittedCandidates fitted = fit_candidates({&ea}, f, [](const std::string &) { return NAN; }, where.omnibus);
  VerdictDecision v;
  v.verdict = Verdict::explained, v.top_effect = "a", v.targeted = false, v.significant = true;
  TempDir dir("calibration_only");
  const std::vector<TraceRun> fresh = {on_file(stepped_run("c1", 0.2), dir / "c1.csv"),
                                       on_file(stepped_run("c2", 0.2), dir / "c2.csv")};
  const ConfirmStep step =
      confirm_with({{"a", &ea}}, fitted, v, where, f, al, [&](double) { return RunsBySpeed{{100.0, fresh}}; });
  ASSERT_FALSE(step.need.has_value());
  const Confirmation &c = step.done;
  EXPECT_NEAR(c.scale, 0.03, 1e-6);
  EXPECT_LT(c.outcome.chi2_after, 1e-3);    // the runs times 1.03 are the measurement
  EXPECT_NEAR(c.outcome.chi2_before, where.omnibus.chi2_within_bound, 1e-12);
  EXPECT_FALSE(c.outcome.confirmed);
  EXPECT_LE(c.confirmed_fraction, 0.0);
}

// ---- how blind: detection limits, look-alikes, the next measurement, false alarms

#include "gap_limits.h"
#include "gap_verdict.h"

namespace {

// The expected likelihood ratio of effect a at magnitude m in HandMade, by hand, the
// measured variances times factor[s]: at 0 < m <= 1 the interpolation weights are 1 - m
// (knot 0) and m (the knot at 1), so u = 10 m on features 0-2 and 0 on 3-5, with the
// variance m^2 (knot's + signature baseline's) the knots' noise puts in it; weights W =
// measured variance x factor + the reference's. Less the baseline's nuisance scale: u - c R,
// R = 100 on every feature, c the weighted least squares of u on R within +-3%.
double hand_strength(const HandMade &h, double m, const std::vector<double> &factor)
{
  double uR = 0, RR = 0;
  const auto W = [&](std::size_t s, std::size_t k) { return h.f.target.err[s][k] * factor[s] + h.f.fresh_err[s][k]; };
  for (std::size_t s = 0; s < 2; ++s)
    for (std::size_t k = 0; k < 6; ++k) uR += (k < 3 ? 10 * m : 0.0) * 100.0 / W(s, k), RR += 1e4 / W(s, k);
  const double c = std::clamp(uR / RR, -GapThresholds::calibration_scale_bound, GapThresholds::calibration_scale_bound);
  double lam = 0;
  for (std::size_t s = 0; s < 2; ++s)
    for (std::size_t k = 0; k < 6; ++k) {
      const double knot = 1e-4 * std::pow(k < 3 ? 110.0 : 100.0, 2) / 2, sig_base = 1e-4 * 100 * 100 / 2;
      const double u = k < 3 ? 10 * m : 0.0, var = m * m * (knot + sig_base);
      lam += (std::pow(u - 100.0 * c, 2) - var) / W(s, k);
    }
  return std::max(0.0, lam);
}

// every measured variance times x (a noisier measurement, the same means)
void noisier(HandMade &h, double x)
{
  for (auto &row : h.f.target.err)
    for (auto &e : row) e *= x;
}

}    // namespace

TEST(GapLimits, TheLimitAndTheRunsNeededOnAHandMadeSignature)
{
  // 30 x the measured variance: lambda(1) above the threshold (by
  // hand_strength), so the limit lies inside the knot, where lambda reaches the threshold
  HandMade h(0.5);
  noisier(h, 30);
  const std::vector<double> now(2, 1.0);
  const EffectData ed = effect_data(h.ea, h.f);
  const EffectFit fit = fit_candidate(ed, h.f);
  for (double m : {0.2, 0.7, 1.0})
    EXPECT_NEAR(signature_strength(ed, h.f.target, m, now), hand_strength(h, m, now), 1e-9 * hand_strength(h, 1, now)) << m;
  ASSERT_GT(hand_strength(h, 1.0, now), fit.lr_threshold);
  const DetectionLimit L = detection_limit(h.ea, ed, fit, h.f);
  EXPECT_EQ(L.effect, "a");
  EXPECT_EQ(L.reference, 1.0);
  ASSERT_TRUE(L.limit.has_value());
  // the bisection's tolerance: 40 halvings of a 1/200 step (4.5e-15), and lambda rises
  // monotonically there: the hand's lambda crosses the threshold within it
  EXPECT_GE(hand_strength(h, *L.limit, now), fit.lr_threshold * (1 - 1e-9));
  EXPECT_LT(hand_strength(h, *L.limit - 1e-9, now), fit.lr_threshold);
  EXPECT_FALSE(L.limit_other_side.has_value());    // one-sided
  // runs needed: the fewest n per speed with lambda(1; measured variance x 2 / n) >= T
  auto runs_for_reference = [&](const HandMade &hh, double T) {
    int n = 1;
    while (hand_strength(hh, 1.0, std::vector<double>(2, 2.0 / n)) < T) ++n;
    return n;
  };
  ASSERT_TRUE(L.runs_needed.has_value());
  EXPECT_EQ(*L.runs_needed, runs_for_reference(h, fit.lr_threshold));
  // twice noisier: the knot itself is no longer detected (no limit), and more runs are needed
  noisier(h, 2);
  const EffectData ed2 = effect_data(h.ea, h.f);
  const EffectFit fit2 = fit_candidate(ed2, h.f);
  ASSERT_LT(hand_strength(h, 1.0, now), fit2.lr_threshold);
  const DetectionLimit L2 = detection_limit(h.ea, ed2, fit2, h.f);
  EXPECT_FALSE(L2.limit.has_value());
  ASSERT_TRUE(L2.runs_needed.has_value());
  EXPECT_EQ(*L2.runs_needed, runs_for_reference(h, fit2.lr_threshold));
  EXPECT_GT(*L2.runs_needed, 2);
}

TEST(GapLimits, LookAlikesAreATieWithTheRunsThatCannotSeparateThem)
{
  // a and c have the same signature's shape (c twice as strong), b an orthogonal one: a and c
  // both explain the gap with the same evidence, so the answer is a tie naming both
  HandMade h(0.5);
  Significance omnibus;
  omnibus.significant = true;
  omnibus.nfeatures = 12;
  const FittedCandidates fitted = fit_candidates({&h.ea, &h.eb, &h.ec}, h.f, [](const std::string &) { return NAN; }, omnibus);
  const auto &data = fitted.data;
  const FitEvidence &d = fitted.evidence;
  const VerdictDecision v = decide_verdict(d);
  EXPECT_EQ(v.verdict, Verdict::tie);
  EXPECT_TRUE(v.top_effect.empty());
  ASSERT_EQ(v.tie.size(), 2u);
  EXPECT_EQ(std::set<std::string>(v.tie.begin(), v.tie.end()), (std::set<std::string>{"a", "c"}));
  const std::map<std::string, const Effect *> by_name{{"a", &h.ea}, {"b", &h.eb}, {"c", &h.ec}};
  const auto pairs = look_alikes(d.ranking, data, by_name, h.f);
  ASSERT_EQ(pairs.size(), 3u);
  for (const auto &p : pairs) {
    const std::set<std::string> ab{p.a, p.b};
    if (ab == std::set<std::string>{"a", "c"}) {
      // parallel signatures, the same fitted prediction (+5 on features 0-2)
      EXPECT_NEAR(p.angle_deg, 0.0, 1e-5);
      EXPECT_NEAR(p.separation, 0.0, 1e-3);
      EXPECT_TRUE(p.look_alike);
      EXPECT_NEAR(p.fit_separation, 0.0, 1e-6);
    } else {
      // b is orthogonal to both: each stands off the other's multiples and the fits' scale of
      // the reference (100 everywhere, within 3%), the shorter counts. With a: a's, +10 on
      // features 0-2 at 2 speeds, the scale takes 3 of it (b's multiple -0.3 takes the scale's
      // 3 on features 3-5 back out): 6 x 7^2 / W, weights 1e-4 x 105^2 / 2 + 0.5 (the measured
      // mean's and the reference's variances). With c (+20 there): b's own, +10 on features
      // 3-5, the same 6 x 7^2 over weights 0.5 + 0.5 (c's, 17^2, is longer)
      EXPECT_NEAR(p.angle_deg, 90.0, 1e-9);
      const double W = ab.count("a") ? 1e-4 * 105 * 105 / 2 + 0.5 : 1.0;
      EXPECT_NEAR(p.separation, std::sqrt(6 * 49.0 / W), 1e-9);
      EXPECT_FALSE(p.look_alike);
      // their fits: a's (or c's) prediction 105 on features 0-2 and 100 on 3-5 (no scale);
      // b's at magnitude 0 (one-sided) with the nuisance scale s of the target on the
      // reference, 100 (1 + s) everywhere: 6 ((5 - 100 s)^2 / W1 + (100 s)^2 / 1.0) at most
      // (the knots' noise subtracted: a quarter of a knot's and the signature baseline's
      // variances per feature at a's 0.5, (0.605 + 0.5) / 4 / W, at most 3.4 over the 12)
      const double W1 = 1e-4 * 105 * 105 / 2 + 0.5, s = (3 * 500.0 / W1) / (3 * 1e4 / W1 + 3 * 1e4);
      const double hand = 6 * (std::pow(5 - 100 * s, 2) / W1 + std::pow(100 * s, 2));
      EXPECT_LE(p.fit_separation * p.fit_separation, hand + 1e-9);
      EXPECT_GT(p.fit_separation * p.fit_separation, hand - 3.4);
    }
  }
  // what would separate them: nothing the measurement can do (they predict the same)
  const auto next = next_measurement(d.ranking, data, h.f, v.verdict);
  ASSERT_TRUE(next.has_value());
  EXPECT_EQ(next->goal, "separate");
  EXPECT_EQ(std::set<std::string>(next->effects.begin(), next->effects.end()), (std::set<std::string>{"a", "c"}));
  EXPECT_FALSE(next->reaches);
  EXPECT_NEAR(next->gain(), 0.0, 1e-9);
}

TEST(GapLimits, TheNextMeasurementDetectsTheUndetectedCandidate)
{
  // 100 x the measured variance: the gap (a at 0.5) is not detected; more runs at one speed
  // shrink that speed's measured variance by n / (n + r), and the fewest r that bring a's
  // expected likelihood ratio to its threshold is the answer (both speeds are alike here: the
  // first is named), at the magnitude whose expected ratio is the measured one: lambda is
  // k m^2 while the nuisance scale is inside its bound (it grows with m), so sqrt(lr / k)
  HandMade h(0.5);
  noisier(h, 100);
  Significance omnibus;
  omnibus.nfeatures = 12;
  const FittedCandidates fitted = fit_candidates({&h.ea, &h.eb}, h.f, [](const std::string &) { return NAN; }, omnibus);
  const auto &data = fitted.data;
  const FitEvidence &d = fitted.evidence;
  const VerdictDecision v = decide_verdict(d);
  EXPECT_EQ(v.verdict, Verdict::none);
  const EffectFit &a = d.ranking[0].name == "a" ? d.ranking[0] : d.ranking[1];
  ASSERT_FALSE(a.detected);
  EXPECT_NEAR(a.magnitude, 0.5, 1e-3);
  const auto next = next_measurement(d.ranking, data, h.f, v.verdict);
  ASSERT_TRUE(next.has_value());
  EXPECT_EQ(next->goal, "detect");
  EXPECT_EQ(next->effects, (std::vector<std::string>{"a"}));
  EXPECT_EQ(next->v0, 50.0);
  // (the nuisance scale, gap_fit.h, takes half of the squared gap at magnitude 0: +5 on three
  // of six features of 100 is to a uniform scale 2.5% (inside the 3% bound) plus +-2.5; the
  // expected ratio takes the same half, so the magnitude is the fit's, 0.5, a little above
  // as the measured ratio has no knot noise taken off)
  const double k = hand_strength(h, 0.5, {1.0, 1.0}) / 0.25;
  const double m = std::sqrt(a.lr / k);
  EXPECT_NEAR(m, 0.5, 0.01);
  int r = 1;
  while (hand_strength(h, m, {2.0 / (2.0 + r), 1.0}) < a.lr_threshold) ++r;
  ASSERT_LE(r, MAX_RUNS_PER_SPEED);
  EXPECT_TRUE(next->reaches);
  EXPECT_EQ(next->runs, r);
  // the bisection's tolerance on m, squared into lambda
  EXPECT_NEAR(next->now, a.lr, 1e-6 * next->target);
  // an explained verdict asks for nothing more
  EXPECT_FALSE(next_measurement(d.ranking, data, h.f, Verdict::explained).has_value());
  EXPECT_GE(next->after, next->target);
  EXPECT_GT(next->gain(), 0.0);
}

TEST(GapWhich, FalseAlarmsOnTheNullReplicates)
{
  // the two null replicates are noise the size of one standard error: both `none`
  HandMade h(0.5);
  const EffectData ea = effect_data(h.ea, h.f), eb = effect_data(h.eb, h.f);
  const std::map<std::string, EffectData> data{{"a", ea}, {"b", eb}};
  const std::vector<EffectFit> fits{fit_candidate(ea, h.f), fit_candidate(eb, h.f)};
  const FalseAlarms fa = null_false_alarms({&h.ea, &h.eb}, data, fits, h.f);
  EXPECT_EQ(fa.replicates, 2);
  EXPECT_EQ(fa.not_none, 0);
  EXPECT_EQ(fa.verdicts.at("none"), 2);
  // one replicate that is the measurement itself (effect a at 0.5): that one is a false alarm,
  // found with a threshold calibrated on the other replicate alone
  HandMade g(0.5);
  g.f.nulls[0] = g.f.target;
  const EffectData ga = effect_data(g.ea, g.f), gb = effect_data(g.eb, g.f);
  const FalseAlarms fg = null_false_alarms({&g.ea, &g.eb}, {{"a", ga}, {"b", gb}},
                                           {fit_candidate(ga, g.f), fit_candidate(gb, g.f)}, g.f);
  EXPECT_EQ(fg.not_none, 1);
  EXPECT_EQ(fg.verdicts.at("explained"), 1);
  EXPECT_DOUBLE_EQ(fg.rate(), 0.5);
}

// ---- the residual (gap_residual.h)

#include "gap_residual.h"

#include <random>

namespace {

// runs of a constant mean with AR(1) noise (15%, c 0.6), 10 kHz, z from -0.5 to 4.2 cm, plus
// a sine of amplitude A at frequency line(v0) (none when A = 0)
std::vector<TraceRun> noisy_runs(double v0, unsigned seed0, int n, double A, double (*line)(double))
{
  std::vector<TraceRun> runs;
  for (int r = 0; r < n; ++r) {
    std::mt19937 rng(seed0 + r);
    std::normal_distribution<double> n01;
    TraceRun run;
    run.v0 = v0;
    double x = 0;
    for (int i = 0;; ++i) {
      const double t = i * 1e-4, z = std::round(v0 * t * 1e6) / 1e6 - 0.5;
      if (z > 4.2) break;
      x = 0.6 * x + 0.8 * n01(rng);
      run.t.push_back(t), run.z.push_back(z);
      run.F.push_back(z > 0 ? 1e5 * (1 + 0.15 * x) + (A > 0 ? A * std::sin(2 * M_PI * line(v0) * t) : 0.0) : 0.0);
    }
    runs.push_back(run);
  }
  return runs;
}

std::vector<const TraceRun *> ptrs(const std::vector<TraceRun> &runs)
{
  std::vector<const TraceRun *> p;
  for (const auto &r : runs) p.push_back(&r);
  return p;
}

double wavelength_line(double v0) { return v0 / 0.2; }    // a 0.2 cm wavelength
double fixed_line(double) { return 700.0; }                // a resonance

}    // namespace

TEST(GapResidual, ANarrowLineItsFrequencyAndWhetherItScalesWithV0)
{
  // 8 runs a side: the log ratio's standard deviation is sqrt(2 trigamma(8)) = 0.52; a sine of
  // 2e4 dyne (2e8 dyne^2 in one or two bins) on noise of 1.5e4 RMS spread over 80 to 320 bins
  // stands 6 to 10 of them above its neighbours (half that amplitude: 5 to 7, too near the
  // threshold of 5 for a test)
  const GapGrid grid;
  for (auto line : {wavelength_line, fixed_line}) {
    std::vector<SpectralLine> lines;
    for (double v0 : {50.0, 100.0, 200.0}) {
      const auto model = noisy_runs(v0, 100, 8, 0, line), real = noisy_runs(v0, 200, 8, 2e4, line);
      SpectralLine l;
      l.v0 = v0;
      std::vector<double> freq, ratio;
      ASSERT_TRUE(find_line(ptrs(real), ptrs(model), grid, l, freq, ratio)) << v0;
      // within a frequency bin: 1 / (the span's duration, 4 cm / v0)
      EXPECT_NEAR(l.freq, line(v0), v0 / 4.0) << v0;
      EXPECT_GT(l.sigma, 5.0);
      EXPECT_EQ(freq.size(), ratio.size());
      lines.push_back(l);
      // no line without the sine: the same noise on both sides
      const auto plain = noisy_runs(v0, 300, 8, 0, line);
      EXPECT_FALSE(find_line(ptrs(plain), ptrs(model), grid, l, freq, ratio)) << v0;
    }
    EXPECT_EQ(line_scaling(lines), line == wavelength_line ? "scales with v0" : "fixed");
  }
  EXPECT_EQ(line_scaling({}), "");
}

TEST(GapResidual, WhereItLiesWhatItMovesAndTheNearestCandidate)
{
  // a grid of 8 bins (0 < z <= 2), 2 fluctuation windows, 4 bands: 14 features; two speeds;
  // both sides' variances 1 (the difference's 2); the measured bin means 10 above the model's
  // at bins 2 and 3 (0.5 < z <= 1.0) at the first speed
  GapGrid grid;
  grid.zmax = 2.0;
  ASSERT_EQ(grid.nfeatures(), 14u);
  ResidualSide R, M;
  for (int s = 0; s < 2; ++s) {
    M.mean.push_back(std::vector<double>(14, 100.0)), M.err.push_back(std::vector<double>(14, 1.0));
    R.mean.push_back(M.mean.back()), R.err.push_back(M.err.back());
  }
  R.mean[0][2] += 10, R.mean[0][3] += 10;
  ResidualContext ctx;
  ctx.speeds = {50, 100};
  ctx.z_transient_end = {1.5, 1.5};
  ctx.peak_end = 0.7;    // bin 2 (centre 0.625) is in the peak regime, bin 3 (0.875) in the transient
  ctx.verdict = Verdict::unexplained;
  EffectFit near, far;
  near.name = "near", near.explained = 0.3, near.heldout_explained = 0.4, near.detected = true, near.lr = 40, near.lr_threshold = 15.1;
  far.name = "far", far.explained = 0.1, far.heldout_explained = 0.1, far.lr = 3, far.lr_threshold = 15.1;
  ctx.ranking = {near, far};
  // why a candidate was not the answer is the verdict's record of it
  ctx.records = decide_verdict(fit_evidence(false, ctx.ranking)).candidates;
  Residual r = describe_residual(R, M, grid, ctx);
  EXPECT_EQ(r.regimes, (std::vector<std::string>{"peak", "transient"}));
  EXPECT_DOUBLE_EQ(r.z_from, 0.5);
  EXPECT_DOUBLE_EQ(r.z_to, 1.0);
  // chi^2 = 2 x 10^2 / 2 over 16 bin means; nothing in the 12 fluctuation features
  EXPECT_DOUBLE_EQ(r.chi2_means, 100.0);
  EXPECT_EQ(r.dof_means, 16);
  EXPECT_EQ(r.dof_fluct, 12);
  EXPECT_EQ(r.moves, "bin means");
  EXPECT_TRUE(r.band.empty());
  ASSERT_EQ(r.curves.size(), 2u);
  EXPECT_EQ(r.curves[0].resid[2], 10.0);
  EXPECT_NEAR(r.curves[0].band[2], 2 * std::sqrt(2.0), 1e-12);
  EXPECT_EQ(r.nearest, "near");
  EXPECT_EQ(r.why_rejected, "it explains 0.30 of the gap (0.5 needed)");
  // the spectrum too: band 450-1350 Hz (feature 8 + 2 + 2 = 12) 20% up at both speeds
  R.mean[0][12] = R.mean[1][12] = 120;
  r = describe_residual(R, M, grid, ctx);
  EXPECT_EQ(r.moves, "both");
  EXPECT_EQ(r.band, "450-1350 Hz");
  EXPECT_DOUBLE_EQ(r.band_ratio, 1.2);
  // only the spectrum, and within the noise: neither
  R.mean[0][2] = R.mean[0][3] = 100;
  EXPECT_EQ(describe_residual(R, M, grid, ctx).moves, "spectrum");
  R.mean[0][12] = R.mean[1][12] = 101;
  EXPECT_EQ(describe_residual(R, M, grid, ctx).moves, "neither");
  EXPECT_TRUE(r.lines.empty());    // no runs: no periodogram
}

// ---- the sweep layer's side: what a sweep folder holds, the cluster script

TEST(SweepCache, FinishedTracesAndBedsOfASweep)
{
  TempDir root("cache");
  EXPECT_TRUE(finished_traces(root.path.string(), "absent").empty());
  fs::create_directories(root.path / "s" / "traces");
  fs::create_directories(root.path / "s" / "beds");
  for (const char *f : {"b.csv", "a.csv", "c.csv"}) write_file(root / (std::string("s/traces/") + f), "");
  write_file(root / "s/traces/b.csv.done", "");
  write_file(root / "s/traces/a.csv.done", "");
  write_file(root / "s/beds/bed_2.info", "");
  write_file(root / "s/beds/bed_1.info", "");
  write_file(root / "s/beds/bed_1.restart", "");
  // c.csv is unfinished (no marker); sorted
  EXPECT_EQ(finished_traces(root.path.string(), "s"), (std::vector<std::string>{root / "s/traces/a.csv", root / "s/traces/b.csv"}));
  EXPECT_EQ(bed_info_files(root.path.string(), "s"), (std::vector<std::string>{root / "s/beds/bed_1.info", root / "s/beds/bed_2.info"}));
  EXPECT_EQ(sweep_of_trace(finished_traces(root.path.string(), "s")[0]), "s");
}

TEST(SlurmScript, JobArraysChainedByAfterok)
{
  TempDir dir("slurm");
  const std::string file = dir / "submit.sh";
  // an empty middle stage is left out: the third array depends on the first
  write_slurm_arrays({"granpen gap: the tiny cache."},
                     {{"p", "pours", 0, 3, "cli --only"}, {"x", "none", 0, -1, "cli --only"}, {"q", "pushes", 4, 9, "cli --only"}},
                     2, file);
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(),
            "#!/bin/bash\n# granpen gap: the tiny cache.\nset -euo pipefail\n"
            "SBATCH_OPTS=${SBATCH_OPTS:-}   # e.g. --partition=... --time=...\n"
            "pours=$(sbatch --parsable $SBATCH_OPTS --job-name=p --ntasks=2 --array=0-3 --wrap=\"cli --only \\$SLURM_ARRAY_TASK_ID\")\n"
            "echo \"p: job $pours (tasks 0-3)\"\n"
            "pushes=$(sbatch --parsable $SBATCH_OPTS --job-name=q --ntasks=2 --dependency=afterok:$pours --array=4-9 "
            "--wrap=\"cli --only \\$SLURM_ARRAY_TASK_ID\")\n"
            "echo \"q: job $pushes (tasks 4-9)\"\n");
  // a double quote would end --wrap early: refused, nothing written
  EXPECT_THROW(write_slurm_arrays({}, {{"p", "pours", 0, 1, "cli \"x\""}}, 1, dir / "bad.sh"), InputError);
  EXPECT_FALSE(fs::exists(dir / "bad.sh"));
  EXPECT_FALSE(this_executable("fallback").empty());
}

// ---- report: the output moved into place whole, or not at all

#include "gap_report.h"

TEST(GapReport, OutputReplacesAnOlderOneOnlyWhenComplete)
{
  TempDir dir("report");
  const std::string out = dir / "out";
  fs::create_directories(out);
  write_file(out + "/keep", "before");
  Diagnosis d;
  d.scenario = "hand";
  d.real_dir = dir / "real";
  // a simulated trace that has gone: the copy fails, OUT stays as it was, no partial left
  d.baseline_files = {dir / "cache/baseline/traces/gone.csv"};
  try {
    write_gap_output(d, out);
    ADD_FAILURE() << "no error";
  } catch (const InputError &e) {
    EXPECT_NE(std::string(e.what()).find("out.partial: cannot write the output"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::exists(out + "/keep"));
  EXPECT_FALSE(fs::exists(out + ".partial"));
  // the trace there: the new OUT replaces the old whole, the trace named after its sweep
  fs::create_directories(dir.path / "cache/baseline/traces");
  write_file(dir / "cache/baseline/traces/gone.csv", "x");
  write_gap_output(d, out);
  EXPECT_FALSE(fs::exists(out + "/keep"));
  EXPECT_TRUE(fs::exists(out + "/diagnosis.json"));
  EXPECT_TRUE(fs::exists(out + "/report.md"));
  EXPECT_TRUE(fs::exists(out + "/baseline/baseline_gone.csv"));
  EXPECT_TRUE(fs::exists(out + "/corrected/baseline_gone.csv"));    // nothing added: the baseline's
  EXPECT_FALSE(fs::exists(out + ".partial"));
  EXPECT_FALSE(fs::exists(out + ".old"));
}

// ---- the stages in order: a whole diagnosis in the synthetic world (tests/support/fake_lmp)

#if defined(GRANPEN_FAKE_LMP) && defined(GRANPEN_INPUTS_DIR)
#include "gap_diagnosis.h"
#include "sweep_runner.h"

TEST(GapDiagnosis, StagesReportProgressInOrderThroughTheCallback)
{
  TempDir dir("whole");
  RunnerOptions runner;
  runner.lmp = GRANPEN_FAKE_LMP;
  runner.inputs = GRANPEN_INPUTS_DIR;
  runner.jobs = 1;
  runner.progress_seconds = 1e9;
  // the "measurement": the tiny scenario with rolling resistance 0.2, on beds no diagnosis uses
  SweepSpec truth;
  truth.name = "truth";
  truth.path = "(test)";
  truth.presets = {"tiny"};
  truth.seeds = {"101", "102"};
  truth.v0 = {"50", "100"};
  truth.set = {{"mu_roll", "0.2"}};
  runner.out_root = dir / "measured";
  ASSERT_EQ(run_sweep(truth, runner), 0);

  GapOptions opt;
  opt.real = dir / "measured/truth/traces";
  opt.scenario = "tiny";
  opt.out = dir / "out";
  opt.cache = dir / "cache";
  opt.effects = std::string("rolling_resistance");
  opt.fit_only = true;    // the confirming runs are confirm's own test
  opt.runner = runner;
  std::vector<GapProgress> seen;
  ASSERT_EQ(run_gap(opt, [&](const GapProgress &p) { seen.push_back(p); }), 0);
  std::vector<std::string> steps, details;
  for (const auto &p : seen) {
    if (p.kind == GapProgress::STEP) steps.push_back(std::to_string(p.done) + "/" + std::to_string(p.total) + " " + p.stage);
    if (p.kind == GapProgress::DETAIL) details.push_back(p.stage + " " + std::to_string(p.done) + "/" + std::to_string(p.total));
  }
  EXPECT_EQ(steps, (std::vector<std::string>{"1/4 simulate", "2/4 align", "3/4 which", "4/4 confirm"}));
  EXPECT_EQ(details, (std::vector<std::string>{"which 1/1"}));
  ASSERT_FALSE(seen.empty());
  EXPECT_EQ(seen.front().stage, "validate");
  EXPECT_NE(seen.front().message.find("4 measured runs at 2 speeds (50 100 cm/s) against scenario tiny"), std::string::npos)
      << seen.front().message;
  EXPECT_EQ(seen.back().stage, "report");
  // the last report is the verdict line; which verdict is not this test's (stages and their
  // order are): since fake_lmp gives every pour its own bed field (the faithful world), two
  // measured beds against two-bed knots leave rolling resistance explaining 0.45 of the gap
  // (3 degrees of freedom in the noise model), an honest `unexplained`, not the earlier explained
  EXPECT_EQ(seen.back().message.rfind("verdict ", 0), 0u) << seen.back().message;
  EXPECT_TRUE(fs::exists(dir.path / "out" / "diagnosis.json"));
  EXPECT_FALSE(fs::exists(dir.path / "out.partial"));

  // refused input: nothing reported, nothing started, OUT as it was
  std::vector<GapProgress> none;
  opt.effects = std::string("");
  opt.out = dir / "out2";
  opt.cache = dir / "cache2";
  EXPECT_THROW(run_gap(opt, [&](const GapProgress &p) { none.push_back(p); }), GapRefused);
  EXPECT_TRUE(none.empty());
  EXPECT_FALSE(fs::exists(dir.path / "out2"));
  EXPECT_FALSE(fs::exists(dir.path / "cache2"));
}
#endif

// ---- report: diagnosis.json's keys and values, as the hand-built writer wrote them

#include <nlohmann/json.hpp>

namespace {

// A diagnosis with every field the report writes set to a value of its own (two speeds,
// three candidates, a refinement), so that a key written from the wrong field shows.
Diagnosis filled_diagnosis(const std::string &real_dir)
{
  Diagnosis d;
  d.scenario = "hand";
  d.real_dir = real_dir;
  d.grid.zmax = 0.75;
  d.peak_end = 0.7;
  d.notes = {"first note", "a note with \"quotes\" and a tab\t"};
  d.chi2_0 = 93.61, d.p_value = 2.5e-7, d.chi2_after = 54.8, d.confirmed_fraction = 0.71234;
  d.nfeatures = 24, d.significant = true, d.targeted = false, d.n_null = 6, d.n_reference = 4;
  d.proj_before = 5.7612, d.proj_after = -1.234567;
  d.refined = true, d.refined_from = -0.078, d.gap_after_first = 0.1401, d.proj_refined = 0.05;
  Finding w;
  w.regime = "peak", w.observable = "peak_F", w.v0 = 50, w.real = 1234.5, w.sim = 1100.25, w.real_se = 20.5,
  w.sim_se = 15.125, w.zscore = 5.2345, w.significant = true;
  d.where.push_back(w);
  w.regime = "linear", w.observable = "k_z", w.v0 = 100, w.real = 3.1e5, w.sim = 3.0e5, w.zscore = 0.8, w.significant = false;
  d.where.push_back(w);
  for (int i = 0; i < 3; ++i) {
    EffectFit r;
    r.name = i == 0 ? "packing" : i == 1 ? "rolling_resistance" : "sidewalls";
    r.magnitude = -0.15 + 0.1 * i, r.chi2_0 = 93.61, r.chi2 = 40.0 + 10 * i, r.explained = 0.9 - 0.3 * i;
    r.heldout_explained = 0.8 - 0.2 * i, r.score = 0.8 - 0.3 * i, r.at_edge = i == 2, r.lr = 50.5 - 20 * i;
    r.lr_null_mean = 1.2 + i, r.lr_threshold = 18.2 + 15 * i, r.detected = i < 2;
    d.ranking.push_back(r);
  }
  d.magnitude_note["packing"] = "pour friction 0.150: phi_0 0.5812 against the baseline's 0.5801";
  d.verdict = Verdict::explained, d.top_effect = "packing", d.tested_effect = "packing";
  d.magnitude = -0.150123, d.magnitude_unit = "pour friction minus 0.3";
  for (double v : {50.0, 100.0}) {
    SpeedCurves c;
    c.v0 = v, c.n_real = 4, c.n_base = 4, c.n_corr = 4;
    c.z = {0.125, 0.375, 0.625};
    c.real = {100 + v, 200 + v, 300 + v}, c.real_se = {5, 6, 7};
    c.base = {90 + v, 210 + v, 280 + v}, c.base_se = {4, 5, 6};
    c.corr = {99 + v, 201 + v, 301 + v}, c.corr_se = {4, 5, 6};
    c.gap = {10, -10, 20}, c.band = {12.8, 15.6, 18.4};
    c.G_before = 0.1 + v / 1000, c.G_after = 0.02 + v / 10000, c.z_transient_end = 0.75;
    d.speeds.push_back(c);
  }
  d.gap_before = 0.151234, d.gap_after = 0.030456;
  d.gap_by_regime["peak"] = {0.2, 0.05};
  d.gap_by_regime["linear"] = {0.1, 0.01};
  d.heldout_v0 = 100, d.heldout_before = 0.193, d.heldout_after = 0.156, d.heldout_magnitude = -0.064;
  d.n_real_min = 4, d.n_sim = 4;
  return d;
}

nlohmann::json read_json_file(const std::string &path)
{
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

}    // namespace

// Every key and value the hand-built writer wrote (tests/analysis/gap/data/gap_report_before_nlohmann.json:
// its output for filled_diagnosis, kept from before the move to nlohmann) is written again,
// numbers to the printed precision; what the new writer adds is listed, nothing else.
void expect_same_json(const nlohmann::json &before, const nlohmann::json &now, const std::string &at)
{
  if (before.is_number() && now.is_number()) {
    // the old text rounded each number to its printf format; the new rounds it the same
    // way, so the two read back equal up to the last printed digit's rounding
    EXPECT_NEAR(before.get<double>(), now.get<double>(), 1e-12 * std::abs(before.get<double>()) + 1e-300) << at;
    return;
  }
  ASSERT_EQ(before.type(), now.type()) << at;
  if (before.is_object()) {
    for (auto it = before.begin(); it != before.end(); ++it) {
      ASSERT_TRUE(now.contains(it.key())) << at << "." << it.key() << " is gone";
      expect_same_json(it.value(), now[it.key()], at + "." + it.key());
    }
  } else if (before.is_array()) {
    ASSERT_EQ(before.size(), now.size()) << at;
    for (std::size_t i = 0; i < before.size(); ++i) expect_same_json(before[i], now[i], at + "[" + std::to_string(i) + "]");
  } else {
    EXPECT_EQ(before, now) << at;
  }
}

TEST(GapReport, DiagnosisJsonKeysAndValuesAsTheHandBuiltWriterWroteThem)
{
  TempDir dir("report_json");
  write_gap_report(filled_diagnosis("real"), dir.path.string());
  const nlohmann::json now = read_json_file(dir / "diagnosis.json");
  nlohmann::json before = read_json_file(GRANPEN_GAP_REPORT_FIXTURE);
  // the one value changed since, on purpose: gap_before, gap_after and the held-out figures
  // are G_all now (filled_diagnosis sets them as numbers, so they compare equal)
  EXPECT_EQ(before["gap_metric"], "shared/formats/gap-metric.md v1");
  before["gap_metric"] = "shared/formats/gap-metric.md v2";
  expect_same_json(before, now, "diagnosis.json");
  // the top-level keys added since (issue 21; nlohmann::json orders them by name)
  std::vector<std::string> added;
  for (auto it = now.begin(); it != now.end(); ++it)
    if (!before.contains(it.key())) added.push_back(it.key());
  // (and issue 37's plan: the cost range, what was spent, what was simulated and skipped; its
  // pair verdict's two effects and the pair stage's record; the false-alarm rate measured at the
  // scenario's scale: gap_bench_rate.h)
  EXPECT_EQ(added, (std::vector<std::string>{"detection_limits", "false_alarms", "false_alarms_measured", "gap_parts",
                                             "knot_bends", "look_alikes", "next_measurement", "pair", "pairs", "plan",
                                             "residual", "scale_only", "thresholds", "tie"}));
  // written through the atomic writer: no temporary left beside it
  for (const auto &e : fs::directory_iterator(dir.path))
    EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos) << e.path();
}

namespace {

// every number of a JSON document, its strings' numbers included (a unit such as "pour
// friction minus 0.3" is text of diagnosis.json too)
void json_numbers(const nlohmann::json &j, std::vector<double> &out)
{
  if (j.is_number()) out.push_back(j.get<double>());
  else if (j.is_string()) {
    const std::string s = j.get<std::string>();
    static const std::regex num("[0-9]+(\\.[0-9]+)?");
    for (auto it = std::sregex_iterator(s.begin(), s.end(), num); it != std::sregex_iterator(); ++it) out.push_back(std::stod(it->str()));
  } else if (j.is_structured())    // (a primitive iterates over itself)
    for (const auto &e : j) json_numbers(e, out);
}

// every number of a part of report.md that is not one of diagnosis.json's to its printed
// precision (a percentage: 100 times one, either sign)
std::vector<std::string> stray_numbers_in(const std::string &screen, const std::string &dir)
{
  std::vector<double> nums;
  json_numbers(read_json_file(dir + "/diagnosis.json"), nums);
  std::vector<std::string> stray;
  static const std::regex tok("[-+]?[0-9]+(\\.([0-9]+))?(e([-+]?[0-9]+))?(%?)");
  for (auto it = std::sregex_iterator(screen.begin(), screen.end(), tok); it != std::sregex_iterator(); ++it) {
    const auto &m = *it;
    const std::size_t at = (std::size_t) m.position();
    if (at > 0 && (std::isalnum((unsigned char) screen[at - 1]) || screen[at - 1] == '_' || screen[at - 1] == '^')) continue;
    const double x = std::stod(m.str(0));
    const int decimals = m[2].matched ? (int) m[2].length() : 0, exponent = m[4].matched ? std::stoi(m[4].str()) : 0;
    // half a unit of the last printed digit
    const double tol = 0.5 * std::pow(10.0, exponent - decimals) * (1 + 1e-9);
    const bool percent = m[5].length() > 0;
    const bool found = std::any_of(nums.begin(), nums.end(), [&](double y) {
      return percent ? std::abs(std::abs(x) - std::abs(100 * y)) <= tol : std::abs(x - y) <= tol || std::abs(x + y) <= tol;
    });
    if (!found) stray.push_back(m.str(0));
  }
  return stray;
}

// The first screen of report.md ("## In short" and its list): its lines, and every
// number on it that is not one of diagnosis.json's to its printed precision (a percentage:
// 100 times one, either sign).
std::vector<std::string> stray_numbers(const std::string &dir, int &lines)
{
  std::ifstream in(dir + "/report.md");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto from = text.find("## In short");
  const auto to = text.find("\n\n", text.find("\n- ", from));    // the list's end
  const std::string screen = from == std::string::npos ? "" : text.substr(from, to - from);
  lines = (int) std::count(screen.begin(), screen.end(), '\n');
  return stray_numbers_in(screen, dir);
}

}    // namespace

// report.md's first screen (issue 37, section 4) fits a terminal and every number on it is
// one of diagnosis.json's, for an explained verdict, a none (with the detection limits of the
// effects commonest in labs and the next measurement) and a scale_only
TEST(GapReport, TheFirstScreenFitsATerminalAndQuotesOnlyTheDiagnosisNumbers)
{
  TempDir dir("report_first_screen");
  Diagnosis d = filled_diagnosis("real");
  d.ranking[0].magnitude_error = 0.0123;
  d.false_alarms.replicates = 6, d.false_alarms.not_none = 1;
  int lines = 0;
  write_gap_report(d, dir.path.string());
  EXPECT_EQ(stray_numbers(dir.path.string(), lines), std::vector<std::string>{});
  EXPECT_GT(lines, 3);
  EXPECT_LE(lines, 12);    // with its blank lines: a terminal's first screen is 24 lines
  // none: how blind, for the effects commonest in labs, and the next measurement
  d.verdict = Verdict::none, d.top_effect.clear(), d.tested_effect.clear();
  DetectionLimit L;
  L.effect = "friction", L.unit = "mu - 0.3", L.reference = 0.15, L.limit = 0.0812, L.threshold = 17.3;
  d.limits = {L};
  L.effect = "cohesion", L.limit = 1234.5;    // not common in labs: not on the first screen
  d.limits.push_back(L);
  NextMeasurement m;
  m.goal = "detect", m.effects = {"friction"}, m.v0 = 50, m.runs = 7, m.now = 6.25, m.after = 17.5, m.target = 17.3, m.reaches = true;
  d.next = m;
  TempDir none_dir("report_first_screen_none");
  write_gap_report(d, none_dir.path.string());
  EXPECT_EQ(stray_numbers(none_dir.path.string(), lines), std::vector<std::string>{});
  std::ifstream in(none_dir / "report.md");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string screen = text.substr(0, text.find("\nScenario"));
  EXPECT_NE(screen.find("friction 0.0812 (reference 0.15)"), std::string::npos) << screen;
  EXPECT_EQ(screen.find("cohesion"), std::string::npos) << screen;
  EXPECT_NE(screen.find("7 more measured run(s) at 50 cm/s"), std::string::npos) << screen;
  // a tie confirmed with one of its candidates: the runs are named as that one's and as not
  // separating the tie (they would shrink the gap alike with the others)
  d.verdict = Verdict::tie, d.tie = {"packing", "sidewalls", "force_scale"}, d.tested_effect = "packing";
  TempDir tie_dir("report_first_screen_tie");
  write_gap_report(d, tie_dir.path.string());
  EXPECT_EQ(stray_numbers(tie_dir.path.string(), lines), std::vector<std::string>{});
  std::ifstream in_tie(tie_dir / "report.md");
  const std::string text_tie((std::istreambuf_iterator<char>(in_tie)), std::istreambuf_iterator<char>());
  EXPECT_NE(text_tie.find("with packing on fresh seeds (one of the tie: these runs cannot tell it from sidewalls or force_scale)"),
            std::string::npos) << text_tie.substr(0, 1500);
  d.tie.clear(), d.tested_effect.clear();
  // scale_only: the force's scale in percent, and a weighed calibration next
  d.verdict = Verdict::scale_only, d.scale_effect = "packing", d.next.reset();
  ScaleFinding sf;
  sf.scale = 0.131, sf.scale_error = 0.011, sf.bound = 0.03;
  sf.causes = {{"calibration", "gain", 0.131, "relative", -1, "a weighed calibration", std::nullopt},
               {"density", "rho", 0.131, "relative", -1, "the grains weighed", std::nullopt}};
  d.scale_only = sf;
  TempDir scale_dir("report_first_screen_scale");
  write_gap_report(d, scale_dir.path.string());
  EXPECT_EQ(stray_numbers(scale_dir.path.string(), lines), std::vector<std::string>{});
  std::ifstream in2(scale_dir / "report.md");
  const std::string text2((std::istreambuf_iterator<char>(in2)), std::istreambuf_iterator<char>());
  EXPECT_NE(text2.find("The force is 13.1% high at every depth and speed"), std::string::npos);
  EXPECT_NE(text2.find("Next: a weighed calibration"), std::string::npos);
}

// report.md's Which table shows each candidate's chi^2 as simulated and within the calibration
// bound, each column headed by its baseline, and those baselines are the verdict's own numbers
// (Gap significance's raw chi^2, the confirmation's chi^2 before, within the bound): no number
// of the table contradicts a sentence of the verdict, and every one is diagnosis.json's
TEST(GapReport, TheWhichTableNamesItsChi2sFootingAndQuotesOnlyTheDiagnosisNumbers)
{
  TempDir dir("report_which");
  Diagnosis d = filled_diagnosis("real");
  d.chi2_within_bound = 71.32, d.scale_within_bound = 0.0213;
  for (std::size_t i = 0; i < d.ranking.size(); ++i) {
    auto &r = d.ranking[i];
    r.chi2_0_within_bound = d.chi2_within_bound, r.chi2_within_bound = 38.25 + 7 * (double) i, r.scale = 0.01 * (double) i;
  }
  write_gap_report(d, dir.path.string());
  std::ifstream in(dir / "report.md");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto from = text.find("\n## Which");
  ASSERT_NE(from, std::string::npos);
  const std::string which = text.substr(from, text.find("\n## ", from + 1) - from);
  EXPECT_NE(which.find("chi^2 as simulated (baseline 93.6)"), std::string::npos) << which;
  EXPECT_NE(which.find("chi^2 within the calibration bound (baseline 71.3)"), std::string::npos) << which;
  // the verdict's sentences quote the same two
  EXPECT_NE(text.find("chi^2 = 93.6 over"), std::string::npos);
  EXPECT_NE(text.find("chi^2 71.3 (against the baseline within the calibration bound)"), std::string::npos);
  // the top candidate's row: 40.0 as simulated, 38.2 within the bound (38.25 printed to %.1f)
  EXPECT_NE(which.find("| 40.0 | 38.2 |"), std::string::npos) << which;
  EXPECT_EQ(stray_numbers_in(which, dir.path.string()), std::vector<std::string>{});
  const nlohmann::json j = read_json_file(dir / "diagnosis.json");
  EXPECT_DOUBLE_EQ(j["ranking"][0]["chi2_within_bound"].get<double>(), 38.25);
  EXPECT_DOUBLE_EQ(j["ranking"][0]["chi2_baseline_within_bound"].get<double>(), 71.32);
  EXPECT_DOUBLE_EQ(j["significance"]["chi2_within_bound"].get<double>(), 71.32);
}

// The gap per regime splits the bins where the diagnosis says the peak regime ends
// (d.peak_end), as the residual's description does, not at a depth of its own: a gap in a
// bin beyond peak_end is the transient's.
TEST(GapReport, GapByRegimeEndsThePeakAtTheDiagnosisPeakEnd)
{
  Diagnosis d;
  GapGrid grid;
  grid.zmax = 2.0;    // 8 bins of 0.25: centres 0.125, 0.375, 0.625, ...
  d.peak_end = 0.5;   // bins 0 and 1 are the peak regime, bin 2 (0.625) the transient
  SpeedCurves c;
  c.v0 = 100;
  c.z_transient_end = 1.5;
  c.base.assign(grid.nbins(), 100.0);
  c.corr = c.base;
  c.real = c.base;
  c.real[2] += 10;    // the only gap: in the transient regime
  d.speeds = {c};
  // the where stage's function, given the diagnosis's peak_end (as gap_diagnosis.cpp calls
  // it); with D = 2 a peak end of its own, 0.35 D = 0.7, would put bin 2 in the peak
  auto by_regime = gap_by_regime(grid, d.peak_end, d.speeds);
  ASSERT_TRUE(by_regime.count("peak"));
  ASSERT_TRUE(by_regime.count("transient"));
  EXPECT_EQ(by_regime["peak"].first, 0.0);
  EXPECT_GT(by_regime["transient"].first, 0.0);
}

// The record (stage 12) is the stages' results put together once: until a confirmation has
// simulated, the "after" is the "before" (the corrected curves the baseline's, G and the
// held-out G unchanged); once it has, the after is its runs'. The notes keep the order the
// stages said them in, and G per regime comes from the curves the record holds.
TEST(GapRecord, TheRecordIsTheStagesResultsAndAfterIsBeforeUntilRunsAreSimulated)
{
  GapGrid grid;
  grid.zmax = 0.5;    // two bins of 0.25 cm: centres 0.125 and 0.375
  WhereResult where;
  SpeedCurves c;
  c.v0 = 100, c.n_real = 8, c.n_base = 4;
  c.z = {0.125, 0.375}, c.real = {110, 110}, c.base = {100, 100}, c.base_se = {1, 1}, c.gap = {10, 10};
  c.G_before = 0.1, c.z_transient_end = 0.5;
  where.before.speeds = {c};
  where.before.parts = GapParts{0.1, 0.0, 8, 4};
  where.before.gap = 0.1, where.before.n_real_min = 8, where.before.n_sim = 4;
  where.notes = {"where: a note"};
  where.omnibus = Significance{50.0, 1e-5, 12, true};
  where.heldout = HeldOut{0, 100, 0.1};
  where.baseline_files = {"ref.csv"};
  FittedCandidates fitted;
  EffectFit a;
  a.name = "a", a.lr = 1, a.lr_threshold = 15;    // not detected: the fits' verdict is none
  fitted.evidence = fit_evidence(false, {a});
  fitted.evidence.n_null = 2;
  const VerdictDecision fits_verdict = decide_verdict(fitted.evidence);
  ASSERT_EQ(fits_verdict.verdict, Verdict::none);
  DiagnosisInputs in{"hand", "real", {"m.csv"}, {"input: a note"}, grid, 0.2, 4};
  const Confirmation nothing;
  const Diagnosis d = assemble_diagnosis(in, where, fitted, fits_verdict, nothing, fits_verdict, Blindness{}, std::nullopt);
  EXPECT_EQ(d.verdict, Verdict::none);
  EXPECT_EQ(d.gap_before, 0.1);
  EXPECT_EQ(d.gap_after, 0.1);
  EXPECT_EQ(d.heldout_after, d.heldout_before);
  EXPECT_EQ(d.speeds[0].corr, c.base);
  EXPECT_EQ(d.speeds[0].n_corr, 4);
  EXPECT_TRUE(d.corrected_files.empty());
  EXPECT_EQ(d.baseline_files, where.baseline_files);
  EXPECT_EQ(d.n_null, 2);
  EXPECT_EQ(d.chi2_0, 50.0);
  // the inputs' note, where's, then the fits' verdict's sentences (none: within the noise)
  ASSERT_GE(d.notes.size(), 3u);
  EXPECT_EQ(d.notes[0], "input: a note");
  EXPECT_EQ(d.notes[1], "where: a note");
  EXPECT_EQ(d.notes[2].rfind("verdict: the gap is within the noise", 0), 0u) << d.notes[2];
  // peak_end 0.2: bin 0 the peak, bin 1 the transient; before and after alike
  ASSERT_TRUE(d.gap_by_regime.count("peak"));
  EXPECT_EQ(d.gap_by_regime.at("peak").first, d.gap_by_regime.at("peak").second);

  // a confirmation that simulated: its runs are the after (the corrected curve closes the gap)
  Confirmation ran;
  ran.outcome.kind = ConfirmationResult::Kind::simulated;
  ran.effect = ran.tested_effect = "a", ran.unit = "u", ran.magnitude = 0.4;
  SpeedAfter after;
  after.n = 4, after.mean = {110, 110}, after.se = {1, 1}, after.G = 0.0;
  ran.after.speeds = {after};
  ran.after.runs = 4;
  ran.after.files = {"confirm.csv"};
  const Diagnosis e = assemble_diagnosis(in, where, fitted, fits_verdict, ran, fits_verdict, Blindness{}, std::nullopt);
  EXPECT_EQ(e.gap_after, ran.after.all());
  EXPECT_EQ(e.speeds[0].corr, after.mean);
  EXPECT_EQ(e.corrected_files, ran.after.files);
  EXPECT_EQ(e.tested_effect, "a");
  EXPECT_EQ(e.magnitude, 0.4);
  EXPECT_EQ(e.magnitude_unit, "u");
  EXPECT_GT(e.gap_by_regime.at("peak").first, 0.0);
  EXPECT_EQ(e.gap_by_regime.at("peak").second, 0.0);    // measured = corrected: no gap after
}
