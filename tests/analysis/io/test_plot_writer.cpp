// The figure library (io/plot_writer.h): gnuplot quoting, the generic figures write what
// they are given, gnuplot makes non-empty PNG and SVG (skipped without gnuplot), and a
// failing or a missing gnuplot and an unwritable folder give clear errors naming the
// script or the folder.
#include "plot_test_files.h"
#include "plot_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

using namespace granpen;
using namespace plot_test;
namespace fs = std::filesystem;

namespace {

const fs::path ROOT = GRANPEN_PLOT_WRITER_TEST_DIR;

fs::path fresh(const std::string &name) { return fresh_folder(ROOT, name); }

}    // namespace

// ---------------------------------------------------------------- the library

TEST(PlotWriter, QuotesAndLiterals)
{
  EXPECT_EQ(gp_quote("a \"b\" \\ c"), "\"a \\\"b\\\" \\\\ c\"");
  EXPECT_EQ(gp_quote("two\nlines"), "\"two\\nlines\"");
  EXPECT_EQ(gp_literal("bench_mu0.3_s1"), "\"bench\\\\_mu0.3\\\\_s1\"");
  EXPECT_EQ(gp_number(NAN), "NaN");
  EXPECT_EQ(gp_number(2.5e-7), "2.5e-07");
  EXPECT_EQ(plot_shade("#1f77b4", 0, 1), "#1f77b4");
  EXPECT_NE(plot_shade("#1f77b4", 0, 2), plot_shade("#1f77b4", 1, 2));
}

TEST(PlotWriter, SeriesFigureWritesItsNumbersAndScript)
{
  const fs::path d = fresh("lib_series");
  SeriesFigure fig;
  fig.name = "gap";
  fig.title = "measured, simulated, corrected";
  SeriesPanel p;
  p.xlabel = "z (cm)";
  p.ylabel = "F (dyne)";
  PlotSeries s;
  s.title = "measured";
  s.x = {0, 1, 2};
  s.y = {1, 2, NAN};
  s.band_lo = {0.5, 1.5, 2.5};
  s.band_hi = {1.5, 2.5, 3.5};
  s.band_title = "± sd";
  PlotSeries e;
  e.title = "simulated";
  e.style = "points";
  e.x = {0.5, 1.5};
  e.y = {10, 20};
  e.y_err = {1, 2};
  p.series = {s, e, PlotSeries{}};    // an empty series is left out
  PlotHBand hb;
  hb.lo = 0.8, hb.hi = 1.2, hb.title = "1 ± 0.2";
  p.hbands.push_back(hb);
  PlotGuide g;
  g.expression = "2*x";
  g.title = "guide";
  p.guides.push_back(g);
  fig.panels = {p};
  const PlotFiles f = series_figure(fig);
  ASSERT_EQ(f.blocks.size(), 2u);
  const PlotResult r = write_plot(d.string(), f, false);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_TRUE(r.written);
  EXPECT_FALSE(r.ran);
  const auto b0 = block(d / "gap.dat", 0), b1 = block(d / "gap.dat", 1);
  ASSERT_EQ(b0.size(), 3u);
  EXPECT_EQ(b0[1], (std::vector<double>{1, 2, 1.5, 2.5}));
  EXPECT_TRUE(std::isnan(b0[2][1]));
  ASSERT_EQ(b1.size(), 2u);
  EXPECT_EQ(b1[1], (std::vector<double>{1.5, 20, 2}));
  const std::string gp = slurp(d / "gap.gp");
  EXPECT_NE(gp.find("data = \"gap.dat\""), std::string::npos);
  EXPECT_NE(gp.find("data index 0 using 1:3:4 with filledcurves"), std::string::npos);
  EXPECT_NE(gp.find("data index 1 using 1:2:3 with yerrorbars"), std::string::npos);
  EXPECT_NE(gp.find("2*x with lines"), std::string::npos);
  EXPECT_NE(gp.find("keyentry"), std::string::npos);
  EXPECT_NE(gp.find("set xlabel \"z (cm)\""), std::string::npos);
  EXPECT_NE(gp.find("formats"), std::string::npos);
}

TEST(PlotWriter, BarChartWritesValuesAndLabels)
{
  const fs::path d = fresh("lib_bars");
  BarChart c;
  c.name = "explained";
  c.ylabel = "fraction of the gap explained";
  c.labels = {"wall friction", "grain shape", "rest"};
  c.values = {0.5, 0.3, -0.1};
  c.errors = {0.05, 0.1, 0.02};
  c.colours = {"#ff0000"};
  const PlotResult r = write_plot(d.string(), bar_chart(c), false);
  ASSERT_TRUE(r.ok()) << r.error;
  const auto rows = block(d / "explained.dat", 0);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0], (std::vector<double>{0, 0.5, 0.05, (double) 0xff0000}));
  EXPECT_EQ(rows[2][1], -0.1);
  const std::string gp = slurp(d / "explained.gp");
  EXPECT_NE(gp.find("\"wall friction\" 0, \"grain shape\" 1, \"rest\" 2"), std::string::npos);
  c.labels[2] = "k_z";    // labels are literal text
  EXPECT_NE(bar_chart(c).body.find("\"k\\\\_z\" 2"), std::string::npos);
  EXPECT_NE(gp.find("with boxes"), std::string::npos);
}

TEST(PlotWriter, GnuplotMakesPngAndSvg)
{
  if (!have_gnuplot()) GTEST_SKIP() << "gnuplot with pngcairo and svg not available";
  const fs::path d = fresh("lib_run");
  SeriesFigure fig;
  fig.name = "two_panels_and_inset";
  fig.title = "two panels, an inset";
  SeriesPanel a, b, in;
  PlotSeries s;
  s.title = "x^2";
  for (int i = 1; i <= 20; ++i) s.x.push_back(i), s.y.push_back(i * i), s.band_lo.push_back(i * i * 0.9),
                                 s.band_hi.push_back(i * i * 1.1);
  a.series = {s};
  b.series = {s};
  b.logx = b.logy = true;
  b.key = "column";
  in.series = {s};
  in.at_x = 0.1, in.at_y = 0.5, in.at_w = 0.2, in.at_h = 0.3;
  in.key = "off";
  fig.panels = {a, b, in};
  fig.grid_width = 0.8;
  const PlotResult r = write_plot(d.string(), series_figure(fig));
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_TRUE(r.ran);
  EXPECT_TRUE(non_empty(r.png) && is_png(r.png));
  EXPECT_TRUE(non_empty(r.svg) && is_svg(r.svg));

  BarChart c;
  c.name = "bars";
  c.labels = {"a_b", "c"};
  c.values = {1, 2};
  c.errors = {0.1, 0.2};
  PlotGuide g;
  g.expression = "1.5", g.title = "total";
  c.guides = {g};
  const PlotResult rb = write_plot(d.string(), bar_chart(c));
  ASSERT_TRUE(rb.ok()) << rb.error;
  EXPECT_TRUE(is_png(rb.png) && is_svg(rb.svg));

  // an empty figure still makes an image ("no data")
  SeriesFigure empty;
  empty.name = "empty";
  empty.panels = {SeriesPanel{}};
  EXPECT_TRUE(write_plot(d.string(), series_figure(empty)).ran);
}

TEST(PlotWriter, GnuplotFailureNamesTheScript)
{
  if (!have_gnuplot()) GTEST_SKIP() << "gnuplot not available";
  const fs::path d = fresh("lib_fail");
  PlotFiles f;
  f.name = "broken";
  f.body = "plot no_such_function(x)\n";
  const PlotResult r = write_plot(d.string(), f);
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(r.written);
  EXPECT_FALSE(r.gnuplot_missing);
  EXPECT_NE(r.error.find((d / "broken.gp").string()), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("gnuplot failed"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("no_such_function"), std::string::npos) << r.error;    // gnuplot's own words
}

TEST(PlotWriter, MissingGnuplotIsReported)
{
  const fs::path d = fresh("lib_missing");
  setenv("GRANPEN_GNUPLOT", "/nonexistent/gnuplot", 1);
  PlotFiles f;
  f.name = "lonely";
  f.body = "plot x\n";
  const PlotResult r = write_plot(d.string(), f);
  unsetenv("GRANPEN_GNUPLOT");
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(r.gnuplot_missing);
  EXPECT_TRUE(fs::exists(d / "lonely.gp") && fs::exists(d / "lonely.dat"));
  EXPECT_NE(r.error.find((d / "lonely.gp").string()), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("not found"), std::string::npos) << r.error;
}

TEST(PlotWriter, UnwritableFolder)
{
  const fs::path d = fresh("lib_unwritable");
  write(d / "file", "x");
  PlotFiles f;
  f.name = "x";
  const PlotResult r = write_plot((d / "file" / "sub").string(), f);
  EXPECT_FALSE(r.ok());
  EXPECT_FALSE(r.written);
  EXPECT_NE(r.error.find("cannot create folder"), std::string::npos) << r.error;
  f.name = "a/b";
  EXPECT_NE(write_plot(d.string(), f).error.find("figure name"), std::string::npos);
}
