// granpen calibration SWEEP_DIR: the friction-calibration table of a sweep folder,
// phi_0 and k_z against mu: read (io/calibration_sweep.h), fit and tabulate
// (core/calibration_study.h), write.
#include "atomic_file.h"
#include "calibration_study.h"
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

  const CalibrationSweep sw = read_calibration_sweep(sweep);
  CalibrationStudyParams sp;
  sp.zmin = zmin, sp.zmax = zmax;
  const CalibrationStudy st = run_calibration_study(sw.beds, sw.pushes, sp);
  std::vector<std::string> problems, notes;
  calibration_messages(sw, st, problems, notes);
  for (const auto &m : problems) std::fprintf(stderr, "granpen calibration: %s\n", m.c_str());
  const auto &rows = st.rows;
  std::printf("granpen calibration: %s: %zu beds, %zu pushes fitted over z = %g..%g cm\n\n", sweep.c_str(),
              sw.beds.size(), st.pushes.size(), zmin, zmax);
  std::fputs(calibration_markdown(rows, zmin, zmax).c_str(), stdout);
  for (const auto &n : notes) std::printf("note: %s\n", n.c_str());

  make_output_dir(out);
  int status = problems.empty() ? 0 : 1;
  const auto outputs = calibration_files(rows, sweep, zmin, zmax, problems, out);
  const auto figures = calibration_figures(rows);
  std::vector<std::string> inputs = sw.info_files;
  inputs.insert(inputs.end(), sw.trace_files.begin(), sw.trace_files.end());
  for (const auto &o : outputs) refuse_overwriting_inputs(o.first, "--out", inputs);
  for (const auto &f : figures)
    for (const char *ext : {".gp", ".dat"}) refuse_overwriting_inputs((fs::path(out) / (f.name + ext)).string(), "--out", inputs);
  write_files_atomic(outputs);
  for (const auto &o : outputs) std::printf("wrote %s\n", o.first.c_str());
  for (const auto &f : figures) {
    const PlotResult r = write_plot(out, f, true);
    if (r.ran) std::printf("wrote %s and %s (script %s, data %s)\n", r.png.c_str(), r.svg.c_str(), r.script.c_str(), r.data.c_str());
    else if (r.written && r.gnuplot_missing)
      std::printf("granpen calibration: no plot: %s; the tables are written\n", r.error.c_str());
    else {
      std::fprintf(stderr, "granpen calibration: %s\n", r.error.c_str());
      status = 1;
    }
  }
  if (!problems.empty())
    std::printf("granpen calibration: %zu problem%s (see above)\n", problems.size(), problems.size() == 1 ? "" : "s");
  return status;
}

int granpen::cli::calibration(int argc, char **argv) { return run_parsed(parse_calibration, run_calibration, argc, argv); }
