// LAMMPS dump reader: frames written here (text and gzip), columns in any order,
// scaled and unwrapped coordinates, many files and frames, a frame of 0 atoms, exact
// number parsing, progress; every rejection with its file and line; the committed
// fuzz corpus and crash regressions replayed; and (DumpLammps.*, run by ctest after
// LAMMPS wrote them) dumps of a small deck against LAMMPS's own values.
#include "dump_reader.h"
#include "fuzz_bodies.h"
#include "fuzz_instrument_body.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

using namespace granpen;
namespace fs = std::filesystem;

namespace {

std::string tmp(const std::string &name)
{
  return testing::TempDir() + "granpen_dump_" + name;
}

void write_text(const std::string &path, const std::string &text)
{
  std::ofstream f(path, std::ios::binary);
  f << text;
  ASSERT_TRUE(f.good()) << path;
}

void write_gz(const std::string &path, const std::string &text)
{
  gzFile g = gzopen(path.c_str(), "wb6");
  ASSERT_NE(g, nullptr) << path;
  ASSERT_EQ(gzwrite(g, text.data(), static_cast<unsigned>(text.size())), static_cast<int>(text.size()));
  ASSERT_EQ(gzclose(g), Z_OK);
}

std::string read_bytes(const std::string &path)
{
  std::ifstream f(path, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

// one frame in LAMMPS's layout: 9 header lines, then the atom lines
std::string frame_text(long long step, const std::string &columns, const std::vector<std::string> &rows,
                       const char *bounds = "0 4\n0 4\n0 8\n", const char *box_item = "ITEM: BOX BOUNDS pp pp fm")
{
  std::ostringstream o;
  o << "ITEM: TIMESTEP\n" << step << "\nITEM: NUMBER OF ATOMS\n" << rows.size() << "\n" << box_item << "\n"
    << bounds << "ITEM: ATOMS " << columns << "\n";
  for (auto &r : rows) o << r << "\n";
  return o.str();
}

const std::string kCols = "id type x y z vx vy vz radius";

// n atoms of the default columns; values derived from step and atom index
std::vector<std::string> rows(int n, long long step = 0)
{
  std::vector<std::string> out;
  for (int i = 0; i < n; ++i) {
    std::ostringstream o;
    o.precision(17);
    o << i + 1 << " 1 " << 0.1 * i << " " << 0.2 * i + step << " " << 0.5 + i << " " << -1.5 * i << " 2.25 "
      << 1e-3 * step << " 0.2";
    out.push_back(o.str());
  }
  return out;
}

std::vector<DumpFrame> read_all(const std::vector<std::string> &paths,
                                const std::vector<std::string> &required = {"id", "type", "x", "y", "z", "vx",
                                                                            "vy", "vz", "radius"})
{
  DumpReader r(paths, required);
  std::vector<DumpFrame> out;
  DumpFrame f;
  while (r.next(f)) out.push_back(f);
  EXPECT_FALSE(r.next(f));    // the end stays the end
  return out;
}

// reading `paths` fails with a message matching `pattern`
void expect_error(const std::vector<std::string> &paths, const std::string &pattern,
                  const std::vector<std::string> &required = {"id", "type", "x", "y", "z", "vx", "vy", "vz",
                                                              "radius"})
{
  DumpReader r(paths, required);
  DumpFrame f;
  try {
    while (r.next(f)) {
    }
    ADD_FAILURE() << "no error: expected one matching " << pattern;
    return;
  } catch (InputError &e) {
    EXPECT_TRUE(std::regex_search(e.what(), std::regex(pattern))) << "message: " << e.what() << "\nexpected: " << pattern;
    EXPECT_EQ(f.natoms(), 0u) << "a partly read frame was left behind";
    EXPECT_TRUE(f.columns.empty());
    // the reader stays failed, with the same message
    try {
      r.next(f);
      ADD_FAILURE() << "next() after an error returned";
    } catch (InputError &again) {
      EXPECT_STREQ(again.what(), e.what());
    }
  }
}

void expect_text_error(const std::string &name, const std::string &text, const std::string &pattern,
                       const std::vector<std::string> &required = {"id", "type", "x", "y", "z", "vx", "vy", "vz",
                                                                   "radius"})
{
  const std::string p = tmp(name);
  write_text(p, text);
  expect_error({p}, std::regex_replace(p, std::regex(R"([.^$|()\[\]{}*+?\\])"), R"(\$&)") + pattern, required);
}

}    // namespace

// ---------------------------------------------------------------- reading

TEST(DumpReader, ReadsAFrameOfText)
{
  const std::string p = tmp("one.dump");
  write_text(p, frame_text(100, kCols, rows(5, 100), "-1 3\n-2.5 2.5\n0 1.2e1\n"));
  auto frames = read_all({p});
  ASSERT_EQ(frames.size(), 1u);
  const DumpFrame &f = frames[0];
  EXPECT_EQ(f.file, p);
  EXPECT_EQ(f.line, 1);
  EXPECT_EQ(f.timestep, 100);
  EXPECT_EQ(f.natoms(), 5u);
  EXPECT_EQ(f.lo[0], -1.0);
  EXPECT_EQ(f.hi[0], 3.0);
  EXPECT_EQ(f.lo[1], -2.5);
  EXPECT_EQ(f.hi[2], 12.0);
  EXPECT_EQ(f.columns, (std::vector<std::string>{"id", "type", "x", "y", "z", "vx", "vy", "vz", "radius"}));
  EXPECT_TRUE(f.has("vz"));
  EXPECT_FALSE(f.has("fx"));
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(f.col("id")[i], i + 1);
    EXPECT_EQ(f.col("x")[i], 0.1 * i);
    EXPECT_EQ(f.col("y")[i], 0.2 * i + 100);
    EXPECT_EQ(f.col("vx")[i], -1.5 * i);
    EXPECT_EQ(f.col("vz")[i], 0.1);
    EXPECT_EQ(f.col("radius")[i], 0.2);
  }
}

TEST(DumpReader, ColumnMissingFromAFrameNamesFileAndLine)
{
  const std::string p = tmp("col.dump");
  write_text(p, frame_text(0, kCols, rows(2)) + frame_text(7, kCols, rows(2)));
  auto frames = read_all({p});
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[1].line, 12);
  try {
    frames[1].col("fx");
    FAIL() << "no error";
  } catch (InputError &e) {
    EXPECT_EQ(std::string(e.what()), p + ":12: frame has no column fx");
  }
}

TEST(DumpReader, ShuffledColumnsScaledCoordinatesGzip)
{
  // box x -2..6, y 1..3, z -4..0: xs 0.25 -> 0, 0.5 -> 2, 0.125 -> -1 (exact in binary)
  const std::string p = tmp("shuffled.dump.gz.not-by-name");
  write_gz(p, frame_text(5, "radius vz id zs vy xs type vx ys",
                         {"0.2 -3 11 0.5 2 0.25 1 1 0", "0.3 -4 12 1 5 0.5 2 1.5 0.75", "0.25 0 13 0 6 0.125 1 2 1"},
                         "-2 6\n1 3\n-4 0\n"));
  auto frames = read_all({p});
  ASSERT_EQ(frames.size(), 1u);
  const DumpFrame &f = frames[0];
  EXPECT_EQ(f.columns, (std::vector<std::string>{"radius", "vz", "id", "z", "vy", "x", "type", "vx", "y"}));
  EXPECT_EQ(f.col("x"), (std::vector<double>{0.0, 2.0, -1.0}));
  EXPECT_EQ(f.col("y"), (std::vector<double>{1.0, 2.5, 3.0}));
  EXPECT_EQ(f.col("z"), (std::vector<double>{-2.0, 0.0, -4.0}));
  EXPECT_EQ(f.col("id"), (std::vector<double>{11, 12, 13}));
  EXPECT_EQ(f.col("vz"), (std::vector<double>{-3, -4, 0}));
  EXPECT_EQ(f.col("radius"), (std::vector<double>{0.2, 0.3, 0.25}));
  EXPECT_FALSE(f.has("xs"));
}

TEST(DumpReader, ScaledCoordinatesAgainstLammpsFormula)
{
  // x = lo + xs (hi - lo) for arbitrary values, as LAMMPS's read_dump unscales
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-0.1, 1.1);
  const double lo[3] = {-1.3, 0.7, 2.0}, hi[3] = {4.1, 9.9, 2.5};
  std::vector<std::string> r;
  std::vector<double> xs[3];
  char line[200];
  for (int i = 0; i < 50; ++i) {
    for (auto &v : xs) v.push_back(u(rng));
    std::snprintf(line, sizeof line, "%d 1 %.17g %.17g %.17g 0 0 0 0.2", i + 1, xs[0].back(), xs[1].back(), xs[2].back());
    r.push_back(line);
  }
  const std::string p = tmp("scaled.dump");
  write_text(p, frame_text(0, "id type xs ys zs vx vy vz radius", r, "-1.3 4.1\n0.7 9.9\n2.0 2.5\n"));
  auto f = read_all({p}).at(0);
  const char *axis[3] = {"x", "y", "z"};
  for (int d = 0; d < 3; ++d)
    for (int i = 0; i < 50; ++i) EXPECT_EQ(f.col(axis[d])[i], lo[d] + xs[d][i] * (hi[d] - lo[d]));
}

TEST(DumpReader, UnwrappedRenamedAndPlainPositionsPreferred)
{
  const std::string p = tmp("unwrapped.dump");
  write_text(p, frame_text(0, "id type xu yu zu vx vy vz radius", {"1 1 -0.5 5 9 0 0 0 0.2"}) +
                    // both x and xs: x is kept, xs stays xs; yu beats ys
                    frame_text(1, "id type x xs yu ys zsu vx vy vz radius", {"1 1 7 0.5 3 0.25 0.5 0 0 0 0.2"}));
  auto frames = read_all({p});
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0].columns[2], "x");
  EXPECT_EQ(frames[0].col("x")[0], -0.5);
  EXPECT_EQ(frames[0].col("y")[0], 5.0);
  EXPECT_EQ(frames[0].col("z")[0], 9.0);
  EXPECT_EQ(frames[1].columns, (std::vector<std::string>{"id", "type", "x", "xs", "y", "ys", "z", "vx", "vy", "vz",
                                                         "radius"}));
  EXPECT_EQ(frames[1].col("x")[0], 7.0);
  EXPECT_EQ(frames[1].col("xs")[0], 0.5);
  EXPECT_EQ(frames[1].col("y")[0], 3.0);
  EXPECT_EQ(frames[1].col("z")[0], 4.0);    // zsu 0.5 of 0..8
}

TEST(DumpReader, ManyFilesAndFramesInOrder)
{
  // three files, text, gzip, text, of 40 frames each with a varying number of atoms
  std::vector<std::string> paths;
  std::uint64_t total = 0;
  long long step = 0;
  std::vector<std::pair<long long, int>> expect;    // timestep, atoms
  for (int file = 0; file < 3; ++file) {
    std::string text;
    for (int k = 0; k < 40; ++k, step += 10) {
      const int n = (k * 37 + file * 11) % 23;
      text += frame_text(step, kCols, rows(n, step));
      expect.emplace_back(step, n);
    }
    const std::string p = tmp("many" + std::to_string(file) + (file == 1 ? ".gz" : ".txt"));
    if (file == 1)
      write_gz(p, text);
    else
      write_text(p, text);
    total += fs::file_size(p);
    paths.push_back(p);
  }
  DumpReader r(paths);
  DumpFrame f;
  std::size_t i = 0;
  long line = 0;
  while (r.next(f)) {
    ASSERT_LT(i, expect.size());
    EXPECT_EQ(f.timestep, expect[i].first);
    EXPECT_EQ(f.natoms(), static_cast<std::size_t>(expect[i].second));
    EXPECT_EQ(f.file, paths[i / 40]);
    if (i % 40 == 0) line = 1;
    EXPECT_EQ(f.line, line);
    line += 9 + expect[i].second;
    for (int a = 0; a < expect[i].second; ++a) ASSERT_EQ(f.col("y")[a], 0.2 * a + f.timestep);
    ++i;
  }
  EXPECT_EQ(i, expect.size());
  auto prog = r.progress();
  EXPECT_EQ(prog.frames, expect.size());
  EXPECT_EQ(prog.bytes, total);
}

TEST(DumpReader, ConcatenatedGzipMembersAndCrlf)
{
  std::string a = frame_text(0, kCols, rows(3)), b = frame_text(1, kCols, rows(2));
  const std::string pa = tmp("member_a.gz"), pb = tmp("member_b.gz"), p = tmp("members.gz");
  write_gz(pa, a);
  write_gz(pb, b);
  write_text(p, read_bytes(pa) + read_bytes(pb));    // what `cat a.gz b.gz` makes
  auto frames = read_all({p});
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[1].line, 13);
  // Windows line ends
  const std::string c = tmp("crlf.dump");
  write_text(c, std::regex_replace(a, std::regex("\n"), "\r\n"));
  frames = read_all({c});
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].col("radius")[2], 0.2);
}

TEST(DumpReader, FrameOfZeroAtoms)
{
  const std::string p = tmp("zero.dump");
  write_text(p, frame_text(0, kCols, rows(3)) + frame_text(10, kCols, {}) + frame_text(20, kCols, rows(1)));
  auto frames = read_all({p});
  ASSERT_EQ(frames.size(), 3u);
  EXPECT_EQ(frames[1].natoms(), 0u);
  EXPECT_EQ(frames[1].timestep, 10);
  EXPECT_EQ(frames[1].columns.size(), 9u);
  EXPECT_TRUE(frames[1].col("x").empty());
  EXPECT_EQ(frames[2].line, 22);
  EXPECT_EQ(frames[2].natoms(), 1u);
}

TEST(DumpReader, OptionalUnitsAndTimeItems)
{
  const std::string p = tmp("units.dump");
  write_text(p, "ITEM: UNITS\ncgs\nITEM: TIME\n0.0025\n" + frame_text(500, kCols, rows(2)));
  auto frames = read_all({p});
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].line, 5);
  EXPECT_EQ(frames[0].timestep, 500);
}

TEST(DumpReader, NoRequiredColumns)
{
  const std::string p = tmp("few.dump");
  write_text(p, frame_text(0, "id c_ke", {"1 2.5", "2 -3"}));
  auto frames = read_all({p}, {});
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].col("c_ke")[1], -3.0);
}

TEST(DumpReader, NumbersParseExactlyAsStrtod)
{
  std::vector<std::string> text = {"0", "-0", "1", "+1.5", "1e22", "1e23", "9007199254740992", "9007199254740993",
                                   "18446744073709551617", "123456789012345678901234567890", "4.9e-324",
                                   "2.2250738585072014e-308", "1.7976931348623157e308", ".5", "5.", "1E5",
                                   "0.000000000000000000000000000001", "3.14159265358979323846264338327950288",
                                   "0.1", "0.30000000000000004", "-7.0e-5", "2147483647", "1.00000000000000011102230246251565404236316680908203125",
                                   "1.00000000000000011102230246251565404236316680908203124", "00012.500",
                                   "1e-400", "-1e-400"};
  std::mt19937_64 rng(11);
  const char *formats[] = {"%g", "%.17g", "%.6e", "%.3f", "%.12g", "%.15g", "%.16e", "%.0f", "%.9g"};
  std::uniform_real_distribution<double> mant(-10.0, 10.0);
  std::uniform_int_distribution<int> ex(-30, 30);
  char buf[128];
  for (int i = 0; i < 20000; ++i) {
    double v = mant(rng) * std::pow(10.0, ex(rng));
    std::snprintf(buf, sizeof buf, formats[i % 9], v);
    text.emplace_back(buf);
  }
  for (int i = 0; i < 2000; ++i) {    // arbitrary bit patterns
    std::uint64_t bits = rng();
    double v;
    std::memcpy(&v, &bits, 8);
    if (!std::isfinite(v)) continue;
    std::snprintf(buf, sizeof buf, i % 2 ? "%.17g" : "%.25g", v);
    text.emplace_back(buf);
  }
  std::vector<std::string> r;
  for (std::size_t i = 0; i < text.size(); ++i) r.push_back(std::to_string(i + 1) + " " + text[i]);
  const std::string p = tmp("numbers.dump");
  write_text(p, frame_text(0, "id v", r));
  auto f = read_all({p}, {}).at(0);
  ASSERT_EQ(f.natoms(), text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    double want = std::strtod(text[i].c_str(), nullptr), got = f.col("v")[i];
    EXPECT_EQ(std::memcmp(&want, &got, 8), 0) << text[i] << ": read " << got << ", strtod " << want;
  }
}

TEST(DumpReader, ProgressCallback)
{
  const std::string p = tmp("progress.dump");
  std::string text;
  for (int k = 0; k < 20; ++k) text += frame_text(k, kCols, rows(50, k));
  write_text(p, text);
  DumpReader r({p});
  std::vector<DumpProgress> seen;
  r.on_progress([&](const DumpProgress &pr) { seen.push_back(pr); }, 0.0);
  DumpFrame f;
  int n = 0;
  while (r.next(f)) ++n;
  EXPECT_EQ(n, 20);
  ASSERT_FALSE(seen.empty());
  EXPECT_EQ(seen.back().frames, 20u);
  EXPECT_EQ(seen.back().bytes, text.size());
  for (std::size_t i = 1; i < seen.size(); ++i) {
    EXPECT_GE(seen[i].bytes, seen[i - 1].bytes);
    EXPECT_GE(seen[i].frames, seen[i - 1].frames);
    EXPECT_GE(seen[i].seconds, seen[i - 1].seconds);
  }
}

// ---------------------------------------------------------------- rejections

TEST(DumpReaderErrors, FewerAtomLinesThanNumberOfAtoms)
{
  // frame 1 claims 3 atoms, has 2, then frame 2 begins at line 12
  std::string f1 = frame_text(0, kCols, rows(2));
  f1.replace(f1.find("ATOMS\n2\n"), 8, "ATOMS\n3\n");
  expect_text_error("short.dump", f1 + frame_text(1, kCols, rows(2)),
                    ":12: frame truncated: 'ITEM: TIMESTEP' after 2 of 3 atom lines \\(frame of timestep 0, "
                    "ITEM: TIMESTEP at line 1\\)");
}

TEST(DumpReaderErrors, EndOfFileInsideAFrame)
{
  std::string f = frame_text(0, kCols, rows(4)) + frame_text(5, kCols, rows(4));
  // cut after the 2nd atom line of frame 2 (lines 14..22 header, 23.. atoms)
  std::size_t cut = 0;
  for (int l = 0; l < 13 + 11; ++l) cut = f.find('\n', cut) + 1;
  expect_text_error("eof_atoms.dump", f.substr(0, cut),
                    ":24: file ends inside the frame of timestep 5 \\(ITEM: TIMESTEP at line 14\\): 2 of 4 atom lines");
  // ... and in the header, after the box bounds
  cut = 0;
  for (int l = 0; l < 13 + 8; ++l) cut = f.find('\n', cut) + 1;
  expect_text_error("eof_header.dump", f.substr(0, cut),
                    ":21: file ends inside the frame of timestep 5 \\(ITEM: TIMESTEP at line 14\\): expected "
                    "'ITEM: ATOMS'");
  // ... and in the middle of a line, without its newline
  expect_text_error("eof_midline.dump", f.substr(0, f.size() - 9), ":26: atom line has [0-9] fields, expected 9");
}

TEST(DumpReaderErrors, GzipCutInTheMiddle)
{
  std::string text;
  for (int k = 0; k < 200; ++k) text += frame_text(k, kCols, rows(40, k));
  const std::string full = tmp("full.dump.gz"), cut = tmp("cut.dump.gz");
  write_gz(full, text);
  std::string bytes = read_bytes(full);
  write_text(cut, bytes.substr(0, bytes.size() / 2));
  // frames before the cut come out whole; then the truncation is an error
  DumpReader r({cut});
  DumpFrame f;
  int n = 0;
  try {
    while (r.next(f)) {
      ASSERT_EQ(f.natoms(), 40u);
      ASSERT_EQ(f.timestep, n);
      ++n;
    }
    FAIL() << "a gzip file cut short read as complete (" << n << " frames)";
  } catch (InputError &e) {
    EXPECT_TRUE(std::regex_search(e.what(), std::regex("cut\\.dump\\.gz:[0-9]+: gzip stream truncated")))
        << e.what();
  }
  EXPECT_GT(n, 10);
  EXPECT_LT(n, 200);
  // cut at many places, including inside the header and the trailer: never a clean end
  for (std::size_t len : {std::size_t(2), std::size_t(5), std::size_t(11), std::size_t(30), bytes.size() / 3,
                          bytes.size() - 9, bytes.size() - 4, bytes.size() - 1}) {
    write_text(cut, bytes.substr(0, len));
    expect_error({cut}, "cut\\.dump\\.gz:[0-9]+: (gzip stream truncated|corrupt gzip)");
  }
}

TEST(DumpReaderErrors, CorruptGzip)
{
  const std::string full = tmp("crc.dump.gz"), bad = tmp("badcrc.dump.gz");
  write_gz(full, frame_text(0, kCols, rows(30)));
  std::string bytes = read_bytes(full);
  bytes[bytes.size() - 6] ^= 0x5a;    // the CRC-32 in the trailer
  write_text(bad, bytes);
  expect_error({bad}, "badcrc\\.dump\\.gz:[0-9]+: corrupt gzip stream \\(zlib: incorrect data check\\)");
  // the deflate data itself: whatever comes out first, it is an error naming the file
  bytes = read_bytes(full);
  for (std::size_t i = 12; i < bytes.size() - 8; i += 7) bytes[i] ^= 0xff;
  write_text(bad, bytes);
  expect_error({bad}, "badcrc\\.dump\\.gz:[0-9]+: ");
}

TEST(DumpReaderErrors, MissingRequiredColumn)
{
  expect_text_error("noradius.dump", frame_text(0, "id type x y z vx vy vz", {"1 1 0 0 0 0 0 0"}),
                    ":9: frame has no column radius \\(required; columns: id type x y z vx vy vz\\)");
  expect_text_error("custom_required.dump", frame_text(0, "id x", {"1 0"}), ":9: frame has no column c_p",
                    {"id", "c_p"});
}

TEST(DumpReaderErrors, BadValues)
{
  auto r = rows(3);
  r[1] = "2 1 0.1 0.2 abc 0 0 0 0.2";
  expect_text_error("nonnumeric.dump", frame_text(0, kCols, r), ":11: column z value 'abc' is not a number");
  r = rows(3);
  r[2] = "3 1 0.1 0.2 0.3 1.5e 0 0 0.2";
  expect_text_error("badexp.dump", frame_text(0, kCols, r), ":12: column vx value '1.5e' is not a number");
  r = rows(3);
  r[0] = "1 1 0.1 0.2 0.3 0 nan 0 0.2";
  expect_text_error("nan.dump", frame_text(0, kCols, r), ":10: column vy value 'nan' is not finite");
  r[0] = "1 1 0.1 0.2 0.3 0 0 -inf 0.2";
  expect_text_error("inf.dump", frame_text(0, kCols, r), ":10: column vz value '-inf' is not finite");
  r[0] = "1 1 0.1 0.2 0.3 0 0 1e999 0.2";
  expect_text_error("huge.dump", frame_text(0, kCols, r), ":10: column vz value '1e999' is not finite");
  r[0] = "1 1 0.1 0.2 0.3 0 0 0x10 0.2";
  expect_text_error("hex.dump", frame_text(0, kCols, r), ":10: column vz value '0x10' is not a number");
}

TEST(DumpReaderErrors, WrongNumberOfFields)
{
  auto r = rows(3);
  r[1] = "2 1 0.1 0.2 0.3 0 0 0";
  expect_text_error("fewer.dump", frame_text(0, kCols, r), ":11: atom line has 8 fields, expected 9");
  r[1] = "2 1 0.1 0.2 0.3 0 0 0 0.2 7 8";
  expect_text_error("more.dump", frame_text(0, kCols, r), ":11: atom line has 11 fields, expected 9");
  r[1] = "";
  expect_text_error("blank.dump", frame_text(0, kCols, r), ":11: atom line has 0 fields, expected 9");
  // more atom lines than NUMBER OF ATOMS: the next frame does not start
  std::string f = frame_text(0, kCols, rows(2));
  f.replace(f.find("ATOMS\n2\n"), 8, "ATOMS\n1\n");
  expect_text_error("extra.dump", f, ":11: expected 'ITEM: TIMESTEP', found '2 1 0\\.1.*' \\(more atom lines than "
                                     "NUMBER OF ATOMS in the previous frame\\?\\)");
}

TEST(DumpReaderErrors, MissingOrMalformedItemLines)
{
  std::string f = frame_text(0, kCols, rows(2));
  auto without = [&](const std::string &what, const std::string &with) {
    std::string s = f;
    s.replace(s.find(what), what.size(), with);
    return s;
  };
  expect_text_error("no_timestep.dump", without("ITEM: TIMESTEP\n0\n", ""),
                    ":1: expected 'ITEM: TIMESTEP', found 'ITEM: NUMBER OF ATOMS'");
  expect_text_error("timesteps.dump", without("ITEM: TIMESTEP", "ITEM: TIMESTEPS"),
                    ":1: expected 'ITEM: TIMESTEP', found 'ITEM: TIMESTEPS'");
  expect_text_error("bad_step.dump", without("TIMESTEP\n0\n", "TIMESTEP\n1.5\n"), ":2: timestep '1.5' is not an integer");
  expect_text_error("no_natoms.dump", without("ITEM: NUMBER OF ATOMS\n2\n", ""),
                    ":3: expected 'ITEM: NUMBER OF ATOMS', found 'ITEM: BOX BOUNDS pp pp fm'");
  expect_text_error("bad_natoms.dump", without("ATOMS\n2\n", "ATOMS\n-2\n"),
                    ":4: number of atoms '-2' is not an integer >= 0");
  expect_text_error("no_box.dump", without("ITEM: BOX BOUNDS pp pp fm\n", ""),
                    ":5: expected 'ITEM: BOX BOUNDS', found '0 4'");
  expect_text_error("bad_bound.dump", without("0 8\n", "0 eight\n"), ":8: box bound 'eight' is not a finite number");
  expect_text_error("one_bound.dump", without("0 8\n", "0\n"), ":8: box bounds line must hold 'lo hi', found '0'");
  expect_text_error("inverted.dump", without("0 8\n", "8 0\n"), ":8: box bounds lo > hi");
  expect_text_error("no_atoms_item.dump", without("ITEM: ATOMS " + kCols + "\n", ""),
                    ":9: expected 'ITEM: ATOMS', found '1 1 0 0 0.5 -0 2.25 0 0.2'");
  expect_text_error("no_columns.dump", without("ITEM: ATOMS " + kCols, "ITEM: ATOMS"), ":9: 'ITEM: ATOMS' names no columns");
  expect_text_error("twice.dump", without("ITEM: ATOMS id", "ITEM: ATOMS x id"),
                    ":9: column 'x' appears twice in 'ITEM: ATOMS'");
  expect_text_error("not_a_dump.dump", "t,z,F\n0,0,0\n", ":1: expected 'ITEM: TIMESTEP', found 't,z,F' \\(not a LAMMPS text dump\\?\\)");
}

TEST(DumpReaderErrors, TriclinicBox)
{
  expect_text_error("tri.dump",
                    frame_text(0, kCols, rows(2), "0 4 0.5\n0 4 0\n0 8 0\n", "ITEM: BOX BOUNDS xy xz yz pp pp pp"),
                    ":5: triclinic box \\('ITEM: BOX BOUNDS xy xz yz pp pp pp'\\): only orthogonal boxes are supported");
  // tilt factors without the header words
  expect_text_error("tri2.dump", frame_text(0, kCols, rows(2), "0 4 0.5\n0 4 0\n0 8 0\n"),
                    ":6: box bounds with a tilt factor: triclinic boxes are not supported");
}

TEST(DumpReaderErrors, FilesWithoutFrames)
{
  expect_text_error("empty.dump", "", ":1: no dump frames in file");
  expect_text_error("blank.dump", "\n  \n\n", ":3: no dump frames in file");
  // a good file, then an empty one: the second is named
  const std::string good = tmp("good.dump"), empty = tmp("empty2.dump");
  write_text(good, frame_text(0, kCols, rows(2)));
  write_text(empty, "");
  DumpReader r({good, empty});
  DumpFrame f;
  ASSERT_TRUE(r.next(f));
  try {
    r.next(f);
    FAIL() << "no error";
  } catch (InputError &e) {
    EXPECT_EQ(std::string(e.what()), empty + ":1: no dump frames in file (empty or blank)");
  }
  expect_error({tmp("does_not_exist.dump")}, "does_not_exist\\.dump: cannot open dump file \\(No such file");
  expect_text_error("zstd.dump", std::string("\x28\xb5\x2f\xfd\x00\x01", 6),
                    ":1: zstd-compressed file: only plain text and gzip dumps are read");
  EXPECT_THROW(DumpReader(std::vector<std::string>{}), InputError);
}

TEST(DumpReaderErrors, AnEarlierFrameIsNotDisturbed)
{
  // the good frames before an error come out whole; the bad one never does
  const std::string p = tmp("later_bad.dump");
  auto r = rows(3);
  r[2] = "3 1 0 0 0 0 0 0";
  write_text(p, frame_text(0, kCols, rows(3)) + frame_text(1, kCols, r));
  DumpReader reader({p});
  DumpFrame f;
  ASSERT_TRUE(reader.next(f));
  EXPECT_EQ(f.natoms(), 3u);
  EXPECT_THROW(reader.next(f), InputError);
  EXPECT_EQ(f.natoms(), 0u);
  EXPECT_TRUE(f.data.empty());
}

// ---------------------------------------------------------------- fuzz corpus and regressions

// Every committed fuzz input (seed corpus and crash regressions, tests/fuzz/) goes
// through the fuzz targets' own bodies (tests/fuzz/fuzz_bodies.h): each is read or
// rejected with InputError, with every invariant holding; a broken one aborts.
TEST(FuzzRegressions, CommittedInputsReplayCleanly)
{
  const fs::path root = GRANPEN_FUZZ_DIR;
  int n = 0;
  for (const char *kind : {"dump", "trace", "instrument"})
    for (const char *sub : {"corpus", "regressions"}) {
      const fs::path dir = root / sub / kind;
      if (!fs::is_directory(dir)) continue;
      for (auto &e : fs::directory_iterator(dir)) {
        if (!e.is_regular_file() || e.path().filename().string()[0] == '.') continue;
        SCOPED_TRACE(e.path().string());
        if (std::string(kind) == "dump")
          granpen_fuzz::dump_body(e.path().string(), fs::file_size(e.path()));
        else if (std::string(kind) == "instrument")
          granpen_fuzz::instrument_body(read_bytes(e.path().string()));
        else
          granpen_fuzz::trace_body(read_bytes(e.path().string()));
        ++n;
      }
    }
  EXPECT_GT(n, 10) << "fuzz inputs under " << root;
}

// ---------------------------------------------------------------- real LAMMPS dumps

namespace {

// the rows of fix ave/time's file: step, then values
std::map<long long, std::vector<double>> ave_time_rows(const std::string &path)
{
  std::map<long long, std::vector<double>> out;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    long long step;
    s >> step;
    double v;
    while (s >> v) out[step].push_back(v);
  }
  return out;
}

double sum(const std::vector<double> &v)
{
  double s = 0;
  for (double x : v) s += x;
  return s;
}

std::size_t index_of_id(const DumpFrame &f, double id)
{
  const auto &ids = f.col("id");
  for (std::size_t i = 0; i < ids.size(); ++i)
    if (ids[i] == id) return i;
  ADD_FAILURE() << "no atom " << id;
  return 0;
}

}    // namespace

// tests/analysis/io/dump_small.lmp, run by lmp_granpen (ctest fixture dump_lammps), wrote the
// same 3 frames of 384 grains as dump custom (%.17g), dump custom/gz (shuffled
// columns, scaled coordinates, %.17g) and dump custom at LAMMPS's default %g with
// unwrapped coordinates; and, by fix ave/time, the sums of x y z vx vy vz radius and
// the values of three atoms, at 17 digits.
TEST(DumpLammps, AgreesWithLammpsOwnValues)
{
  const char *dir_env = std::getenv("GRANPEN_DUMP_LAMMPS_DIR");
  if (!dir_env) GTEST_SKIP() << "GRANPEN_DUMP_LAMMPS_DIR not set (ctest runs this after LAMMPS wrote the dumps)";
  const std::string dir = dir_env;
  auto sums = ave_time_rows(dir + "/sums.txt");
  auto atoms = ave_time_rows(dir + "/atoms.txt");
  ASSERT_EQ(sums.size(), 3u);
  ASSERT_EQ(atoms.size(), 3u);

  const std::vector<std::string> files = {dir + "/small.dump", dir + "/small_shuffled.dump.gz",
                                          dir + "/small_default.dump"};
  for (const auto &file : files) {
    SCOPED_TRACE(file);
    const bool full_precision = file.find("default") == std::string::npos;
    const double rtol = full_precision ? 1e-13 : 2e-6;    // %g keeps 6 digits
    DumpReader r({file});
    DumpFrame f;
    int n = 0;
    while (r.next(f)) {
      ASSERT_EQ(f.natoms(), 384u);
      ASSERT_TRUE(sums.count(f.timestep)) << f.timestep;
      const auto &want = sums[f.timestep];
      ASSERT_EQ(want.size(), 7u);
      const char *names[] = {"x", "y", "z", "vx", "vy", "vz", "radius"};
      for (int c = 0; c < 7; ++c) {
        const double got = sum(f.col(names[c]));
        EXPECT_NEAR(got, want[c], rtol * std::max(1.0, std::fabs(want[c])) * (c >= 3 && c < 6 ? 100 : 1))
            << names[c] << " at step " << f.timestep;
      }
      EXPECT_EQ(sum(f.col("id")), 384.0 * 385.0 / 2.0);
      // atoms 1, 17 and 384: x y z vx
      const auto &a = atoms[f.timestep];
      ASSERT_EQ(a.size(), 12u);
      int k = 0;
      for (double id : {1.0, 17.0, 384.0}) {
        const std::size_t i = index_of_id(f, id);
        for (const char *name : {"x", "y", "z", "vx"}) {
          const double w = a[k++];
          EXPECT_NEAR(f.col(name)[i], w, rtol * std::max(1.0, std::fabs(w)) * 4) << name << " of atom " << id;
        }
      }
      EXPECT_EQ(f.lo[0], 0.0);
      EXPECT_EQ(f.hi[0], 4.0);
      EXPECT_EQ(f.hi[2], 6.0);
      ++n;
    }
    EXPECT_EQ(n, 3);
  }
}

// issue 19: timesteps that go backwards were accepted; a repeated step (a resumed run's
// first dump) still is
TEST(DumpReaderErrors, TimestepGoingBackwardsIsNamed)
{
  const std::string f0 = frame_text(1000, kCols, rows(2)), f1 = frame_text(500, kCols, rows(2));
  // the second frame's TIMESTEP is at line 12, its step at line 13
  expect_text_error("backwards.dump", f0 + f1,
                    ":13: timestep 500 goes backwards \\(after timestep 1000 at .*backwards\\.dump:1\\)$");
  EXPECT_EQ(read_all({[&] {
                       const std::string p = tmp("repeat.dump");
                       write_text(p, f0 + frame_text(1000, kCols, rows(2)) + frame_text(1500, kCols, rows(2)));
                       return p;
                     }()})
                .size(),
            3u);
  // across files: given out of order (as a shell glob sorts dump.1000 after dump.500 ... )
  const std::string a = tmp("order_a.dump"), b = tmp("order_b.dump");
  write_text(a, f0);
  write_text(b, f1);
  expect_error({a, b}, "order_b\\.dump:2: timestep 500 goes backwards \\(after timestep 1000 at .*order_a\\.dump:1\\): "
                       "dump files are read in the order given; give them in time order");
}
