// granpen sweep: what a sweep folder holds (see sweep_cache.h).
#include "sweep_cache.h"

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace granpen {

namespace fs = std::filesystem;

namespace {

// the files of OUT_ROOT/NAME/SUB ending in ext, sorted, each accepted by keep
template <class Keep>
std::vector<std::string> files_in(const std::string &out_root, const std::string &name, const char *sub,
                                  const char *ext, Keep keep)
{
  std::vector<std::string> out;
  std::error_code ec;
  const fs::path dir = fs::path(out_root) / name / sub;
  if (!fs::is_directory(dir, ec)) return out;
  for (const auto &entry : fs::directory_iterator(dir, ec)) {
    const auto p = entry.path();
    if (p.extension() == ext && keep(p)) out.push_back(p.string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

}    // namespace

std::vector<std::string> finished_traces(const std::string &out_root, const std::string &name)
{
  return files_in(out_root, name, "traces", ".csv", [](const fs::path &p) { return fs::exists(p.string() + ".done"); });
}

std::string sweep_of_trace(const std::string &trace_path)
{
  return fs::path(trace_path).parent_path().parent_path().filename().string();    // NAME/traces/FILE
}

std::vector<std::string> bed_info_files(const std::string &out_root, const std::string &name)
{
  return files_in(out_root, name, "beds", ".info", [](const fs::path &) { return true; });
}

std::vector<PlannedRun> pending_runs(const SweepTask &task, const std::string &out_root)
{
  std::vector<PlannedRun> out;
  const fs::path dir = fs::path(out_root) / task.spec.name;
  for (const auto &run : plan_sweep(task.spec)) {
    if (run.kind == PlannedRun::POUR) {
      if (!task.beds_from.empty() || fs::exists(dir / "beds" / (run.id + ".info"))) continue;
    } else if (fs::exists(dir / "traces" / (run.id + ".csv.done"))) {
      continue;
    }
    out.push_back(run);
  }
  return out;
}

}    // namespace granpen
