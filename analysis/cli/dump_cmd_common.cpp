// granpen flow / granpen momentum: shared parts (dump_cmd_common.h).
#include "dump_cmd_common.h"

#include "atomic_file.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace granpen {
namespace cli {

namespace fs = std::filesystem;

bool read_rod_options(const ParsedArgs &args, RodOptions &ro, std::string &message)
{
  double v;
  if (args.number("--rod-type", v)) {
    if (v != std::floor(v) || v < 1) {
      message = "--rod-type must be a positive integer";
      return false;
    }
    ro.rod_type = (int) v;
  }
  const auto axis = args.numbers.find("--axis");
  if (axis != args.numbers.end()) ro.have_axis = true, ro.axis_x = axis->second[0], ro.axis_y = axis->second[1];
  if (args.number("--tip", ro.tip)) ro.have_tip = true;
  return true;
}

bool periodic_axes(const std::string &axes, bool &x, bool &y)
{
  if (axes != "xy" && axes != "x" && axes != "y" && axes != "none") return false;
  x = axes == "xy" || axes == "x", y = axes == "xy" || axes == "y";
  return true;
}

namespace {
void progress_line(const DumpProgress &p, const std::string &tool)
{
  const double mb = (double) p.bytes / 1.0e6;
  const double rate = p.seconds > 0.0 ? mb / p.seconds : 0.0;
  std::fprintf(stderr, "%s: %llu frames, %.1f MB, %.1f MB/s\n", tool.c_str(), (unsigned long long) p.frames, mb, rate);
  std::fflush(stderr);
}
}    // namespace

void report_progress(DumpReader &reader, const std::string &tool)
{
  reader.on_progress([tool](const DumpProgress &p) { progress_line(p, tool); }, 2.0);
}

bool write_outputs(const std::string &dir, const std::vector<std::pair<std::string, std::string>> &files,
                   std::string &message)
{
  try {
    make_output_dir(dir);
    std::vector<std::pair<std::string, std::string>> paths;
    for (const auto &f : files) paths.emplace_back((fs::path(dir) / f.first).string(), f.second);
    write_files_atomic(paths);
  } catch (const OutputError &e) {
    message = e.what();
    return false;
  }
  return true;
}

void refuse_outputs_over_inputs(const std::string &dir, const std::vector<const char *> &names, const ParsedArgs &args)
{
  std::vector<std::string> inputs = args.positional;
  if (args.has("--trace")) inputs.push_back(args.value("--trace", ""));
  for (const char *name : names) refuse_overwriting_inputs((fs::path(dir) / name).string(), "--out", inputs);
}

}    // namespace cli
}    // namespace granpen
