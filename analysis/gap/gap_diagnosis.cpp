#include "gap_diagnosis.h"

#include "effects.h"
#include "gap_plan.h"
#include "gap_sims.h"
#include "scenario.h"
#include "errors.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <unistd.h>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace granpen {

namespace fs = std::filesystem;

namespace {

std::vector<const Effect *> chosen_effects(const std::string &list)
{
  std::vector<const Effect *> out;
  if (list.empty()) {
    for (const auto &e : effect_library()) out.push_back(&e);
    return out;
  }
  std::stringstream in(list);
  std::string name;
  while (std::getline(in, name, ',')) {
    const Effect *e = find_effect(name);
    if (!e) {
      std::string known;
      for (const auto &x : effect_library()) known += " " + x.name;
      throw InputError("--effects: unknown effect '" + name + "' (known:" + known + ")");
    }
    out.push_back(e);
  }
  if (out.empty()) throw InputError("--effects: empty list");
  return out;
}

}    // namespace

int run_gap_diagnosis(const GapOptions &opt, const Scenario &sc, const std::vector<const Effect *> &effects,
                      const RunnerOptions &runner);    // gap_analysis.cpp

double estimate_core_hours(const Scenario &sc, const std::vector<SimRequest> &requests, const std::string &cache)
{
  const double lat = sc.number("lat"), box = sc.number("box"), lo = sc.number("fill_lo");
  const double across = std::floor((box - 2.0 * lo) / lat + 1.0);
  const double grains = across * across * std::floor((sc.number("zfill_hi") - sc.number("zfill_lo")) / lat + 1.0);
  const double rate = 1.1e7 * 3600.0;    // atom-steps per core-hour
  double h = 0.0;
  for (const auto &r : requests) {
    const fs::path dir = fs::path(cache) / r.spec.name;
    for (const auto &run : plan_sweep(r.spec)) {
      if (run.kind == PlannedRun::POUR) {
        if (!r.beds_from.empty() || fs::exists(dir / "beds" / (run.id + ".info"))) continue;
        h += grains * 0.6 / sc.number("dt_pour") / rate;
      } else {
        if (fs::exists(dir / "traces" / (run.id + ".csv.done"))) continue;
        h += grains * (sc.gap + sc.depth) / std::atof(run.v0.c_str()) / sc.number("dt_push") / rate;
      }
    }
  }
  return h;
}

int run_gap(const GapOptions &opt)
{
  const Scenario sc = read_scenario(opt.runner.inputs, opt.scenario);
  const auto effects = chosen_effects(opt.effects);
  RunnerOptions runner = opt.runner;
  runner.out_root = opt.cache + "/" + opt.scenario;
  runner.progress_seconds = 30.0;
  fs::create_directories(runner.out_root);
  std::vector<std::string> v0;
  if (opt.prepare_only || !opt.slurm.empty()) {
    std::stringstream in(opt.v0);
    std::string v;
    while (in >> v) v0.push_back(v);
    if (v0.empty()) throw InputError("--prepare-only and --slurm need --v0 \"SPEEDS\"");
  }
  if (!opt.slurm.empty()) {
    // one allocation runs the cache's sweeps, --jobs at a time, each on --ranks MPI ranks
    const auto req = signature_requests(opt.scenario, v0, effects);
    const double h = estimate_core_hours(sc, req, runner.out_root);
    char self[4096];
    const ssize_t n = readlink("/proc/self/exe", self, sizeof(self) - 1);
    const std::string cli = n > 0 ? std::string(self, n) : "granpen-cli";
    std::ofstream f(opt.slurm);
    if (!f) throw InputError(opt.slurm + ": cannot write");
    const std::string abs_cache = fs::absolute(opt.cache).string(), abs_inputs = fs::absolute(opt.runner.inputs).string();
    f << "#!/bin/bash\n# granpen gap: the " << opt.scenario << " cache (" << req.size() << " sweeps, about " << (long) std::ceil(h)
      << " core-hours at 1.1e7 atom-steps/s/core).\n# Submit with: sbatch [--partition=... --time=...] " << opt.slurm
      << "\n#SBATCH --job-name=granpen-gap-" << opt.scenario << "\n#SBATCH --ntasks=" << runner.jobs * runner.ranks
      << "\nset -e\n" << cli << " gap --prepare-only --scenario " << opt.scenario << " --v0 \"" << opt.v0 << "\" --jobs "
      << runner.jobs << " --mpirun srun --ranks " << runner.ranks << " --cache " << abs_cache << " --inputs "
      << abs_inputs << " --lmp "
      << (opt.runner.lmp.find('/') == std::string::npos ? opt.runner.lmp : fs::absolute(opt.runner.lmp).string())
      << (opt.effects.empty() ? "" : " --effects " + opt.effects) << "\n";
    std::printf("granpen gap: wrote %s: the %zu sweeps of the %s cache, about %.0f core-hours; when it has run, "
                "rerun this diagnosis with --cache %s\n", opt.slurm.c_str(), req.size(), opt.scenario.c_str(), h,
                abs_cache.c_str());
    return 0;
  }
  if (opt.prepare_only) {
    const auto req = signature_requests(opt.scenario, v0, effects);
    std::printf("granpen gap: preparing the %s cache in %s: %zu sweeps\n", opt.scenario.c_str(),
                runner.out_root.c_str(), req.size());
    return run_requests(req, runner) == 0 ? 0 : 1;
  }
  return run_gap_diagnosis(opt, sc, effects, runner);
}

}    // namespace granpen
