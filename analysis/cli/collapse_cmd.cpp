// granpen collapse TRACE-OR-FOLDER...: F/F_z against t~ = (z/v0) sqrt(g/D) over a set of
// traces, the crossover t~*, the collapse quality and the peak law (core/collapse.h).
#include "atomic_file.h"
#include "subcommand.h"
#include "collapse.h"
#include "json_text.h"
#include "collapse_tables.h"
#include "json_writer.h"
#include "subcommands.h"
#include "trace_fit.h"
#include "trace_files.h"
#include "trace_reader.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

using granpen::json_number;

namespace {

const char *HELP =
    "usage: granpen collapse TRACE-OR-FOLDER... [--kz-zmin Z] [--kz-zmax Z] [--alpha A --mu MU --rho RHO]\n"
    "                        [--band B] [--tbin W] [--zmin Z] [--csv FILE] [--json FILE]\n"
    "Divides each trace's F by its depth term F_z = k_z z and plots it, binned, against\n"
    "t~ = (z / v0) sqrt(g / D) (paper: F/F_z joins 1 at t~ = 1). k_z comes from each trace's\n"
    "linear fit over z from --kz-zmin (default 3 cm, the paper's) to --kz-zmax (default: the\n"
    "deepest point), or from --alpha: F_z = alpha mu rho_g g D^2 z (mu, rho_g from the headers\n"
    "unless given). Reports per trace the crossover t~* (start of the first t~ bin of width\n"
    "--tbin (0.1) after which F/F_z stays within 1 +- --band (0.2)), their mean and spread; the\n"
    "collapse quality (spread of the curves against z, before, and against t~, after); the\n"
    "peak height (0 < z < 0.7 R) against v0 on log axes: exponent and 95% interval; k_z\n"
    "against v0. --csv writes the binned curves (trace, v0, g, D, t~, F/F_z); --json all.\n"
    "Outputs are written whole or not at all, never over an input.\n";

}    // namespace

int granpen::cli::collapse(int argc, char **argv)
{
  Command cmd("collapse", HELP);
  std::vector<std::string> inputs;
  double kz_zmin = 3.0, kz_zmax = INFINITY, alpha = 0.0, mu_opt = 0.0, rho_opt = 0.0;
  std::string csv, json;
  CollapseParams p;
  cmd.app.add_option("traces", inputs, "trace files, or folders of them")->required();
  cmd.number("--kz-zmin", kz_zmin, "k_z window start, cm (default 3)", true)->type_name("Z");
  cmd.number("--kz-zmax", kz_zmax, "k_z window end, cm (default: the deepest point)", true)->type_name("Z");
  cmd.app.add_option("--alpha", alpha, "F_z = alpha mu rho_g g D^2 z instead of a fit, > 0")->check(positive_number())->type_name("A");
  cmd.app.add_option("--mu", mu_opt, "friction for --alpha (default: header key mu, else 0.3)")->check(positive_number())->type_name("MU");
  cmd.app.add_option("--rho", rho_opt, "grain density for --alpha (default: header key rho_g, else 3)")
      ->check(positive_number())->type_name("RHO");
  cmd.app.add_option("--band", p.band, "crossover: F/F_z within 1 +- B (default 0.2)")->check(positive_number())->type_name("B");
  cmd.app.add_option("--tbin", p.tbin, "t~ bin width (default 0.1)")->check(positive_number())->type_name("W");
  cmd.number("--zmin", p.zmin, "depths used from Z, cm (default 0.2)", true)->type_name("Z");
  cmd.app.add_option("--csv", csv, "write the binned curves (trace, v0, g, D, t~, F/F_z)")->type_name("FILE");
  cmd.app.add_option("--json", json, "write every result as JSON")->type_name("FILE");
  if (!cmd.parse(argc, argv)) return EXIT_OK;
  if (!(kz_zmin < kz_zmax)) throw UsageError("--kz-zmin must be below --kz-zmax");

  std::vector<std::string> problems;
  const auto files = expand_trace_paths(inputs, problems);
  DepthTerm dt;
  dt.kz_zmin = kz_zmin, dt.kz_zmax = kz_zmax, dt.alpha = alpha, dt.mu = mu_opt, dt.rho_g = rho_opt;
  const std::vector<CollapseInput> in = read_collapse_inputs(files, dt, problems);

  for (const auto &o : {std::make_pair("--csv", csv), std::make_pair("--json", json)})
    if (!o.second.empty()) refuse_overwriting_inputs(o.second, o.first, files);
  for (const auto &m : problems) std::fprintf(stderr, "granpen collapse: %s\n", m.c_str());
  if (in.empty()) {
    std::fprintf(stderr, "granpen collapse: no usable trace\n");
    return 1;
  }

  const CollapseResult r = granpen::collapse(in, p);
  std::printf("granpen collapse: %zu traces, band 1 +- %g, t~ bins of %g\n", r.curves.size(), p.band, p.tbin);
  for (const auto &c : r.curves)
    std::printf("  %s: v0 = %g cm/s, g = %g, D = %g, k_z = %.4g dyne/cm, peak %.4g dyne at z = %.3g cm, t~* = %s\n",
                c.name.c_str(), c.v0, c.g, c.D, c.k_z, c.peak, c.peak_z,
                c.crossed ? json_number("%.2f", c.t_star).c_str() : "not reached");
  std::printf("crossover: t~* = %.2f +- %.2f over %d of %zu traces (paper: 1)\n", r.t_star_mean, r.t_star_sd,
              r.n_crossed, r.curves.size());
  if (r.ens_crossed)
    std::printf("ensemble crossover: the mean of F/F_z over the traces stays within 1 +- %g from t~* = %.2f "
                "(bins with at least %d traces)\n",
                p.band, r.t_star_ensemble, std::min<int>(p.min_curves, static_cast<int>(r.curves.size())));
  else
    std::printf("ensemble crossover: the mean of F/F_z over the traces does not stay within 1 +- %g\n", p.band);
  std::printf("collapse quality: spread of F/F_z across traces %.3f against z, %.3f against t~ (ratio %.2f)\n",
              r.spread_z, r.spread_t, r.spread_z > 0 ? r.spread_t / r.spread_z : 0.0);
  if (r.peak_ok)
    std::printf("peak law: peak ~ v0^%.2f +- %.2f (95%%; paper: 2)\n", r.peak_exponent, r.peak_exponent_ci95);
  else
    std::printf("peak law: needs at least 3 traces over 2 or more speeds\n");

  if (!csv.empty()) {
    write_file_atomic(csv, collapse_curves_csv(r));
    std::printf("wrote %s\n", csv.c_str());
  }
  if (!json.empty()) {
    write_json(json, collapse_json(r, p), 1);
    std::printf("wrote %s\n", json.c_str());
  }
  return problems.empty() ? 0 : 1;
}
