// granpen flow / granpen momentum: shared parts (dump_cmd_common.h).
#include "dump_cmd_common.h"

#include "atomic_file.h"
#include "rod_frame.h"
#include "scaling_laws.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace granpen {
namespace cli {

namespace fs = std::filesystem;

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
                     frame.lo[1], frame.hi[1], SURFACE_COLUMNS, nempty);
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

void refuse_outputs_over_inputs(const std::string &dir, const std::vector<const char *> &names,
                                const std::vector<std::string> &dumps, const std::string &trace)
{
  std::vector<std::string> inputs = dumps;
  if (!trace.empty()) inputs.push_back(trace);
  for (const char *name : names) refuse_overwriting_inputs((fs::path(dir) / name).string(), "--out", inputs);
}

}    // namespace cli
}    // namespace granpen
