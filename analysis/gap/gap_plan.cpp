#include "gap_plan.h"

namespace granpen {

// signature beds; the reference beds the fits measure the gap against (and split for the
// null replicates); the confirmation's beds, used by no fit
const std::vector<std::string> SIGNATURE_SEEDS = {"1", "2"}, REFERENCE_SEEDS = {"11", "12", "13", "14"},
                               CONFIRM_SEEDS = {"21", "22", "23", "24"}, REFINE_SEEDS = {"31", "32", "33", "34"};

std::vector<SimRequest> signature_requests(const std::string &scenario, const std::vector<std::string> &v0,
                                           const std::vector<const Effect *> &effects)
{
  // the baseline on the signature beds, and on the reference beds: what the fits measure
  // the gap against, and the null replicates of the targeted test
  std::vector<SimRequest> out{baseline_request(scenario, v0, SIGNATURE_SEEDS, "baseline"),
                              baseline_request(scenario, v0, REFERENCE_SEEDS, "fresh_baseline")};
  for (const Effect *e : effects)
    for (double a : e->knots) {
      SimRequest r = effect_request(scenario, *e, a, v0, SIGNATURE_SEEDS, effect_sweep_name(*e, a));
      if (!e->pour_level) r.beds_from = "baseline";
      out.push_back(r);
    }
  return out;
}

std::vector<SimRequest> confirm_requests(const std::string &scenario, const Effect &e, double a,
                                         const std::vector<std::string> &v0, const std::string &tag,
                                         const std::vector<std::string> &seeds)
{
  std::vector<SimRequest> out;
  SimRequest r = effect_request(scenario, e, a, v0, seeds, tag + "_" + effect_sweep_name(e, a));
  if (!e.pour_level) {
    // the confirmation's beds, poured once for every push-only confirmation (pours only:
    // the baseline's pushes on them would enter nothing)
    const std::string beds = seeds == CONFIRM_SEEDS ? "confirm_beds" : "refine_beds";
    out.push_back(baseline_request(scenario, {}, seeds, beds));
    r.beds_from = beds;
  }
  out.push_back(r);
  return out;
}

}    // namespace granpen
