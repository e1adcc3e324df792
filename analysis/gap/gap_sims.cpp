#include "gap_sims.h"

#include "bed_info.h"
#include "gap_plan.h"
#include "onset_alignment.h"
#include "sweep_cache.h"
#include "text_util.h"
#include "trace_reader.h"
#include "trace_writer.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

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

namespace {

// A corrected run as a trace file: the source's header (a line `derived` said), t and z, its
// F transformed (when a transform is given) and times 1 + scale (in the file's units: both
// are linear)
std::string corrected_trace_text(const std::string &path, const Effect *e, double a, double scale)
{
  const Trace t = read_trace(path);
  TraceHeader h;
  h.units = t.units, h.v0 = t.v0, h.D = t.D, h.g = t.g;
  for (const auto &[k, v] : t.keys)
    if (k != "units" && k != "v0" && k != "D" && k != "g") h.extra.emplace_back(k, v);
  const std::string scaled = "times 1 + c = " + printf_number("%.6g", 1.0 + scale) + " (c = " + printf_number("%.6g", scale) +
                             ": the force scale fitted with it; the prediction the verdict compared)";
  h.extra.emplace_back("derived", e ? e->name + " " + deck_number(a) + ": F transformed by granpen gap (analysis/gap/effects.cpp)" +
                                          (scale != 0.0 ? "; " + scaled : "")
                                    : "F " + scaled + " by granpen gap");
  const double dt = t.t.size() > 1 ? (t.t.back() - t.t.front()) / (double) (t.t.size() - 1) : 1.0;
  std::vector<double> F = e ? e->transform(t.F, dt, a) : t.F;
  for (double &x : F) x *= 1.0 + scale;
  std::string text = format_trace_header(h);
  for (std::size_t i = 0; i < F.size(); ++i) text += format_trace_row({t.t[i], t.z[i], F[i]});
  return text;
}

}    // namespace

std::vector<std::pair<std::string, std::string>> corrected_trace_files(const std::vector<std::string> &paths,
                                                                      const Effect *transform, double a, double scale)
{
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto &f : paths)
    out.emplace_back(sweep_of_trace(f) + "_" + std::filesystem::path(f).filename().string(),
                     corrected_trace_text(f, transform, a, scale));
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

std::vector<SimRequest> needed_requests(const RunsNeeded &need, const Effect &e, const SimContext &sim)
{
  std::vector<SimRequest> req;
  for (const RunSet &set : need.sets) {
    const std::size_t earlier = req.size();
    for (auto &r : confirm_requests(sim.scenario, e, set.magnitude, set.speeds.empty() ? sim.v0s : set.speeds, set.tag, set.seeds))
      if (std::none_of(req.begin(), req.begin() + (long) earlier, [&](const SimRequest &q) { return q.spec.name == r.spec.name; }))
        req.push_back(r);
  }
  return req;
}

void simulate_needed(const RunsNeeded &need, const Effect &e, const SimContext &sim, StageRuns &given)
{
  const std::vector<SimRequest> req = needed_requests(need, e, sim);
  if (run_requests(req, sim.runner) != 0)
    throw InputError(need.what + " simulations failed: see the manifests under " + sim.runner.out_root + " (rerun to retry)");
  for (const RunSet &set : need.sets) {
    RunsBySpeed runs = load_sweep_runs(sim.runner.out_root, confirm_sweep(e, set.magnitude, set.tag, set.seeds));
    given[set.tag] = by_transform(e, set.magnitude) ? transformed_runs(e, set.magnitude, runs) : runs;
  }
}

}    // namespace granpen
