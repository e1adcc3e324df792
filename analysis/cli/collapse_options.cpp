// granpen collapse: its command line (collapse_options.h).
#include "collapse_options.h"

#include "args.h"

namespace {

const char *HELP =
    "usage: granpen collapse TRACE-OR-FOLDER... [--kz-zmin Z] [--kz-zmax Z] [--alpha A --mu MU --rho RHO]\n"
    "                        [--band B] [--tbin W] [--zmin Z] [--csv FILE] [--json FILE]\n"
    "                        [--ensemble [--ensemble-bin W] [--bootstrap B]]\n"
    "Divides each trace's F by its depth term F_z = k_z z and plots it, binned, against\n"
    "t~ = (z / v0) sqrt(g / D) (paper: F/F_z joins 1 at t~ = 1). k_z comes from each trace's\n"
    "linear fit over z from --kz-zmin (default 3 cm, the paper's) to --kz-zmax (default: the\n"
    "deepest point; a window the data do not fill is shortened to the deeper half of the\n"
    "trace, with a note), or from --alpha: F_z = alpha mu rho_g g D^2 z (mu, rho_g from the\n"
    "headers unless given). Reports per trace the crossover t~* (start of the first t~ bin of\n"
    "width --tbin (0.1) after which F/F_z stays within 1 +- --band (0.2)), their mean and\n"
    "spread; the collapse quality (spread of the curves against z, before, and against t~,\n"
    "after); the peak height (0 < z < 0.7 R) against v0 on log axes: exponent and 95%\n"
    "interval, over every trace read (it needs no k_z); k_z against v0. A trace without a\n"
    "positive k_z is named and left out of F/F_z.\n"
    "--csv writes the binned curves (trace, v0, g, D, t~, F/F_z); --json all.\n"
    "With --ensemble, then the same from one curve per ensemble (below), each number +- its\n"
    "standard error over runs (--json: \"ensemble\"; --csv: rows \"ensemble v0=...\").\n"
    "Outputs are written whole or not at all, never over an input. Exit status: 0, also when\n"
    "traces were left out; 1 when a file could not be read or nothing is left to collapse;\n"
    "2 for a usage error.\n";

}    // namespace

granpen::cli::CollapseOptions granpen::cli::parse_collapse(int argc, char **argv)
{
  Command cmd("collapse", HELP);
  CollapseOptions o;
  DepthTerm &dt = o.depth;
  CollapseParams &p = o.params;
  cmd.app.add_option("traces", o.traces, "trace files, or folders of them")->required();
  cmd.number("--kz-zmin", dt.kz_zmin, "k_z window start, cm (default 3)", true)->type_name("Z");
  cmd.number("--kz-zmax", dt.kz_zmax, "k_z window end, cm (default: the deepest point)", true)->type_name("Z");
  cmd.app.add_option("--alpha", dt.alpha, "F_z = alpha mu rho_g g D^2 z instead of a fit, > 0")->check(positive_number())->type_name("A");
  cmd.app.add_option("--mu", dt.mu, "friction for --alpha (default: header key mu, else 0.3)")->check(positive_number())->type_name("MU");
  cmd.app.add_option("--rho", dt.rho_g, "grain density for --alpha (default: header key rho_g, else 3)")
      ->check(positive_number())->type_name("RHO");
  cmd.app.add_option("--band", p.band, "crossover: F/F_z within 1 +- B (default 0.2)")->check(positive_number())->type_name("B");
  cmd.app.add_option("--tbin", p.tbin, "t~ bin width (default 0.1)")->check(positive_number())->type_name("W");
  cmd.number("--zmin", p.zmin, "depths used from Z, cm (default 0.2)", true)->type_name("Z");
  cmd.app.add_option("--csv", o.csv, "write the binned curves (trace, v0, g, D, t~, F/F_z)")->check(file_name())->type_name("FILE");
  cmd.app.add_option("--json", o.json, "write every result as JSON")->check(file_name())->type_name("FILE");
  add_ensemble_options(cmd, o.ensemble);
  if (!cmd.parse(argc, argv, o.help)) return o;
  check_ensemble_options(cmd, o.ensemble);
  if (!(dt.kz_zmin < dt.kz_zmax)) throw UsageError("--kz-zmin must be below --kz-zmax");
  return o;
}
