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
#include "gap_plan.h"
#include "gap_where.h"
#include "gap_which.h"
#include "slurm_script.h"
#include "sweep_cache.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
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
  EXPECT_EQ(choose_effects(std::nullopt).size(), effect_library().size());
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
  // the baseline (seeds 1 2), the reference beds (11-14), the mount's two knots on the baseline's beds
  ASSERT_EQ(p.requests.size(), 4u);
  EXPECT_EQ(p.requests[2].beds_from, "baseline");
  // by hand: grains on the lattice, 8 x 8 across ((4 - 2 x 0.25) / 0.5 + 1) and 5 high;
  // 6 pours of 0.6 s (the knots reuse the baseline's beds), (2 + 4 + 2 + 2) beds pushed
  // 2.5 cm at each speed; 1.1e7 atom-steps per core-second
  const double grains = 8 * 8 * 5;
  const double steps = 6 * 0.6 / 5e-6 + 10 * (2.5 / 50 + 2.5 / 100) / 2e-6;
  EXPECT_NEAR(p.core_hours, grains * steps / (1.1e7 * 3600), 1e-9 * p.core_hours);    // rounding only
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
// magnitude, effect "b" +10 to features 3-5 (one knot each, at 1); the measurement is the
// baseline plus `a` units of effect a's signature. Null replicates: the reference moved by
// +-0.5 on alternate features (noise the size of one standard error).
struct HandMade {
  Effect ea, eb;
  Features f;
  HandMade(double a)
  {
    ea.name = "a", ea.unit = "u", ea.knots = {1.0};
    eb.name = "b", eb.unit = "u", eb.knots = {1.0};
    const std::size_t P = 6;
    auto ens = [&](double v0, std::vector<double> mean) { return make_ensemble(v0, {mean, mean}); };
    for (double v : {50.0, 100.0}) {
      std::vector<double> base(P, 100.0), ka = base, kb = base, meas = base;
      for (std::size_t k = 0; k < 3; ++k) ka[k] += 10.0, kb[k + 3] += 10.0, meas[k] += 10.0 * a;
      f.speeds.push_back(v);
      f.real.push_back(ens(v, meas));
      f.base.push_back(ens(v, base));
      f.fresh.push_back(ens(v, base));
      f.knots["a_1"].push_back(ens(v, ka));
      f.knots["b_1"].push_back(ens(v, kb));
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
  Diagnosis d;
  gap_curves(h.f, grid, d);
  ASSERT_EQ(d.speeds.size(), 2u);
  // both bins 5 above a reference of 100, no scatter in either ensemble (two equal runs):
  // G = sqrt(2 x 5^2 / (2 x 105^2)) = 5 / 105 at each speed; rounding only
  EXPECT_NEAR(d.speeds[0].G_before, 5.0 / 105.0, 1e-12);
  EXPECT_NEAR(d.gap_before, 5.0 / 105.0, 1e-12);
  EXPECT_EQ(d.speeds[1].gap, (std::vector<double>{5.0, 5.0}));
  EXPECT_NEAR(d.speeds[0].band[0], 2.0 * std::sqrt(1e-4 * 105 * 105 / 2 + 0.5), 1e-12);
  EXPECT_EQ(d.n_real_min, 2);
  EXPECT_EQ(d.n_sim, 4);
  gap_significance(h.f, grid, d);
  // chi^2 = 2 speeds x 3 features x 5^2 / (1e-4 x 105^2 / 2 + 0.5)
  EXPECT_NEAR(d.chi2_0, 150.0 / (1e-4 * 105 * 105 / 2 + 0.5), 1e-9);
  EXPECT_EQ(d.nfeatures, 12u);
  EXPECT_LT(d.p_value, 1e-20);
  EXPECT_TRUE(d.significant);
  Diagnosis d0;
  gap_significance(HandMade(0.0).f, grid, d0);
  EXPECT_EQ(d0.chi2_0, 0.0);
  EXPECT_FALSE(d0.significant);
}

TEST(GapWhich, TheVerdictOnAHandMadeFeatureSet)
{
  HandMade h(0.5);
  Diagnosis d;
  d.significant = true;    // the omnibus route: chi^2 about 150 over 12 features (by hand)
  d.nfeatures = 12;
  const auto data = fit_candidates({&h.ea, &h.eb}, h.f, [](const std::string &) { return NAN; }, d);
  ASSERT_EQ(d.ranking.size(), 2u);
  EXPECT_EQ(d.verdict, "explained");
  EXPECT_EQ(d.top_effect, "a");
  // the model is linear between the knots 0 and 1 and the data noise-free: exact
  EXPECT_NEAR(d.ranking[0].magnitude, 0.5, 1e-3);
  EXPECT_GT(d.ranking[0].explained, 0.99);
  EXPECT_TRUE(d.ranking[0].detected);
  // b's signature is orthogonal to the gap: it explains nothing
  EXPECT_EQ(d.ranking[1].name, "b");
  EXPECT_LT(d.ranking[1].explained, 0.01);
  EXPECT_EQ(d.n_null, 2);
  EXPECT_EQ(data.count("a"), 1u);
  EXPECT_EQ(data.count("b"), 1u);

  // no gap at all, and the omnibus test finds none: none
  HandMade z(0.0);
  Diagnosis dz;
  fit_candidates({&z.ea, &z.eb}, z.f, [](const std::string &) { return NAN; }, dz);
  EXPECT_EQ(dz.verdict, "none");
  EXPECT_TRUE(dz.top_effect.empty());
}

TEST(GapConfirm, TheGapAlongTheSignatureAndTheConfirmationTest)
{
  HandMade h(0.5);
  const EffectData ed = effect_data(h.ea, h.f);
  // by hand: u = 5 on 3 features at 2 speeds, the gap 5 there, the variance w = 0.5 (the
  // reference's mean) + 1e-4 x 105^2 / 2 (the measured mean's): sum u g / w over
  // sqrt(sum u^2 / w) = sqrt(150 / w); rounding only
  const double w = 0.5 + 1e-4 * 105.0 * 105.0 / 2.0;
  EXPECT_NEAR(signature_sigma(ed, 0.5, h.f), std::sqrt(150.0 / w), 1e-9);
  HandMade z(0.0);
  EXPECT_NEAR(signature_sigma(effect_data(z.ea, z.f), 0.5, z.f), 0.0, 1e-12);
  // omnibus route: chi^2 150 over 12 features, noise 3 sqrt(24) = 14.7
  Diagnosis d;
  d.chi2_0 = 150, d.nfeatures = 12;
  EXPECT_TRUE(confirms(d, 20.0, 0.0));      // excess 138 -> 8: 94% removed
  EXPECT_FALSE(confirms(d, 140.0, 0.0));    // within the noise of chi^2
  EXPECT_FALSE(confirms(d, 120.0, 0.0));    // beyond the noise, but 22% of the excess removed (< 25%)
  // targeted route: the squared projection must drop by 9 without chi^2 growing beyond its noise
  d.targeted = true;
  d.proj_before = 4.0;
  EXPECT_TRUE(confirms(d, 150.0, 2.0));     // 16 -> 4
  EXPECT_FALSE(confirms(d, 150.0, 3.0));    // 16 -> 9: 7 only
  EXPECT_FALSE(confirms(d, 170.0, 0.0));    // chi^2 up by 20 > 14.7
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

TEST(SlurmScript, OneAllocationWrittenWhole)
{
  TempDir dir("slurm");
  SlurmAllocation job;
  job.job_name = "granpen-gap-tiny";
  job.ntasks = 8;
  job.what = "granpen gap: the tiny cache.";
  job.command = "granpen-cli gap --prepare-only --scenario tiny";
  const std::string file = dir / "prepare.sh";
  write_slurm_allocation(job, file);
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), "#!/bin/bash\n# granpen gap: the tiny cache.\n# Submit with: sbatch [--partition=... --time=...] " +
                            file + "\n#SBATCH --job-name=granpen-gap-tiny\n#SBATCH --ntasks=8\nset -e\n"
                                   "granpen-cli gap --prepare-only --scenario tiny\n");
  EXPECT_FALSE(fs::exists(file + ".tmp"));
  // a folder that does not exist: a named error, nothing left behind
  try {
    write_slurm_allocation(job, dir / "no/such/prepare.sh");
    ADD_FAILURE() << "no error";
  } catch (const InputError &e) {
    EXPECT_NE(std::string(e.what()).find("no/such/prepare.sh: cannot write"), std::string::npos) << e.what();
  }
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
  EXPECT_EQ(seen.back().message.rfind("verdict explained (rolling_resistance, magnitude ", 0), 0u) << seen.back().message;
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
