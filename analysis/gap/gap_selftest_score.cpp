// granpen gap: the selftest's scoring (see gap_selftest_score.h).
#include "gap_selftest_score.h"

#include "errors.h"
#include "json_path.h"

#include <algorithm>
#include <stdexcept>

namespace granpen {

namespace {

struct VerdictKind {
  Verdict verdict;
  VerdictReading reading;
};

// How the selftest reads each verdict kind of gap_verdict.h: a new kind is one line here
// (until it is, a diagnosis with it is refused by name).
const VerdictKind VERDICT_READINGS[] = {
    {Verdict::none, VerdictReading::no_gap},
    {Verdict::explained, VerdictReading::names_top},
    {Verdict::tie, VerdictReading::names_candidates},
    {Verdict::unexplained, VerdictReading::gap_unnamed},
    {Verdict::scale_only, VerdictReading::names_scale},
    {Verdict::pair, VerdictReading::names_pair},
};

// An outside case named as its stand-in effect is right at its magnitude within two of the
// fit's standard errors: a 95% band for the fit's own scatter (over six sets of seeds the
// light grains were named 0.0 to 1.6 errors off, tests/analysis/gap/CMakeLists.txt).
constexpr double AS_EFFECT_ERRORS = 2.0;

// the one value at path, or InputError naming source and what is missing
const Json &need(const Json &d, const std::string &path, const std::string &source)
{
  const JsonLookup r = json_lookup(d, path);
  if (!r.complete()) throw InputError(source + ": " + r.missing);
  if (r.values.size() != 1) throw InputError(source + ": '" + path + "' is not one value");
  return *r.values[0];
}

// v (the value at path) as a number, or unknown when null
MaybeNumber number_or_null(const Json &v, const std::string &path, const std::string &source)
{
  if (v.is_null()) return {};
  if (!v.is_number()) throw InputError(source + ": '" + path + "' is " + json_value_text(v) + ", not a number or null");
  return {true, v.get<double>()};
}

MaybeNumber maybe_number(const Json &d, const std::string &path, const std::string &source)
{
  return number_or_null(need(d, path, source), path, source);
}

// member key of the object at parent, unknown when the parent is null
MaybeNumber maybe_member(const Json &d, const std::string &parent, const std::string &key, const std::string &source)
{
  const Json &p = need(d, parent, source);
  if (p.is_null()) return {};
  return maybe_number(d, parent + "." + key, source);
}

double number(const Json &d, const std::string &path, const std::string &source)
{
  const MaybeNumber n = maybe_number(d, path, source);
  if (!n.known) throw InputError(source + ": '" + path + "' is null, not a number");
  return n.value;
}

std::string maybe_string(const Json &d, const std::string &path, const std::string &source)
{
  const Json &v = need(d, path, source);
  if (v.is_null()) return "";
  if (!v.is_string()) throw InputError(source + ": '" + path + "' is " + json_value_text(v) + ", not a string or null");
  return v.get<std::string>();
}

std::vector<std::string> names(const Json &d, const std::string &path, const std::string &source)
{
  const Json &v = need(d, path, source);
  std::vector<std::string> out;
  if (v.is_null()) return out;
  if (!v.is_array()) throw InputError(source + ": '" + path + "' is not a list of names or null");
  for (const auto &e : v) out.push_back(json_value_text(e));
  return out;
}

// the truth's detection limit on its side of 0 (effect at magnitude), and whether the truth lies below it
SelftestLimit detection_limit(const Json &d, const std::string &effect, double magnitude, const std::string &source)
{
  SelftestLimit lim;
  const JsonLookup entry = json_lookup(d, "detection_limits[effect=" + effect + "]");
  if (!entry.complete()) {
    lim.kind = SelftestLimit::Kind::missing;
    return lim;
  }
  const Json &e = *entry.values[0];
  const std::string at = "detection_limits[effect=" + effect + "]";
  const MaybeNumber ref = number_or_null(need(e, "reference", source), at + ".reference", source);
  const std::string side = magnitude * (ref.known ? ref.value : 0.0) >= 0 ? "limit" : "limit_other_side";
  const MaybeNumber l = number_or_null(need(e, side, source), at + "." + side, source);
  if (!l.known) {
    lim.kind = SelftestLimit::Kind::none_within_knots;
    lim.truth_below = true;
    return lim;
  }
  lim.kind = SelftestLimit::Kind::value;
  lim.value = l.value;
  lim.truth_below = magnitude * magnitude < l.value * l.value;
  return lim;
}

// A pair case: both named by a pair verdict; one of the two named alone (as an explained
// verdict, a tie or a scale's cause would name a single truth); a miss when a member lies
// below its limit. Whatever else is named is wrong.
void judge_pair_case(const Json &d, const SelftestCase &c, SelftestScore &s)
{
  const VerdictReading r = verdict_reading(s.verdict);
  auto in_truth = [&](const std::string &name) { return name == c.effect || name == c.effect2; };
  switch (r) {
  case VerdictReading::names_pair:
    s.pass = s.pair_names_truth = s.pair.size() == 2 && in_truth(s.pair[0]) && in_truth(s.pair[1]) && s.pair[0] != s.pair[1];
    return;
  case VerdictReading::names_top:
    s.pass = s.names_part_of_pair = in_truth(s.top_effect) && gap_shrinks(s.gap_before, s.gap_after);
    return;
  case VerdictReading::names_candidates:
    s.pass = s.names_part_of_pair = std::any_of(s.tie.begin(), s.tie.end(), in_truth);
    return;
  case VerdictReading::names_scale:
    s.pass = s.names_part_of_pair = json_lookup(d, "scale_only.causes[cause=" + c.effect + "]").complete() ||
                                    json_lookup(d, "scale_only.causes[cause=" + c.effect2 + "]").complete();
    if (s.pass) return;
    break;
  case VerdictReading::no_gap:
  case VerdictReading::gap_unnamed: break;
  }
  if (s.limit.truth_below || s.limit2.truth_below) s.pass = s.missed_below_limit = true;
}

// a verdict that names no physical effect: below the truth's detection limit it is right (a
// scale_only names no effect either, issue 37)
bool is_miss(VerdictReading r)
{
  return r == VerdictReading::no_gap || r == VerdictReading::gap_unnamed || r == VerdictReading::names_scale;
}

// whether s passes c, with how (the flags of s)
void judge(const Json &d, const SelftestCase &c, const std::string &source, SelftestScore &s)
{
  const VerdictReading r = verdict_reading(s.verdict);
  switch (c.truth) {
  case SelftestCase::Truth::none: s.pass = r == VerdictReading::no_gap; return;
  case SelftestCase::Truth::pair: judge_pair_case(d, c, s); return;
  case SelftestCase::Truth::outside:
    s.pass = r != VerdictReading::names_top && r != VerdictReading::names_pair;
    if (r == VerdictReading::names_top && !c.as_effect.empty() && s.top_effect == c.as_effect) {
      s.named_as_effect = true;
      const JsonLookup fe = json_lookup(d, "ranking[effect=" + c.as_effect + "].magnitude_error");
      if (fe.complete()) s.as_effect_error = number_or_null(*fe.values[0], "ranking[effect=" + c.as_effect + "].magnitude_error", source);
      const double off = (s.magnitude.known ? s.magnitude.value : 0.0) - c.as_magnitude;
      s.pass = s.as_effect_error.known &&
               off * off <= AS_EFFECT_ERRORS * AS_EFFECT_ERRORS * s.as_effect_error.value * s.as_effect_error.value;
    }
    return;
  case SelftestCase::Truth::library:
    s.pass = r == VerdictReading::names_top && s.top_effect == c.effect && gap_shrinks(s.gap_before, s.gap_after);
    if (r == VerdictReading::names_candidates && std::find(s.tie.begin(), s.tie.end(), c.effect) != s.tie.end())
      s.pass = s.tie_names_truth = true;
    // a scale whose listed causes hold the truth is right as a tie that holds it is
    if (r == VerdictReading::names_scale && json_lookup(d, "scale_only.causes[cause=" + c.effect + "]").complete())
      s.pass = s.scale_causes_hold_truth = true;
    if (s.limit.truth_below && is_miss(r)) s.pass = s.missed_below_limit = true;
    // at about half its limit: a miss is right whatever this data's limit says; naming the
    // truth is right too; naming another effect alone, or a tie without the truth, is not
    if (c.below_limit) {
      if (is_miss(r)) s.pass = s.missed_below_limit = true;
      if (r == VerdictReading::names_top && s.top_effect == c.effect) s.pass = true;
    }
    return;
  }
}

}    // namespace

VerdictReading verdict_reading(Verdict v)
{
  for (const auto &k : VERDICT_READINGS)
    if (k.verdict == v) return k.reading;
  throw std::invalid_argument(std::string("verdict '") + verdict_name(v) + "' has no reading in the selftest's table");
}

bool verdict_from_name(const std::string &name, Verdict &v)
{
  for (const auto &k : VERDICT_READINGS)
    if (name == verdict_name(k.verdict)) {
      v = k.verdict;
      return true;
    }
  return false;
}

SelftestScore score_selftest(const Json &d, const SelftestCase &c, const std::string &source)
{
  SelftestScore s;
  const Json &verdict = need(d, "verdict", source);
  if (!verdict.is_string() || !verdict_from_name(verdict.get<std::string>(), s.verdict))
    throw InputError(source + ": verdict '" + json_value_text(verdict) +
                     "' is not a kind the selftest scores (gap_selftest_score.cpp, VERDICT_READINGS)");
  s.top_effect = maybe_string(d, "top_effect", source);
  s.tie = names(d, "tie", source);
  s.magnitude = maybe_number(d, "magnitude", source);
  s.gap_before = number(d, "gap_before", source);
  s.gap_after = number(d, "gap_after", source);
  s.heldout_v0 = maybe_member(d, "heldout", "v0", source);
  s.heldout_before = maybe_member(d, "heldout", "gap_before", source);
  s.heldout_after = maybe_member(d, "heldout", "gap_after", source);
  s.explained_fraction = maybe_member(d, "confirmation", "explained_fraction", source);
  // "pair" is read where the diagnosis has it (older ones lack the key: no pair)
  if (json_lookup(d, "pair").complete()) s.pair = names(d, "pair", source);
  if (c.truth == SelftestCase::Truth::library || c.truth == SelftestCase::Truth::pair)
    s.limit = detection_limit(d, c.effect, c.magnitude, source);
  if (c.truth == SelftestCase::Truth::pair) s.limit2 = detection_limit(d, c.effect2, c.magnitude2, source);
  judge(d, c, source, s);
  return s;
}

}    // namespace granpen
