// granpen calibration: its command line (calibration_options.h).
#include "calibration_options.h"

#include "args.h"

namespace {

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

granpen::cli::CalibrationOptions granpen::cli::parse_calibration(int argc, char **argv)
{
  Command cmd("calibration", HELP);
  CalibrationOptions o;
  cmd.app.add_option("sweep", o.sweep, "the sweep folder (beds/, traces/)")->required()->check(file_name());
  cmd.number("--zmin", o.zmin, "window start, cm (default 1.0)")->type_name("Z");
  cmd.number("--zmax", o.zmax, "window end, cm (default 3.0). The defaults are the bench scenario's\n"
                               "usable depths: its bed is about 5.7 cm deep and the push goes to\n"
                               "4 cm, so the last centimetre feels the floor, and the first grows\n"
                               "through the impact peak. The paper fits z >= 3 cm in a 13.5 cm bed:\n"
                               "widen the window for deeper beds.")
      ->type_name("Z");
  cmd.app.add_option("--out", o.out, "where to write (default SWEEP_DIR): calibration.csv, calibration.json,\n"
                                     "calibration.md, and the figures calibration_phi0 and calibration_kz\n"
                                     "(.gp and .dat; with gnuplot .png and .svg)")
      ->check(file_name())->type_name("DIR");
  if (!cmd.parse(argc, argv, o.help)) return o;
  if (!(o.zmin < o.zmax)) throw UsageError("--zmin must be below --zmax");
  if (o.out.empty()) o.out = o.sweep;
  return o;
}
