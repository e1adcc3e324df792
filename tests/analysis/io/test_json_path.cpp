// io/json_path: values of a JSON document by key path (what `granpen get` prints and the gap
// selftest's scorer reads), and the reading of a JSON file with its errors named.
#include "errors.h"
#include "json_path.h"
#include "json_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using granpen::InputError;
using granpen::Json;
using granpen::JsonPathStep;

namespace {

// the message of the InputError fn throws ("" when it throws none)
template <class Fn>
std::string error_of(Fn fn)
{
  try {
    fn();
  } catch (const InputError &e) {
    return e.what();
  }
  return "";
}

Json sample()
{
  return Json::parse(R"({"verdict": "tie", "heldout": {"v0": 50, "gap_before": 0.13893, "magnitude": null},
    "tie": ["force_scale", "packing"],
    "ranking": [{"effect": "packing", "magnitude_error": 0.0288973}, {"effect": "cohesion", "magnitude_error": 120.602}],
    "per_speed": [{"v0": 50, "n": 8}, {"v0": 100, "n": 7}], "empty": []})");
}

std::vector<std::string> texts(const granpen::JsonLookup &r)
{
  std::vector<std::string> out;
  for (const Json *v : r.values) out.push_back(v ? granpen::json_value_text(*v) : "<missing>");
  return out;
}

}    // namespace

TEST(JsonPath, StepsOfAPath)
{
  const auto s = granpen::parse_json_path("detection_limits[effect=cohesion].limit");
  ASSERT_EQ(s.size(), 3u);
  EXPECT_EQ(s[0].kind, JsonPathStep::member);
  EXPECT_EQ(s[0].name, "detection_limits");
  EXPECT_EQ(s[1].kind, JsonPathStep::match);
  EXPECT_EQ(s[1].name, "effect");
  EXPECT_EQ(s[1].value, "cohesion");
  EXPECT_EQ(s[2].name, "limit");
  const auto t = granpen::parse_json_path("per_speed[12][*]");
  ASSERT_EQ(t.size(), 3u);
  EXPECT_EQ(t[1].kind, JsonPathStep::index);
  EXPECT_EQ(t[1].at, 12u);
  EXPECT_EQ(t[2].kind, JsonPathStep::every);
}

TEST(JsonPath, MalformedPathsAreNamed)
{
  for (const char *bad : {"", "a..b", ".a", "a.", "a[", "a[]", "a[x]", "a[-1]", "a]b", "a[0]b", "a[=x]"}) {
    const std::string m = error_of([&] { granpen::parse_json_path(bad); });
    EXPECT_NE(m.find("key path '" + std::string(bad) + "'"), std::string::npos) << bad << " -> " << m;
  }
}

TEST(JsonPath, LookupByMemberIndexMatchAndEvery)
{
  const Json d = sample();
  using V = std::vector<std::string>;
  EXPECT_EQ(texts(granpen::json_lookup(d, "verdict")), V{"tie"});                  // a string, no quotes
  EXPECT_EQ(texts(granpen::json_lookup(d, "heldout.gap_before")), V{"0.13893"});
  EXPECT_EQ(texts(granpen::json_lookup(d, "heldout.magnitude")), V{"null"});
  EXPECT_EQ(texts(granpen::json_lookup(d, "tie")), V{R"(["force_scale","packing"])"});
  EXPECT_EQ(texts(granpen::json_lookup(d, "tie[1]")), V{"packing"});
  EXPECT_EQ(texts(granpen::json_lookup(d, "ranking[effect=cohesion].magnitude_error")), V{"120.602"});
  EXPECT_EQ(texts(granpen::json_lookup(d, "per_speed[v0=100].n")), V{"7"});      // a number by its text
  EXPECT_EQ(texts(granpen::json_lookup(d, "per_speed[*].v0")), (V{"50", "100"}));
  EXPECT_TRUE(granpen::json_lookup(d, "empty[*].x").values.empty());
  EXPECT_TRUE(granpen::json_lookup(d, "per_speed[*].v0").complete());
}

TEST(JsonPath, WhatIsMissingIsNamed)
{
  const Json d = sample();
  const auto miss = [&](const std::string &p) {
    const auto r = granpen::json_lookup(d, p);
    EXPECT_FALSE(r.complete()) << p;
    return r.missing;
  };
  EXPECT_EQ(miss("heldout.v1"), "no member 'v1' in 'heldout'");
  EXPECT_EQ(miss("nothing"), "no member 'nothing' in the document");
  EXPECT_EQ(miss("tie[2]"), "index 2 past the end of 'tie' (2 elements)");
  EXPECT_EQ(miss("ranking[effect=friction]"), "no element of 'ranking' with effect = friction");
  EXPECT_EQ(miss("verdict.x"), "'verdict' is a string, not an object with member 'x'");
  EXPECT_EQ(miss("heldout[0]"), "'heldout' is an object, not an array");
  // under [*], an element that lacks the member is missing alone: the others are found
  const Json runs = Json::parse(R"({"runs": [{"v0": "28"}, {"id": "bed"}, {"v0": "50"}]})");
  const auto r = granpen::json_lookup(runs, "runs[*].v0");
  EXPECT_EQ(texts(r), (std::vector<std::string>{"28", "<missing>", "50"}));
  EXPECT_EQ(r.missing, "no member 'v0' in 'runs[*]'");
}

// Two routes to a value's text: the writer's (json_layout, what a grep of the file used to
// return) and get's (the file read back, json_value_text): the same characters, for the
// printf formats the tools round with.
TEST(JsonPath, GetPrintsWhatTheWriterWrote)
{
  for (double v : {0.123456789, 25300.0, 1e-7, -3.5e12, 2.0 / 3.0, 1.0e20, -0.011086499999999999, 70.46, 0.0}) {
    for (const char *f : {"%.6g", "%.10g", "%g", "%.3f", "%.17g"}) {
      Json j;
      j["x"] = granpen::json_rounded(f, v);
      const std::string text = granpen::json_layout(j, 1);
      const std::string written = text.substr(text.find(": ") + 2, text.find('\n', text.find(": ")) - text.find(": ") - 2);
      const Json back = Json::parse(text);
      EXPECT_EQ(granpen::json_value_text(*granpen::json_lookup(back, "x").values.at(0)), written) << f << " " << v;
    }
  }
}

TEST(JsonPath, ReadingAFileNamesWhatIsWrong)
{
  const fs::path d = fs::path(GRANPEN_JSON_PATH_DIR);
  fs::remove_all(d);
  fs::create_directories(d);
  std::ofstream(d / "good.json") << "{\"a\": [1, 2]}\n";
  std::ofstream(d / "bad.json") << "{\n  \"a\": 1,\n  \"b\": tru\n}\n";
  EXPECT_EQ(granpen::read_json_file((d / "good.json").string())["a"][1], 2);
  const std::string bad = error_of([&] { granpen::read_json_file((d / "bad.json").string()); });
  EXPECT_EQ(bad.rfind((d / "bad.json").string() + ":3:", 0), 0u) << bad;    // file and line
  EXPECT_NE(bad.find("not JSON"), std::string::npos) << bad;
  EXPECT_EQ(bad.find("json.exception"), std::string::npos) << bad;    // no raw library text
  EXPECT_NE(error_of([&] { granpen::read_json_file((d / "none.json").string()); }).find("none.json: cannot read it"), std::string::npos);
  EXPECT_NE(error_of([&] { granpen::read_json_file(d.string()); }).find("a folder, not a JSON file"), std::string::npos);
}
