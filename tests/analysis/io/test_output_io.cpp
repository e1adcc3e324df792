// The output side every subcommand shares: io/atomic_file (checked writes, temporary and
// rename, output==input refusal) and io/json_writer (nlohmann JSON, granpen's layout,
// numbers rounded as the printf formats the tools always used).
#include "atomic_file.h"
#include "json_writer.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace fs = std::filesystem;
using granpen::Json;

namespace {

fs::path fresh(const std::string &name)
{
  const fs::path d = fs::path(GRANPEN_OUTPUT_IO_DIR) / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::string slurp(const fs::path &p)
{
  std::ifstream in(p, std::ios::binary);
  std::ostringstream o;
  o << in.rdbuf();
  return o.str();
}

// the names in d that are not in keep
std::vector<std::string> others(const fs::path &d, const std::vector<std::string> &keep)
{
  std::vector<std::string> o;
  for (const auto &e : fs::directory_iterator(d))
    if (std::find(keep.begin(), keep.end(), e.path().filename().string()) == keep.end())
      o.push_back(e.path().filename().string());
  return o;
}

}    // namespace

// json_rounded: the value printf's format would print, read back; whole values as integers
TEST(JsonWriter, RoundedIsWhatPrintfPrinted)
{
  for (double v : {0.123456789, 25300.0, 1e-7, -3.5e12, 2.0 / 3.0, 1.0e20, -0.0}) {
    for (const char *f : {"%.6g", "%.10g", "%g", "%.4g"}) {
      char buf[64];
      std::snprintf(buf, sizeof buf, f, v);
      const double printed = std::strtod(buf, nullptr);
      const Json j = granpen::json_rounded(f, v);
      // exact: the JSON text reads back as the double printf's text reads back as
      EXPECT_EQ(Json::parse(j.dump()).get<double>(), printed) << f << " " << v << " -> " << j.dump();
    }
  }
  EXPECT_EQ(granpen::json_rounded("%.6g", 25300.0).dump(), "25300");      // not 25300.0
  EXPECT_EQ(granpen::json_rounded("%.6g", 0.1234567).dump(), "0.123457");  // printf's digits
  EXPECT_EQ(granpen::json_rounded("%g", NAN).dump(), "0");                 // as json_number did
  EXPECT_EQ(granpen::json_rounded("%g", INFINITY).dump(), "0");
}

// one member per line at the top, a table (array of objects) one row per line, the rest inline
// (for a person reading the file; scripts read values through granpen get, json_path.h)
TEST(JsonWriter, LayoutOneMemberPerLineAtTheTop)
{
  Json j;
  j["tool"] = "granpen x";
  j["fit"] = {{"ok", true}, {"k", 1.5}, {"bounds", {1, 2}}};
  j["frames"] = Json::array({{{"timestep", 1}, {"where", "a:1"}}, {{"timestep", 2}, {"where", "b\"2"}}});
  j["empty"] = Json::array();
  j["none"] = Json();
  const std::string want = "{\n"
                           "  \"tool\": \"granpen x\",\n"
                           "  \"fit\": {\"ok\": true, \"k\": 1.5, \"bounds\": [1, 2]},\n"
                           "  \"frames\": [\n"
                           "    {\"timestep\": 1, \"where\": \"a:1\"},\n"
                           "    {\"timestep\": 2, \"where\": \"b\\\"2\"}\n"
                           "  ],\n"
                           "  \"empty\": [],\n"
                           "  \"none\": null\n"
                           "}\n";
  EXPECT_EQ(granpen::json_layout(j, 1), want);
  EXPECT_EQ(Json::parse(granpen::json_layout(j, 1)), j);    // the layout changes no value
  EXPECT_EQ(Json::parse(granpen::json_layout(j, 3)), j);
}

// invalid UTF-8 in a string (a file name) becomes U+FFFD instead of an exception
TEST(JsonWriter, InvalidUtf8IsReplaced)
{
  Json j = {{"file", std::string("a\xff" "b")}};
  EXPECT_NO_THROW(granpen::json_layout(j));
  EXPECT_NE(granpen::json_layout(j).find("a\xef\xbf\xbd" "b"), std::string::npos);
}

TEST(AtomicFile, WritesReplacesAndLeavesNoTemporary)
{
  const fs::path d = fresh("write");
  const std::string p = (d / "out.txt").string();
  granpen::write_file_atomic(p, "first\n");
  EXPECT_EQ(slurp(p), "first\n");
  granpen::write_file_atomic(p, "second, longer\n");
  EXPECT_EQ(slurp(p), "second, longer\n");
  granpen::write_file_atomic(p, "");
  EXPECT_EQ(slurp(p), "");
  EXPECT_TRUE(others(d, {"out.txt"}).empty());
}

TEST(AtomicFile, UnwritablePlacesAreNamed)
{
  const fs::path d = fresh("unwritable");
  const std::string missing = (d / "missing" / "x.json").string();
  try {
    granpen::write_file_atomic(missing, "{}\n");
    FAIL() << "wrote into a missing folder";
  } catch (const granpen::OutputError &e) {
    EXPECT_EQ(std::string(e.what()), "cannot write " + missing + ": No such file or directory");
  }
  EXPECT_FALSE(fs::exists(d / "missing"));
  granpen::write_file_atomic((d / "file").string(), "x");
  const std::string under_file = (d / "file" / "y.csv").string();
  EXPECT_THROW(granpen::write_file_atomic(under_file, "y"), granpen::OutputError);
  EXPECT_THROW(granpen::write_file_atomic((d / "").string(), "y"), granpen::OutputError);    // a folder, no name
  EXPECT_THROW(granpen::make_output_dir((d / "file" / "sub").string()), granpen::OutputError);
  EXPECT_TRUE(others(d, {"file"}).empty());
}

// a failure while writing the temporaries leaves every old file as it was
TEST(AtomicFile, SeveralFilesAllOrNothing)
{
  const fs::path d = fresh("several");
  const std::string a = (d / "a.csv").string(), b = (d / "nowhere" / "b.csv").string();
  granpen::write_file_atomic(a, "old a\n");
  EXPECT_THROW(granpen::write_files_atomic({{a, "new a\n"}, {b, "new b\n"}}), granpen::OutputError);
  EXPECT_EQ(slurp(a), "old a\n");
  EXPECT_TRUE(others(d, {"a.csv"}).empty());
  granpen::write_files_atomic({{a, "new a\n"}, {(d / "c.csv").string(), "c\n"}});
  EXPECT_EQ(slurp(a), "new a\n");
  EXPECT_EQ(slurp(d / "c.csv"), "c\n");
}

TEST(AtomicFile, SameFileThroughLinksAndSpellings)
{
  const fs::path d = fresh("same");
  const std::string t = (d / "t.csv").string();
  granpen::write_file_atomic(t, "t\n");
  fs::create_symlink(t, d / "sym.csv");
  fs::create_hard_link(t, d / "hard.csv");
  EXPECT_TRUE(granpen::same_file(t, (d / "sym.csv").string()));
  EXPECT_TRUE(granpen::same_file(t, (d / "hard.csv").string()));
  EXPECT_TRUE(granpen::same_file(t, (d / "." / "t.csv").string()));
  EXPECT_TRUE(granpen::same_file((d / "new.json").string(), (d / "x" / ".." / "new.json").string()));
  EXPECT_FALSE(granpen::same_file(t, (d / "new.json").string()));
  granpen::write_file_atomic((d / "u.csv").string(), "t\n");    // equal bytes, another file
  EXPECT_FALSE(granpen::same_file(t, (d / "u.csv").string()));
}

TEST(AtomicFile, OutputOverAnInputIsRefused)
{
  const fs::path d = fresh("refuse");
  const std::string t = (d / "t.csv").string();
  granpen::write_file_atomic(t, "input\n");
  try {
    granpen::refuse_overwriting_inputs((d / "." / "t.csv").string(), "--json", {(d / "other.csv").string(), t});
    FAIL() << "not refused";
  } catch (const granpen::OutputError &e) {
    EXPECT_EQ(std::string(e.what()), "--json " + (d / "." / "t.csv").string() + " is the input " + t +
                                         ": refusing to overwrite it");
  }
  EXPECT_EQ(slurp(t), "input\n");
  EXPECT_NO_THROW(granpen::refuse_overwriting_inputs((d / "out.json").string(), "--json", {t}));
}
