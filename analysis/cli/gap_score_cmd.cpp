// granpen gap-score DIAGNOSIS ...: a selftest case's row of bench/gap_selftest.sh's table,
// scored by gap/gap_selftest_score.h.
#include "gap_selftest_score.h"
#include "get_options.h"
#include "json_path.h"
#include "subcommand.h"
#include "subcommands.h"
#include "text_util.h"

#include <cstdio>
#include <cstdlib>

namespace {

using granpen::MaybeNumber;

// the case scored and did not pass (distinct from 1, a diagnosis that cannot be scored)
constexpr int EXIT_CASE_FAILED = 3;

std::string maybe(const char *f, const MaybeNumber &n) { return n.known ? granpen::format_text(f, n.value) : "-"; }

granpen::SelftestCase selftest_case(const granpen::cli::GapScoreOptions &o)
{
  granpen::SelftestCase c;
  if (o.truth == "none") return c;
  if (o.truth == "outside") {
    c.truth = granpen::SelftestCase::Truth::outside;
    c.as_effect = o.as_effect;
    c.as_magnitude = o.as_magnitude;
    return c;
  }
  c.truth = granpen::SelftestCase::Truth::library;
  c.effect = o.truth;
  c.below_limit = o.below_limit;
  c.magnitude = std::strtod(o.magnitude_text.c_str(), nullptr);    // checked by the parse
  if (const auto comma = o.truth.find(','); comma != std::string::npos) {    // a pair: A,B at X,Y (checked by the parse)
    const auto mcomma = o.magnitude_text.find(',');
    c.truth = granpen::SelftestCase::Truth::pair;
    c.effect = o.truth.substr(0, comma), c.effect2 = o.truth.substr(comma + 1);
    c.magnitude2 = std::strtod(o.magnitude_text.c_str() + mcomma + 1, nullptr);
  }
  return c;
}

std::string limit_text(const granpen::SelftestLimit &l)
{
  using K = granpen::SelftestLimit::Kind;
  switch (l.kind) {
  case K::none_within_knots: return "none within the knots";
  case K::value: return granpen::format_text("%.3g", l.value);
  case K::not_applicable:
  case K::missing: break;
  }
  return "-";
}

// the top effect column: the tie that names the truth, the stand-in effect's distance
std::string top_effect_text(const granpen::SelftestScore &s, const granpen::SelftestCase &c)
{
  if (s.pair_names_truth) return "pair: " + s.pair[0] + "," + s.pair[1];
  if (s.names_part_of_pair) return (s.top_effect.empty() ? std::string(granpen::verdict_name(s.verdict)) : s.top_effect) + " (part of the pair)";
  if (s.tie_names_truth) {
    std::string t = "tie: ";
    for (std::size_t i = 0; i < s.tie.size(); ++i) t += (i ? "," : "") + s.tie[i];
    return t;
  }
  if (s.scale_causes_hold_truth) return "scale_only, with " + c.effect;
  if (s.named_as_effect) {
    const double a = s.magnitude.known ? s.magnitude.value : 0.0;
    return s.top_effect + " (" +
           (s.as_effect_error.known
                ? granpen::format_text("%+.1f fit errors off %.3g", (a - c.as_magnitude) / s.as_effect_error.value, c.as_magnitude)
                : std::string("no fit error")) +
           ")";
  }
  return s.top_effect.empty() ? "-" : s.top_effect;
}

}    // namespace

int granpen::cli::run_gap_score(const GapScoreOptions &o)
{
  const SelftestCase c = selftest_case(o);
  const SelftestScore s = score_selftest(read_json_file(o.diagnosis), c, o.diagnosis);
  const std::string pass = !s.pass ? "**no**" : s.missed_below_limit ? "yes (below its limit)" : "yes";
  const std::string row =
      "| " + o.case_name + " | " + o.truth + " | " + o.magnitude_text + " | " + limit_text(s.limit) + " | " +
      verdict_name(s.verdict) + " | " + top_effect_text(s, c) + " | " + maybe("%.3g", s.magnitude) + " | " +
      format_text("%.3f | %.3f", s.gap_before, s.gap_after) + " | " + maybe("%g", s.heldout_v0) + " | " +
      maybe("%.3f", s.heldout_before) + " | " + maybe("%.3f", s.heldout_after) + " | " + maybe("%.2f", s.explained_fraction) +
      " | " + (o.wall_seconds >= 0 ? std::to_string(o.wall_seconds) : "-") + " | " + pass + " |\n";
  std::fputs(row.c_str(), stdout);
  return s.pass ? EXIT_OK : EXIT_CASE_FAILED;
}
int granpen::cli::gap_score(int argc, char **argv) { return run_parsed(parse_gap_score, run_gap_score, argc, argv); }
