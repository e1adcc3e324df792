// granpen calibration SWEEP_DIR: the friction-calibration table of a sweep folder,
// phi_0 and k_z against mu (core/calibration.h, core/trace_fit.h, io/bed_info.h).
#include "atomic_file.h"
#include "calibration_sweep.h"
#include "subcommand.h"
#include "plot_writer.h"
#include "subcommands.h"
#include "trace_reader.h"

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

const char *HELP =
    "usage: granpen calibration SWEEP_DIR [--zmin Z] [--zmax Z] [--out DIR]\n"
    "Summarises a friction-calibration sweep (the paper's Simulation Calibration: mu sets\n"
    "the packing fraction phi_0 of the poured bed, and mu and phi_0 set k_z). SWEEP_DIR holds\n"
    "  beds/NAME.info    written by inputs/in.pour (keys mu, seed, phi_0, z_s, ...)\n"
    "  traces/*.csv      granpen-trace v1 pushes whose headers carry mu, seed, v0 and\n"
    "                    bed = NAME (mu and seed default to the bed's)\n"
    "For each mu (and v0): phi_0 mean and sd over its beds; k_z (slope of F on z over the\n"
    "window, as granpen fit) and alpha = k_z / (mu rho_g g D^2) mean and sd over its pushes.\n"
    "sd is the sample standard deviation (n - 1); with one value it is 0.\n"
    "Exit status: 0 when every bed and trace was used, 1 when one was rejected or could not\n"
    "be fitted (the tables are still written from the rest), 2 for a usage error.\n";


}    // namespace

int granpen::cli::calibration(int argc, char **argv)
{
  Command cmd("calibration", HELP);
  double zmin = 1.0, zmax = 3.0;
  std::string sweep, out;
  cmd.app.add_option("sweep", sweep, "the sweep folder (beds/, traces/)")->required();
  cmd.number("--zmin", zmin, "window start, cm (default 1.0)")->type_name("Z");
  cmd.number("--zmax", zmax, "window end, cm (default 3.0). The defaults are the bench scenario's\n"
                            "usable depths: its bed is about 5.7 cm deep and the push goes to\n"
                            "4 cm, so the last centimetre feels the floor, and the first grows\n"
                            "through the impact peak. The paper fits z >= 3 cm in a 13.5 cm bed:\n"
                            "widen the window for deeper beds.")
      ->type_name("Z");
  cmd.app.add_option("--out", out, "where to write (default SWEEP_DIR): calibration.csv, calibration.json,\n"
                                   "calibration.md, and with gnuplot calibration_phi0.png and\n"
                                   "calibration_kz.png (from calibration.gp, written beside them)")
      ->check(file_name())->type_name("DIR");
  if (!cmd.parse(argc, argv)) return EXIT_OK;
  if (!(zmin < zmax)) throw UsageError("--zmin must be below --zmax");
  if (out.empty()) out = sweep;
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
