// granpen momentum: its command line (momentum_options.h).
#include "momentum_options.h"

#include "args.h"

#include "momentum_class_limits.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace granpen::cli;

const char *HELP =
    "usage: granpen momentum DUMP... --trace TRACE [--out DIR] [options]\n"
    "Sorts the grains outside the rod (r > R = D/2) of each frame of LAMMPS text dumps\n"
    "(dump custom, plain or gzip; columns id type x y z vx vy vz radius, optional mass) by\n"
    "their upward velocity v_z relative to v0, as compute momentum/vbin does:\n"
    "  fast          v_z >= v0/10\n"
    "  intermediate  v0/80 <= v_z < v0/10\n"
    "  slow          v0/320 < v_z < v0/80\n"
    "  noise         v0/640 < v_z <= v0/320\n"
    "and sums per class the count and the upward momentum sum m v_z; M_slow is the mass of\n"
    "the slow class, M_move that of every grain with v_z > v0/320. Against the drag F of the\n"
    "trace at the frame's time: F = k mu g M_move fitted through the origin (the paper's 1:1\n"
    "line is k = 1) and the mean ratio F / (mu g M_move), over the frames with the rod in the\n"
    "bed (z_tip > 0) and M_move > 0.\n"
    "The rod is found in each frame from its atoms (axis = mean x, y; tip = lowest z - radius);\n"
    "its depth is z_tip = z_s - tip with z_s the trace's surface key, and\n"
    "t~ = (z_tip / v0) sqrt(g / D). F is the trace's at the frame's depth (the first time the\n"
    "tip reached it; linear interpolation), or with --push-step at t = (timestep - N) dt.\n"
    "Outputs in DIR (default .): momentum.json (per frame and the fit, with errors),\n"
    "momentum_classes.csv (t_tilde,z_tip,class,count,p_up), momentum_drag.csv\n"
    "(t_tilde,z_tip,F,mu_g_M).\n"
    "Units are the dump's and the trace's (cgs for granpen's decks). Progress goes to stderr.\n"
    "Exit status: 0 on success, 1 for unreadable input (the message names file and line;\n"
    "no output is written), 2 for a usage error.\n";

}    // namespace

granpen::cli::MomentumOptions granpen::cli::parse_momentum(int argc, char **argv)
{
  Command cmd("momentum", HELP);
  MomentumOptions o;
  cmd.app.add_option("dumps", o.dumps, "dumps");
  add_text(cmd, "--trace", o.trace, "FILE", "force trace of the push (required): v0, D, g, mu, rho_g, surface, dt");
  add_text(cmd, "--out", o.out_dir, "DIR", "output folder (made if missing; default .)");
  CLI::Option *thresholds = add_numbers(cmd, "--thresholds", 4, "F1 F2 F3 F4", "class bounds as fractions of v0 (default 1/10 1/80 1/320\n1/640), > 0 and decreasing; M_move then counts v_z > F3 v0");
  add_positive(cmd, "--mthreshold", o.mthreshold, "F", "M_move counts v_z > F v0 instead");
  cmd.app.add_option("--mu", o.mu, "friction for mu g M (default: trace header mu, else 0.3)")
      ->check(non_negative_number())->type_name("MU");
  RodArgs rod;
  add_rod_options(cmd, rod, "fixed rod axis (dumps without rod atoms)", "fixed tip height (dumps without rod atoms)");
  add_positive(cmd, "--D", o.D, "D", "rod diameter (default: the trace's)");
  add_positive(cmd, "--rho", o.rho_g, "RHO", "grain density for masses without a mass column (default: trace\nheader rho_g, else 3.0)");
  add_number(cmd, "--zs", o.z_s, "Z", "bed surface (default: the trace's surface key, else measured in\nthe first frame as compute bed/surface does)");
  std::string push_step;
  CLI::Option *by_time = cmd.app.add_option("--push-step", push_step, "timestep at which the push began: match the trace by time")
                             ->type_name("N");
  add_positive(cmd, "--dt", o.dt, "DT", "timestep size for --push-step (default: the trace's dt key)");
  add_periodic_option(cmd, o.periodic);
  if (!cmd.parse(argc, argv, o.help)) return o;
  if (o.dumps.empty()) throw UsageError("no dump given");
  if (o.trace.empty()) throw UsageError("--trace TRACE is required (v0, D, g and the drag come from it)");
  finish_rod_options(rod, o.rod);
  o.by_time = by_time->count() > 0;
  if (o.by_time && !integer_arg(push_step, o.push_step))
    throw UsageError("--push-step '" + push_step + "' is not an integer");
  finish_periodic(o.periodic, o.px, o.py);
  o.thresholds = take_numbers(thresholds, 4);
  // the classes' bounds as momentum_classes checks them (for a speed of 1: they scale)
  if (!o.thresholds.empty()) {
    try {
      momentum_classes(1.0, o.thresholds.data(), std::isfinite(o.mthreshold) ? o.mthreshold : 0.0);
    } catch (const std::invalid_argument &e) {
      throw UsageError(std::string("--thresholds: ") + e.what());
    }
  }
  return o;
}
