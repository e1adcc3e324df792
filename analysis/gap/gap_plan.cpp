#include "gap_plan.h"

#include "sweep_cache.h"
#include "text_util.h"
#include "errors.h"    // InputError

#include <cmath>
#include <cstdlib>

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
      if (by_transform(*e, a)) continue;    // the baseline's runs, transformed
      SimRequest r = effect_request(scenario, *e, a, v0, SIGNATURE_SEEDS, effect_sweep_name(*e, a));
      if (!e->pour_level) r.beds_from = "baseline";
      out.push_back(r);
    }
  return out;
}

std::string confirm_sweep(const Effect &e, double a, const std::string &tag, const std::vector<std::string> &seeds)
{
  if (by_transform(e, a)) return seeds == CONFIRM_SEEDS ? "confirm_baseline" : "refine_baseline";
  return tag + "_" + effect_sweep_name(e, a);
}

std::vector<SimRequest> confirm_requests(const std::string &scenario, const Effect &e, double a,
                                         const std::vector<std::string> &v0, const std::string &tag,
                                         const std::vector<std::string> &seeds)
{
  // the confirmation's beds, poured once for every push-only confirmation (pours only:
  // nothing pushes in this sweep)
  const std::string beds = seeds == CONFIRM_SEEDS ? "confirm_beds" : "refine_beds";
  std::vector<SimRequest> out;
  if (!e.pour_level) out.push_back(baseline_request(scenario, {}, seeds, beds));
  const std::string name = confirm_sweep(e, a, tag, seeds);
  SimRequest r = by_transform(e, a) ? baseline_request(scenario, v0, seeds, name)
                                    : effect_request(scenario, e, a, v0, seeds, name);
  if (!e.pour_level) r.beds_from = beds;
  out.push_back(r);
  return out;
}

double preset_grains(const Scenario &sc)
{
  const double lat = sc.number("lat"), box = sc.number("box"), lo = sc.number("fill_lo");
  const double across = std::floor((box - 2.0 * lo) / lat + 1.0);
  return across * across * std::floor((sc.number("zfill_hi") - sc.number("zfill_lo")) / lat + 1.0);
}

PlanCost plan_cost(const Scenario &sc, const std::vector<SimRequest> &requests, const std::string &cache,
                   double probe_grains)
{
  const double grains = preset_grains(sc);
  PlanCost c;
  for (const auto &r : requests)
    for (const auto &run : pending_runs(r, cache)) {
      if (run.kind == PlannedRun::POUR) {
        ++c.pours;
        c.atom_steps += grains * 0.6 / sc.number("dt_pour");
      } else {
        ++c.pushes;
        c.atom_steps += grains * (sc.gap + sc.depth) / std::atof(run.v0.c_str()) / sc.number("dt_push");
      }
    }
  c.core_hours = c.atom_steps / (1.1e7 * 3600.0);
  if (probe_grains > 0) c.probe_pours = c.atom_steps / (probe_grains * PROBE_POUR_STEPS);
  return c;
}

std::string plan_summary(const PlanCost &c)
{
  return std::to_string(c.pours) + " pours, " + std::to_string(c.pushes) + " pushes, " +
         printf_number("%.3g", c.atom_steps) + " atom-steps: about " +
         (c.probe_pours > 0 ? printf_number("%.3g", c.probe_pours) + " probe pours, " : std::string()) +
         printf_number("%.3g", c.core_hours) + " core-hours";
}

double estimate_core_hours(const Scenario &sc, const std::vector<SimRequest> &requests, const std::string &cache)
{
  return plan_cost(sc, requests, cache, 0.0).core_hours;
}

ArrayTasks array_tasks(const std::vector<SimRequest> &requests)
{
  ArrayTasks out;
  for (size_t r = 0; r < requests.size(); ++r) {
    const auto plan = plan_sweep(requests[r].spec);
    for (size_t k = 0; k < plan.size(); ++k) {
      if (plan[k].kind == PlannedRun::PUSH) out.pushes.push_back({r, (int) k});
      else if (requests[r].beds_from.empty()) out.pours.push_back({r, (int) k});
    }
  }
  return out;
}

SimulationPlan plan_simulations(const Scenario &sc, const std::vector<std::string> &v0s,
                                const std::vector<const Effect *> &effects, const std::string &cache, bool local)
{
  SimulationPlan p;
  p.requests = signature_requests(sc.name, v0s, effects);
  p.core_hours = estimate_core_hours(sc, p.requests, cache);
  if (p.core_hours > LOCAL_CORE_HOURS && !local) {
    std::string speeds;
    for (const auto &v : v0s) speeds += (speeds.empty() ? "" : " ") + v;
    throw InputError("the simulations this diagnosis still needs cost about " + printf_number("%.0f", p.core_hours) +
                     " core-hours (scenario '" + sc.name + "'): write them out for a cluster with --slurm FILE --v0 \"" +
                     speeds + "\" (then rerun with the filled cache), or run them here with --local");
  }
  return p;
}

}    // namespace granpen
