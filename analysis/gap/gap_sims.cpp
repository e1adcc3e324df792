#include "gap_sims.h"

#include <algorithm>
#include <filesystem>

namespace granpen {

namespace fs = std::filesystem;

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

std::vector<std::string> finished_traces(const std::string &cache_dir, const std::string &sweep)
{
  std::vector<std::string> out;
  const fs::path dir = fs::path(cache_dir) / sweep / "traces";
  if (!fs::is_directory(dir)) return out;
  for (const auto &entry : fs::directory_iterator(dir)) {
    const auto p = entry.path();
    if (p.extension() == ".csv" && fs::exists(p.string() + ".done")) out.push_back(p.string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

}    // namespace granpen
