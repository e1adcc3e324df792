// granpen gap: the adaptive plan's decision and its record (see gap_adaptive.h).
#include "gap_adaptive.h"

#include "text_util.h"

#include <algorithm>
#include <cmath>

namespace granpen {

std::vector<PurchaseDecision> decide_purchases(const CheapStageSeen &seen, const std::vector<PourCandidate> &candidates,
                                               double lr_floor, double margin)
{
  std::vector<PourCandidate> order = candidates;
  std::stable_sort(order.begin(), order.end(), [](const PourCandidate &a, const PourCandidate &b) { return a.cost < b.cost; });
  // a physical cheap candidate that explains the gap stands unless another comes within the
  // margin of its evidence (a tie) or beyond; a scale names no cause, so its look-alikes
  // (the pour-level signatures near a uniform scale) are needed whatever it explains
  const bool stands = seen.best_explains && !seen.best_is_scale;
  const double needed = stands ? std::max(lr_floor, seen.best_evidence - margin) : lr_floor;
  std::vector<PurchaseDecision> out;
  for (const PourCandidate &c : order) {
    PurchaseDecision d;
    d.effect = c.effect;
    d.cost = c.cost;
    d.needed = needed;
    d.bound = c.projection2 ? std::min(*c.projection2, seen.chi2_0) : seen.chi2_0;
    d.simulate = d.bound >= needed;
    const std::string along = c.projection2 ? "the squared gap along its signature" : "the whole squared gap (its direction unknown)";
    const std::string against = stands ? "within the evidence margin of " + seen.best + "'s " + printf_number("%.1f", seen.best_evidence) +
                                              " (and its threshold)"
                                        : "its threshold";
    d.why = (d.simulate ? "simulated: " : "skipped: ") + along + ", " + printf_number("%.1f", d.bound) +
            (d.simulate ? ", can reach " : ", cannot reach ") + printf_number("%.1f", needed) + ", " + against;
    out.push_back(d);
  }
  return out;
}

std::string plan_record_text(const PlanRecord &r)
{
  std::string s = "Cost (probe pours of core time; wall time at --jobs " + std::to_string(r.jobs) + "): this run " +
                  printf_number("%.3g", r.spent) + " (" + printf_number("%.3g", r.wall_spent) + " of wall time) within the plan's " +
                  printf_number("%.3g", r.least) + " to " + printf_number("%.3g", r.most) + " (" +
                  printf_number("%.3g", r.wall_least) + " to " + printf_number("%.3g", r.wall_most) +
                  " of wall time), counted as a cold cache runs it; where a run lands: " + r.decides + ".";
  int skipped = 0;
  for (const auto &d : r.decisions) skipped += !d.simulate;
  if (!r.decisions.empty())
    s += " Pour-level candidates: " + std::to_string(r.decisions.size() - skipped) + " simulated, " + std::to_string(skipped) +
         " skipped.";
  for (const auto &d : r.decisions) s += "\n- " + d.effect + " (" + printf_number("%.3g", d.cost) + " probe pours): " + d.why;
  if (!r.confirmation.empty()) {
    s += "\n- the confirmation: ";
    for (std::size_t i = 0; i < r.confirmation.size(); ++i) s += (i ? ", " : "") + r.confirmation[i];
  }
  return s;
}

}    // namespace granpen
