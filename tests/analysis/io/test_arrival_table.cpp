// io/arrival_table.h: observe/arrival.lmp's files read back (the times on the trace's clock,
// each ring's columns), and every malformed input refused with the file and key named.
#include "arrival_table.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace fs = std::filesystem;
using granpen::InputError;
using granpen::read_arrival_table;

namespace {

const char *INFO = "# granpen arrival: rings about the rod axis\nstep0 = 1000\ndt = 2e-6\nradii = 1.5 2.5\nwidth = 0.5\nlayer = 1.5\n";

// a push's trace stem in a fresh folder, with the info text and a table of rows from step
// 1000 every 10 steps: ring 1's kinetic energy the row index, ring 2's ten times it
std::string write_push(const std::string &name, const std::string &info, int rows = 12, const std::string &head = "")
{
  const fs::path dir = fs::temp_directory_path() / ("granpen_arrival_table_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string stem = (dir / "push.csv").string();
  std::ofstream(stem + ".arrival.info") << info;
  std::ofstream t(stem + ".arrival.txt");
  t << "# Time-averaged data for fix arr_out\n"
    << (head.empty() ? "# TimeStep c_arr_1[1] c_arr_1[2] c_arr_2[1] c_arr_2[2]" : head) << "\n";
  for (int i = 0; i < rows; ++i) t << 1000 + 10 * i << " " << i << " " << -i << " " << 10 * i << " " << -10 * i << "\n";
  return stem;
}

std::string refusal(const std::string &stem)
{
  try {
    read_arrival_table(stem, 100, 2, 981);
  } catch (const InputError &e) {
    return e.what();
  }
  return "";
}

}    // namespace

TEST(ArrivalTable, ReadsTheRingsOnTheTracesClock)
{
  const auto a = read_arrival_table(write_push("ok", INFO), 100, 2, 981);
  ASSERT_EQ(a.radii.size(), 2u);
  EXPECT_DOUBLE_EQ(a.radii[1], 2.5);
  EXPECT_DOUBLE_EQ(a.width, 0.5);
  EXPECT_DOUBLE_EQ(a.layer, 1.5);
  ASSERT_EQ(a.t.size(), 12u);
  // t = (step - step0) dt: the first row at the push's first step is t = 0
  EXPECT_DOUBLE_EQ(a.t[0], 0.0);
  EXPECT_NEAR(a.t[3], 30 * 2e-6, 1e-18);
  ASSERT_EQ(a.ke.size(), 2u);
  EXPECT_DOUBLE_EQ(a.ke[0][5], 5);
  EXPECT_DOUBLE_EQ(a.ke[1][5], 50);
  EXPECT_DOUBLE_EQ(a.pv[1][5], -50);
}

TEST(ArrivalTable, RefusesWhatItCannotRead)
{
  EXPECT_NE(refusal(write_push("nostep", "dt = 2e-6\nradii = 1.5 2.5\nwidth = 0.5\nlayer = 1.5\n")).find("no key 'step0'"),
            std::string::npos);
  EXPECT_NE(refusal(write_push("late", "step0 = 1100\ndt = 2e-6\nradii = 1.5 2.5\nwidth = 0.5\nlayer = 1.5\n")).find("step0 lies after"),
            std::string::npos);
  EXPECT_NE(refusal(write_push("order", "step0 = 1000\ndt = 2e-6\nradii = 2.5 1.5\nwidth = 0.5\nlayer = 1.5\n")).find("increasing"),
            std::string::npos);
  EXPECT_NE(refusal(write_push("word", "step0 = 1000\ndt = 2e-6\nradii = 1.5 two\nwidth = 0.5\nlayer = 1.5\n")).find("radii: 'two' is not a number"),
            std::string::npos);
  EXPECT_NE(refusal(write_push("twice", std::string(INFO) + "dt = 1e-6\n")).find(":7: key 'dt' given twice"), std::string::npos);
  // three rings named, the table has two: the missing column named with the file and line
  const std::string three = "step0 = 1000\ndt = 2e-6\nradii = 1.5 2.5 3.5\nwidth = 0.5\nlayer = 1.5\n";
  EXPECT_NE(refusal(write_push("cols", three)).find("no column 'c_arr_3[1]'"), std::string::npos);
  const std::string stem = write_push("gone", INFO);
  fs::remove(stem + ".arrival.txt");
  EXPECT_NE(refusal(stem).find("push.csv.arrival.txt"), std::string::npos);
}
