// granpen fit: its command line (fit_options.h).
#include "fit_options.h"

#include "args.h"

namespace {

const char *HELP =
    "usage: granpen fit TRACE... [--zmin Z | --tmin T] [--zmax Z] [--mu MU] [--rho RHO] [--json FILE] [--csv FILE]\n"
    "                [--ensemble [--ensemble-bin W] [--bootstrap B] [--ensemble-csv FILE]]\n"
    "Fits each force trace (granpen-trace v1; SI traces are converted to cgs). A folder\n"
    "argument stands for every *.csv in it. Per trace:\n"
    "  k_z    slope of F on z over the window (linear least squares), with its standard error\n"
    "  alpha  k_z / (mu rho_g g D^2), the paper's depth-term prefactor (35 +- 5 at 40 cm/s)\n"
    "  k_z0, alpha0  the same through the origin, F = k_z0 z (the paper's form F_z = k_z z;\n"
    "         in --csv and --json): the depth term granpen collapse --alpha takes\n"
    "  quad_a, quad_b  F = a z + b z^2 over the window, through the origin (in --csv and\n"
    "         --json), with alpha_a = a / (mu rho_g g D^2) and beta_b = b / (mu rho_g g D):\n"
    "         a tip-like term and a shaft-like one (side friction grows as D z^2)\n"
    "  peak   largest F and its depth over 0 < z < 0.7 R (R = D/2), the transient yield peak\n"
    "  wavelength  dominant wavelength of F about the fit in the window (resampled to the\n"
    "         median dz, mean removed, Hann window, FFT; the lowest two bins excluded);\n"
    "         the paper sees fluctuations of wavelength about d_g\n"
    "A window the data do not fill (e.g. z >= 3 cm on a 2 cm push) is shortened to the\n"
    "deeper half of the trace, and a note says so.\n"
    "With --ensemble, after the per-trace lines, one line per ensemble: the same numbers on\n"
    "the ensemble mean, each +- its standard error over runs (--json: \"ensembles\";\n"
    "--ensemble-csv: the mean curves z, F_mean, F_se).\n"
    "Exit status: 0 when every trace was read, 1 when a trace (or an output file) failed,\n"
    "2 for a usage error. Quantities that cannot be fitted (e.g. a window without data)\n"
    "are reported as undefined and do not change the exit status.\n";

}    // namespace

granpen::cli::FitOptions granpen::cli::parse_fit(int argc, char **argv)
{
  Command cmd("fit", HELP);
  FitOptions o;
  FitWindow &w = o.window;
  auto &app = cmd.app;
  app.add_option("traces", o.traces, "trace files, or folders of them")->required();
  auto *zmin_opt = cmd.number("--zmin", w.zmin, "window start, cm (default 3, the paper's z >= 3 cm)")->type_name("Z");
  auto *tmin_opt = app.add_option("--tmin", w.tmin, "window start by t~ = (z/v0) sqrt(g/D) instead: z >= T v0 sqrt(D/g)\n"
                                                    "per trace (the deep regime is t~ > 1)")
                       ->check(positive_number())->type_name("T");
  cmd.number("--zmax", w.zmax, "window end, cm (default: the deepest depth of each trace)")->type_name("Z");
  app.add_option("--mu", w.mu, "grain friction for alpha (default: header key mu, else 0.3)")
      ->check(positive_number())->type_name("MU");
  app.add_option("--rho", w.rho_g, "grain density for alpha, g/cm^3 (default: header key rho_g,\n"
                                   "else 3.0); d_g comes from header key d_g, else 0.4 cm;\n"
                                   "the summary says which values were defaults")
      ->check(positive_number())->type_name("RHO");
  app.add_option("--json", o.json, "write the results as JSON (units cgs; undefined values are 0\n"
                                   "with a false *_ok flag; unreadable traces under \"errors\")")
      ->check(file_name())->type_name("FILE");
  app.add_option("--csv", o.csv, "write one CSV row per fitted trace")->check(file_name())->type_name("FILE");
  add_ensemble_options(cmd, o.ensemble);
  app.add_option("--ensemble-csv", o.ensemble_csv, "--ensemble: write the mean curves (v0, g, D, runs, z, F_mean, F_se, F_sd)")
      ->check(file_name())->type_name("FILE");
  if (!cmd.parse(argc, argv, o.help)) return o;
  check_ensemble_options(cmd, o.ensemble);
  if (!o.ensemble.on && !o.ensemble_csv.empty()) throw UsageError("--ensemble-csv needs --ensemble");
  if (zmin_opt->count() > 0 && tmin_opt->count() > 0) throw UsageError("give --zmin or --tmin, not both");
  if (!(tmin_opt->count() > 0) && !(w.zmin < w.zmax)) throw UsageError("--zmin must be below --zmax");
  return o;
}
