// granpen calibration SWEEP_DIR: the friction-calibration table of a sweep folder,
// phi_0 and k_z against mu (core/calibration.h, core/trace_fit.h, io/bed_info.h).
#include "atomic_file.h"
#include "calibration_sweep.h"
#include "calibration_options.h"
#include "plot_writer.h"
#include "subcommands.h"
#include "trace_reader.h"

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

}    // namespace

int granpen::cli::run_calibration(const CalibrationOptions &o)
{
  const double zmin = o.zmin, zmax = o.zmax;
  const std::string &sweep = o.sweep, &out = o.out;
  // nothing is created for a sweep that cannot be read
  std::error_code dir_ec;
  if (!fs::is_directory(sweep, dir_ec)) throw InputError(sweep + ": not a readable folder (a sweep folder holds beds/ and traces/)");

  const CalibrationSweep sw = read_calibration_sweep(sweep, zmin, zmax);
  for (const auto &m : sw.problems) std::fprintf(stderr, "granpen calibration: %s\n", m.c_str());
  const auto rows = calibration_table(sw.beds, sw.pushes);
  std::printf("granpen calibration: %s: %zu beds, %zu pushes fitted over z = %g..%g cm\n\n", sweep.c_str(),
              sw.beds.size(), sw.pushes.size(), zmin, zmax);
  std::fputs(calibration_markdown(rows, zmin, zmax).c_str(), stdout);
  for (const auto &n : sw.notes) std::printf("note: %s\n", n.c_str());

  make_output_dir(out);
  const fs::path od(out);
  int status = sw.problems.empty() ? 0 : 1;
  const auto outputs = calibration_files(rows, sweep, zmin, zmax, sw.problems, out);
  std::vector<std::string> inputs = sw.info_files;
  inputs.insert(inputs.end(), sw.trace_files.begin(), sw.trace_files.end());
  for (const auto &o : outputs) refuse_overwriting_inputs(o.first, "--out", inputs);
  write_files_atomic(outputs);
  for (std::size_t k = 0; k + 1 < outputs.size(); ++k) std::printf("wrote %s\n", outputs[k].first.c_str());
  bool missing = false;
  const std::string why = granpen::run_gnuplot(od.string(), "calibration.gp", missing);
  if (!why.empty() && !missing) status = 1;
  if (why.empty())
    std::printf("wrote %s and %s (script %s)\n", (od / "calibration_phi0.png").c_str(),
                (od / "calibration_kz.png").c_str(), (od / "calibration.gp").c_str());
  else
    std::printf("granpen calibration: no plots: %s; the tables are written (script %s)\n", why.c_str(),
                (od / "calibration.gp").c_str());
  if (!sw.problems.empty())
    std::printf("granpen calibration: %zu problem%s (see above)\n", sw.problems.size(), sw.problems.size() == 1 ? "" : "s");
  return status;
}

int granpen::cli::calibration(int argc, char **argv) { return run_parsed(parse_calibration, run_calibration, argc, argv); }
