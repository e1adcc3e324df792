// The subcommands' parse functions (analysis/cli/NAME_options.h), driven in process: the CLI
// fuzz target's body (tests/fuzz/fuzz_cli_body.h) on the committed corpus and regressions
// and on a fixed number of seeded mutations of them (the driver CI runs without clang and
// libFuzzer), with nothing printed; and the checks of a few options by known answers.
#include "fuzz_cli_body.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace granpen::cli;

namespace {

std::string read_bytes(const fs::path &p)
{
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// the committed inputs: corpus/cli and regressions/cli
std::vector<std::string> committed_inputs()
{
  std::vector<std::string> out;
  for (const char *sub : {"corpus", "regressions"}) {
    const fs::path dir = fs::path(GRANPEN_FUZZ_DIR) / sub / "cli";
    if (!fs::is_directory(dir)) continue;
    for (const auto &e : fs::directory_iterator(dir))
      if (e.is_regular_file() && e.path().filename().string()[0] != '.') out.push_back(read_bytes(e.path()));
  }
  return out;
}

// the dictionary's words (cli.dict: "WORD" or "WORD\x0a" a line)
std::vector<std::string> dictionary_words()
{
  std::vector<std::string> words;
  std::ifstream in(fs::path(GRANPEN_FUZZ_DIR) / "cli.dict");
  for (std::string line; std::getline(in, line);) {
    if (line.size() < 2 || line[0] != '"') continue;
    std::string w = line.substr(1, line.rfind('"') - 1);
    const auto nl = w.find("\\x0a");
    if (nl != std::string::npos) w.erase(nl);
    words.push_back(w);
  }
  return words;
}

// words joined as the fuzz body reads them
std::string join(const std::vector<std::string> &words)
{
  std::string s;
  for (std::size_t k = 0; k < words.size(); ++k) s += (k ? "\n" : "") + words[k];
  return s;
}

// one mutation of an input's words: a word replaced by a dictionary word, inserted,
// removed, a value's characters changed, or two words swapped
std::string mutate(const std::string &input, const std::vector<std::string> &dict, std::mt19937 &rng)
{
  std::vector<std::string> w = granpen_fuzz::cli_words(input);
  auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); };
  const int rounds = 1 + (int) pick(4);
  for (int r = 0; r < rounds; ++r) {
    const std::size_t at = 1 + pick(w.size());    // never the subcommand itself
    switch (pick(5)) {
      case 0: if (at < w.size()) w[at] = dict[pick(dict.size())]; break;
      case 1: w.insert(w.begin() + (long) std::min(at, w.size()), dict[pick(dict.size())]); break;
      case 2: if (at < w.size()) w.erase(w.begin() + (long) at); break;
      case 3:
        if (at < w.size() && !w[at].empty()) w[at][pick(w[at].size())] = "-0.e9x:= "[pick(10)];
        break;
      default:
        if (at < w.size()) std::swap(w[at], w[1 + pick(w.size() - 1)]);
        break;
    }
  }
  return join(w);
}

// the body on input, with stdout and stderr captured: a parse prints nothing
void parse_silently(const std::string &input)
{
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  granpen_fuzz::cli_body(input);
  const std::string out = testing::internal::GetCapturedStdout(), err = testing::internal::GetCapturedStderr();
  EXPECT_EQ(out + err, "") << "a parse printed, for input:\n" << input;
}

}    // namespace

TEST(CliOptionsFuzz, CommittedInputsParseCleanlyAndSilently)
{
  const auto inputs = committed_inputs();
  ASSERT_GT(inputs.size(), 40u) << "the corpus of " << GRANPEN_FUZZ_DIR;
  for (const auto &in : inputs) parse_silently(in);
}

// The non-libFuzzer driver: 30,000 seeded mutations of the corpus (a fixed number, about
// a second), each through the fuzz body. A broken check aborts with the check's text.
TEST(CliOptionsFuzz, SeededMutationsKeepTheChecks)
{
  const auto inputs = committed_inputs();
  const auto dict = dictionary_words();
  ASSERT_GT(dict.size(), 60u);
  std::mt19937 rng(20240519);
  int accepted = 0;
  for (int k = 0; k < 30000; ++k) {
    const std::string in = mutate(inputs[k % inputs.size()], dict, rng);
    granpen_fuzz::cli_body(in);
    ++accepted;
  }
  EXPECT_EQ(accepted, 30000);
}

namespace {

template <class Options>
Options parse_words(Options (*parse)(int, char **), std::vector<std::string> words)
{
  std::vector<char *> argv;
  for (auto &w : words) argv.push_back(&w[0]);
  return parse((int) words.size(), argv.data());
}

template <class Options>
std::string usage_error(Options (*parse)(int, char **), std::vector<std::string> words)
{
  try {
    parse_words(parse, words);
  } catch (const UsageError &e) {
    return e.what();
  }
  return "(accepted)";
}

}    // namespace

TEST(CliOptions, KnownAnswers)
{
  const FitOptions fit = parse_words(parse_fit, {"t.csv", "--zmax", "9", "--mu", "0.5", "--json", "f.json"});
  EXPECT_EQ(fit.traces, std::vector<std::string>{"t.csv"});
  EXPECT_EQ(fit.window.zmin, 3.0);
  EXPECT_EQ(fit.window.zmax, 9.0);
  EXPECT_EQ(fit.window.mu, 0.5);
  EXPECT_EQ(fit.json, "f.json");
  EXPECT_FALSE(fit.help_requested());
  EXPECT_EQ(usage_error(parse_fit, {"t.csv", "--zmin", "1", "--tmin", "1"}), "give --zmin or --tmin, not both");
  EXPECT_EQ(usage_error(parse_fit, {"t.csv", "--zmin", "5", "--zmax", "4"}), "--zmin must be below --zmax");

  const ConvertOptions c = parse_words(parse_convert, {"a.txt", "--v0", "100", "--dt", "2e-6", "--D", "2", "--g", "981",
                                                       "--out", "a.csv", "--sign", "-1", "--mu", "0.3"});
  EXPECT_EQ(c.spec.sign, -1.0);
  EXPECT_EQ(c.spec.dt, 2e-6);
  ASSERT_EQ(c.extra.size(), 1u);
  EXPECT_EQ(c.extra[0], std::make_pair(std::string("mu"), std::string("0.3")));
  EXPECT_EQ(usage_error(parse_convert, {"a.txt", "--v0", "1", "--dt", "1", "--D", "1", "--g", "1", "--out", ""}),
            "--out needs a name");

  const FlowOptions f = parse_words(parse_flow, {"d.dump", "--periodic", "x", "--steps", "100:200", "--strip", "1", "2"});
  EXPECT_TRUE(f.px);
  EXPECT_FALSE(f.py);
  EXPECT_EQ(f.step_lo, 100);
  EXPECT_EQ(f.step_hi, 200);
  EXPECT_EQ(f.strip1, 1.0);
  EXPECT_EQ(usage_error(parse_flow, {"d.dump", "--rod-type", "1e300"}), "--rod-type must be a positive integer");
  // the numbers typed: given ones bound, the rest NaN (the trace's, the frame's or a default
  // then); an option given twice refused
  const FlowOptions ft = parse_words(parse_flow, {"d.dump", "--D", "2", "--edge", "0.1", "0.2", "--axis", "3",
                                                  "4", "--tip", "1.5", "--rod-type", "3", "--trace", "t.csv"});
  EXPECT_EQ(ft.D, 2.0);
  EXPECT_EQ(ft.edge_wr, 0.1);
  EXPECT_EQ(ft.edge_wz, 0.2);
  EXPECT_TRUE(ft.rod.have_axis && ft.rod.have_tip);
  EXPECT_EQ(ft.rod.axis_y, 4.0);
  EXPECT_EQ(ft.rod.tip, 1.5);
  EXPECT_EQ(ft.rod.rod_type, 3);
  EXPECT_EQ(ft.trace, "t.csv");
  EXPECT_TRUE(std::isnan(ft.d_g) && std::isnan(ft.z_s) && std::isnan(ft.dr));
  EXPECT_EQ(usage_error(parse_flow, {"d.dump", "--axis", "1"}), "--axis needs 2 values");
  EXPECT_EQ(usage_error(parse_flow, {"d.dump", "--strip", "1", "2", "--strip", "1", "3"}), "--strip needs 2 values");
  EXPECT_EQ(usage_error(parse_flow, {"d.dump", "--D", "1", "--D", "2"}).compare(0, 4, "--D:"), 0);
  EXPECT_EQ(usage_error(parse_flow, {"d.dump", "--dr", "0"}), "--dr must be > 0, got '0'");
  EXPECT_EQ(usage_error(parse_flow, {"d.dump", "--zs", "high"}), "--zs needs a number, got 'high'");
  EXPECT_EQ(usage_error(parse_flow, {"d.dump", "--periodic", "z"}), "--periodic must be xy, x, y or none");
  const MomentumOptions m = parse_words(parse_momentum, {"d.dump", "--trace", "t.csv", "--mu", "0", "--push-step", "-7",
                                                         "--thresholds", "0.2", "0.1", "0.01", "0.001"});
  EXPECT_EQ(m.mu, 0.0);
  EXPECT_TRUE(m.by_time);
  EXPECT_EQ(m.push_step, -7);
  EXPECT_EQ(m.thresholds, (std::vector<double>{0.2, 0.1, 0.01, 0.001}));
  EXPECT_TRUE(std::isnan(m.D) && std::isnan(m.dt) && std::isnan(m.mthreshold));
  EXPECT_EQ(usage_error(parse_momentum, {"d.dump"}), "--trace TRACE is required (v0, D, g and the drag come from it)");
  EXPECT_EQ(usage_error(parse_momentum, {"d.dump", "--trace", "t.csv", "--push-step", "1.5"}),
            "--push-step '1.5' is not an integer");

  EXPECT_EQ(usage_error(parse_momentum, {"d.dump", "--trace", "t.csv", "--thresholds", "0.1", "0.2", "0.01", "0.001"})
                .compare(0, 14, "--thresholds: "), 0);
  EXPECT_EQ(usage_error(parse_collapse, {"t.csv", "--csv", ""}), "--csv needs a name");
  EXPECT_EQ(usage_error(parse_plot, {"bars", "t.csv", "--out", "p"}),
            "unknown kind 'bars' (force, ratio, peak, kz, flow, momentum, scaling, parting)");

  const PlotOptions help = parse_words(parse_plot, {"--help"});
  EXPECT_TRUE(help.help_requested());
  EXPECT_EQ(help.help.compare(0, 19, "usage: granpen plot"), 0);
  try {
    parse_words(parse_check, {});
    ADD_FAILURE() << "no words accepted";
  } catch (const UsageError &e) {
    EXPECT_STREQ(e.what(), "");
    EXPECT_EQ(e.usage.compare(0, 20, "usage: granpen check"), 0);
  }
}
