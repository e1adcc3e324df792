// granpen flow / granpen momentum: shared parts (dump_cmd_common.h).
#include "dump_cmd_common.h"

#include "atomic_file.h"
#include "rod_frame.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace granpen {
namespace cli {

namespace fs = std::filesystem;

void read_dump_options(DumpOptions &o)
{
  const ParsedArgs &args = o.args;
  double v;
  if (args.number("--rod-type", v)) {
    if (v != std::floor(v) || v < 1) throw UsageError("--rod-type must be a positive integer");
    o.rod.rod_type = (int) v;
  }
  const auto axis = args.numbers.find("--axis");
  if (axis != args.numbers.end()) o.rod.have_axis = true, o.rod.axis_x = axis->second[0], o.rod.axis_y = axis->second[1];
  if (args.number("--tip", o.rod.tip)) o.rod.have_tip = true;
  o.out_dir = args.value("--out", ".");
  if (o.out_dir.empty()) throw UsageError("--out needs a folder");
  o.periodic = args.value("--periodic", "xy");
  const std::string &a = o.periodic;
  if (a != "xy" && a != "x" && a != "y" && a != "none") throw UsageError("--periodic must be xy, x, y or none");
  o.px = a == "xy" || a == "x", o.py = a == "xy" || a == "y";
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

void first_frame(DumpReader &reader, const std::vector<std::string> &dumps, DumpFrame &frame, const std::string &tool)
{
  report_progress(reader, tool);
  if (!reader.next(frame)) throw InputError(dumps[0] + ": no frames");
}

double frame_bed_surface(const DumpFrame &frame, const GrainFrame &g)
{
  const std::vector<double> &X = frame.col("x"), &Y = frame.col("y"), &Z = frame.col("z"), &R = frame.col("radius");
  int nempty = 0;
  return bed_surface(X.data(), Y.data(), Z.data(), R.data(), g.is_rod.data(), X.size(), frame.lo[0], frame.hi[0],
                     frame.lo[1], frame.hi[1], 4, nempty);
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
