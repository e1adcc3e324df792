// granpen sweep: the manifest of a sweep's runs (sweep_manifest.h).
#include "sweep_manifest.h"

#include "atomic_file.h"
#include "errors.h"
#include "sweep_files.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>

namespace granpen {
namespace sweep_run {

// The runs of DIR/manifest.json: its "runs", or, when the file is not valid JSON (written
// by hand, or by a granpen older than the atomic write), every line that is one run's
// record on its own (the writer puts each run on one line); a warning names the file.
std::vector<Json> manifest_runs(const std::string &path)
{
  std::vector<Json> runs;
  const std::string text = slurp(path);
  try {
    const Json m = Json::parse(text);
    if (m.is_object() && m.contains("runs") && m["runs"].is_array())
      for (const auto &r : m["runs"])
        if (r.is_object() && r.contains("id") && r["id"].is_string()) runs.push_back(r);
    return runs;
  } catch (const Json::exception &e) {
    std::fprintf(stderr, "granpen sweep: warning: %s is not valid JSON (%s); keeping the runs of its lines that are\n",
                 path.c_str(), e.what());
  }
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    while (!line.empty() && (line.back() == ',' || line.back() == ' ')) line.pop_back();
    const Json r = Json::parse(line, nullptr, false);
    if (r.is_object() && r.contains("id") && r["id"].is_string()) runs.push_back(r);
  }
  return runs;
}

// Runs of other sweep files with the same name (sharing its beds, e.g. a v0 and a g sweep)
// stay in the manifest, keyed by their ids; so do the records of runs another process holds.
void keep_other_runs(Sweep &sw)
{
  const std::string path = sw.dir + "/manifest.json";
  if (!exists(path)) return;
  for (auto &run : manifest_runs(path)) {
    const std::string id = run["id"].get<std::string>();
    const auto planned = std::find_if(sw.jobs.begin(), sw.jobs.end(), [&](const Job &j) { return j.run.id == id; });
    if (planned == sw.jobs.end()) sw.other_runs.push_back(std::move(run));
    else if (planned->action == "refused") sw.held_runs[id] = std::move(run);
  }
}

// A number of a .info file as JSON: as written when it is a JSON number, else its value.
Json info_number(const std::string &text)
{
  const Json v = Json::parse(text, nullptr, false);
  return v.is_number() ? v : Json(std::strtod(text.c_str(), nullptr));
}

// one run's record of the manifest
Json manifest_run(const Sweep &sw, const Job &j)
{
  const auto &r = j.run;
  Json m;
  m["id"] = r.id;
  m["kind"] = r.kind == PlannedRun::POUR ? "pour" : "push";
  m["status"] = j.status;
  m["action"] = j.action;
  m["preset"] = r.preset;
  m["mu"] = r.mu;
  m["seed"] = r.seed;
  if (r.kind == PlannedRun::POUR) {
    auto info = exists(j.info) ? read_info(j.info) : std::map<std::string, std::string>{};
    for (const char *k : {"z_s", "phi_0", "grains", "wall_seconds"})
      if (info.count(k) && positive_number(info[k])) m[k] = info_number(info[k]);
    m["bed"] = sw.dir + "/beds/" + r.id + ".restart";
  } else {
    m["bed"] = r.bed;
    m["v0"] = r.v0;
    m["g"] = r.g;
    m["D"] = r.D;
    m["depth"] = r.depth;
    m["mu_push"] = r.mu_push;
    m["trace"] = j.trace;
  }
  m["log"] = j.log;
  m["wall_seconds_run"] = json_rounded("%.3f", j.wall);
  m["exit_code"] = j.exit_code;
  m["error"] = j.error;
  return m;
}

// DIR/manifest.json (docs/sweeps.md), every run one line; a run another process holds
// keeps the record that process wrote.
Json manifest_json(const Sweep &sw)
{
  Json m;
  m["sweep"] = sw.spec.name;
  m["spec"] = sw.spec.path;
  m["granpen"] = GRANPEN_VERSION;
  m["lammps"] = sw.lammps_version;
  m["runs"] = Json::array();
  for (const auto &r : sw.other_runs) m["runs"].push_back(r);
  for (const auto &j : sw.jobs) {
    if (j.action == "refused") {
      const auto held = sw.held_runs.find(j.run.id);
      if (held != sw.held_runs.end()) m["runs"].push_back(held->second);
      continue;
    }
    m["runs"].push_back(manifest_run(sw, j));
  }
  return m;
}

// Writes DIR/manifest.json through io/atomic_file (a temporary of this process's own:
// SLURM tasks of one sweep write it too; every step checked). Returns "" or what failed.
std::string write_manifest_file(const Sweep &sw)
{
  try {
    write_json(sw.dir + "/manifest.json", manifest_json(sw), 1);
  } catch (const OutputError &e) {
    return e.what();
  }
  return "";
}

}    // namespace sweep_run
}    // namespace granpen
