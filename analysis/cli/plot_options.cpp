// granpen plot: its command line (plot_options.h).
#include "plot_options.h"

#include "args.h"
#include "ensemble_args.h"

#include <algorithm>
#include <iterator>

namespace {

const char *HELP =
    "usage: granpen plot KIND INPUTS... --out DIR [options]\n"
    "Writes each figure as DIR/NAME.gp, a gnuplot script you can edit and rerun in DIR,\n"
    "with its numbers in DIR/NAME.dat beside it, runs gnuplot to make DIR/NAME.png and\n"
    "DIR/NAME.svg, and writes DIR/KIND.json (the figures and the numbers drawn). Units cgs.\n"
    "kinds:\n"
    "  force TRACE-OR-FOLDER...  F against z, one colour per v0: the mean of the runs at\n"
    "                 each v0 with their range as a band (--each: every run, in shades of\n"
    "                 its v0's colour); inset: the peak region z < 0.7 R.      -> force\n"
    "  ratio TRACE-OR-FOLDER...  F/F_z against z and against t~ = (z/v0) sqrt(g/D): the\n"
    "                 binned curves of granpen collapse (same k_z, bins and options), the\n"
    "                 band 1 +- --band, the paper's crossover t~ = 1.           -> ratio\n"
    "  peak TRACE-OR-FOLDER...   peak height (max F over 0 < z < 0.7 R) against v0 on\n"
    "                 log-log axes, the fitted power law of granpen collapse with its 95%\n"
    "                 interval, and a v0^2 guide through the data's centre.    -> peak\n"
    "  kz TRACE-OR-FOLDER...     k_z against v0 with the standard errors of granpen fit's\n"
    "                 linear fit over the k_z window, the mean +- sd over traces. -> kz\n"
    "  flow DIR       the tables of granpen flow --out DIR: flow_fields.csv (heatmaps of\n"
    "                 phi, v_z, gamma-dot and I in (r, z - z_tip) with the rod drawn),\n"
    "                 flow_profile_below.csv (|v_z| below the face, log axis, with the\n"
    "                 exponential fit of granpen flow, and phi), flow_edge_phi_I.csv (phi\n"
    "                 against I with the paper's phi = 0.57 - 0.35 I), flow_strip.csv (v_z\n"
    "                 of the near-shaft strip against depth), flow_annulus.csv (annulus\n"
    "                 means against t~).  -> flow_heatmaps, flow_profile, flow_phi_I,\n"
    "                 flow_strip, flow_annulus (a missing table is skipped with a note)\n"
    "  momentum DIR   momentum_classes.csv (upward momentum and counts per speed class\n"
    "                 against t~) and momentum_drag.csv (F against mu g M(v_z > v0/320)\n"
    "                 with the 1:1 line).                -> momentum_classes, momentum_drag\n"
    "  scaling TABLE  a CSV of quantities against the grain size ratio, columns quantity,\n"
    "                 D_over_dg (or box_cm: against the box width), value, error and\n"
    "                 optional paper, paper_error, unit, label, series: one panel per\n"
    "                 quantity, the values with their error bars against the axis, a line\n"
    "                 per series (up to 5, named in the title), and the paper's value (the\n"
    "                 paper's own D/d_g or box: # paper_D_over_dg = R, # paper_box_cm = B);\n"
    "                 scaling.json gives each point's distance from\n"
    "                 it in combined standard errors (an empty value: not measured, no\n"
    "                 point).                                                   -> scaling\n"
    "  parting JSON...  granpen parting --json files: each pair's drag ratio against time\n"
    "                 after contact, the threshold's band about 1, each parting marked\n"
    "                 (an open circle).                                         -> parting\n"
    "--ensemble (force, ratio, peak, kz): the runs of each (v0, g, D) aligned at their force\n"
    "onsets and averaged (as granpen fit/collapse --ensemble): force draws each mean with\n"
    "its standard error over runs as a band; ratio the ensembles' F/F_z with that band; peak\n"
    "and kz each ensemble's value +- its se, single runs as small open circles.\n"
    "Every legend lists every group, or says how many entries it folded; a panel or inset\n"
    "with nothing to show is left out with a note.\n"
    "gnuplot (gnuplot-nox; $GRANPEN_GNUPLOT overrides the program) needs the pngcairo\n"
    "and svg terminals. Exit status: 0 when every figure was made, 1 when an input was\n"
    "unusable or gnuplot is missing or failed (the scripts and data are still written),\n"
    "2 for a usage error.\n";

}    // namespace

granpen::cli::PlotOptions granpen::cli::parse_plot(int argc, char **argv)
{
  Command cmd("plot", HELP);
  PlotOptions po;
  figures::Options &o = po.figures;
  const std::string &kind = po.kind;
  auto &app = cmd.app;
  app.add_option("kind", po.kind, "force, ratio, peak, kz, flow, momentum, scaling or parting")->required();
  app.add_option("inputs", po.inputs, "traces or folders (flow, momentum: the tables' folder)");
  app.add_option("--out", o.out, "output folder (required; created)")->check(file_name())->type_name("DIR");
  bool no_run = false;
  app.add_flag("--no-run", no_run, "write the scripts and data only, do not run gnuplot");
  app.add_flag("--each", o.each, "force: draw every run rather than the mean and range per v0");
  cmd.number("--kz-zmin", o.kz_zmin, "k_z window start, cm (default 3, as granpen fit and collapse)")->type_name("Z");
  cmd.number("--kz-zmax", o.kz_zmax, "k_z window end, cm (default: the deepest point)")->type_name("Z");
  app.add_option("--alpha", o.alpha, "ratio: F_z = alpha mu rho_g g D^2 z instead of the fit")
      ->check(non_negative_number())->type_name("A");
  app.add_option("--mu", o.mu, "ratio: friction for --alpha (default: header key mu)")->check(non_negative_number())
      ->type_name("MU");
  app.add_option("--rho", o.rho, "ratio: grain density for --alpha (default: header key rho_g)")
      ->check(non_negative_number())->type_name("RHO");
  app.add_option("--band", o.collapse.band, "ratio: as granpen collapse (default 0.2)")->check(positive_number())
      ->type_name("B");
  app.add_option("--tbin", o.collapse.tbin, "ratio: as granpen collapse (default 0.1)")->check(positive_number())
      ->type_name("W");
  cmd.number("--zmin", o.collapse.zmin, "ratio: as granpen collapse (default 0.2 cm)")->type_name("Z");
  app.add_option("--D", o.D, "flow: rod diameter in cm when the tables' headers do not give it\n(default 2)")
      ->check(non_negative_number())->type_name("D");
  EnsembleOptions ens;
  add_ensemble_options(cmd, ens);
  if (!cmd.parse(argc, argv, po.help)) return po;
  check_ensemble_options(cmd, ens);
  o.ensemble = ens.on, o.ens = ens.mean, o.boot = ens.boot;
  if (ens.on && o.each) throw UsageError("give --ensemble or --each, not both");
  static const char *kinds[] = {"force", "ratio", "peak", "kz", "flow", "momentum", "scaling", "parting"};
  if (std::find_if(std::begin(kinds), std::end(kinds), [&](const char *k) { return kind == k; }) == std::end(kinds))
    throw UsageError("unknown kind '" + kind + "' (force, ratio, peak, kz, flow, momentum, scaling, parting)");
  if (o.out.empty()) throw UsageError("--out DIR is required");
  const bool tables = kind == "flow" || kind == "momentum" || kind == "scaling";
  if (po.inputs.empty())
    throw UsageError(kind == "scaling" ? "give the table" : kind == "parting" ? "give granpen parting's JSON files" : tables ? "give the folder of the tables" : "no trace given");
  if (kind == "parting" && ens.on) throw UsageError("--ensemble is for force, ratio, peak and kz");
  if (tables && ens.on) throw UsageError("--ensemble is for force, ratio, peak and kz");
  if (tables && po.inputs.size() != 1)
    throw UsageError(kind + " takes one " + (kind == "scaling" ? "table" : "folder") + ", got " +
                     std::to_string(po.inputs.size()) + " arguments");
  if (!(o.kz_zmin < o.kz_zmax)) throw UsageError("--kz-zmin must be below --kz-zmax");
  o.run = !no_run;
  return po;
}
