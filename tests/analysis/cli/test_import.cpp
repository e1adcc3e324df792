// granpen import (docs/measurements.md): synthetic traces written out in instrument-like
// layouts (units, delimiters, decimal comma, key=value rows, time-based without a
// position, a force offset, a surface not at the instrument's zero, an end of push with a
// deceleration spike and a retraction) and imported back through granpen-cli must equal
// the originals within the resolution each layout allows; every class of bad input is a
// named error with exit status 1 and nothing written. The files are built here. The
// kernels on arrays: tests/analysis/core/test_instrument_import.cpp.
#include "trace_reader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <sys/resource.h>

namespace fs = std::filesystem;

namespace {

const fs::path ROOT = GRANPEN_IMPORT_DIR;
const std::string CLI = GRANPEN_CLI;

// The original: a push in cgs at v0 = 100 cm/s written every 1e-4 s, as the simulations
// write it: z from -0.49 to 3.5 cm, F = 0 above the surface, rising with z below it.
struct Original {
  double v0 = 100.0, dt = 1e-4;
  std::vector<double> t, z, F;
  Original()
  {
    for (int i = 1; i <= 400; ++i) {
      t.push_back(i * dt);
      z.push_back(-0.5 + v0 * i * dt);
      const double d = z.back();
      F.push_back(d <= 1e-12 ? 0.0 : 5000.0 * d * (1.0 + 0.2 * std::sin(40.0 * d)));
    }
  }
};
const Original ORIG;

fs::path fresh(const std::string &name)
{
  const fs::path d = ROOT / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

void write(const fs::path &p, const std::string &text)
{
  std::ofstream o(p, std::ios::binary);
  o << text;
  ASSERT_TRUE(o.good()) << p;
}

std::string slurp(const fs::path &p)
{
  std::ifstream in(p, std::ios::binary);
  std::ostringstream o;
  o << in.rdbuf();
  return o.str();
}

std::string fmt(const char *f, double v)
{
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

// runs granpen-cli with args; the exit status, stdout and stderr
struct CliRun {
  int status;
  std::string out, err;
};
CliRun cli(const fs::path &dir, const std::string &args)
{
  const std::string o = (dir / "stdout.txt").string(), e = (dir / "stderr.txt").string();
  const int rc = std::system((CLI + " " + args + " > '" + o + "' 2> '" + e + "'").c_str());
  CliRun r{WIFEXITED(rc) ? WEXITSTATUS(rc) : -1, slurp(o), slurp(e)};
  fs::remove(o);
  fs::remove(e);
  return r;
}

// Compares an imported trace with the original: t from the first row, z within z_tol
// (the surface's resolution), F within f_rel of the largest force (the printed digits).
// Rows of the original beyond the imported trace's end are allowed up to `lost` (the end
// cut by the speed rule); the import may hold no row beyond the original's end.
void expect_equal(const granpen::Trace &tr, std::size_t first, double t_shift, double z_tol, double f_rel,
                  std::size_t lost)
{
  const double fmax = 5000.0 * 3.5 * 1.2;
  ASSERT_GE(tr.t.size() + lost, ORIG.t.size() - first) << "too many rows cut";
  ASSERT_LE(tr.t.size(), ORIG.t.size() - first) << "rows beyond the original's end";
  for (std::size_t i = 0; i < tr.t.size(); ++i) {
    const std::size_t k = first + i;
    ASSERT_NEAR(tr.t[i] + t_shift, ORIG.t[k], 1e-9) << "row " << i;
    ASSERT_NEAR(tr.z[i], ORIG.z[k], z_tol) << "row " << i;
    ASSERT_NEAR(tr.F[i], ORIG.F[k], f_rel * fmax) << "row " << i;
  }
}

// the files in d other than the named ones (temporaries included)
std::vector<std::string> listing(const fs::path &d)
{
  std::vector<std::string> o;
  if (fs::exists(d))
    for (const auto &e : fs::directory_iterator(d)) o.push_back(e.path().filename().string());
  return o;
}

}    // namespace

// ---- round trips through granpen-cli

// A DAQ at 100 kHz: semicolon-delimited, decimal comma, metadata header lines, SI units
// (N, mm from the crosshead's own zero), a force offset; surface from a force threshold;
// window-averaged back onto the 1e-4 s grid; the push ends with a deceleration (force
// spike) and a retraction, which are cut.
TEST(ImportRoundTrip, DaqSemicolonDecimalCommaWindowed)
{
  const fs::path d = fresh("daq");
  const double offset_N = 0.37, x0_mm = 123.4, sub = 10;    // 10 instrument rows per window
  std::string s = "Device: DAQ-9000\nOperator: lab\nDate: 2026-11-25\nRate: 100 kHz\n";
  s += "Zeit [s];Kraft [N];Weg [mm];Status\n";
  auto row = [&](double t, double F_dyne, double z_cm) {
    std::string r = fmt("%.7f", t) + ";" + fmt("%.9f", F_dyne * 1e-5 + offset_N) + ";" + fmt("%.6f", x0_mm + 10 * (z_cm + 0.5)) + ";ok\n";
    for (auto &c : r)
      if (c == '.') c = ',';
    return r;
  };
  s += row(0.0, 0.0, -0.5);
  const double dts = ORIG.dt / sub;
  double t = 0.0;
  for (std::size_t i = 0; i < ORIG.t.size(); ++i)
    for (int j = 1; j <= sub; ++j) {
      t = (i * sub + j) * dts;
      s += row(t, ORIG.F[i], -0.5 + ORIG.v0 * t);
    }
  // the rod halts: the speed falls, the force spikes; then it retracts and unloads
  double z = ORIG.z.back();
  for (int j = 1; j <= 40; ++j) {
    t += dts;
    z += ORIG.v0 * dts * (1.0 - j / 40.0);
    s += row(t, ORIG.F.back() * (1.0 + 2.0 * j / 40.0), z);
  }
  for (int j = 1; j <= 100; ++j) {
    t += dts;
    z -= ORIG.v0 * dts;
    s += row(t, ORIG.F.back() * std::max(0.0, 1.0 - j / 20.0), z);
  }
  write(d / "run_a.txt", s);
  write(d / "daq.map", "# a DAQ export\ndelimiter = semicolon\ndecimal = comma\n"
                       "time = Zeit [s]\nforce = Kraft [N]\nforce_unit = N\ndisplacement = Weg [mm]\n"
                       "position_unit = mm\ntare_rows = 200\nonset_force = 2e-5    # N: 2 dyne\n"
                       "speed_rows = 20\nwindow = 1e-4\n");
  const CliRun r = cli(d, "import " + (d / "run_a.txt").string() + " --mapping " + (d / "daq.map").string() + " --out " +
                           (d / "out").string() + " --D 2 --g 981 --v0 100 --d_g 0.4 --rho_g 2.5");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "") << "a constant speed: no warning";
  // 40 halting + 100 retracting rows cut, and at most one block (speed_rows) before them
  std::smatch cut;
  ASSERT_TRUE(std::regex_search(r.out, cut, std::regex("cut ([0-9]+) rows"))) << r.out;
  EXPECT_GE(std::stoi(cut[1]), 140);
  EXPECT_LE(std::stoi(cut[1]), 160);
  const auto tr = granpen::read_trace((d / "out" / "run_a.csv").string());
  EXPECT_EQ(tr.keys.at("d_g"), "0.4");
  EXPECT_EQ(tr.keys.at("run"), "1");
  EXPECT_EQ(tr.keys.at("source"), (d / "run_a.txt").string());
  EXPECT_DOUBLE_EQ(tr.v0, 100.0);
  // z: the threshold is met at the first instrument row below the surface, one row's
  // advance (v0 * 1e-5 s = 1e-3 cm) under it; F: 9 decimals of N = 1e-4 dyne, rounded
  // twice (the row and the offset); the last window may go with the cut block
  expect_equal(tr, 0, 0.0, ORIG.v0 * dts * 1.0001, 2e-4 / (5000.0 * 3.5 * 1.2), 2);
  EXPECT_EQ(cli(d, "check " + (d / "out").string()).status, 0);
}

// A materials tester: tab-delimited, time in ms, force in kN compressive-negative,
// crosshead in inches going down negative, the surface given as the crosshead's reading;
// one row per original row.
TEST(ImportRoundTrip, TesterTabKilonewtonInchesGivenSurface)
{
  const fs::path d = fresh("tester");
  const double offset_kN = -0.002, surface_in = -1.25;
  std::string s = "Test 7\tspecimen sand\n\nTime\tLoad\tExtension\n";
  s += "ms\tkN\tin\n";    // a units line under the names
  for (std::size_t i = 0; i < ORIG.t.size(); ++i)
    s += fmt("%.4f", 1e3 * ORIG.t[i]) + "\t" + fmt("%.12g", -(ORIG.F[i] * 1e-8) + offset_kN) + "\t" +
         fmt("%.10f", surface_in - ORIG.z[i] / 2.54) + "\n";
  write(d / "T7.tsv", s);
  write(d / "tester.map", "delimiter = tab\nheader_lines = 2\ntime = Time\ntime_unit = ms\nforce = Load\n"
                          "force_unit = kN\nforce_sign = -1\ndisplacement = Extension\nposition_unit = in\n"
                          "position_sign = -1\nsurface = -1.25\ntare_rows = 20\nspeed_rows = 10\n");
  // header_lines = 2: the names on line 3, the units line 4 is read as data
  const CliRun r = cli(d, "import " + (d / "T7.tsv").string() + " --mapping " + (d / "tester.map").string() +
                           " --out " + (d / "out").string() + " --D 2 --g 981");
  ASSERT_EQ(r.status, 1) << "line 4 (units) is text in the force column";
  EXPECT_TRUE(std::regex_search(r.err, std::regex("T7.tsv:4: force column 'Load' is not a number: 'kN'"))) << r.err;
  // the units line skipped, as a lab whose files carry one says in its mapping
  write(d / "tester.map", slurp(d / "tester.map") + "lines_after_names = 1\n");
  const CliRun ok = cli(d, "import " + (d / "T7.tsv").string() + " --mapping " + (d / "tester.map").string() +
                            " --out " + (d / "out").string() + " --D 2 --g 981");
  ASSERT_EQ(ok.status, 0) << ok.err;
  const auto tr = granpen::read_trace((d / "out" / "T7.csv").string());
  // v0 measured (none given): the mean of a push at exactly 100 cm/s
  EXPECT_NEAR(tr.v0, 100.0, 1e-3);
  // z: 10 decimals of an inch (2.54e-10 cm); F: 12 significant figures of kN
  expect_equal(tr, 0, ORIG.t[0], 1e-8, 1e-9, 0);
}

// A penetrometer logging at a fixed rate without a position: white-space delimited, no
// column names, columns by index, a stress in kPa on the cone's area, depth from v0 and
// time, surface from a force threshold; the rows after the retraction unloads are cut.
TEST(ImportRoundTrip, PenetrometerTimeBasedStress)
{
  const fs::path d = fresh("cpt");
  const double area_cm2 = M_PI, offset_kPa = 1.5;
  std::string s = "CPT sounding 12   rate 10000 Hz\n";
  for (std::size_t i = 0; i < ORIG.t.size(); ++i)
    s += "  " + fmt("%.12g", ORIG.F[i] / (area_cm2 * 1e-4 * 1e5) / 1e3 + offset_kPa) + "   7.0\n";
  for (int j = 0; j < 30; ++j) s += "  " + fmt("%.12g", offset_kPa) + "   0.0\n";    // rod out
  write(d / "cpt12.dat", s);
  write(d / "cpt.map", "delimiter = whitespace\ncolumn_names = no\nforce = #1\nforce_unit = kPa\narea = 3.14159265358979\n"
                       "area_unit = cm2\nsample_rate = 10000\ntare_rows = 20\nonset_force = 1e-6\n"
                       "v0 = 1000\nv0_unit = mm/s\n");
  const CliRun r = cli(d, "import " + (d / "cpt12.dat").string() + " --mapping " + (d / "cpt.map").string() +
                           " --out " + (d / "out").string() + " --D 2 --g 981 --run 4");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("cut 30 rows"), std::string::npos) << r.out;
  const auto tr = granpen::read_trace((d / "out" / "cpt12.csv").string());
  EXPECT_EQ(tr.keys.at("run"), "4");
  // z: the threshold is met at the first row below the surface, one sample's advance
  // (v0 / 10 kHz = 1e-2 cm) below it, so z is that much short; F: 12 figures
  expect_equal(tr, 0, ORIG.t[0], ORIG.v0 * 1e-4 * 1.0001, 1e-9, 0);
}

// Rows of key=value pairs (a logger's format) in cgs with a force offset; by name.
TEST(ImportRoundTrip, KeyValueRows)
{
  const fs::path d = fresh("kv");
  std::string s = "logger v2\nstart\n";
  for (std::size_t i = 0; i < ORIG.t.size(); ++i)
    s += "t=" + fmt("%.6f", ORIG.t[i]) + ", F=" + fmt("%.10g", ORIG.F[i] + 250.0) + ", pos=" +
         fmt("%.10g", 7.0 + ORIG.z[i]) + ", v=" + fmt("%.10g", ORIG.v0) + "\n";
  write(d / "kv1.log", s);
  write(d / "kv.map", "delimiter = keyvalue\ntime = t\nforce = F\nforce_unit = dyne\ndisplacement = pos\n"
                      "position_unit = cm\nspeed = v\nspeed_unit = cm/s\nsurface = 7\ntare_rows = 10\n"
                      "speed_rows = 10\nv0 = 100\nv0_unit = cm/s\n");
  const CliRun r = cli(d, "import " + (d / "kv1.log").string() + " --mapping " + (d / "kv.map").string() +
                           " --out " + (d / "out").string() + " --D 2 --g 981");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("speed 100 cm/s"), std::string::npos) << r.out;
  const auto tr = granpen::read_trace((d / "out" / "kv1.csv").string());
  expect_equal(tr, 0, ORIG.t[0], 1e-8, 1e-9, 0);
  // the same in SI: the trace's cgs view (trace_reader's to_cgs) is the cgs import's
  const CliRun si = cli(d, "import " + (d / "kv1.log").string() + " --mapping " + (d / "kv.map").string() +
                               " --out " + (d / "si").string() + " --units si --D 0.02 --g 9.81");
  ASSERT_EQ(si.status, 0) << si.err;
  const auto tsi = granpen::read_trace((d / "si" / "kv1.csv").string());
  EXPECT_EQ(tsi.units, "si");
  EXPECT_NEAR(tsi.v0, 1.0, 1e-12);
  expect_equal(granpen::to_cgs(tsi), 0, ORIG.t[0], 1e-8, 1e-9, 0);
}

// --dry-run writes nothing and prints the header it would write
TEST(ImportCli, DryRunWritesNothing)
{
  const fs::path d = fresh("dry");
  std::string s = "t,F,x\n";
  for (std::size_t i = 0; i < ORIG.t.size(); ++i)
    s += fmt("%.6f", ORIG.t[i]) + "," + fmt("%.10g", ORIG.F[i]) + "," + fmt("%.10g", ORIG.z[i]) + "\n";
  write(d / "a.csv", s);
  write(d / "m.map", "time = t\nforce = F\nforce_unit = dyne\ndisplacement = x\nposition_unit = cm\nsurface = 0\ntare_rows = 5\n");
  const CliRun r = cli(d, "import " + (d / "a.csv").string() + " --mapping " + (d / "m.map").string() + " --out " +
                           (d / "out").string() + " --D 2 --g 981 --dry-run");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("# granpen-trace v1"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(d / "out"));
}

// A speed that ripples beyond the tolerance: imported, with a warning naming the file
TEST(ImportCli, UnsteadySpeedIsWarned)
{
  const fs::path d = fresh("ripple");
  std::string s = "t,F,x\n";
  double x = -0.5;
  for (int i = 0; i < 2000; ++i) {
    const double t = i * 1e-4, v = 100.0 * (1.0 + 0.3 * std::sin(i / 30.0));
    x += v * 1e-4;
    s += fmt("%.6f", t) + "," + fmt("%.10g", x > 0 ? 1000 * x : 0.0) + "," + fmt("%.10g", x) + "\n";
  }
  write(d / "wobbly.csv", s);
  write(d / "m.map", "time = t\nforce = F\nforce_unit = dyne\ndisplacement = x\nposition_unit = cm\nsurface = 0\n"
                     "tare_rows = 5\nspeed_rows = 20\nv0 = 100\nv0_unit = cm/s\n");
  const CliRun r = cli(d, "import " + (d / "wobbly.csv").string() + " --mapping " + (d / "m.map").string() + " --out " +
                           (d / "out").string() + " --D 2 --g 981");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(std::regex_search(r.err, std::regex("warning: .*wobbly.csv: speed not constant within 5%"))) << r.err;
}

// ---- bad input: a named error (file and line), exit 1, nothing written
namespace {

struct BadCase {
  const char *name;
  std::function<std::string()> file;    // the instrument file's text
  const char *mapping;
  const char *message;                   // regex on stderr
};

std::string good_csv(const std::function<std::string(std::size_t, double, double, double)> &row)
{
  std::string s = "t,F,x\n";
  for (std::size_t i = 0; i < ORIG.t.size(); ++i) s += row(i, ORIG.t[i], ORIG.F[i], ORIG.z[i]);
  return s;
}
std::string plain(std::size_t, double t, double F, double z)
{
  return fmt("%.6f", t) + "," + fmt("%.10g", F) + "," + fmt("%.10g", z) + "\n";
}
const char *MAP = "time = t\nforce = F\nforce_unit = dyne\ndisplacement = x\nposition_unit = cm\nsurface = 0\ntare_rows = 5\n";

}    // namespace

TEST(ImportBadInput, NamedErrorNothingWritten)
{
  const std::vector<BadCase> cases = {
      {"missing_column", [] { return good_csv(plain); },
       "time = t\nforce = Force\nforce_unit = dyne\ndisplacement = x\nposition_unit = cm\nsurface = 0\n",
       "csv:1: no column 'Force' in the column names \\(t, F, x\\)"},
      {"unknown_unit", [] { return good_csv(plain); },
       "time = t\nforce = F\nforce_unit = kip\ndisplacement = x\nsurface = 0\n",
       "m.map:3: unknown force unit 'kip' \\(N, kN"},
      {"backwards", [] {
         return good_csv([](std::size_t i, double t, double F, double z) {
           return plain(i, t, F, i >= 200 && i < 210 ? z - 0.2 : z);
         });
       },
       MAP, "in.csv:202: displacement goes backwards .* advances past it again at line 212"},
      {"two_speeds", [] {
         return good_csv([](std::size_t i, double t, double F, double z) {
           return plain(i, t, F, i < 200 ? z : ORIG.z[199] + 1.5 * (z - ORIG.z[199]));
         });
       },
       MAP, "in.csv:[0-9]+: two speeds in one file"},
      {"force_text", [] {
         return good_csv([](std::size_t i, double t, double F, double z) {
           return i == 100 ? fmt("%.6f", t) + ",abc," + fmt("%.10g", z) + "\n" : plain(i, t, F, z);
         });
       },
       MAP, "in.csv:102: force column 'F' is not a number: 'abc'"},
      {"time_backwards", [] {
         return good_csv([](std::size_t i, double t, double F, double z) {
           return plain(i, i == 50 ? t - 0.001 : t, F, z);
         });
       },
       MAP, "in.csv:52: time does not increase"},
      {"no_time", [] { return good_csv(plain); }, "force = F\nonset_force = 1\n",
       "m.map: neither a time column nor a sample_rate"},
      // a data row after the rows stopped matching: the end was not one (both lines named)
      // issue 36, class 4 (silently wrong, exit 0 before): a thousands separator splits a
      // force into two fields, every column after it shifted (comma and white space)
      {"thousands_separator", [] {
         return good_csv([](std::size_t i, double t, double F, double z) {
           // F = 12345.6 written "12,345.6"
           return i == 300 ? fmt("%.6f", t) + "," + fmt("%.0f", std::floor(F / 1000.0)) + "," +
                                 fmt("%05.1f", std::fmod(F, 1000.0)) + "," + fmt("%.10g", z) + "\n"
                           : plain(i, t, F, z);
         });
       },
       MAP, "in.csv:302: row has 4 fields, the column names \\(line 1\\) name 3 \\(a thousands separator"},
      {"thousands_separator_blank", [] {
         std::string s = "t F x\n";
         for (std::size_t i = 0; i < ORIG.t.size(); ++i)
           s += fmt("%.6f", ORIG.t[i]) + " " + (i == 350 ? std::string("17 500.5") : fmt("%.10g", ORIG.F[i])) + " " +
                fmt("%.10g", ORIG.z[i]) + "\n";
         return s;
       },
       MAP, "in.csv:352: row has 4 fields, the column names \\(line 1\\) name 3"},
      // one column in two roles: the same name twice, and a name and an index of one column
      {"two_roles_by_name", [] { return good_csv(plain); }, "time = t\nforce = F\nforce_unit = dyne\nspeed = F\ndisplacement = x\n"
       "position_unit = cm\nsurface = 0\ntare_rows = 5\n", "m.map:4: speed = F is the column of force \\(line 2\\): one column, one role"},
      {"two_roles_name_and_index", [] { return good_csv(plain); }, "time = t\nforce = F\nforce_unit = dyne\nspeed = #2\n"
       "displacement = x\nposition_unit = cm\nsurface = 0\ntare_rows = 5\n",
       "csv:1: force 'F' and speed #2 are the same column \\(#2\\): one column, one role"},
      // a NUL byte inside a field (strtod stopped at it: the field's first part was read)
      {"nul_in_field", [] {
         return good_csv([](std::size_t i, double t, double F, double z) {
           return i == 100 ? fmt("%.6f", t) + "," + fmt("%.10g", F) + std::string("\0" "99", 3) + "," + fmt("%.10g", z) + "\n"
                           : plain(i, t, F, z);
         });
       },
       MAP, "in.csv:102: a NUL byte at byte [0-9]+ of the line"},
      {"nul_in_names", [] { return std::string("t,F\0,x\n", 7) + good_csv(plain).substr(6); }, MAP,
       "in.csv:1: a NUL byte at byte 4 of the line"},
      // class 6: one line of 10 MB is refused at the line bound, not read into memory
      {"line_of_10MB", [] { return good_csv(plain) + std::string(10u << 20, '7') + "\n"; }, MAP,
       "in.csv:402: line longer than 1048576 bytes"},
      // class 5 (written with exit 0 before, then refused by check): numbers that reach the
      // trace out of what a trace can hold
      {"surface_1e308", [] { return good_csv(plain); },
       "time = t\nforce = F\nforce_unit = dyne\ndisplacement = x\nposition_unit = cm\nsurface = 1e308\ntare_rows = 5\n",
       "csv:[0-9]+: the trace's z = -1e\\+308 at this row is not finite, or too large for a trace"},
      {"window_1e-20", [] { return good_csv(plain); }, "time = t\nforce = F\nforce_unit = dyne\ndisplacement = x\n"
       "position_unit = cm\nsurface = 0\ntare_rows = 5\nwindow = 1e-20\n",
       "csv:[0-9]+: window = 1e-20 s is too short for t = [0-9.e-]+ s \\(window number"},
      {"sample_rate_1e-300", [] { return good_csv(plain); }, "sample_rate = 1e-300\nforce = F\nforce_unit = dyne\n"
       "displacement = x\nposition_unit = cm\nsurface = 0\ntare_rows = 5\n",
       "csv:[0-9]+: the trace's t = [0-9.e+]+ at this row is not finite, or too large"},
      {"data_after_end", [] {
         return good_csv([](std::size_t i, double t, double F, double z) {
           return i == 200 ? std::string("paused\n") : plain(i, t, F, z);
         });
       },
       MAP, "in.csv:202: 1 fields: no force column 'F' \\(the data seemed to end at this line, but data rows come back at line 203\\)"},
  };
  for (const auto &c : cases) {
    SCOPED_TRACE(c.name);
    const fs::path d = fresh(std::string("bad_") + c.name);
    write(d / "in.csv", c.file());
    write(d / "m.map", c.mapping);
    // a good file beside the bad one: nothing of either is written
    write(d / "good.csv", good_csv(plain));
    const CliRun r = cli(d, "import " + (d / "good.csv").string() + " " + (d / "in.csv").string() + " --mapping " +
                             (d / "m.map").string() + " --out " + (d / "out").string() + " --D 2 --g 981 --v0 100");
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_TRUE(std::regex_search(r.err, std::regex(c.message))) << r.err;
    EXPECT_FALSE(fs::exists(d / "out")) << "written: " << (listing(d / "out").empty() ? "" : listing(d / "out")[0]);
    EXPECT_EQ(r.err.find("what()"), std::string::npos);
  }
}

// an output folder that existed keeps what it held and gains nothing, temporaries included
TEST(ImportBadInput, ExistingFolderKeptClean)
{
  const fs::path d = fresh("keep");
  fs::create_directories(d / "out");
  write(d / "out" / "old.csv", "kept\n");
  write(d / "good.csv", good_csv(plain));
  write(d / "bad.csv", good_csv([](std::size_t i, double t, double F, double z) {
          return i == 300 ? fmt("%.6f", t) + ",1e999," + fmt("%.10g", z) + "\n" : plain(i, t, F, z);
        }));
  write(d / "m.map", MAP);
  const CliRun r = cli(d, "import " + (d / "good.csv").string() + " " + (d / "bad.csv").string() + " --mapping " +
                              (d / "m.map").string() + " --out " + (d / "out").string() + " --D 2 --g 981 --v0 100");
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(std::regex_search(r.err, std::regex("bad.csv:302: force column 'F' is not a number: '1e999'"))) << r.err;
  EXPECT_EQ(listing(d / "out"), std::vector<std::string>{"old.csv"});
  EXPECT_EQ(slurp(d / "out" / "old.csv"), "kept\n");
}

// an output that would overwrite an input is refused before anything is written
TEST(ImportBadInput, OutputOverInputRefused)
{
  const fs::path d = fresh("over");
  write(d / "a.csv", good_csv(plain));
  write(d / "m.map", MAP);
  const std::string before = slurp(d / "a.csv");
  const CliRun r = cli(d, "import " + (d / "a.csv").string() + " --mapping " + (d / "m.map").string() + " --out " +
                           d.string() + " --D 2 --g 981 --v0 100");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_TRUE(std::regex_search(r.err, std::regex("--out .*a.csv is the input .*refusing to overwrite it"))) << r.err;
  EXPECT_EQ(slurp(d / "a.csv"), before);
}

// Streaming: a 500 000-row file (about 15 MB) is imported within a memory bound far below
// what holding it would take (the text alone, plus 24 bytes a row as doubles: > 25 MB).
// The bound, 16 MB, is the importer's fixed cost (about 6 MB resident on this machine:
// the binary's pages, a 4096-row chunk, a 64 kB write buffer) with room to spare.
TEST(ImportCli, MemoryBoundedIndependentlyOfFileSize)
{
  const fs::path d = fresh("stream");
  {
    std::ofstream o(d / "long.csv", std::ios::binary);
    o << "t,F,x\n";
    char b[96];
    for (int i = 0; i < 500000; ++i) {
      const double t = i * 1e-5, x = -0.5 + 100.0 * t;
      std::snprintf(b, sizeof b, "%.5f,%.6f,%.6f\n", t, x > 0 ? 1000.0 * x : 0.0, x);
      o << b;
    }
    ASSERT_TRUE(o.good());
  }
  write(d / "m.map", "time = t\nforce = F\nforce_unit = dyne\ndisplacement = x\nposition_unit = cm\nsurface = 0\n"
                     "tare_rows = 5\nspeed_rows = 100\nv0 = 100\nv0_unit = cm/s\n");
  const CliRun r = cli(d, "import " + (d / "long.csv").string() + " --mapping " + (d / "m.map").string() + " --out " +
                              (d / "out").string() + " --D 2 --g 981");
  ASSERT_EQ(r.status, 0) << r.err;
  struct rusage ru;
  ASSERT_EQ(getrusage(RUSAGE_CHILDREN, &ru), 0);
  EXPECT_LT(ru.ru_maxrss, 16 * 1024) << "kB resident at most in a child";
  EXPECT_GT(fs::file_size(d / "out" / "long.csv"), 10u << 20);
}

// Class 6 of issue 36: a 100 MB line cost 1.4 GB resident (std::getline grew a string to
// the line). Now a line is read in 64 kB pieces up to its 1 MiB bound and refused there:
// resident memory stays within the 16 MB bound of the streaming test above.
TEST(ImportCli, MemoryBoundedOnAHundredMegabyteLine)
{
  const fs::path d = fresh("long_line");
  {
    std::ofstream o(d / "wide.csv", std::ios::binary);
    o << "t,F,x\n0.0001,0,-0.49\n";
    const std::string piece(1u << 20, '5');
    for (int k = 0; k < 100; ++k) o << piece;
    o << "\n";
    ASSERT_TRUE(o.good());
  }
  write(d / "m.map", MAP);
  const CliRun r = cli(d, "import " + (d / "wide.csv").string() + " --mapping " + (d / "m.map").string() + " --out " +
                              (d / "out").string() + " --D 2 --g 981 --v0 100");
  fs::remove(d / "wide.csv");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_TRUE(std::regex_search(r.err, std::regex("wide.csv:3: line longer than 1048576 bytes"))) << r.err;
  EXPECT_FALSE(fs::exists(d / "out"));
  struct rusage ru;
  ASSERT_EQ(getrusage(RUSAGE_CHILDREN, &ru), 0);
  EXPECT_LT(ru.ru_maxrss, 16 * 1024) << "kB resident at most in a child";
}

// ---- a penetrometer's depth-sampled log, as a commercial logger writes it: metadata
// lines, tab-separated columns with units in the names, one row per depth step (no time),
// the force, the measured push speed and the logger's counter; the push ends with a
// deceleration (speed falling, force spiking) and the logger's own trailer after the data.
namespace {

struct DepthLog {
  double v_mm_s = 20.0;         // mean push speed
  double ripple = 0.07;         // relative amplitude of the speed's slow drift
  double wavelength_cm = 4.0;   // of that drift
  double c_N_per_cm = 0.8;      // F = c z (1 + wobble sin 3z) below the surface
  double offset_N = 0.05;       // the load cell's offset
  double wobble = 0.1;          // of the force about c z
  int air_rows = 10, push_rows = 550, decel_rows = 8;
  double step_mm = 0.2;
  std::string after_trailer;    // lines after the trailer (data coming back: an error)

  double z_cm(int i) const { return (i - air_rows + 1) * step_mm / 10.0; }
  // the speed's drift starts at the mean and ends (z = 11 cm) in a trough, 7% below it
  double speed_mm_s(double z) const { return v_mm_s * (1.0 + ripple * std::sin(2.0 * M_PI * z / wavelength_cm)); }
  double force_N(double z) const { return z > 0.0 ? c_N_per_cm * z * (1.0 + wobble * std::sin(3.0 * z)) : 0.0; }
  int header_lines() const { return 6; }
  int data_rows() const { return air_rows + push_rows + decel_rows; }
  int last_data_line() const { return header_lines() + 1 + data_rows(); }
  int trailer_line() const { return last_data_line() + 2; }    // after the '#' line

  std::string text() const
  {
    std::string s = "PENETROLOG PL-500 firmware 3.2.1\nSerial no.: 20-4471\nSounding: S12\n"
                    "Started: 2026-11-20 14:02:11\nRate setpoint: " + fmt("%.1f", v_mm_s) + " mm/s\n\n";
    s += "Depth(mm)\tForce(N)\tSpeed(mm/s)\tCount\n";
    long count = 452304468;
    for (int i = 0; i < air_rows + push_rows; ++i) {
      const double z = z_cm(i);
      count += 37 + i % 5;
      s += fmt("%.2f", 10.0 * z) + "\t" + fmt("%.6f", force_N(z) + offset_N) + "\t" + fmt("%.4f", speed_mm_s(z)) + "\t" +
           std::to_string(count) + "\n";
    }
    const double z_end = z_cm(air_rows + push_rows - 1), v_end = speed_mm_s(z_end), F_end = force_N(z_end);
    for (int j = 1; j <= decel_rows; ++j) {
      const double z = z_end + j * step_mm / 10.0;
      s += fmt("%.2f", 10.0 * z) + "\t" + fmt("%.6f", F_end * (1.0 + j / 8.0) + offset_N) + "\t" +
           fmt("%.4f", v_end * (1.0 - j / 9.0)) + "\t" + std::to_string(count += 400) + "\n";
    }
    return s + "#\n0:\n14:Transmission lost\n15:End of test\n" + after_trailer;
  }
  // t of row i: the integral of dz / v from the first row, by Simpson's rule on 200
  // sub-steps a row (the reference; the importer takes one step a row)
  double t_exact(int i) const
  {
    double t = 0.0;
    for (int k = 1; k <= i; ++k) {
      const double a = z_cm(k - 1), b = z_cm(k), h = (b - a) / 200.0;
      double sum = 0.0;
      for (int m = 0; m <= 200; ++m)
        sum += (m == 0 || m == 200 ? 1.0 : m % 2 ? 4.0 : 2.0) / (0.1 * speed_mm_s(a + m * h));
      t += sum * h / 3.0;
    }
    return t;
  }
};

const char *DEPTH_MAP = "# PENETROLOG PL-500 exports\ndelimiter = tab\ndepth = Depth(mm)\nposition_unit = mm\n"
                        "force = Force(N)\nforce_unit = N\nspeed = Speed(mm/s)\nspeed_unit = mm/s\ntare_rows = 10\n"
                        "speed_rows = 5\n";

}    // namespace

// The round trip: t is the integral of dz / v (the header says t_from = dz/v), z the
// depth, F tared; the deceleration (8 rows) is cut, the slow drift of the speed (7% off
// the mean at the end) is kept and reported; the data end at the trailer, reported.
TEST(ImportRoundTrip, DepthSampledLogWithSpeedAndTrailer)
{
  const fs::path d = fresh("depthlog");
  const DepthLog L;
  write(d / "S12.txt", L.text());
  write(d / "pl500.map", DEPTH_MAP);
  const CliRun r = cli(d, "import " + (d / "S12.txt").string() + " --mapping " + (d / "pl500.map").string() + " --out " +
                           (d / "out").string() + " --D 2 --g 981 --v0 2");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("data end at line " + std::to_string(L.last_data_line()) + "; from line " +
                       std::to_string(L.trailer_line()) + " on, not data rows: '0:'"),
            std::string::npos) << r.out;
  EXPECT_NE(r.out.find("cut 8 rows"), std::string::npos) << "the deceleration only, not the drift: " << r.out;
  EXPECT_NE(r.err.find("S12.txt: speed not constant within 5%"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("(a drift: kept, not cut)"), std::string::npos) << r.err;
  const auto tr = granpen::read_trace((d / "out" / "S12.csv").string());
  EXPECT_EQ(tr.keys.at("t_from"), "dz/v");
  EXPECT_EQ(tr.keys.at("v0_from"), "nominal");
  EXPECT_DOUBLE_EQ(tr.v0, 2.0);
  // the measured mean: about the nominal (the drift's mean over the push is near zero)
  EXPECT_NEAR(std::stod(tr.keys.at("v0_measured")), 2.0, 0.02 * 2.0);
  ASSERT_EQ((int) tr.z.size(), L.air_rows + L.push_rows);
  for (std::size_t i = 0; i < tr.z.size(); ++i) {
    // z: the printed depth exactly; F: 6 decimals of N (0.1 dyne) and the tare's rounding
    ASSERT_NEAR(tr.z[i], L.z_cm((int) i), 1e-9) << "row " << i;
    ASSERT_NEAR(tr.F[i], 1e5 * L.force_N(L.z_cm((int) i)), 0.2) << "row " << i;
    // t: each row's step at the mean of its two speeds is off the integral by about
    // h^2 k^2 ripple / 12 = 6e-6 of it (h = 0.02 cm, k = 2 pi / 4 cm), the printed speeds
    // (4 decimals of 20 mm/s) by 2.5e-6: over the 5.6 s of the push at most 5e-5 s
    ASSERT_NEAR(tr.t[i], L.t_exact((int) i), 5e-5) << "row " << i;
  }
  EXPECT_EQ(cli(d, "check " + (d / "out").string()).status, 0);
}

// Rows after the trailer that read as data: the end was not one; an error naming both lines
TEST(ImportBadInput, DataAfterTrailerNamesBothLines)
{
  const fs::path d = fresh("depthlog_after");
  DepthLog L;
  L.after_trailer = "112.40\t9.5\t18.0000\t452399999\n";
  write(d / "S13.txt", L.text());
  write(d / "pl500.map", DEPTH_MAP);
  const CliRun r = cli(d, "import " + (d / "S13.txt").string() + " --mapping " + (d / "pl500.map").string() + " --out " +
                           (d / "out").string() + " --D 2 --g 981 --v0 2");
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(std::regex_search(r.err, std::regex("S13.txt:" + std::to_string(L.trailer_line()) +
                                                  ": .*the data seemed to end at this line, but data rows come back at line " +
                                                  std::to_string(L.trailer_line() + 3))))
      << r.err;
  EXPECT_FALSE(fs::exists(d / "out"));
}

// A depth with neither a time nor a speed: no t is made up; the trace has z and F only
// (t_from = none), passes check, and a command that needs t refuses by name
TEST(ImportRoundTrip, DepthWithoutTimeOrSpeedHasNoT)
{
  const fs::path d = fresh("depth_only");
  const DepthLog L;
  write(d / "S14.txt", L.text());
  write(d / "m.map", "delimiter = tab\ndepth = Depth(mm)\nposition_unit = mm\nforce = Force(N)\ntare_rows = 10\n");
  const CliRun r = cli(d, "import " + (d / "S14.txt").string() + " --mapping " + (d / "m.map").string() + " --out " +
                           (d / "out").string() + " --D 2 --g 981 --v0 2");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto tr = granpen::read_trace((d / "out" / "S14.csv").string());
  EXPECT_EQ(tr.keys.at("t_from"), "none");
  EXPECT_FALSE(tr.has_t());
  EXPECT_EQ(tr.columns, (std::vector<std::string>{"z", "F"}));
  // without a speed nothing is cut by it: the air, the push and the deceleration
  ASSERT_EQ((int) tr.z.size(), L.air_rows + L.push_rows + L.decel_rows);
  EXPECT_NEAR(tr.z.back(), L.z_cm(L.data_rows() - 1), 1e-9);
  EXPECT_EQ(cli(d, "check " + (d / "out").string()).status, 0);
  // momentum --trace reads the trace before any dump: the refusal names the file and what needs t
  const CliRun mom = cli(d, "momentum " + (d / "none.dump").string() + " --trace " + (d / "out" / "S14.csv").string());
  EXPECT_EQ(mom.status, 1);
  EXPECT_TRUE(std::regex_search(mom.err, std::regex("S14.csv: no t column \\(t_from = none.*--trace .* needs t"))) << mom.err;
  // without a time, a window is refused, not ignored
  write(d / "w.map", slurp(d / "m.map") + "window = 1e-3\n");
  const CliRun w = cli(d, "import " + (d / "S14.txt").string() + " --mapping " + (d / "w.map").string() + " --out " +
                           (d / "out2").string() + " --D 2 --g 981 --v0 2");
  EXPECT_EQ(w.status, 1);
  EXPECT_NE(w.err.find("w.map:6: window needs a time"), std::string::npos) << w.err;
}

// key=value rows with a field without a key (a logger's counter, '%452304468', in
// microseconds) addressed by its position and used as the time
TEST(ImportRoundTrip, KeyValueRowsWithKeylessCounter)
{
  const fs::path d = fresh("kv_counter");
  std::string s = "LOGGER KV-7 v1.4\n";
  for (std::size_t i = 0; i < ORIG.t.size(); ++i)
    s += "%" + std::to_string(452304468L + (long) std::lround(ORIG.t[i] * 1e6)) + " A=" + fmt("%.10g", ORIG.F[i] + 250.0) +
         " D=" + fmt("%.10g", 7.0 + ORIG.z[i]) + "\n";
  s += "#\n0:\n15:End of test\n";
  write(d / "kv7.log", s);
  write(d / "kv.map", "delimiter = keyvalue\ntime = #1\ntime_unit = us\nforce = A\nforce_unit = dyne\n"
                      "displacement = D\nposition_unit = cm\nsurface = 7\ntare_rows = 10\nspeed_rows = 10\n");
  const CliRun r = cli(d, "import " + (d / "kv7.log").string() + " --mapping " + (d / "kv.map").string() + " --out " +
                           (d / "out").string() + " --D 2 --g 981");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("data end at line " + std::to_string(1 + ORIG.t.size())), std::string::npos) << r.out;
  const auto tr = granpen::read_trace((d / "out" / "kv7.csv").string());
  EXPECT_EQ(tr.keys.at("t_from"), "time");
  EXPECT_NEAR(tr.v0, 100.0, 1e-3) << "measured from the counter and the position";
  // t: whole microseconds of a 1e-4 s grid, exact; z, F: 10 significant figures
  expect_equal(tr, 0, ORIG.t[0], 1e-8, 1e-9, 0);
}

// ---- a folder of runs at three nominal speeds (10, 20 and 40 mm/s, three runs each)
// whose measured means scatter by a few percent, imported in one command, averaged per
// nominal speed by fit --ensemble
namespace {

const double NOMINAL_MM_S[3] = {10.0, 20.0, 40.0};
const double SCATTER[3] = {-0.03, 0.01, 0.025};       // measured mean / nominal - 1
const double C_SPREAD[3] = {-0.05, 0.0, 0.05};        // the runs' force coefficients about 0.8 N/cm

// the folder's files (S<speed><run>.txt) and the lab's table of nominal speeds
void write_speed_folder(const fs::path &dir)
{
  fs::create_directories(dir);
  std::string table = "# sounding  nominal rate\n";
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j) {
      DepthLog L;
      L.v_mm_s = NOMINAL_MM_S[k] * (1.0 + SCATTER[j]);
      L.ripple = 0.02;
      L.wobble = 0.0;
      L.c_N_per_cm = 0.8 * (1.0 + C_SPREAD[(j + k) % 3]);
      const std::string name = "S" + std::to_string(k + 1) + std::to_string(j + 1);
      write(dir / (name + ".txt"), L.text());
      table += name + "\t" + fmt("%.0f", NOMINAL_MM_S[k]) + " mm/s\n";
    }
  write(dir.parent_path() / "rates.tsv", table);
}

struct EnsembleLine {
  double v0;
  int runs;
  double k_z, se;
};
// fit's lines "ensemble v0 = V cm/s...: N runs..." and, below, "  mean: k_z = K +- SE"
std::vector<EnsembleLine> ensemble_lines(const std::string &out)
{
  std::vector<EnsembleLine> o;
  const std::regex head("ensemble v0 = ([0-9.e+-]+) cm/s[^\n]*: ([0-9]+) runs?"), kz("  mean: k_z = ([0-9.e+-]+) \\+- ([0-9.e+-]+)");
  std::istringstream in(out);
  std::string line;
  while (std::getline(in, line)) {
    std::smatch m;
    if (std::regex_search(line, m, head)) o.push_back({std::stod(m[1]), std::stoi(m[2]), NAN, NAN});
    else if (!o.empty() && std::regex_search(line, m, kz)) o.back().k_z = std::stod(m[1]), o.back().se = std::stod(m[2]);
  }
  return o;
}

// the three ensembles: their nominal v0, three runs each, and k_z the mean of the runs'
// coefficients (F = c z exactly: the mean of the runs is linear with slope mean c) with a
// standard error over the runs
void expect_three_ensembles(const std::string &out, const double v0_cm_s[3])
{
  const auto e = ensemble_lines(out);
  ASSERT_EQ(e.size(), 3u) << out;
  for (int k = 0; k < 3; ++k) {
    SCOPED_TRACE(k);
    EXPECT_NEAR(e[k].v0, v0_cm_s[k], 1e-3 * v0_cm_s[k]);    // printed to 6 digits; 1e-3 is far above that
    EXPECT_EQ(e[k].runs, 3);
    // the runs' mean coefficient is 0.8 N/cm = 80000 dyne/cm; the force's 6 printed
    // decimals of N and the binning move the fit by far less than 0.5%
    EXPECT_NEAR(e[k].k_z, 80000.0, 0.005 * 80000.0);
    // the coefficients' standard deviation is 5% of the mean: over 3 runs a standard
    // error of about 0.05 / sqrt(3) = 2.9% (a bootstrap's plug-in: 2.4%); 1% to 5% allows
    // for the bootstrap's own scatter
    EXPECT_GT(e[k].se, 0.01 * 80000.0);
    EXPECT_LT(e[k].se, 0.05 * 80000.0);
  }
}

}    // namespace

// One command imports the folder with the table of nominal speeds: each header's v0 is
// the nominal, its measured mean and ripple beside it; fit --ensemble averages per speed
TEST(ImportEnsemble, FolderOfThreeNominalSpeedsByTable)
{
  const fs::path d = fresh("speeds");
  write_speed_folder(d / "lab");
  write(d / "pl500.map", DEPTH_MAP);
  const std::string args = "import " + (d / "lab").string() + " --mapping " + (d / "pl500.map").string() + " --out " +
                           (d / "out").string() + " --D 2 --g 981 --v0-table " + (d / "rates.tsv").string();
  // the dry run: each file's report, then one table, then the warnings
  const CliRun dry = cli(d, args + " --dry-run");
  ASSERT_EQ(dry.status, 0) << dry.err;
  const auto table = dry.out.find("file                         rows kept");
  ASSERT_NE(table, std::string::npos) << dry.out;
  EXPECT_GT(table, dry.out.rfind("granpen import: " + (d / "lab" / "S33.txt").string())) << "the table after the reports";
  EXPECT_TRUE(std::regex_search(dry.out, std::regex("\nS21\\.txt +560 +8 +[0-9]+ +2 n +1\\.9[0-9]* +1\\.[0-9]+% +0\n"))) << dry.out;
  // and the speed against depth of each: S11's 2% drift about its mean, 16 lines of it
  EXPECT_TRUE(std::regex_search(dry.out, std::regex("speed against depth \\(the push at speed in 16 equal times")))
      << dry.out;
  EXPECT_TRUE(std::regex_search(dry.out, std::regex("\n    z +[0-9.-]+\\.\\.[0-9.-]+ +cm [0-9.]+ +[+-][0-9]\\.[0-9]{2}% [+-]*\n")))
      << dry.out;
  EXPECT_FALSE(fs::exists(d / "out"));
  const CliRun r = cli(d, args);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "") << "measured means within 5% of the nominal, a ripple of 2%: no warning";
  const std::string csv = slurp(d / "out" / "import_summary.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 10) << csv;
  EXPECT_NE(csv.find(",S21.csv,568,560,8,"), std::string::npos) << csv;
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j) {
      const auto tr = granpen::read_trace((d / "out" / ("S" + std::to_string(k + 1) + std::to_string(j + 1) + ".csv")).string());
      EXPECT_DOUBLE_EQ(tr.v0, NOMINAL_MM_S[k] / 10.0);
      EXPECT_EQ(tr.keys.at("v0_from"), "nominal");
      // the measured mean: the run's own speed (its 2% ripple averages out over 2.75
      // wavelengths to within 0.5%)
      EXPECT_NEAR(std::stod(tr.keys.at("v0_measured")), NOMINAL_MM_S[k] / 10.0 * (1.0 + SCATTER[j]),
                  0.005 * NOMINAL_MM_S[k] / 10.0);
      EXPECT_NEAR(std::stod(tr.keys.at("v0_ripple")), 0.02 / std::sqrt(2.0), 0.005);
    }
  EXPECT_EQ(cli(d, "check " + (d / "out").string()).status, 0) << "the summary is not read as a trace";
  const CliRun fit = cli(d, "fit " + (d / "out").string() + " --ensemble --zmin 1");
  ASSERT_EQ(fit.status, 0) << fit.err << fit.out;
  const double v0[3] = {1.0, 2.0, 4.0};
  expect_three_ensembles(fit.out, v0);
}

// Without a table: v0 is each run's measured mean; fit --ensemble groups them by a
// tolerance it states, and without one leaves nine ensembles of one run
TEST(ImportEnsemble, MeasuredSpeedsGroupedWithinATolerance)
{
  const fs::path d = fresh("speeds_tol");
  write_speed_folder(d / "lab");
  write(d / "pl500.map", DEPTH_MAP);
  const CliRun r = cli(d, "import " + (d / "lab").string() + " --mapping " + (d / "pl500.map").string() + " --out " +
                           (d / "out").string() + " --D 2 --g 981");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto tr = granpen::read_trace((d / "out" / "S21.csv").string());
  EXPECT_EQ(tr.keys.at("v0_from"), "measured");
  // the header's v0 is the measured mean, written with more digits than v0_measured
  EXPECT_NEAR(tr.v0, std::stod(tr.keys.at("v0_measured")), 1e-5 * tr.v0);
  EXPECT_EQ(ensemble_lines(cli(d, "fit " + (d / "out").string() + " --ensemble --zmin 1").out).size(), 9u);
  const CliRun fit = cli(d, "fit " + (d / "out").string() + " --ensemble --zmin 1 --ensemble-v0-tolerance 0.1");
  ASSERT_EQ(fit.status, 0) << fit.err << fit.out;
  EXPECT_NE(fit.out.find("grouped within 10%"), std::string::npos) << fit.out;
  // each group's v0: the mean of its runs' v0, read here from the headers
  double v0[3] = {0.0, 0.0, 0.0};
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      v0[k] += granpen::read_trace((d / "out" / ("S" + std::to_string(k + 1) + std::to_string(j + 1) + ".csv")).string()).v0 / 3.0;
  expect_three_ensembles(fit.out, v0);
}

// A GEF-CPT file (the open exchange format of cone penetration tests) needs no mapping:
// --mapping gef reads its header (columns by quantity number, units, separators, the
// cone's area); depth in m, cone resistance in MPa on a 10 cm2 cone, elapsed time in s
TEST(ImportRoundTrip, GefConePenetrationTestNeedsNoMapping)
{
  const fs::path d = fresh("gef");
  std::size_t first = 0;
  while (ORIG.z[first] <= 0.0) ++first;    // a sounding starts at the surface
  std::string s = "#GEFID= 1, 1, 0\n#FILEOWNER= granpen lab\n#FILEDATE= 2026, 11, 20\n#PROJECTID= CPT, 4471\n"
                  "#COLUMN= 4\n#COLUMNINFO= 1, m, penetration length, 1\n#COLUMNINFO= 2, MPa, cone resistance, 2\n"
                  "#COLUMNINFO= 3, MPa, local friction, 3\n#COLUMNINFO= 4, s, elapsed time, 12\n#COLUMNSEPARATOR= ;\n"
                  "#RECORDSEPARATOR= !\n#COLUMNVOID= 1, -9999.000000\n"
                  "#MEASUREMENTVAR= 1, 1000, mm2, nom. surface area cone tip\n#EOH=\n";
  for (std::size_t i = first; i < ORIG.t.size(); ++i)    // F dyne on 10 cm2: F * 1e-8 MPa
    s += fmt("%.10g", ORIG.z[i] / 100.0) + ";" + fmt("%.12g", ORIG.F[i] * 1e-8) + ";0.001;" + fmt("%.6f", ORIG.t[i]) + ";!\n";
  write(d / "CPT12.gef", s);
  const CliRun r = cli(d, "import " + (d / "CPT12.gef").string() + " --mapping gef --out " + (d / "out").string() +
                           " --D 2 --g 981");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto tr = granpen::read_trace((d / "out" / "CPT12.csv").string());
  EXPECT_EQ(tr.keys.at("mapping"), "gef");
  EXPECT_NEAR(tr.v0, 100.0, 1e-3) << "measured from the depth and the elapsed time";
  // z: 10 digits of m; F: 12 digits of MPa; t from the sounding's first row
  expect_equal(tr, first, ORIG.t[first], 1e-8, 1e-9, 0);
  EXPECT_EQ(cli(d, "check " + (d / "out").string()).status, 0);
  // without the cone's area there is no force: named
  write(d / "noarea.gef", std::regex_replace(s, std::regex("#MEASUREMENTVAR= 1,[^\n]*\n"), ""));
  const CliRun bad = cli(d, "import " + (d / "noarea.gef").string() + " --mapping gef --out " + (d / "out2").string() +
                             " --D 2 --g 981");
  EXPECT_EQ(bad.status, 1);
  EXPECT_NE(bad.err.find("noarea.gef: GEF: no #MEASUREMENTVAR= 1 (the cone's area)"), std::string::npos) << bad.err;
}

// ---- the property (issue 36, class 5): whatever import writes with exit 0, `granpen check`
// accepts. Generated instrument files and mappings, their numbers drawn over the whole range
// of a double (units, surface, onset force, sample rate, window, --v0, --D, --g, --d_g, the
// values' scale), most of them sound: each import either exits 0 and every trace it wrote
// passes check, or exits 1 or 2 with a message and writes nothing.
namespace {

// 10^u, u uniform in [lo, hi]
double decade(std::mt19937 &rng, double lo, double hi) { return std::pow(10.0, std::uniform_real_distribution<double>(lo, hi)(rng)); }

// a value: mostly ordinary (10^[-3, 3]), sometimes anywhere in a double's range
double wild(std::mt19937 &rng)
{
  return std::uniform_int_distribution<int>(0, 3)(rng) ? decade(rng, -3, 3) : decade(rng, -310, 308);
}

struct GeneratedImport {
  std::string file, mapping, args;
};

GeneratedImport generate(std::mt19937 &rng)
{
  auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); };
  GeneratedImport g;
  const bool sample_rate = pick(4) == 0, tab = pick(2);
  const char sep = tab ? '\t' : ',';
  const double scale_x = pick(5) ? 1.0 : wild(rng), scale_F = pick(5) ? 1.0 : wild(rng);
  const double dt = pick(5) ? 1e-4 : wild(rng);
  const int n = 12 + pick(300);
  g.file = std::string("t") + sep + "F" + sep + "x\n";
  for (int i = 0; i < n; ++i) {
    const double x = (-0.5 + 100.0 * 1e-4 * i) * scale_x, F = (x > 0 ? 5000.0 * x / scale_x : 0.0) * scale_F;
    g.file += fmt("%.10g", i * dt) + sep + fmt("%.10g", F) + sep + fmt("%.10g", x) + "\n";
  }
  static const char *force_units[] = {"N", "kN", "mN", "lbf", "dyne"}, *lengths[] = {"m", "cm", "mm", "um", "in"};
  g.mapping = std::string(sample_rate ? "sample_rate = " + fmt("%.6g", wild(rng)) : "time = t") + "\nforce = F\n" +
              "force_unit = " + force_units[pick(5)] + "\ndisplacement = x\nposition_unit = " + lengths[pick(5)] + "\n" +
              "tare_rows = " + std::to_string(1 + pick(10)) + "\nspeed_rows = " + std::to_string(2 + pick(10)) + "\n";
  if (pick(2))
    g.mapping += "surface = " + fmt("%.6g", (pick(2) ? 1 : -1) * (pick(3) ? 0.0 : wild(rng))) + "\n";
  else
    g.mapping += "onset_force = " + fmt("%.6g", wild(rng)) + "\n";
  if (!pick(3)) g.mapping += "window = " + fmt("%.6g", pick(2) ? decade(rng, -25, 0) : wild(rng)) + "\n";
  g.args = " --D " + fmt("%.6g", pick(3) ? 2.0 : wild(rng)) + " --g " + fmt("%.6g", pick(3) ? 981.0 : wild(rng));
  if (pick(2)) g.args += " --v0 " + fmt("%.6g", pick(2) ? 100.0 : wild(rng));
  if (!pick(4)) g.args += " --d_g " + fmt("%.6g", wild(rng));
  if (!pick(4)) g.args += " --units si";
  return g;
}

}    // namespace

TEST(ImportProperty, WhatImportWritesWithExitZeroPassesCheck)
{
  std::mt19937 rng(36);
  const int cases = 150;
  int written = 0, refused = 0;
  for (int k = 0; k < cases; ++k) {
    const GeneratedImport g = generate(rng);
    const fs::path d = fresh("property");
    write(d / "lab.csv", g.file);
    write(d / "m.map", g.mapping);
    const CliRun r = cli(d, "import " + (d / "lab.csv").string() + " --mapping " + (d / "m.map").string() + " --out " +
                                (d / "out").string() + g.args);
    SCOPED_TRACE("case " + std::to_string(k) + ": mapping\n" + g.mapping + "args" + g.args + "\n" + r.err);
    if (r.status == 0) {
      ++written;
      const CliRun c = cli(d, "check " + (d / "out" / "lab.csv").string());
      EXPECT_EQ(c.status, 0) << c.out << c.err;
    } else {
      ++refused;
      EXPECT_TRUE(r.status == 1 || r.status == 2);
      EXPECT_NE(r.err.find("granpen import: "), std::string::npos);
      EXPECT_EQ(r.err.find("what()"), std::string::npos);
      EXPECT_FALSE(fs::exists(d / "out"));
    }
  }
  // neither side of the property empty (the generator reaches both)
  EXPECT_GT(written, cases / 5);
  EXPECT_GT(refused, cases / 10);
  std::printf("property: %d imports written and checked, %d refused\n", written, refused);
}
