#include "gap_plan.h"

namespace granpen {

const std::vector<std::string> SIGNATURE_SEEDS = {"1", "2"}, CONFIRM_SEEDS = {"11", "12", "13", "14"};

std::vector<SimRequest> signature_requests(const std::string &scenario, const std::vector<std::string> &v0,
                                           const std::vector<const Effect *> &effects)
{
  // the baseline on the signature beds, and on the fresh beds: the null replicates of the
  // targeted test (and the paired baseline of a push-only effect's confirmation)
  std::vector<SimRequest> out{baseline_request(scenario, v0, SIGNATURE_SEEDS, "baseline"),
                              baseline_request(scenario, v0, CONFIRM_SEEDS, "fresh_baseline")};
  for (const Effect *e : effects)
    for (double a : e->knots) {
      SimRequest r = effect_request(scenario, *e, a, v0, SIGNATURE_SEEDS, effect_sweep_name(*e, a));
      if (!e->pour_level) r.beds_from = "baseline";
      out.push_back(r);
    }
  return out;
}

std::vector<SimRequest> confirm_requests(const std::string &scenario, const Effect &e, double a,
                                         const std::vector<std::string> &v0, const std::string &tag)
{
  std::vector<SimRequest> out;
  SimRequest r = effect_request(scenario, e, a, v0, CONFIRM_SEEDS, tag + "_" + effect_sweep_name(e, a));
  if (!e.pour_level) {
    // fresh baseline beds, poured once for every push-only confirmation; their own pushes
    // give the baseline on the same fresh beds, so the confirmation is a paired comparison
    out.push_back(baseline_request(scenario, v0, CONFIRM_SEEDS, "fresh_baseline"));
    r.beds_from = "fresh_baseline";
  }
  out.push_back(r);
  return out;
}

}    // namespace granpen
