// granpen gap: the pair stage in diagnosis.json and report.md (see gap_report_pairs.h).
#include "gap_report_pairs.h"

#include "gap_thresholds.h"
#include "text_util.h"

#include <cmath>

namespace granpen {

namespace {

Json num(double v, const char *f = "%.6g") { return std::isfinite(v) ? json_rounded(f, v) : Json(); }
std::string fmt(double v, const char *f = "%.4g") { return printf_number(f, v); }

Json pair_fit_json(const PairFit &p)
{
  return Json{{"effects", Json::array({p.a, p.b})},
              {"magnitudes", Json::array({num(p.magnitude_a), num(p.magnitude_b)})},
              {"scale", num(p.scale, "%.4g")},
              {"explained_fraction", num(p.explained, "%.4f")},
              {"heldout_explained", num(p.heldout_explained, "%.4f")},
              {"likelihood_ratio", num(p.lr, "%.4g")},
              {"lr_null_mean", num(p.lr_null_mean, "%.4g")},
              {"lr_threshold", num(p.lr_threshold, "%.4g")},
              {"evidence", num(p.evidence, "%.4g")},
              {"best_single", p.best_single},
              {"best_single_evidence", num(p.best_single_evidence, "%.4g")},
              {"margin", num(p.margin, "%.4g")},
              {"at_edge", p.at_edge},
              {"passes", p.passes},
              {"why_not", p.why.empty() ? Json() : Json(p.why)}};
}

}    // namespace

Json pair_stage_json(const std::optional<PairStage> &stage)
{
  if (!stage) return Json();
  const PairSearch &s = stage->search;
  Json tried = Json::array();
  for (const PairFit &p : s.tried) tried.push_back(pair_fit_json(p));
  Json seeded_knots = Json::array();
  for (double a : s.seeded_knots) seeded_knots.push_back(num(a, "%.4g"));
  Json seeded;
  if (s.seeded_single)
    seeded = Json{{"magnitude", num(s.seeded_single->magnitude)},
                  {"evidence", num(lr_evidence(*s.seeded_single), "%.4g")},
                  {"explained_fraction", num(s.seeded_single->explained, "%.4f")}};
  Json confirmation;
  if (stage->confirmation && stage->confirmation->outcome.kind == PairOutcome::Kind::simulated) {
    const PairConfirmation &c = *stage->confirmation;
    confirmation = Json{{"chi2_before", num(c.chi2_before, "%.4g")},
                        {"chi2_after", num(c.chi2_after, "%.4g")},
                        {"explained_fraction", num(c.confirmed_fraction, "%.4f")},
                        {"signature_sigma_before", num(c.proj_before, "%.4f")},
                        {"signature_sigma_after", num(c.proj_after, "%.4f")},
                        {"gap_before", num(c.outcome.gap_before)},
                        {"gap_after", num(c.outcome.gap_after)},
                        {"confirmed", c.outcome.confirmed}};
  }
  return Json{{"why", s.why},
              {"line_freq", num(s.line_freq, "%.4g")},
              {"seeded_knots", seeded_knots},
              {"seeded_single", seeded},
              {"tried", tried},
              {"named", s.named ? pair_fit_json(*s.named) : Json()},
              {"confirmation", confirmation},
              {"thresholds", Json{{"lr_chi2_2_p1e4", GapThresholds::lr_chi2_2_p1e4}, {"margin", GapThresholds::lr_chi2_1_p1e4}}}};
}

std::string pair_plain_verdict(const PairStage &stage, bool provisional)
{
  if (!stage.confirmation) return "Two effects at once.";
  const PairConfirmation &c = *stage.confirmation;
  std::string s = "The gap is explained by two effects at once: " + c.filter + " at " + fmt(c.magnitude_filter) + " (" +
                  c.unit_filter + ") and " + c.other + " at " + fmt(c.magnitude_other) + " (" + c.unit_other + ")";
  if (const auto &p = stage.search.named)
    s += "; their evidence " + fmt(p->evidence, "%.1f") + " (its likelihood ratio " + fmt(p->lr, "%.1f") + " is above its threshold " +
         fmt(p->lr_threshold, "%.1f") + ") is beyond the best single member's (" + p->best_single + ", " +
         fmt(p->best_single_evidence, "%.1f") + ") by " + fmt(p->margin, "%.1f") + " (" + fmt(GapThresholds::lr_chi2_1_p1e4, "%.1f") +
         " needed)";
  return s + (provisional ? "; provisional (--fit-only: not confirmed)." : "; confirmed together on fresh seeds.");
}

std::string pair_stage_markdown(const std::optional<PairStage> &stage)
{
  if (!stage) return "";
  const PairSearch &s = stage->search;
  std::string md = "\n## Two effects at once\n\nThe pair stage was " + s.why + ".";
  if (!s.seeded_knots.empty()) {
    std::string knots;
    for (double a : s.seeded_knots) knots += (knots.empty() ? "" : ", ") + fmt(a);
    md += (std::isfinite(s.line_freq) ? " The residual's line at " + fmt(s.line_freq, "%.0f") + " Hz set the filter's knot search: knots at "
                                      : std::string(" The filter's knot search (no line: the segment of its knots its own fit lies in, then the pair's magnitude): knots at ")) +
          knots +
          (s.seeded_single ? " (the filter alone with them: evidence " + fmt(lr_evidence(*s.seeded_single), "%.1f") + ", explained " +
                                 fmt(s.seeded_single->explained, "%.2f") + ")"
                           : std::string()) +
          ".";
  }
  md += "\n\n| pair | magnitudes | explained | held out | likelihood ratio (threshold) | evidence | best single | margin | passes |\n"
        "|---|---|---|---|---|---|---|---|---|\n";
  for (const PairFit &p : s.tried)
    md += "| " + p.a + " + " + p.b + " | " + fmt(p.magnitude_a) + ", " + fmt(p.magnitude_b) + " | " + fmt(p.explained, "%.2f") +
          " | " + fmt(p.heldout_explained, "%.2f") + " | " + fmt(p.lr, "%.1f") + " (" + fmt(p.lr_threshold, "%.1f") + ") | " +
          fmt(p.evidence, "%.1f") + " | " + p.best_single + " " + fmt(p.best_single_evidence, "%.1f") + " | " +
          fmt(p.margin, "%.1f") + " | " + (p.passes ? "yes" : "no: " + p.why) + " |\n";
  if (stage->confirmation && stage->confirmation->outcome.kind == PairOutcome::Kind::simulated) {
    const PairConfirmation &c = *stage->confirmation;
    md += "\nOn fresh seeds (" + c.other + " simulated at " + fmt(c.magnitude_other) + ", filtered by " + c.filter + " at " +
          fmt(c.magnitude_filter) + "): G_all " + fmt(c.outcome.gap_before, "%.3f") + " -> " + fmt(c.outcome.gap_after, "%.3f") +
          ", chi^2 after " + fmt(c.chi2_after, "%.1f") + ", along the pair's signature " + fmt(c.proj_before, "%.2f") + " -> " +
          fmt(c.proj_after, "%.2f") + " sigma: " + (c.outcome.confirmed ? "confirmed" : "not confirmed") + ".\n";
  }
  return md;
}

}    // namespace granpen
