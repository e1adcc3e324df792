// The sweep manifest (docs/sweeps.md) written through io/json_writer: the manifest of
// manifest_sweeps.sh's sweeps (fake_lmp) against manifest_before.json, the manifest the
// same sweeps gave when it was hand-built text (commit 71436ce), compared as parsed JSON:
// the same keys in the same order, the same values. What differs between two runs is
// normalised in both: the output folder (GRANPEN_MANIFEST_OUT, "@OUT@" in the fixture)
// and the measured wall times. Run by ctest after manifest_sweeps.sh (sweep_manifest_json).
#include "json_writer.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

using granpen::Json;

namespace {

std::string slurp(const std::string &path)
{
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// out replaced by "@OUT@" in every string; wall times (measured) set to 0
void normalise(Json &j, const std::string &out)
{
  if (j.is_string()) {
    std::string s = j.get<std::string>();
    for (std::size_t at; !out.empty() && (at = s.find(out)) != std::string::npos;) s.replace(at, out.size(), "@OUT@");
    j = s;
  } else if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it) {
      if (it.key() == "wall_seconds_run") it.value() = 0;
      else normalise(it.value(), out);
    }
  } else if (j.is_array()) {
    for (auto &e : j) normalise(e, out);
  }
}

}    // namespace

TEST(SweepManifest, SameKeysAndValuesAsTheHandBuiltOne)
{
  const char *out = std::getenv("GRANPEN_MANIFEST_OUT");
  if (!out) GTEST_SKIP() << "GRANPEN_MANIFEST_OUT not set (ctest sets it after manifest_sweeps.sh)";
  const std::string text = slurp(std::string(out) + "/runs/manifest_demo/manifest.json");
  Json after = Json::parse(text), before = Json::parse(slurp(GRANPEN_MANIFEST_BEFORE));
  normalise(after, out);
  normalise(before, "");
  // the version of granpen may move on; the fixture's is not the point
  after["granpen"] = before["granpen"];
  ASSERT_EQ(after["runs"].size(), 7u) << "2 pours, 4 pushes of a.sweep, 1 push of b.sweep";
  for (std::size_t k = 0; k < after["runs"].size(); ++k) {
    SCOPED_TRACE(before["runs"][k].value("id", "?"));
    // ordered_json: == compares the key order too
    EXPECT_EQ(after["runs"][k], before["runs"][k]) << after["runs"][k].dump() << "\n" << before["runs"][k].dump();
  }
  EXPECT_EQ(after, before);
  // the layout: one member a line, one run a line (keep_other_runs' fallback reads lines)
  std::istringstream lines(text);
  int run_lines = 0;
  for (std::string line; std::getline(lines, line);) run_lines += line.rfind("    {\"id\": ", 0) == 0;
  EXPECT_EQ(run_lines, 7) << text;
}
