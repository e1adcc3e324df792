#include "gap_plan.h"

#include "gap_pairs.h"
#include "sweep_cache.h"
#include "text_util.h"
#include "errors.h"    // InputError

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace granpen {

std::vector<SimRequest> signature_requests(const std::string &scenario, const std::vector<std::string> &v0,
                                           const std::vector<const Effect *> &effects)
{
  // the baseline on the signature beds, and on the reference beds: what the fits measure
  // the gap against, and the null replicates of the targeted test
  std::vector<SimRequest> out{baseline_request(scenario, v0, SIGNATURE_SEEDS, "baseline"),
                              baseline_request(scenario, v0, REFERENCE_SEEDS, "fresh_baseline")};
  for (const Effect *e : effects)
    for (SimRequest &r : knot_requests(scenario, v0, *e)) out.push_back(std::move(r));
  return out;
}

std::vector<SimRequest> knot_requests(const std::string &scenario, const std::vector<std::string> &v0, const Effect &e,
                                      const std::vector<std::string> &seeds, const std::string &prefix)
{
  std::vector<SimRequest> out;
  for (double a : e.knots) {
    if (by_transform(e, a)) continue;    // the baseline's runs, transformed
    SimRequest r = effect_request(scenario, e, a, v0, seeds, prefix + effect_sweep_name(e, a));
    if (!e.pour_level) r.beds_from = prefix + "baseline";
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

namespace {

// a deck variable of a request (its pour and push keys, then its push keys alone), or "" 
std::string request_var(const SimRequest &r, const std::string &key)
{
  for (const auto *vars : {&r.spec.set, &r.spec.push_set})
    for (const auto &[k, v] : *vars)
      if (k == key) return v;
  return "";
}

double request_number(const SimRequest &r, const std::string &key, double fallback)
{
  const std::string v = request_var(r, key);
  return v.empty() ? fallback : std::atof(v.c_str());
}

// the grains of the probe pour when the bench preset cannot be read (its .info)
constexpr double PROBE_POUR_GRAINS = 6300;

}    // namespace

double route_cost_factor(const SimRequest &r)
{
  // knots' CPU s over their counted atom-steps, bench cold cache 2026-11-27 (docs/gap.md,
  // "The plan's cost"): cohesion's 2 knots (JKR) 1217 s for 7.25 probe pours counted, rolling
  // resistance's (sds) 886 s, at a probe pour of 76.6 s and runs side by side at 0.95
  if (request_number(r, "cohesion", 0) != 0) return 2.1;
  if (request_number(r, "mu_roll", 0) != 0) return 1.5;
  return 1.0;
}

namespace {

// the cost of the given runs of the requests (each request's runs from runs_of)
template <class RunsOf>
PlanCost runs_cost(const Scenario &sc, const std::vector<SimRequest> &requests, double probe_grains, RunsOf runs_of)
{
  const double grains = preset_grains(sc);
  const double probe = (probe_grains > 0 ? probe_grains : PROBE_POUR_GRAINS) * PROBE_POUR_STEPS;
  PlanCost c;
  for (const auto &r : requests) {
    const double factor = route_cost_factor(r);
    // each run at its own time step (contact_stiffness scales them); a ramp adds its travel
    // at half the speed, i.e. its travel at v0 (fix rod/drive ramp)
    const double dt_pour = request_number(r, "dt_pour", sc.number("dt_pour"));
    const double dt_push = request_number(r, "dt_push", sc.number("dt_push"));
    const double travel = sc.gap + sc.depth + request_number(r, "ramp", 0);
    for (const auto &run : runs_of(r)) {
      const bool pour = run.kind == PlannedRun::POUR;
      const double steps = grains * (pour ? 0.6 / dt_pour : travel / std::atof(run.v0.c_str()) / dt_push);
      const double pp = steps * factor / probe;
      ++(pour ? c.pours : c.pushes);
      c.atom_steps += steps;
      c.probe_pours += pp;
      double &longest = pour ? c.longest_pour : c.longest_push;
      longest = std::max(longest, pp);
    }
  }
  c.core_hours = c.probe_pours * PROBE_POUR_SECONDS / 3600.0;
  return c;
}

}    // namespace

PlanCost cold_cost(const Scenario &sc, const std::vector<SimRequest> &requests, double probe_grains)
{
  return runs_cost(sc, requests, probe_grains, [](const SimRequest &r) {
    std::vector<PlannedRun> runs;
    for (const auto &run : plan_sweep(r.spec))
      if (run.kind == PlannedRun::PUSH || r.beds_from.empty()) runs.push_back(run);
    return runs;
  });
}

PlanCost plan_cost(const Scenario &sc, const std::vector<SimRequest> &requests, const std::string &cache,
                   double probe_grains)
{
  if (cache.empty()) return cold_cost(sc, requests, probe_grains);
  return runs_cost(sc, requests, probe_grains, [&](const SimRequest &r) { return pending_runs(r, cache); });
}

PlanCost operator+(const PlanCost &a, const PlanCost &b)
{
  PlanCost c = a;
  c.pours += b.pours, c.pushes += b.pushes;
  c.atom_steps += b.atom_steps, c.core_hours += b.core_hours, c.probe_pours += b.probe_pours;
  c.longest_pour = std::max(a.longest_pour, b.longest_pour);
  c.longest_push = std::max(a.longest_push, b.longest_push);
  return c;
}

double wall_probe_pours(const PlanCost &c, int jobs)
{
  if (c.probe_pours <= 0) return 0;
  const int n = std::max(1, jobs);
  const double speed = n > 1 ? SIDE_BY_SIDE_SPEED : 1.0;
  return std::max(c.probe_pours / (n * speed), (c.longest_pour + c.longest_push) / speed);
}

std::string cost_phrase(const PlanCost &c, int jobs)
{
  return printf_number("%.3g", c.probe_pours) + " probe pours of core time (" + printf_number("%.3g", c.core_hours) +
         " core-hours), " + printf_number("%.3g", wall_probe_pours(c, jobs)) + " of wall time at --jobs " +
         std::to_string(std::max(1, jobs));
}

std::string plan_summary(const PlanCost &c, int jobs)
{
  return std::to_string(c.pours) + " pours, " + std::to_string(c.pushes) + " pushes, " +
         printf_number("%.3g", c.atom_steps) + " atom-steps: about " + cost_phrase(c, jobs);
}

double estimate_core_hours(const Scenario &sc, const std::vector<SimRequest> &requests, const std::string &cache)
{
  return plan_cost(sc, requests, cache, 0.0).core_hours;
}

std::vector<SimRequest> largest_confirmation(const std::string &scenario, const Effect &e, double a,
                                             const std::vector<std::string> &v0)
{
  std::string slowest;
  for (const auto &v : v0)
    if (slowest.empty() || std::atof(v.c_str()) < std::atof(slowest.c_str())) slowest = v;
  std::vector<SimRequest> out;
  auto add = [&](std::vector<SimRequest> more) {
    for (auto &r : more)
      if (std::none_of(out.begin(), out.end(), [&](const SimRequest &q) { return q.spec.name == r.spec.name; }))
        out.push_back(std::move(r));
  };
  add(confirm_requests(scenario, e, a, v0, "confirm"));
  if (!slowest.empty()) add(confirm_requests(scenario, e, a, {slowest}, "heldout"));
  add(confirm_requests(scenario, e, a, v0, "refine", REFINE_SEEDS));
  return out;
}

std::vector<SimRequest> pair_confirmation(const std::string &scenario, const Effect &other, double b,
                                          const std::vector<std::string> &v0)
{
  return confirm_requests(scenario, other, b, v0, "confirm");
}

namespace {

// the costliest of the request sets each effect at its outermost knots asks for (empty: none)
template <class RequestsOf>
std::vector<SimRequest> costliest(const Scenario &sc, const std::vector<const Effect *> &effects, const std::string &cache,
                                  double probe_grains, RequestsOf requests_of)
{
  std::vector<SimRequest> best;
  double most = 0;
  for (const Effect *e : effects) {
    if (e->knots.empty()) continue;
    const auto [lo, hi] = std::minmax_element(e->knots.begin(), e->knots.end());
    for (double a : {*lo, *hi}) {
      std::vector<SimRequest> r = requests_of(*e, a);
      const double c = plan_cost(sc, r, cache, probe_grains).probe_pours;
      if (c > most) most = c, best = std::move(r);
    }
  }
  return best;
}

}    // namespace

PlanCost confirmation_most(const Scenario &sc, const std::vector<std::string> &v0,
                           const std::vector<const Effect *> &effects, const std::string &cache, double probe_grains)
{
  std::vector<SimRequest> most = costliest(sc, effects, cache, probe_grains, [&](const Effect &e, double a) {
    return largest_confirmation(sc.name, e, a, v0);
  });
  const bool pair_possible = std::any_of(effects.begin(), effects.end(), [](const Effect *e) { return pair_filter(*e); });
  std::vector<const Effect *> partners;
  for (const Effect *e : effects)
    if (pair_partner(*e)) partners.push_back(e);
  if (pair_possible)
    for (SimRequest &r : costliest(sc, partners, cache, probe_grains, [&](const Effect &e, double b) {
           return pair_confirmation(sc.name, e, b, v0);
         }))
      // the fresh beds a single's push-only confirmation poured are poured once; every push
      // counts (the pair's member runs at its own magnitude, not the single's)
      if (!r.spec.v0.empty() || std::none_of(most.begin(), most.end(), [&](const SimRequest &q) { return q.spec.name == r.spec.name; }))
        most.push_back(std::move(r));
  return plan_cost(sc, most, cache, probe_grains);
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
