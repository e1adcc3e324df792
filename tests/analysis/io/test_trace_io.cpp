// Trace writer and reader: a round trip, unit conversion, and every
// rejection the format demands, each naming file and line.
#include "trace_header.h"
#include "trace_reader.h"
#include "trace_writer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

using namespace granpen;

namespace {

std::string good_header(const std::string &units = "cgs")
{
  return "# granpen-trace v1\n# units = " + units +
         "\n# v0 = 100\n# D = 2.0\n# d_g = 0.4\n# rho_g = 3.0\n# g = 981\n# run = 1\n"
         "# source = test\n";
}

std::string rows(int n, double dt = 1e-4)
{
  std::ostringstream o;
  for (int i = 0; i < n; ++i) o << i * dt << "," << -0.5 + i * 0.01 << "," << 10.0 * i << "\n";
  return o.str();
}

void expect_rejected(const std::string &text, const std::string &pattern)
{
  try {
    parse_trace(text, "bad.csv");
    FAIL() << "accepted: expected an error matching " << pattern;
  } catch (InputError &e) {
    EXPECT_TRUE(std::regex_search(e.what(), std::regex(pattern))) << e.what();
  }
}

}    // namespace

TEST(TraceIO, WriterOutputReadsBackExactly)
{
  const std::string path = testing::TempDir() + "granpen_roundtrip.csv";
  TraceHeader h;
  h.units = "cgs";
  h.v0 = 100.0;
  h.D = 2.0;
  h.g = 981.0;
  h.extra = {{"d_g", "0.4"}, {"run", "3"}};
  {
    TraceWriter w;
    ASSERT_TRUE(w.open(path, h, false));
    for (int i = 0; i < 20; ++i) w.row({i * 1e-4, -0.5 + i * 0.01, std::sin(i) * 1234.5678901});
  }
  Trace t = read_trace(path);
  ASSERT_EQ(t.t.size(), 20u);
  EXPECT_EQ(t.units, "cgs");
  EXPECT_EQ(t.v0, 100.0);
  EXPECT_EQ(t.keys["run"], "3");
  for (int i = 0; i < 20; ++i) {
    EXPECT_NEAR(t.t[i], i * 1e-4, 1e-15);
    EXPECT_NEAR(t.F[i], std::sin(i) * 1234.5678901, 1e-6);
  }
  std::remove(path.c_str());
}

TEST(TraceIO, AppendKeepsHeaderAndRows)
{
  const std::string path = testing::TempDir() + "granpen_append.csv";
  TraceHeader h{"cgs", 50.0, 2.0, 981.0};
  {
    TraceWriter w;
    ASSERT_TRUE(w.open(path, h, false));
    for (int i = 0; i < 6; ++i) w.row({i * 1e-4, 0.0, 1.0});
  }
  {
    TraceWriter w;
    ASSERT_TRUE(w.open(path, h, true));
    for (int i = 6; i < 12; ++i) w.row({i * 1e-4, 0.0, 1.0});
  }
  EXPECT_EQ(read_trace(path).t.size(), 12u);
  std::remove(path.c_str());
}

TEST(TraceIO, ColumnsInAnyOrderAndExtraColumns)
{
  std::string text = good_header() + "F,extra,z,t\n";
  for (int i = 0; i < 12; ++i) text += std::to_string(i * 2.0) + ",7," + std::to_string(i * 0.1) + "," + std::to_string(i * 1e-3) + "\n";
  Trace t = parse_trace(text, "order.csv");
  EXPECT_DOUBLE_EQ(t.F[5], 10.0);
  EXPECT_DOUBLE_EQ(t.z[5], 0.5);
  EXPECT_DOUBLE_EQ(t.t[5], 5e-3);
  EXPECT_DOUBLE_EQ(t.other["extra"][3], 7.0);
}

TEST(TraceIO, SiConvertsToCgs)
{
  std::string text = "# granpen-trace v1\n# units = si\n# v0 = 1.0\n# D = 0.02\n# g = 9.81\n# d_g = 0.004\n# rho_g = 3000\nt,z,F\n";
  for (int i = 0; i < 10; ++i) text += std::to_string(i * 1e-4) + "," + std::to_string(0.001 * i) + ",0.5\n";
  Trace c = to_cgs(parse_trace(text, "si.csv"));
  EXPECT_DOUBLE_EQ(c.v0, 100.0);
  EXPECT_DOUBLE_EQ(c.D, 2.0);
  EXPECT_DOUBLE_EQ(c.g, 981.0);
  EXPECT_NEAR(c.z[3], 0.3, 1e-12);
  EXPECT_DOUBLE_EQ(c.F[0], 5.0e4);
  EXPECT_NEAR(c.number("d_g", 0), 0.4, 1e-12);
  EXPECT_NEAR(c.number("rho_g", 0), 3.0, 1e-12);
}

TEST(TraceIO, RejectsWhatTheFormatForbids)
{
  expect_rejected("# granpen-trace v2\n" + good_header().substr(19) + "t,z,F\n" + rows(12),
                  "bad\\.csv:1: first line");
  expect_rejected("# granpen-trace v1\n# units = cgs\n# v0 = 1\n# D = 2\nt,z,F\n" + rows(12),
                  "bad\\.csv:5: missing required header key 'g'");
  expect_rejected(good_header("imperial") + "t,z,F\n" + rows(12), "bad\\.csv:10: unknown unit system 'imperial'");
  expect_rejected(good_header() + "t,z,F\n" + rows(5) + "0.0005,0.0,abc\n" + rows(6, 1.0).substr(0),
                  "bad\\.csv:16: column F value 'abc' is not a number");
  expect_rejected(good_header() + "t,z,F\n" + rows(5) + "0.0005,nan,1\n" + rows(6),
                  "bad\\.csv:16: column z value 'nan' is not finite");
  expect_rejected(good_header() + "t,z,F\n" + rows(5) + "0.0005,0.1\n", "bad\\.csv:16: row has 2 fields, expected 3");
  expect_rejected(good_header() + "t,z,F\n" + rows(5) + "0.0001,0.1,1\n", "bad\\.csv:16: t does not increase");
  expect_rejected(good_header() + "t,z,F\n" + rows(9), "bad\\.csv:19: only 9 data rows");
  expect_rejected(good_header() + "t,z,G\n" + rows(12), "bad\\.csv:10: column line must name t, z and F");
  expect_rejected("", "bad\\.csv:1: empty file");
}

TEST(TraceIO, MissingFileIsNamed)
{
  EXPECT_THROW(read_trace("/nonexistent/x.csv"), InputError);
}

TEST(TraceIO, ResumeDropsRowsAfterTheRestartPointAndAppends)
{
  const std::string path = testing::TempDir() + "granpen_resume.csv";
  TraceHeader h{"cgs", 100.0, 2.0, 981.0};
  h.columns = {"z", "t", "F"};    // t not first: the resume finds it by name
  {
    TraceWriter w;
    ASSERT_TRUE(w.open(path, h, false));
    for (int i = 0; i < 20; ++i) w.row({0.01 * i, i * 1e-4, 5.0});
  }
  long dropped = -1;
  {
    TraceWriter w;
    ASSERT_TRUE(w.open_resume(path, h, 9e-4, dropped));
    for (int i = 10; i < 15; ++i) w.row({0.01 * i, i * 1e-4, 6.0});
  }
  EXPECT_EQ(dropped, 10);
  Trace t = read_trace(path);    // t increases throughout: the reader would reject repeats
  ASSERT_EQ(t.t.size(), 15u);
  EXPECT_DOUBLE_EQ(t.F[9], 5.0);
  EXPECT_DOUBLE_EQ(t.F[10], 6.0);
  // resuming into a file that does not exist starts afresh
  std::remove(path.c_str());
  {
    TraceWriter w;
    ASSERT_TRUE(w.open_resume(path, h, 9e-4, dropped));
    for (int i = 10; i < 20; ++i) w.row({0.01 * i, i * 1e-4, 6.0});
  }
  EXPECT_EQ(dropped, 0);
  EXPECT_EQ(read_trace(path).t.size(), 10u);
  std::remove(path.c_str());
}

// issue 19: what `check` used to accept. Each class with the exact message, file and line.
TEST(TraceIO, RejectsHeaderValuesNoToolCanUse)
{
  auto header = [](const std::string &v0, const std::string &D, const std::string &g, const std::string &more = "") {
    return "# granpen-trace v1\n# units = cgs\n# v0 = " + v0 + "\n# D = " + D + "\n# g = " + g + "\n" + more + "t,z,F\n";
  };
  // the column line is line 6 (7 with one more key): header errors are reported there
  expect_rejected(header("0", "2", "981") + rows(12), "^bad\\.csv:6: header v0 = 0 must be positive \\(the push speed\\)$");
  expect_rejected(header("-100", "2", "981") + rows(12), "^bad\\.csv:6: header v0 = -100 must be positive");
  expect_rejected(header("100", "0", "981") + rows(12), "^bad\\.csv:6: header D = 0 must be positive \\(the rod diameter\\)$");
  expect_rejected(header("100", "-2", "981") + rows(12), "^bad\\.csv:6: header D = -2 must be positive");
  expect_rejected(header("100", "2", "-981") + rows(12), "^bad\\.csv:6: header g = -981 must be positive \\(gravity, downwards\\)$");
  expect_rejected(header("100", "2", "0") + rows(12), "^bad\\.csv:6: header g = 0 must be positive");
  expect_rejected(header("inf", "2", "981") + rows(12), "^bad\\.csv:6: header v0 'inf' is not finite$");
  expect_rejected(header("100", "nan", "981") + rows(12), "^bad\\.csv:6: header D 'nan' is not finite$");
  expect_rejected(header("100", "2", "981", "# d_g = 0\n") + rows(12), "^bad\\.csv:7: header d_g = 0 must be positive$");
  expect_rejected(header("100", "2", "981", "# rho_g = three\n") + rows(12), "^bad\\.csv:7: header rho_g 'three' is not a number$");
  expect_rejected(header("100", "2", "981", "# mu = -0.1\n") + rows(12), "^bad\\.csv:7: header mu = -0.1 must be zero or positive$");
  EXPECT_NO_THROW(parse_trace(header("100", "2", "981", "# mu = 0\n") + rows(12), "ok.csv"));
}

TEST(TraceIO, RejectsAHeaderKeyGivenTwice)
{
  expect_rejected(good_header() + "# v0 = 200\nt,z,F\n" + rows(12),
                  "^bad\\.csv:10: header key 'v0' given twice \\(first at line 3\\)$");
  // also a key no tool reads: a file that says two things is wrong whichever is read
  expect_rejected(good_header() + "# run = 2\nt,z,F\n" + rows(12),
                  "^bad\\.csv:10: header key 'run' given twice \\(first at line 8\\)$");
  expect_rejected(good_header() + "t,z,F,z\n" + rows(12), "^bad\\.csv:10: column 'z' named twice$");
}

TEST(TraceIO, RejectsACommaDecimalRowNamingItsLine)
{
  // a row written with a decimal comma (0,0005 for 0.0005) has more fields than columns:
  // it used to be read as its first three fields, or dropped
  expect_rejected(good_header() + "t,z,F\n" + rows(5) + "0,0005,0,1,1,5\n" + rows(6, 1.0),
                  "^bad\\.csv:16: row has 6 fields, expected 3 \\(a comma used as decimal separator\\? the decimal mark is '\\.'\\)$");
  expect_rejected(good_header() + "t,z,F\n" + rows(5) + "0.0005,0.1,1,\n" + rows(6, 1.0),
                  "^bad\\.csv:16: row has 4 fields, expected 3");
}

TEST(TraceIO, RejectsADepthThatDecreasesOverThePush)
{
  // z is depth, growing as the rod goes in; a height column (sign flipped) shrinks: error
  std::string flipped;
  for (int i = 0; i < 12; ++i) flipped += std::to_string(i * 1e-4) + "," + std::to_string(0.5 - i * 0.01) + ",1\n";
  expect_rejected(good_header() + "t,z,F\n" + flipped,
                  "^bad\\.csv:22: z decreases over the push \\(0\\.5 at line 11, 0\\.39 at the last row\\): z is the depth");
  // a constant depth (a rod held still) and a noisy depth that ends deeper are fine
  std::string still, noisy;
  for (int i = 0; i < 12; ++i) {
    still += std::to_string(i * 1e-4) + ",0.2,1\n";
    noisy += std::to_string(i * 1e-4) + "," + std::to_string(0.01 * i + (i % 2 ? -0.03 : 0.0)) + ",1\n";
  }
  EXPECT_NO_THROW(parse_trace(good_header() + "t,z,F\n" + still, "still.csv"));
  EXPECT_NO_THROW(parse_trace(good_header() + "t,z,F\n" + noisy, "noisy.csv"));
}

TEST(TraceIO, ScanAgreesWithReadAndKeepsNoRows)
{
  const std::string path = testing::TempDir() + "granpen_scan.csv";
  {
    std::ofstream f(path);
    f << "# granpen-trace v1\n# units = si\n# v0 = 1\n# D = 0.02\n# g = 9.81\nt,z,F\n";
    for (int i = 0; i < 50; ++i) f << i * 1e-4 << "," << -0.005 + i * 1e-4 << "," << std::sin(0.3 * i) << "\n";
  }
  const Trace t = to_cgs(read_trace(path));
  const TraceSummary s = to_cgs(scan_trace(path));
  EXPECT_EQ(s.rows, t.t.size());
  EXPECT_TRUE(s.header.t.empty());
  EXPECT_EQ(s.header.v0, t.v0);
  EXPECT_EQ(s.z_first, t.z.front());
  EXPECT_EQ(s.z_last, t.z.back());
  EXPECT_EQ(s.t_last, t.t.back());
  EXPECT_EQ(s.F_max, *std::max_element(t.F.begin(), t.F.end()));
  // the same rejections, from the same parser
  {
    std::ofstream f(path, std::ios::app);
    f << "0.1,0,1,2\n";
  }
  try {
    scan_trace(path);
    FAIL() << "accepted";
  } catch (InputError &e) {
    EXPECT_TRUE(std::regex_search(e.what(), std::regex(":57: row has 4 fields, expected 3"))) << e.what();
  }
  std::remove(path.c_str());
}

// The header alone: of a trace of one row (too few for read_trace) its keys and columns as
// read_trace gives them for the same header with enough rows; a broken header is the same
// named error; a missing file is named.
TEST(TraceIO, HeaderAloneAgreesWithReadAndChecksTheHeader)
{
  const std::string path = testing::TempDir() + "granpen_header.csv";
  const auto write = [&](const std::string &text) { std::ofstream(path) << text; };
  write(good_header() + "t,z,F\n" + rows(1));
  EXPECT_THROW(read_trace(path), InputError);    // one row: not a trace to read_trace
  const Trace h = read_trace_header(path);
  write(good_header() + "t,z,F\n" + rows(20));
  const Trace t = read_trace(path);
  EXPECT_EQ(h.keys, t.keys);
  EXPECT_EQ(h.columns, t.columns);
  EXPECT_EQ(h.units, t.units);
  EXPECT_EQ(h.v0, t.v0);
  EXPECT_EQ(h.path, path);
  EXPECT_TRUE(h.t.empty() && h.z.empty() && h.F.empty());
  write("# granpen-trace v1\n# units = cgs\n# v0 = 100\n# v0 = 50\n# D = 2\n# g = 981\nt,z,F\n");
  try {
    read_trace_header(path);
    FAIL() << "accepted a key given twice";
  } catch (InputError &e) {
    EXPECT_TRUE(std::regex_search(e.what(), std::regex(":4: header key 'v0' given twice"))) << e.what();
  }
  std::remove(path.c_str());
  EXPECT_THROW(read_trace_header(path), InputError);
}

TEST(TraceIO, ALineLongerThanTheLimitIsNamedNotAllocated)
{
  expect_rejected(good_header() + "t,z,F\n" + rows(5) + std::string(kMaxTraceLine + 10, '1') + "\n",
                  "^bad\\.csv:16: line longer than 1048576 bytes: not a trace$");
  // a long line under the limit is read whole (it is read in pieces)
  const std::string source(20000, 'x');
  const Trace t = parse_trace(good_header() + "# note = " + source + "\nt,z,F\n" + rows(12), "long.csv");
  EXPECT_EQ(t.keys.at("note"), source);
  EXPECT_EQ(t.t.size(), 12u);
}

TEST(TraceIO, MoreRowsThanTheLimitIsNamed)
{
  // the limit is kMaxTraceRows (10 million); a small one here, through the same code
  try {
    parse_trace(good_header() + "t,z,F\n" + rows(30), "big.csv", 20);
    FAIL() << "accepted";
  } catch (InputError &e) {
    EXPECT_TRUE(std::regex_search(e.what(), std::regex("^big\\.csv:31: more than 20 data rows \\(the limit of a trace read into memory")))
        << e.what();
  }
  EXPECT_EQ(parse_trace(good_header() + "t,z,F\n" + rows(20), "ok.csv", 20).t.size(), 20u);
}

// a kill or a full disk can cut the last row short; resuming must not keep half a row
// (here one whose t, read as far as it goes, is before the restart point)
TEST(TraceIO, ResumeDropsALastRowCutShort)
{
  const std::string path = testing::TempDir() + "granpen_resume_cut.csv";
  TraceHeader h{"cgs", 100.0, 2.0, 981.0};
  {
    TraceWriter w;
    ASSERT_TRUE(w.open(path, h, false));
    for (int i = 0; i < 8; ++i) w.row({i * 1e-4, 0.01 * i, 5.0});
  }
  {
    std::ofstream f(path, std::ios::app);
    f << "0.0008,0.0";    // row 8 cut after its z: no F, no '\n'
  }
  long dropped = -1;
  {
    TraceWriter w;
    ASSERT_TRUE(w.open_resume(path, h, 9e-4, dropped));
    for (int i = 8; i < 14; ++i) w.row({i * 1e-4, 0.01 * i, 6.0});
  }
  EXPECT_EQ(dropped, 1);
  const Trace t = read_trace(path);
  ASSERT_EQ(t.t.size(), 14u);
  EXPECT_DOUBLE_EQ(t.F[7], 5.0);
  EXPECT_DOUBLE_EQ(t.F[8], 6.0);
  EXPECT_DOUBLE_EQ(t.z[8], 0.08);
  std::remove(path.c_str());
}

// A trace without t (a depth-sampled import with neither time nor speed) is read only when
// its header says so (t_from = none): z and F as written, no t, and require_t names it;
// without that key a missing t is the error it always was
TEST(TraceIO, UntimedTraceOnlyWhenTheHeaderSaysSo)
{
  std::ostringstream zf;
  for (int i = 0; i < 12; ++i) zf << -0.5 + i * 0.01 << "," << 10.0 * i << "\n";
  const Trace tr = parse_trace(good_header() + "# t_from = none\nz,F\n" + zf.str(), "untimed.csv");
  EXPECT_FALSE(tr.has_t());
  EXPECT_TRUE(tr.t.empty());
  ASSERT_EQ(tr.z.size(), 12u);
  EXPECT_DOUBLE_EQ(tr.z[11], -0.5 + 11 * 0.01);
  EXPECT_DOUBLE_EQ(tr.F[11], 110.0);
  try {
    require_t(tr, "granpen gap");
    FAIL() << "a trace without t passed require_t";
  } catch (InputError &e) {
    EXPECT_TRUE(std::regex_search(e.what(), std::regex("^untimed\\.csv: no t column \\(t_from = none.*granpen gap needs t")))
        << e.what();
  }
  EXPECT_NO_THROW(require_t(parse_trace(good_header() + "t,z,F\n" + rows(12), "timed.csv"), "granpen gap"));
  expect_rejected(good_header() + "z,F\n" + zf.str(), "bad\\.csv:10: column line must name t, z and F");
  expect_rejected(good_header() + "# t_from = none\nt,z,F\n" + rows(12), "bad\\.csv:11: header t_from = none, but the column line names t");
}

namespace {

// fix ave/time output with three value columns over 12 rows: column c of row i is c * 100 + i
std::string ave_time_text()
{
  std::ostringstream o;
  o << "# Time-averaged data for fix arr\n# TimeStep c_a[1] c_a[2] c_b\n";
  for (int i = 0; i < 12; ++i) o << 1000 + 10 * i << " " << 100 + i << " " << 200 + i << " " << 300 + i << "\n";
  return o.str();
}

AveTimeSpec ave_spec(const std::string &column)
{
  AveTimeSpec spec;
  spec.column = column, spec.v0 = 100, spec.D = 2, spec.g = 981, spec.dt = 1e-6, spec.step0 = 1000;
  return spec;
}

}    // namespace

// Two routes: the table read once and each column taken from it equals parse_ave_time of
// that column alone, value for value (the same parse, so exactly); and the table keeps only
// the columns asked for, in the order asked
TEST(TraceIO, AveTimeTableReadOnceAgreesWithEachColumnAlone)
{
  const std::string text = ave_time_text();
  const AveTimeTable table = parse_ave_time_table(text, "arr.txt", {"c_b", "c_a[1]", ""});
  ASSERT_EQ(table.names, (std::vector<std::string>{"c_b", "c_a[1]", "c_a[1]"}));
  ASSERT_EQ(table.steps.size(), 12u);
  for (const std::string column : {"c_b", "c_a[1]", ""}) {
    const Trace once = ave_time_trace(table, ave_spec(column));
    const Trace alone = parse_ave_time(text, "arr.txt", ave_spec(column));
    EXPECT_EQ(once.t, alone.t) << column;
    EXPECT_EQ(once.z, alone.z) << column;
    EXPECT_EQ(once.F, alone.F) << column;
  }
  const Trace b = ave_time_trace(table, ave_spec("c_b"));
  EXPECT_EQ(b.F.front(), 300.0);
  EXPECT_EQ(b.F.back(), 311.0);
  EXPECT_DOUBLE_EQ(b.t.back(), 110 * 1e-6);    // (1110 - step0) dt
}

TEST(TraceIO, AveTimeTableNamesAColumnNotThere)
{
  try {
    parse_ave_time_table(ave_time_text(), "arr.txt", {"c_a[1]", "c_c"});
    FAIL() << "accepted a column the file lacks";
  } catch (InputError &e) {
    EXPECT_NE(std::string(e.what()).find("arr.txt:2: no column 'c_c' (columns: c_a[1] c_a[2] c_b)"), std::string::npos) << e.what();
  }
  // a trace of a column the table did not keep is the caller's error, named
  const AveTimeTable table = parse_ave_time_table(ave_time_text(), "arr.txt", {"c_a[1]"});
  EXPECT_THROW(ave_time_trace(table, ave_spec("c_b")), InputError);
}
