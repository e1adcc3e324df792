// granpen calibration's io (io/calibration_sweep.h) on hand-made records: the fit's
// messages land after the reading's messages of their own file, in file order; the
// figures carry exactly the table's numbers (beds, means and sds per mu, pushes per v0).
#include "calibration_sweep.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace granpen;

// Three pushes read (a, b, c): a had a note, b none, c a note; between b and c a file that
// could not be read (a problem). The study could not fit b and found no alpha for c: b's
// problem goes before the unreadable file's, c's note after c's own.
TEST(CalibrationSweep, FitMessagesInFileOrder)
{
  CalibrationSweep sw;
  sw.pushes.resize(3);
  sw.push_files = {"a.csv", "b.csv", "c.csv"};
  sw.notes = {"a.csv: no rho_g", "c.csv: no bed"};
  sw.problems = {"x.csv:3: broken"};
  sw.problems_at = {0, 0, 1}, sw.notes_at = {1, 1, 2};
  CalibrationStudy st;
  st.fits.resize(3);
  st.fits[0].ok = st.fits[0].alpha_ok = true;
  st.fits[1].why = "k_z undefined";
  st.fits[2].ok = true;
  std::vector<std::string> problems, notes;
  calibration_messages(sw, st, problems, notes);
  EXPECT_EQ(problems, (std::vector<std::string>{"b.csv: k_z undefined", "x.csv:3: broken"}));
  EXPECT_EQ(notes, (std::vector<std::string>{"a.csv: no rho_g", "c.csv: no bed", "c.csv: alpha undefined, counted as 0"}));
  // a refused fit is the fit's own message, not prefixed
  st.fits[1].refused = true, st.fits[1].why = "fit_trace: z and F differ in length";
  calibration_messages(sw, st, problems, notes);
  EXPECT_EQ(problems.front(), "fit_trace: z and F differ in length");
}

// Two mu values, the second at two speeds: phi_0's figure has one point per bed and one
// mean +- sd per mu; k_z's a mean +- sd series and a pushes series per v0.
TEST(CalibrationSweep, FiguresDrawTheTable)
{
  const auto bed = [](double mu, double phi) {
    CalibrationBed b;
    b.mu = mu, b.phi_0 = phi;
    return b;
  };
  const auto push = [](double mu, double v0, double k) {
    CalibrationPush p;
    p.mu = mu, p.v0 = v0, p.k_z = k;
    return p;
  };
  const std::vector<CalibrationBed> beds = {bed(0.1, 0.59), bed(0.1, 0.60), bed(0.3, 0.57)};
  const std::vector<CalibrationPush> pushes = {push(0.1, 50, 2e4), push(0.3, 50, 3e4), push(0.3, 100, 4e4),
                                               push(0.3, 100, 5e4)};
  const auto rows = calibration_table(beds, pushes);
  const auto figs = calibration_figures(rows);
  ASSERT_EQ(figs.size(), 2u);
  EXPECT_EQ(figs[0].name, "calibration_phi0");
  EXPECT_EQ(figs[1].name, "calibration_kz");
  // phi_0: block 0 the means (x, y, y_err), block 1 the beds
  ASSERT_EQ(figs[0].blocks.size(), 2u);
  const auto &means = figs[0].blocks[0].rows;
  ASSERT_EQ(means.size(), 2u);
  EXPECT_DOUBLE_EQ(means[0][0], 0.1);
  EXPECT_NEAR(means[0][1], 0.595, 1e-12);    // the mean of 0.59 and 0.60, to rounding
  EXPECT_EQ(figs[0].blocks[1].rows.size(), 3u);
  // k_z: per v0 (50, 100) a means block and a pushes block
  ASSERT_EQ(figs[1].blocks.size(), 4u);
  EXPECT_EQ(figs[1].blocks[0].rows.size(), 2u);    // v0 = 50 at mu 0.1 and 0.3
  EXPECT_EQ(figs[1].blocks[3].rows.size(), 2u);    // the two pushes at v0 = 100
  EXPECT_NEAR(figs[1].blocks[2].rows[0][1], 4.5e4, 1e-6);    // their mean
  EXPECT_NE(figs[1].body.find("grain friction coefficient"), std::string::npos);
}
