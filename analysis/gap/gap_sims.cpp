#include "gap_sims.h"

#include "bed_info.h"
#include "onset_alignment.h"
#include "sweep_cache.h"

#include <cmath>

namespace granpen {

SimRequest baseline_request(const std::string &scenario, const std::vector<std::string> &v0,
                            const std::vector<std::string> &seeds, const std::string &name)
{
  SimRequest r;
  r.spec.name = name;
  r.spec.presets = {scenario};
  r.spec.seeds = seeds;
  r.spec.v0 = v0;
  r.spec.path = "(granpen gap)";
  return r;
}

SimRequest effect_request(const std::string &scenario, const Effect &e, double a,
                          const std::vector<std::string> &v0, const std::vector<std::string> &seeds,
                          const std::string &name)
{
  SimRequest r = baseline_request(scenario, v0, seeds, name);
  if (e.set) r.spec.set = e.set(a);
  if (e.push_set) r.spec.push_set = e.push_set(a);
  if (e.pour_mu_at) {
    r.spec.mu = {e.pour_mu_at(a)};
    if (!e.push_mu_follows) r.spec.mu_push = {"0.3"};    // packing: only the bed differs
  }
  return r;
}

int run_requests(const std::vector<SimRequest> &requests, const RunnerOptions &opt)
{
  if (opt.pool) return run_sweeps(requests, opt);
  int failed = 0;
  for (const auto &r : requests) failed += run_sweeps({r}, opt);
  return failed;
}

RunsBySpeed load_sweep_runs(const std::string &cache, const std::string &sweep)
{
  RunsBySpeed out;
  for (const auto &p : finished_traces(cache, sweep)) {
    TraceRun r = run_of_trace(read_trace(p));
    out[r.v0].push_back(std::move(r));
  }
  return out;
}

TraceRun transformed_run(const Effect &e, double a, const TraceRun &run)
{
  TraceRun r = run;
  if (r.t.size() < 2) return r;
  const double dt = (r.t.back() - r.t.front()) / (double) (r.t.size() - 1);
  r.F = e.transform(run.F, dt, a);
  r.onset = force_onset(r.z, r.F);
  if (!std::isfinite(r.onset))
    throw InputError(run.path + ": no force onset after " + effect_sweep_name(e, a) + " (F never rises above zero)");
  return r;
}

RunsBySpeed transformed_runs(const Effect &e, double a, const RunsBySpeed &runs)
{
  RunsBySpeed out;
  for (const auto &[v, rs] : runs)
    for (const auto &r : rs) out[v].push_back(transformed_run(e, a, r));
  return out;
}

SimulatedRuns load_simulations(const std::string &cache, const std::vector<const Effect *> &effects)
{
  SimulatedRuns s;
  s.base = load_sweep_runs(cache, "baseline");
  for (const Effect *e : effects)
    for (double a : e->knots)
      s.knots[effect_sweep_name(*e, a)] =
          by_transform(*e, a) ? transformed_runs(*e, a, s.base) : load_sweep_runs(cache, effect_sweep_name(*e, a));
  s.fresh = load_sweep_runs(cache, "fresh_baseline");
  return s;
}

double mean_phi0(const std::string &cache, const std::string &sweep)
{
  double s = 0;
  int n = 0;
  for (const auto &p : bed_info_files(cache, sweep)) s += read_bed_info(p).phi_0, ++n;
  return n ? s / n : NAN;
}

}    // namespace granpen
