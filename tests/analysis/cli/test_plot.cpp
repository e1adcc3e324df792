// granpen plot: the data files hold the library's numbers (peak law, F/F_z curves, k_z
// and its error, the flow fits), gnuplot makes non-empty PNG and SVG (skipped without
// gnuplot), and bad inputs, a failing or a missing gnuplot give clear errors naming the
// file or the script. The command runs in-process (granpen::cli::plot, compiled into
// this test). The figure library itself: tests/analysis/io/test_plot_writer.cpp.
#include "collapse.h"
#include "flow_fields.h"
#include "json_text.h"
#include "linear_fit.h"
#include "momentum_classes.h"
#include "plot_test_files.h"
#include "plot_writer.h"
#include "subcommand.h"
#include "subcommands.h"
#include "trace_fit.h"
#include "trace_reader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

using namespace granpen;
using namespace plot_test;
namespace fs = std::filesystem;

namespace {

const fs::path ROOT = GRANPEN_PLOT_TEST_DIR;

fs::path fresh(const std::string &name) { return fresh_folder(ROOT, name); }

// the index of the block whose title line holds `text`, -1 when none
int block_with(const fs::path &dat, const std::string &text)
{
  std::istringstream in(slurp(dat));
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("# index ", 0) == 0 && line.find(text) != std::string::npos) return std::atoi(line.c_str() + 8);
  return -1;
}

// a JSON number member "key": value, the first after `after` in the text
double json_value(const std::string &json, const std::string &key, const std::string &after = "")
{
  std::size_t from = after.empty() ? 0 : json.find(after);
  if (from == std::string::npos) return NAN;
  const auto k = json.find("\"" + key + "\": ", from);
  if (k == std::string::npos) return NAN;
  return std::strtod(json.c_str() + k + key.size() + 4, nullptr);
}

struct Outcome {
  int status = 0;
  std::string out, err;
};

Outcome run_plot(std::vector<std::string> args)
{
  std::vector<char *> argv;
  for (auto &a : args) argv.push_back(&a[0]);
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  Outcome o;
  o.status = granpen::cli::run_subcommand("plot", granpen::cli::plot, (int) argv.size(), argv.data());
  o.out = testing::internal::GetCapturedStdout();
  o.err = testing::internal::GetCapturedStderr();
  return o;
}

// A cgs trace: z = -0.5 .. 5 cm at 0.01 cm; F = k z (z > 0) plus a transient peak
// c v0^2 (1 + e) exp(-((z - 0.3) / 0.05)^2) at z = 0.3 cm < 0.7 R.
std::string trace_text(double v0, double k, double c, double e, int seed)
{
  std::ostringstream o;
  o << "# granpen-trace v1\n# units = cgs\n# v0 = " << v0 << "\n# D = 2\n# g = 981\n# d_g = 0.4\n# rho_g = 3\n# mu = 0.3\n"
    << "# seed = " << seed << "\nt,z,F\n";
  o.precision(12);
  for (int i = 0; i <= 550; ++i) {
    const double z = -0.5 + 0.01 * i;
    const double F = z > 0 ? k * z + c * v0 * v0 * (1 + e) * std::exp(-std::pow((z - 0.3) / 0.05, 2)) : 0.0;
    o << (z + 0.5) / v0 << "," << z << "," << F << "\n";
  }
  return o.str();
}

// 3 speeds x 2 seeds with a known v0^2 peak law and k_z = 25300 dyne/cm
fs::path synthetic_traces(const std::string &name)
{
  const fs::path d = fresh(name);
  for (double v0 : {50.0, 100.0, 200.0})
    for (int s : {1, 2})
      write(d / ("v" + std::to_string((int) v0) + "_s" + std::to_string(s) + ".csv"),
            trace_text(v0, 25300.0, 200.0, s == 1 ? 0.04 : -0.04, s));
  return d;
}

std::vector<std::string> files_in(const fs::path &d)
{
  std::vector<std::string> f;
  for (const auto &e : fs::directory_iterator(d)) f.push_back(e.path().string());
  std::sort(f.begin(), f.end());
  return f;
}

// curve indices in the order granpen plot draws them: by v0, then input order
std::vector<std::size_t> by_v0(const CollapseResult &r)
{
  std::vector<std::size_t> o(r.curves.size());
  for (std::size_t i = 0; i < o.size(); ++i) o[i] = i;
  std::stable_sort(o.begin(), o.end(), [&](std::size_t a, std::size_t b) { return r.curves[a].v0 < r.curves[b].v0; });
  return o;
}

}    // namespace

// ---------------------------------------------------------------- granpen plot: numbers

TEST(PlotCli, PeakExponentIsTheLibrarys)
{
  const fs::path in = synthetic_traces("peak_in"), out = fresh("peak_out");
  const Outcome o = run_plot({"peak", in.string(), "--out", out.string(), "--no-run"});
  ASSERT_EQ(o.status, 0) << o.err;
  // the library on the same traces
  std::vector<CollapseInput> ci;
  for (const auto &f : files_in(in)) {
    const Trace t = read_trace(f);
    CollapseInput c;
    c.name = f, c.z = t.z, c.F = t.F, c.v0 = t.v0, c.D = t.D, c.g = t.g, c.k_z = 1.0;
    ci.push_back(c);
  }
  const CollapseResult r = collapse(ci, CollapseParams{});
  ASSERT_TRUE(r.peak_law.ok);
  EXPECT_NEAR(r.peak_law.exponent, 2.0, 0.05);    // the v0^2 law put in
  const std::string json = slurp(out / "peak.json");
  EXPECT_NEAR(json_value(json, "exponent"), r.peak_law.exponent, 1e-9);
  EXPECT_NEAR(json_value(json, "exponent_ci95"), r.peak_law.exponent_ci95, 1e-9);
  const int fb = block_with(out / "peak.dat", "peak law");
  ASSERT_GE(fb, 0);
  const auto fit = block(out / "peak.dat", fb);
  ASSERT_EQ(fit.size(), 1u);
  EXPECT_NEAR(fit[0][0], r.peak_law.exponent, 1e-9);
  // the prefactor is the same least squares' intercept; the line is in the script
  std::vector<double> lv, lp;
  for (const auto &c : r.curves) lv.push_back(std::log(c.v0)), lp.push_back(std::log(c.peak));
  const LinearFit lf = linear_fit(lv, lp);
  EXPECT_NEAR(fit[0][3], std::exp(lf.a), 1e-8 * std::exp(lf.a));
  EXPECT_NE(slurp(out / "peak.gp").find("*x**" + gp_number(r.peak_law.exponent)), std::string::npos);
  // every peak is drawn
  const int pb = block_with(out / "peak.dat", "peaks:");
  const auto pts = block(out / "peak.dat", pb);
  const auto order = by_v0(r);
  ASSERT_EQ(pts.size(), 6u);
  for (std::size_t j = 0; j < pts.size(); ++j) {
    EXPECT_EQ(pts[j][0], r.curves[order[j]].v0);
    EXPECT_NEAR(pts[j][1], r.curves[order[j]].peak, 1e-9 * r.curves[order[j]].peak);
  }
}

TEST(PlotCli, RatioCurvesAreCollapses)
{
  const fs::path in = synthetic_traces("ratio_in"), out = fresh("ratio_out");
  const Outcome o = run_plot({"ratio", in.string(), "--out", out.string(), "--no-run", "--kz-zmin", "1"});
  ASSERT_EQ(o.status, 0) << o.err;
  std::vector<CollapseInput> ci;
  for (const auto &f : files_in(in)) {
    const Trace t = read_trace(f);
    TraceFitParams fp;
    fp.zlo = 1.0, fp.D = t.D;
    CollapseInput c;
    c.name = f, c.z = t.z, c.F = t.F, c.v0 = t.v0, c.D = t.D, c.g = t.g, c.k_z = fit_trace(t.z, t.F, fp).k_z;
    ci.push_back(c);
  }
  const CollapseResult r = collapse(ci, CollapseParams{});
  // blocks: panel (a) curves, then panel (b) curves, in order of v0 then file
  const std::size_t n = r.curves.size();
  const auto order = by_v0(r);
  for (std::size_t j = 0; j < n; ++j) {
    const auto &c = r.curves[order[j]];
    const auto a = block(out / "ratio.dat", (int) j), b = block(out / "ratio.dat", (int) (n + j));
    ASSERT_EQ(b.size(), c.t.size());
    const double scale = std::sqrt(c.g / c.D) / c.v0;
    for (std::size_t k = 0; k < c.t.size(); ++k) {
      EXPECT_NEAR(b[k][0], c.t[k], 1e-9);
      EXPECT_NEAR(b[k][1], c.ratio[k], 1e-9 * std::fabs(c.ratio[k]));
      EXPECT_NEAR(a[k][0], c.t[k] / scale, 1e-9);
    }
  }
  const std::string json = slurp(out / "ratio.json");
  EXPECT_NEAR(json_value(json, "spread_t"), r.spread_t, 1e-6 * r.spread_t);
  EXPECT_NE(slurp(out / "ratio.gp").find("first 0.8 to graph 1, first 1.2"), std::string::npos);    // the band
}

// Two pushes of one bed at one speed, D = 1 and 2 cm, are both "seed 1": the legend names
// their diameters (it named them alike before, so a reader could not tell them apart).
TEST(PlotCli, RatioLegendTellsDiametersApart)
{
  const fs::path in = fresh("ratio_D_in"), out = fresh("ratio_D_out");
  for (int D : {1, 2}) {
    std::string text = trace_text(100, 25300, 0, 0, 1);
    const auto at = text.find("# D = 2\n");
    ASSERT_NE(at, std::string::npos);
    text.replace(at, 8, "# D = " + std::to_string(D) + "\n");
    write(in / ("D" + std::to_string(D) + ".csv"), text);
  }
  const Outcome o = run_plot({"ratio", in.string(), "--out", out.string(), "--no-run", "--alpha", "30"});
  ASSERT_EQ(o.status, 0) << o.err;
  const std::string gp = slurp(out / "ratio.gp");
  EXPECT_NE(gp.find("v_0 = 100 cm/s, D = 1 cm, seed 1"), std::string::npos) << gp;
  EXPECT_NE(gp.find("v_0 = 100 cm/s, D = 2 cm, seed 1"), std::string::npos) << gp;
}

TEST(PlotCli, KzWithTheFitsErrors)
{
  const fs::path in = synthetic_traces("kz_in"), out = fresh("kz_out");
  const Outcome o = run_plot({"kz", in.string(), "--out", out.string(), "--no-run", "--kz-zmin", "1", "--kz-zmax", "4"});
  ASSERT_EQ(o.status, 0) << o.err;
  const auto files = files_in(in);
  std::map<std::string, TraceFit> fits;
  for (const auto &f : files) {
    const Trace t = read_trace(f);
    TraceFitParams fp;
    fp.zlo = 1.0, fp.zhi = 4.0, fp.D = t.D;
    fits[f] = fit_trace(t.z, t.F, fp);
  }
  const std::string json = slurp(out / "kz.json");
  for (const auto &f : files) {
    EXPECT_NEAR(json_value(json, "k_z", json_string(f)), fits[f].k_z, 1e-6 * fits[f].k_z) << f;
    EXPECT_NEAR(json_value(json, "k_z_se", json_string(f)), fits[f].k_z_se, 1e-6 * fits[f].k_z_se + 1e-12) << f;
  }
  // block 0 = v0 50 (the two seeds): k_z and its error bar in 10^4 dyne/cm
  const auto b = block(out / "kz.dat", 0);
  const TraceFit &f50 = fits[(in / "v50_s1.csv").string()];
  ASSERT_EQ(b.size(), 2u);
  EXPECT_NEAR(b[0][1] * 1e4, f50.k_z, 1e-6 * f50.k_z);
  EXPECT_NEAR(b[0][2] * 1e4, f50.k_z_se, 1e-6 * f50.k_z_se + 1e-9);
  EXPECT_NE(slurp(out / "kz.gp").find("10^{4} dyne/cm"), std::string::npos);
}

TEST(PlotCli, ForceMeanAndRangeOfTheRuns)
{
  const fs::path in = fresh("force_in"), out = fresh("force_out");
  write(in / "a.csv", trace_text(100, 20000, 0, 0, 1));
  write(in / "b.csv", trace_text(100, 40000, 0, 0, 2));
  const Outcome o = run_plot({"force", in.string(), "--out", out.string(), "--no-run"});
  ASSERT_EQ(o.status, 0) << o.err;
  const auto b = block(out / "force.dat", 0);    // x, mean, lo, hi in 10^5 dyne
  ASSERT_EQ(b.size(), 551u);
  for (const auto &row : b)
    if (row[0] > 0.5) {
      EXPECT_NEAR(row[1], 0.3 * row[0], 1e-9);
      EXPECT_NEAR(row[2], 0.2 * row[0], 1e-9);
      EXPECT_NEAR(row[3], 0.4 * row[0], 1e-9);
    }
  EXPECT_NE(slurp(out / "force.gp").find("10^{5} dyne"), std::string::npos);
  // --each: every run, its own block
  const Outcome e = run_plot({"force", in.string(), "--out", out.string(), "--no-run", "--each"});
  ASSERT_EQ(e.status, 0) << e.err;
  EXPECT_NEAR(block(out / "force.dat", 1).back()[1], 40000 * 5.0 / 1e5, 1e-9);
}

// ---------------------------------------------------------------- gnuplot end to end

TEST(PlotCli, TraceKindsMakeImages)
{
  if (!have_gnuplot()) GTEST_SKIP() << "gnuplot with pngcairo and svg not available";
  const fs::path in = synthetic_traces("images_in"), out = fresh("images_out");
  for (const char *kind : {"force", "ratio", "peak", "kz"}) {
    const Outcome o = run_plot({kind, in.string(), "--out", out.string(), "--kz-zmin", "1"});
    EXPECT_EQ(o.status, 0) << kind << ": " << o.err;
    for (const char *ext : {".png", ".svg", ".gp", ".dat"})
      EXPECT_TRUE(non_empty((out / (std::string(kind) + ext)).string())) << kind << ext;
    EXPECT_TRUE(is_png((out / (std::string(kind) + ".png")).string()));
    EXPECT_TRUE(is_svg((out / (std::string(kind) + ".svg")).string()));
    EXPECT_NE(slurp(out / (std::string(kind) + ".json")).find("\"made\": true"), std::string::npos);
  }
}

TEST(PlotCli, BenchSweepMakesImages)
{
  if (!have_gnuplot()) GTEST_SKIP() << "gnuplot with pngcairo and svg not available";
  const fs::path out = fresh("bench_out");
  for (const char *kind : {"force", "peak"}) {
    const Outcome o = run_plot({kind, GRANPEN_BENCH_TRACES, "--out", out.string()});
    EXPECT_EQ(o.status, 0) << kind << ": " << o.err;
    EXPECT_TRUE(is_png((out / (std::string(kind) + ".png")).string()));
  }
}

// ---------------------------------------------------------------- flow and momentum tables

namespace {

fs::path synthetic_flow(const std::string &name)
{
  const fs::path d = fresh(name);
  std::ostringstream f;
  f << "# D = 2\nr,z,count,phi,phi_centre,vr,vz,T,gammadot,p,I\n";
  for (int iz = 0; iz < 12; ++iz)
    for (int ir = 0; ir < 8; ++ir) {
      const double r = 0.25 + 0.5 * ir, z = -4.75 + 0.5 * iz;
      if (r < 1 && z > 0) {
        f << r << "," << z << ",0,0,0,0,0,0,0,0,0\n";
        continue;
      }
      const double gd = 100 * std::exp(z / 1.5 - r), p = 1e4 * (2 - z);
      f << r << "," << z << ",10," << 0.58 - 0.02 * std::exp(z - r) << ",0.58,0," << -50 * std::exp(z / 2 - r) << ",1," << gd
        << "," << p << "," << gd * 0.4 / std::sqrt(p / 3) << "\n";
    }
  write(d / "flow_fields.csv", f.str());
  std::ostringstream pr;
  pr << "z,vz,vz_se,phi\n";
  for (int k = 0; k < 15; ++k) {
    const double z = -0.1 - 0.2 * k;
    pr << z << "," << -80 * std::exp(z / 1.9) * (1 + 0.03 * std::sin(5.0 * k)) << "," << 1 + 0.5 * k << "," << 0.57 << "\n";
  }
  write(d / "flow_profile_below.csv", pr.str());
  std::ostringstream e;
  e << "I,phi\n";
  for (int k = 0; k < 10; ++k) e << 0.02 * k << "," << 0.57 - 0.35 * 0.02 * k + 0.002 * ((k % 3) - 1) << "\n";
  write(d / "flow_edge_phi_I.csv", e.str());
  write(d / "flow_strip.csv", "z,vz\n-0.5,3\n-1,1\n-1.5,0\n-2,-0.5\n");
  write(d / "flow_annulus.csv", "t_tilde,z_tip,phi,vz,T\n0.2,0.5,0.57,2,1\n0.6,1.5,0.56,1,0.5\n1.2,3,0.575,-0.2,0.1\n");
  std::ostringstream m;
  m << "t_tilde,z_tip,class,count,p_up\n";
  for (int k = 0; k < 10; ++k)
    for (const char *c : {"fast", "intermediate", "slow", "noise"}) m << 0.2 * k << "," << 0.4 * k << "," << c << "," << 10 + k << "," << 100.0 / (k + 1) << "\n";
  write(d / "momentum_classes.csv", m.str());
  std::ostringstream dr;
  dr << "t_tilde,z_tip,F,mu_g_M\n";
  for (int k = 1; k <= 10; ++k) dr << 0.2 * k << "," << 0.4 * k << "," << 1e5 * k * (1 + 0.02 * (k % 2)) << "," << 1e5 * k << "\n";
  write(d / "momentum_drag.csv", dr.str());
  return d;
}

}    // namespace

TEST(PlotCli, FlowAndMomentumFitsAreTheLibrarys)
{
  const fs::path in = synthetic_flow("flow_in"), out = fresh("flow_out");
  const bool images = have_gnuplot();
  std::vector<std::string> args = {"flow", in.string(), "--out", out.string()};
  if (!images) args.push_back("--no-run");
  const Outcome o = run_plot(args);
  ASSERT_EQ(o.status, 0) << o.err;
  for (const char *name : {"flow_heatmaps", "flow_profile", "flow_phi_I", "flow_strip", "flow_annulus"}) {
    EXPECT_TRUE(non_empty((out / (std::string(name) + ".gp")).string())) << name;
    if (images) {
      EXPECT_TRUE(is_png((out / (std::string(name) + ".png")).string())) << name;
      EXPECT_TRUE(is_svg((out / (std::string(name) + ".svg")).string())) << name;
    }
  }
  const std::string json = slurp(out / "flow.json");
  // lambda: fit_exponential on the table's columns
  std::vector<double> z, v, se;
  for (int k = 0; k < 15; ++k) {
    const double zz = -0.1 - 0.2 * k;
    z.push_back(zz), v.push_back(-80 * std::exp(zz / 1.9) * (1 + 0.03 * std::sin(5.0 * k))), se.push_back(1 + 0.5 * k);
  }
  // the table holds the numbers as printed: compare with a tolerance of their precision
  const ExpFit ef = fit_exponential(z, v, se);
  ASSERT_TRUE(ef.ok);
  EXPECT_NEAR(json_value(json, "lambda"), ef.lambda, 1e-4 * ef.lambda);
  EXPECT_NEAR(json_value(json, "lambda"), 1.9, 0.1);
  std::vector<double> I, phi;
  for (int k = 0; k < 10; ++k) I.push_back(0.02 * k), phi.push_back(0.57 - 0.35 * 0.02 * k + 0.002 * ((k % 3) - 1));
  const LinearFit edge = linear_fit(I, phi);
  EXPECT_NEAR(json_value(json, "slope"), edge.b, 1e-5);
  EXPECT_NEAR(json_value(json, "intercept"), edge.a, 1e-5);
  EXPECT_NEAR(json_value(json, "slope"), -0.35, 0.02);
  // the paper's values beside the fits (core/paper_values.h), as the paper states them
  // (../shared/papers/README.md, "flow below rod" and "rheology")
  const std::string profile_gp = slurp(out / "flow_profile.gp"), phi_gp = slurp(out / "flow_phi_I.gp");
  EXPECT_NE(profile_gp.find("paper: 0.98 ± 0.15"), std::string::npos) << "panel (c)'s band";
  EXPECT_NE(profile_gp.find("(paper: 0.98 D ± 0.15)"), std::string::npos) << "the fit's title";
  EXPECT_NE(phi_gp.find("paper: φ = 0.57 − 0.35 I"), std::string::npos);
  EXPECT_NE(phi_gp.find("0.57 - 0.35*x"), std::string::npos) << "the paper's line drawn";
  // the heatmap grid: 8 x 12 bins, the rod's bins empty (NaN)
  const auto b = block(out / "flow_heatmaps.dat", 0);
  ASSERT_EQ(b.size(), 96u);
  EXPECT_TRUE(std::isnan(b[80][2]));     // r = 0.25, z = 0.25: inside the rod, empty
  EXPECT_NEAR(b[95][2], 0.58 - 0.02 * std::exp(0.75 - 3.75), 1e-6);    // r = 3.75, z = 0.75

  args[0] = "momentum";
  const Outcome m = run_plot(args);
  ASSERT_EQ(m.status, 0) << m.err;
  std::vector<double> F, M;
  for (int k = 1; k <= 10; ++k) F.push_back(1e5 * k * (1 + 0.02 * (k % 2))), M.push_back(1e5 * k);
  const DragComparison dc = compare_drag(M, F);
  ASSERT_TRUE(dc.ok);
  const std::string mj = slurp(out / "momentum.json");
  EXPECT_NEAR(json_value(mj, "k"), dc.fit.b, 1e-5);
  EXPECT_NEAR(json_value(mj, "ratio_mean"), dc.ratio_mean, 1e-5);
  EXPECT_NE(slurp(out / "momentum_drag.gp").find("x with lines"), std::string::npos);    // the 1:1 line
  for (const char *name : {"momentum_classes", "momentum_drag"})
    if (images) EXPECT_TRUE(is_png((out / (std::string(name) + ".png")).string())) << name;
  // four classes, each its own series, in the paper's order
  const std::string cls = slurp(out / "momentum_classes.dat");
  EXPECT_LT(cls.find("fast: "), cls.find("intermediate: "));
  EXPECT_LT(cls.find("intermediate: "), cls.find("slow: "));
}

// ---------------------------------------------------------------- scaling with D/d_g

TEST(PlotCli, ScalingPointsInOrderWithTheirDistanceFromThePaper)
{
  const fs::path in = fresh("scaling_in"), out = fresh("scaling_out");
  // rows out of order, a ratio not yet measured (empty value), a quantity without a paper value
  write(in / "t.csv",
        "# paper_D_over_dg = 10\n"
        "quantity,D_over_dg,value,error,paper,paper_error\n"
        "peak exponent,6.67,1.57,0.05,2,0\n"
        "peak exponent,5,1.48,0.07,2,0\n"
        "peak exponent,10,,,2,0\n"
        "lambda_vz / D,6.67,0.40,0.01,0.98,0.15\n"
        "phi_0,5,0.578,0,,\n");
  const bool images = have_gnuplot();
  std::vector<std::string> args = {"scaling", (in / "t.csv").string(), "--out", out.string()};
  if (!images) args.push_back("--no-run");
  const Outcome o = run_plot(args);
  ASSERT_EQ(o.status, 0) << o.err;
  if (images) EXPECT_TRUE(is_png((out / "scaling.png").string()));
  // the peak exponent's block: its two measured points by D/d_g, with their error bars
  const auto b = block(out / "scaling.dat", 0);
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(b[0][0], 5.0);
  EXPECT_EQ(b[0][1], 1.48);
  EXPECT_EQ(b[1][0], 6.67);
  // distance from the paper in combined standard errors, by hand: (1.48 - 2) / 0.07 and
  // (0.40 - 0.98) / sqrt(0.01^2 + 0.15^2); printed to 4 digits
  const std::string j = slurp(out / "scaling.json");
  EXPECT_NEAR(json_value(j, "sigmas_from_paper"), (1.48 - 2.0) / 0.07, 1e-3);
  EXPECT_NEAR(json_value(j, "sigmas_from_paper", "lambda_vz"), (0.40 - 0.98) / std::sqrt(0.01 * 0.01 + 0.15 * 0.15), 1e-3);
  // no paper value: no distance (null), a title that says so
  EXPECT_NE(j.find("\"quantity\": \"phi_0\", \"paper\": null"), std::string::npos) << j;
  const std::string gp = slurp(out / "scaling.gp");
  EXPECT_NE(gp.find("phi\\\\_0   (no paper value)"), std::string::npos) << "the name's _ drawn literally";
  EXPECT_NE(gp.find("paper: 0.98 ± 0.15"), std::string::npos);
  // the paper's ratio is on every panel's x range: [4, 11] from ratios 5 to 10
  EXPECT_NE(gp.find("set xrange [4:11]"), std::string::npos) << gp;

  // a contradicting paper value is a problem named by file and line; the rest is drawn
  write(in / "bad.csv", "quantity,D_over_dg,value,error,paper\nk,5,1,0.1,2\nk,6.67,1.1,0.1,3\nk,-1,1,0.1,2\n");
  const Outcome bad = run_plot({"scaling", (in / "bad.csv").string(), "--out", fresh("scaling_bad").string(), "--no-run"});
  EXPECT_EQ(bad.status, 1);
  EXPECT_NE(bad.err.find("bad.csv:3: paper value 3 of k differs from 2 given above"), std::string::npos) << bad.err;
  EXPECT_NE(bad.err.find("bad.csv:4: D_over_dg must be positive"), std::string::npos) << bad.err;
  const Outcome none = run_plot({"scaling", (in / "nothing.csv").string(), "--out", fresh("scaling_none").string()});
  EXPECT_EQ(none.status, 1);
  EXPECT_NE(none.err.find("nothing.csv"), std::string::npos) << none.err;
  const Outcome two = run_plot({"scaling", "a.csv", "b.csv", "--out", "o"});
  EXPECT_EQ(two.status, 2);
  EXPECT_NE(two.err.find("scaling takes one table, got 2 arguments"), std::string::npos) << two.err;
}

// the box series: the same figure against the box width (column box_cm), the paper's 20 cm
// marked, the axis named; a table with both axes, or neither, is refused by name
TEST(PlotCli, ScalingAgainstTheBoxWidth)
{
  const fs::path in = fresh("scaling_box_in"), out = fresh("scaling_box_out");
  write(in / "box.csv",
        "# paper_box_cm = 20\n"
        "quantity,box_cm,value,error,paper,paper_error\n"
        "peak exponent,16,1.8,0.1,2,0\n"
        "peak exponent,8,1.7,0.1,2,0\n"
        "peak exponent,12,,,2,0\n");
  const Outcome o = run_plot({"scaling", (in / "box.csv").string(), "--out", out.string(), "--no-run"});
  ASSERT_EQ(o.status, 0) << o.err;
  const auto b = block(out / "scaling.dat", 0);
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(b[0][0], 8.0);    // in order of the box
  EXPECT_EQ(b[1][0], 16.0);
  const std::string gp = slurp(out / "scaling.gp");
  EXPECT_NE(gp.find("box width (cm)"), std::string::npos) << gp;
  EXPECT_EQ(gp.find("D/d_g"), std::string::npos) << "the D/d_g axis label on a box table";
  // the x range holds every listed box and the paper's 20 cm: [7, 21]
  EXPECT_NE(gp.find("set xrange [7:21]"), std::string::npos) << gp;
  EXPECT_NE(slurp(out / "scaling.json").find("\"box_cm\": 8"), std::string::npos);
  write(in / "both.csv", "quantity,D_over_dg,box_cm,value,error\nk,5,8,1,0.1\n");
  const Outcome both = run_plot({"scaling", (in / "both.csv").string(), "--out", fresh("scaling_both").string(), "--no-run"});
  EXPECT_EQ(both.status, 1);
  EXPECT_NE(both.err.find("both D_over_dg and box_cm columns"), std::string::npos) << both.err;
  write(in / "neither.csv", "quantity,value,error\nk,1,0.1\n");
  const Outcome neither = run_plot({"scaling", (in / "neither.csv").string(), "--out", fresh("scaling_neither").string(), "--no-run"});
  EXPECT_EQ(neither.status, 1);
  EXPECT_NE(neither.err.find("no axis column (D_over_dg or box_cm)"), std::string::npos) << neither.err;
}

// a column series (e.g. the grains a box was filled with): one line per series and quantity,
// each series its own colour and marker (never the paper's red) named in the title, which is
// the legend; drawn a little aside in x where two series share a box; JSON keeps the true x
TEST(PlotCli, ScalingSeriesOneLineEachNamedInTheTitle)
{
  const fs::path in = fresh("scaling_series_in"), out = fresh("scaling_series_out");
  write(in / "box.csv",
        "# paper_box_cm = 20\n"
        "quantity,box_cm,value,error,paper,paper_error,series\n"
        "peak exponent,20,1.44,0.07,2,0,bench grains\n"
        "peak exponent,8,1.34,0.06,2,0,bench grains\n"
        "peak exponent,10,1.47,0.05,2,0,dg10 grains\n"
        "peak exponent,20,,,2,0,dg10 grains\n"
        "lambda,8,0.45,0.02,0.98,0.15,bench grains\n"
        "lambda,20,,,0.98,0.15,dg10 grains\n");
  const Outcome o = run_plot({"scaling", (in / "box.csv").string(), "--out", out.string(), "--no-run"});
  ASSERT_EQ(o.status, 0) << o.err;
  // x range [7, 21]: the series 1.2% of 14 apart, each half of it either side of its box
  const double half = 0.5 * 0.012 * 14;
  const auto bench = block(out / "scaling.dat", 0), dg10 = block(out / "scaling.dat", 1);
  ASSERT_EQ(bench.size(), 2u);
  EXPECT_NEAR(bench[0][0], 8 - half, 1e-9);    // in order of the box, drawn aside to the left
  EXPECT_NEAR(bench[1][0], 20 - half, 1e-9);
  EXPECT_EQ(bench[1][1], 1.44);
  ASSERT_EQ(dg10.size(), 1u) << "dg10's 20 cm row has no value yet: no point";
  EXPECT_NEAR(dg10[0][0], 10 + half, 1e-9);
  // lambda: bench's point alone (dg10 not measured): the third block, one point
  const auto lambda = block(out / "scaling.dat", 2);
  ASSERT_EQ(lambda.size(), 1u);
  EXPECT_NEAR(lambda[0][0], 8 - half, 1e-9);
  const std::string j = slurp(out / "scaling.json");
  EXPECT_NE(j.find("{\"box_cm\": 10, \"value\": 1.47, \"error\": 0.05, \"sigmas_from_paper\": -10.6, \"series\": \"dg10 grains\"}"),
            std::string::npos) << j;
  const std::string gp = slurp(out / "scaling.gp");
  EXPECT_NE(gp.find("bench grains (blue circles), dg10 grains (green squares)"), std::string::npos) << gp;
  EXPECT_NE(gp.find("#1f77b4"), std::string::npos);
  EXPECT_NE(gp.find("#2ca02c"), std::string::npos);
  // no per-panel key (the title is the legend): both panels unset theirs
  const std::size_t k1 = gp.find("unset key");
  EXPECT_NE(k1, std::string::npos) << gp;
  EXPECT_NE(gp.find("unset key", k1 + 1), std::string::npos) << gp;
  // more series than looks: refused by file and line
  std::string many = "quantity,box_cm,value,error,series\n";
  for (int k = 0; k < 6; ++k) many += "q," + std::to_string(8 + k) + ",1,0.1,s" + std::to_string(k) + "\n";
  write(in / "many.csv", many);
  const Outcome m = run_plot({"scaling", (in / "many.csv").string(), "--out", fresh("scaling_many").string(), "--no-run"});
  EXPECT_EQ(m.status, 1);
  EXPECT_NE(m.err.find("many.csv:7: series \"s5\" is one more than the 5"), std::string::npos) << m.err;
}

TEST(PlotCli, PartingCurvesAreTheRatiosGranpenPartingWrote)
{
  const fs::path in = fresh("parting_in"), out = fresh("parting_out");
  // two pairs as granpen parting --json writes them: one parts at 1 ms, one does not
  write(in / "a.json",
        "{\"window_ms\": 0.5, \"threshold\": 0.03, \"parted\": true, \"t_part_ms\": 1, \"ratio_at_part\": 1.2,\n"
        " \"windows\": [{\"t_lo_ms\": 0, \"t_hi_ms\": 0.5, \"ratio\": 1}, {\"t_lo_ms\": 0.5, \"t_hi_ms\": 1, \"ratio\": 1.01},\n"
        "  {\"t_lo_ms\": 1, \"t_hi_ms\": 1.5, \"ratio\": 1.2}, {\"t_lo_ms\": 1.5, \"t_hi_ms\": 2, \"ratio\": 1.4},\n"
        "  {\"t_lo_ms\": 2, \"t_hi_ms\": 2.5, \"ratio\": null}]}\n");
  write(in / "b.json",
        "{\"window_ms\": 0.5, \"threshold\": 0.03, \"parted\": false,\n"
        " \"windows\": [{\"t_lo_ms\": 0, \"t_hi_ms\": 0.5, \"ratio\": 1}, {\"t_lo_ms\": 0.5, \"t_hi_ms\": 1, \"ratio\": 0.99}]}\n");
  const Outcome o = run_plot({"parting", (in / "a.json").string(), (in / "b.json").string(), "--out", out.string(), "--no-run"});
  ASSERT_EQ(o.status, 0) << o.err;
  // the first pair's curve: window centres and ratios, the window without a ratio left out
  const auto a = block(out / "parting.dat", 0);
  ASSERT_EQ(a.size(), 4u);
  EXPECT_DOUBLE_EQ(a[2][0], 1.25);
  EXPECT_DOUBLE_EQ(a[3][1], 1.4);
  // its parting marked at the centre of its first window apart
  const auto mark = block(out / "parting.dat", 1);
  ASSERT_EQ(mark.size(), 1u);
  EXPECT_DOUBLE_EQ(mark[0][0], 1.25);
  EXPECT_DOUBLE_EQ(mark[0][1], 1.2);
  const std::string gp = slurp(out / "parting.gp");
  EXPECT_NE(gp.find("a: parts at 1 ms"), std::string::npos) << gp;
  EXPECT_NE(gp.find("b: does not part"), std::string::npos) << gp;
  EXPECT_NE(gp.find("3%"), std::string::npos) << "the threshold's band in the key";
  // a file of another threshold, and one that is not granpen parting's, are named
  write(in / "c.json", "{\"window_ms\": 0.5, \"threshold\": 0.05, \"parted\": false, \"windows\": []}\n");
  write(in / "d.json", "{\"rows\": []}\n");
  const Outcome bad = run_plot({"parting", (in / "a.json").string(), (in / "c.json").string(), (in / "d.json").string(),
                                "--out", fresh("parting_bad").string(), "--no-run"});
  EXPECT_EQ(bad.status, 1);
  EXPECT_NE(bad.err.find("c.json: threshold 0.05, not the 0.03 of the files before it"), std::string::npos) << bad.err;
  EXPECT_NE(bad.err.find("d.json: no 'windows' (not granpen parting --json output)"), std::string::npos) << bad.err;
}

// ---------------------------------------------------------------- bad inputs

TEST(PlotCli, UsageErrors)
{
  Outcome o = run_plot({"--help"});
  EXPECT_EQ(o.status, 0);
  EXPECT_NE(o.out.find("usage: granpen plot KIND"), std::string::npos);
  o = run_plot({"pie", "x.csv", "--out", "o"});
  EXPECT_EQ(o.status, 2);
  EXPECT_NE(o.err.find("unknown kind 'pie'"), std::string::npos) << o.err;
  o = run_plot({"peak", "x.csv"});
  EXPECT_EQ(o.status, 2);
  EXPECT_NE(o.err.find("--out DIR is required"), std::string::npos) << o.err;
  o = run_plot({"peak", "--out", "o"});
  EXPECT_EQ(o.status, 2);
  EXPECT_NE(o.err.find("no trace given"), std::string::npos) << o.err;
  o = run_plot({"ratio", "x.csv", "--out", "o", "--band", "wide"});
  EXPECT_EQ(o.status, 2);
  EXPECT_NE(o.err.find("--band needs a number, got 'wide'"), std::string::npos) << o.err;
  o = run_plot({"kz", "x.csv", "--out", "o", "--colour", "red"});
  EXPECT_EQ(o.status, 2);
  EXPECT_NE(o.err.find("unknown option '--colour'"), std::string::npos) << o.err;
  o = run_plot({"flow", "a", "b", "--out", "o"});
  EXPECT_EQ(o.status, 2);
  EXPECT_NE(o.err.find("flow takes one folder"), std::string::npos) << o.err;
}

TEST(PlotCli, BadTracesAreNamed)
{
  const fs::path in = synthetic_traces("bad_in"), out = fresh("bad_out");
  write(in / "broken.csv", "# granpen-trace v1\n# units = cgs\n# v0 = 100\n# D = 2\n# g = 981\nt,z,F\n0,0,0\n0.0001,0.01\n");
  const Outcome o = run_plot({"peak", in.string(), (in / "missing.csv").string(), "--out", out.string(), "--no-run"});
  EXPECT_EQ(o.status, 1);
  EXPECT_NE(o.err.find("broken.csv:8: row has 2 fields, expected 3"), std::string::npos) << o.err;
  EXPECT_NE(o.err.find("missing.csv"), std::string::npos) << o.err;
  EXPECT_TRUE(fs::exists(out / "peak.gp"));    // the good traces are still drawn
  EXPECT_NE(slurp(out / "peak.json").find("broken.csv:8"), std::string::npos);
}

TEST(PlotCli, BadTablesAreNamed)
{
  const fs::path in = fresh("badflow_in"), out = fresh("badflow_out");
  Outcome o = run_plot({"flow", in.string(), "--out", out.string(), "--no-run"});
  EXPECT_EQ(o.status, 1);
  EXPECT_NE(o.err.find("none of flow_fields.csv"), std::string::npos) << o.err;
  write(in / "flow_fields.csv", "r,z,count,phi\n0.5,-1,3,0.58\n");
  write(in / "flow_strip.csv", "z,vz\n-0.5,3\n-1,fast\n");
  write(in / "flow_edge_phi_I.csv", "I,phi\n0.1,0.5,7\n");
  o = run_plot({"flow", in.string(), "--out", out.string(), "--no-run"});
  EXPECT_EQ(o.status, 1);
  EXPECT_NE(o.err.find("flow_fields.csv: missing columns vz, gammadot, I"), std::string::npos) << o.err;
  EXPECT_NE(o.err.find("flow_strip.csv:3: column vz value 'fast' is not a finite number"), std::string::npos) << o.err;
  EXPECT_NE(o.err.find("flow_edge_phi_I.csv:2: row has 3 fields, expected 2"), std::string::npos) << o.err;
  EXPECT_NE(o.out.find("flow_annulus.csv not found"), std::string::npos) << o.out;
  o = run_plot({"momentum", (in / "nowhere").string(), "--out", out.string()});
  EXPECT_EQ(o.status, 1);
  EXPECT_NE(o.err.find("nowhere: not a folder"), std::string::npos) << o.err;
}

TEST(PlotCli, MissingGnuplotNamesTheScriptAndExitsOne)
{
  const fs::path in = synthetic_traces("nognuplot_in"), out = fresh("nognuplot_out");
  setenv("GRANPEN_GNUPLOT", "/nonexistent/gnuplot", 1);
  const Outcome o = run_plot({"peak", in.string(), "--out", out.string()});
  unsetenv("GRANPEN_GNUPLOT");
  EXPECT_EQ(o.status, 1);
  EXPECT_NE(o.err.find((out / "peak.gp").string() + " not run"), std::string::npos) << o.err;
  EXPECT_NE(o.err.find("not found"), std::string::npos) << o.err;
  EXPECT_TRUE(fs::exists(out / "peak.gp") && fs::exists(out / "peak.dat"));
}

TEST(PlotCli, UndefinedTimeFallsBackToDepth)
{
  const fs::path in = fresh("nan_time_in"), out = fresh("nan_time_out");
  write(in / "flow_annulus.csv", "t_tilde,z_tip,phi,vz,T\nnan,0.5,0.57,2,1\nnan,1.5,0.56,1,0.5\nnan,3,0.575,-0.2,0.1\n");
  const Outcome o = run_plot({"flow", in.string(), "--out", out.string(), "--no-run"});
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.out.find("t_tilde undefined (nan): drawn against z_tip"), std::string::npos) << o.out;
  EXPECT_NE(slurp(out / "flow_annulus.gp").find("rod tip depth z_{tip} (cm)"), std::string::npos);
  EXPECT_EQ(block(out / "flow_annulus.dat", 0)[2][0], 3.0);
}

// ---------------------------------------------------------------- real data sets (issue 20)

namespace {

// 22 penetrometer-like soundings at nine speeds (2 or 3 each), depths to 14 m at 2 cm, a
// cone of D = 3.57 cm: 0.7 R = 1.25 cm holds no sample, so there is no peak region to show
fs::path soundings(const std::string &name)
{
  const fs::path d = fresh(name);
  const double speeds[] = {0.5, 1, 2, 5, 10, 20, 50, 100, 200};
  const int runs[] = {3, 3, 3, 2, 2, 2, 3, 2, 2};
  int id = 0;
  for (int s = 0; s < 9; ++s)
    for (int r = 0; r < runs[s]; ++r, ++id) {
      std::ostringstream o;
      o << "# granpen-trace v1\n# units = cgs\n# v0 = " << speeds[s] << "\n# D = 3.57\n# g = 981\n# d_g = 0.05\n"
        << "# rho_g = 2.65\n# run = " << r + 1 << "\nt,z,F\n";
      o.precision(10);
      for (int i = 0; i <= 705; ++i) {
        const double z = -10 + 2.0 * i;
        const double F = z > 0 ? 4e5 * std::pow(z, 0.8) * (1 + 0.08 * std::sin(0.05 * z + id)) : 0.0;
        o << (z + 10) / speeds[s] << "," << z << "," << F << "\n";
      }
      write(d / ("sounding_" + std::to_string(id) + ".csv"), o.str());
    }
  return d;
}

// the legend entries of a script: every `title "..."` (key titles excluded)
std::vector<std::string> legend_titles(const std::string &gp)
{
  std::vector<std::string> t;
  const std::regex re(" title \"([^\"]*)\"");
  for (auto it = std::sregex_iterator(gp.begin(), gp.end(), re); it != std::sregex_iterator(); ++it)
    t.push_back((*it)[1]);
  return t;
}

int count_containing(const std::vector<std::string> &v, const std::string &s)
{
  return (int) std::count_if(v.begin(), v.end(), [&](const std::string &x) { return x.find(s) != std::string::npos; });
}

}    // namespace

TEST(PlotCli, NineSpeedsOfSoundingsAllInTheLegendWithoutAnEmptyInset)
{
  const fs::path in = soundings("soundings_in"), out = fresh("soundings_out");
  const bool run = have_gnuplot();
  std::vector<std::string> extra = run ? std::vector<std::string>{} : std::vector<std::string>{"--no-run"};
  const auto plot = [&](std::vector<std::string> a) {
    a.insert(a.end(), {"--out", out.string()});
    a.insert(a.end(), extra.begin(), extra.end());
    return run_plot(a);
  };
  // force, mean per speed: nine entries, each speed once; no inset (no sample in the peak
  // region), and a note saying so
  Outcome o = plot({"force", in.string()});
  ASSERT_EQ(o.status, 0) << o.err;
  std::string gp = slurp(out / "force.gp");
  auto titles = legend_titles(gp);
  for (const char *v : {"= 0.5 cm/s", "= 1 cm/s", "= 2 cm/s", "= 5 cm/s", "= 10 cm/s", "= 20 cm/s", "= 50 cm/s",
                        "= 100 cm/s", "= 200 cm/s"})
    EXPECT_EQ(count_containing(titles, v), 1) << v << "\n" << gp;
  EXPECT_EQ(gp.find("peak region"), std::string::npos);
  EXPECT_NE(o.out.find("no enlarged view"), std::string::npos) << o.out;
  EXPECT_EQ(count_containing(titles, "more not listed"), 0);
  // every run: 22 entries (or the legend says what it folded), never silently cut
  o = plot({"force", in.string(), "--each"});
  ASSERT_EQ(o.status, 0) << o.err;
  titles = legend_titles(slurp(out / "force.gp"));
  EXPECT_EQ(count_containing(titles, "v_0 = "), 22);
  // kz, ratio: one entry per speed; peak: none of them has a sample in the peak region
  o = plot({"peak", in.string()});
  EXPECT_NE(o.out.find("22 of 22 traces have no positive force at 0 < z < 0.7 R"), std::string::npos) << o.out;
  for (const char *kind : {"kz", "ratio"}) {
    o = plot({kind, in.string(), "--kz-zmin", "300"});
    ASSERT_EQ(o.status, 0) << kind << ": " << o.err;
    titles = legend_titles(slurp(out / (std::string(kind) + ".gp")));
    EXPECT_EQ(count_containing(titles, "v_0 = "), 9) << kind;
  }
  if (run) EXPECT_TRUE(is_png((out / "force.png").string()));
}

TEST(PlotCli, ALegendLongerThanItsColumnSaysHowManyItFolded)
{
  // 60 runs at 60 speeds, every one its own entry: 60 lines do not fit 720 px
  const fs::path in = fresh("many_in"), out = fresh("many_out");
  for (int i = 0; i < 60; ++i) write(in / ("v" + std::to_string(i) + ".csv"), trace_text(10 + 5 * i, 20000, 0, 0, 1));
  const Outcome o = run_plot({"force", in.string(), "--each", "--out", out.string(), "--no-run"});
  ASSERT_EQ(o.status, 0) << o.err;
  const auto titles = legend_titles(slurp(out / "force.gp"));
  ASSERT_EQ(count_containing(titles, "more not listed"), 1);
  const std::string more = titles[(std::size_t) (std::find_if(titles.begin(), titles.end(), [](const std::string &t) {
                                                   return t.find("more not listed") != std::string::npos;
                                                 }) - titles.begin())];
  const int folded = std::atoi(more.c_str() + 2);
  EXPECT_EQ(count_containing(titles, "v_0 = ") + folded, 60) << more;
  EXPECT_NE(o.out.find("folded"), std::string::npos) << o.out;
}

TEST(PlotCli, AMillimetreTraceHasNoPeakInsetAndAShortenedWindow)
{
  const fs::path in = fresh("mm_in"), out = fresh("mm_out");
  std::ostringstream t;
  t << "# granpen-trace v1\n# units = cgs\n# v0 = 1\n# D = 2\n# g = 981\nt,z,F\n";
  for (int i = 0; i <= 350; ++i) {
    const double z = -0.05 + 0.001 * i;
    t << z + 0.05 << "," << z << "," << (z > 0 ? 3e4 * z : 0.0) << "\n";
  }
  write(in / "mm.csv", t.str());
  Outcome o = run_plot({"force", in.string(), "--out", out.string(), "--no-run"});
  ASSERT_EQ(o.status, 0) << o.err;
  EXPECT_EQ(slurp(out / "force.gp").find("peak region"), std::string::npos);
  EXPECT_NE(o.out.find("half or more of the depth drawn"), std::string::npos) << o.out;
  // k_z over the default z >= 3 cm: the window is the deeper half of the trace, said
  o = run_plot({"kz", in.string(), "--out", out.string(), "--no-run"});
  ASSERT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.out.find("shortened to z = 0.15..0.3 cm"), std::string::npos) << o.out;
}

TEST(PlotCli, EnsembleBandsAreTheStandardErrorOverRuns)
{
  // two runs at 100 cm/s, F = 20000 z and 40000 z: the ensemble's band is mean +- |a - b| / 2 z
  const fs::path in = fresh("ens_in"), out = fresh("ens_out");
  write(in / "a.csv", trace_text(100, 20000, 0, 0, 1));
  write(in / "b.csv", trace_text(100, 40000, 0, 0, 2));
  const Outcome o = run_plot({"force", in.string(), "--ensemble", "--out", out.string(), "--no-run"});
  ASSERT_EQ(o.status, 0) << o.err;
  const auto b = block(out / "force.dat", 0);    // x, mean, mean - se, mean + se in 10^5 dyne
  ASSERT_GT(b.size(), 400u);
  for (const auto &row : b)
    if (row[0] > 0.5) {
      // bins of 0.01 cm with one sample each, off the centre by up to 0.005 cm
      EXPECT_NEAR(row[1], 0.3 * row[0], 0.3 * 0.006);
      EXPECT_NEAR(row[3] - row[1], 0.1 * row[0], 0.1 * 0.011);
    }
  EXPECT_NE(slurp(out / "force.gp").find("standard error over runs"), std::string::npos);
  EXPECT_EQ(run_plot({"force", in.string(), "--ensemble", "--each", "--out", out.string()}).status, 2);
}
