// granpen collapse TRACE-OR-FOLDER...: F/F_z against t~ = (z/v0) sqrt(g/D) over a set of
// traces, the crossover t~*, the collapse quality and the peak law (core/collapse.h).
#include "args.h"
#include "collapse.h"
#include "json_text.h"
#include "subcommands.h"
#include "trace_fit.h"
#include "trace_files.h"
#include "trace_reader.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

using granpen::json_number;
using granpen::json_string;

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
    "against v0. --csv writes the binned curves (trace, v0, g, D, t~, F/F_z); --json all.\n";

const granpen::cli::Usage usage{"collapse", HELP};

}    // namespace

int granpen::cli::collapse(int argc, char **argv)
{
  if (argc < 1) return usage.no_arguments();
  if (!std::strcmp(argv[0], "--help")) return usage.help_asked();
  std::vector<std::string> inputs;
  double kz_zmin = 3.0, kz_zmax = INFINITY, alpha = 0.0, mu_opt = 0.0, rho_opt = 0.0;
  std::string csv, json;
  CollapseParams p;
  for (int i = 0; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.compare(0, 2, "--") != 0) {
      inputs.push_back(a);
      continue;
    }
    std::string v;
    if (!next_value(argc, argv, i, v)) return usage.bare(needs_value(a));
    double x = 0.0;
    bool ok = true;
    if (a == "--csv") csv = v;
    else if (a == "--json") json = v;
    else if (!(ok = number_arg(v, x, /*accept_underflow=*/true))) ;
    else if (a == "--kz-zmin") kz_zmin = x;
    else if (a == "--kz-zmax") kz_zmax = x;
    else if (a == "--alpha") alpha = x;
    else if (a == "--mu") mu_opt = x;
    else if (a == "--rho") rho_opt = x;
    else if (a == "--band") p.band = x;
    else if (a == "--tbin") p.tbin = x;
    else if (a == "--zmin") p.zmin = x;
    else return usage.with_help(unknown_option(a));
    if (!ok) return usage.bare(needs_number(a, v));
  }
  if (!(p.band > 0 && p.tbin > 0 && kz_zmin < kz_zmax))
    return usage.bare("--band and --tbin must be positive, --kz-zmin below --kz-zmax");

  std::vector<std::string> problems;
  const auto files = expand_trace_paths(inputs, problems);
  std::vector<CollapseInput> in;
  for (const auto &f : files) {
    try {
      auto tr = to_cgs(read_trace(f));
      CollapseInput c;
      c.name = f;
      c.z = tr.z;
      c.F = tr.F;
      c.v0 = tr.v0, c.D = tr.D, c.g = tr.g;
      if (alpha > 0.0) {
        const double mu = mu_opt > 0 ? mu_opt : tr.number("mu", 0.3);
        const double rho = rho_opt > 0 ? rho_opt : tr.number("rho_g", 3.0);
        c.k_z = alpha * mu * rho * tr.g * tr.D * tr.D;
      } else {
        TraceFitParams fp;
        fp.zlo = kz_zmin, fp.zhi = kz_zmax, fp.v0 = tr.v0, fp.D = tr.D, fp.g = tr.g;
        auto fit = fit_trace(tr.z, tr.F, fp);
        if (!fit.slope_ok || !(fit.k_z > 0)) {
          problems.push_back(f + ": no positive depth term over the k_z window (use --kz-zmin/--kz-zmax or --alpha)");
          continue;
        }
        c.k_z = fit.k_z;
      }
      in.push_back(c);
    } catch (InputError &e) {
      problems.push_back(e.what());
    }
  }
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
    std::ofstream o(csv);
    o << "trace,v0,g,D,t_tilde,F_over_Fz\n";
    for (const auto &c : r.curves)
      for (std::size_t k = 0; k < c.t.size(); ++k)
        o << c.name << "," << json_number("%.10g", c.v0) << "," << json_number("%.10g", c.g) << ","
          << json_number("%.10g", c.D) << "," << json_number("%.6g", c.t[k]) << "," << json_number("%.6g", c.ratio[k])
          << "\n";
    std::printf("wrote %s\n", csv.c_str());
  }
  if (!json.empty()) {
    std::ofstream o(json);
    o << "{\n  \"tool\": \"granpen collapse\",\n  \"band\": " << json_number("%g", p.band)
      << ",\n  \"t_star_mean\": " << json_number("%.6g", r.t_star_mean) << ",\n  \"t_star_sd\": "
      << json_number("%.6g", r.t_star_sd) << ",\n  \"n_crossed\": " << r.n_crossed << ",\n  \"spread_z\": "
      << json_number("%.6g", r.spread_z) << ",\n  \"spread_t\": " << json_number("%.6g", r.spread_t)
      << ",\n  \"ensemble_crossed\": " << (r.ens_crossed ? "true" : "false") << ",\n  \"t_star_ensemble\": "
      << json_number("%.6g", r.t_star_ensemble) << ",\n  \"peak_exponent\": " << json_number("%.6g", r.peak_exponent) << ",\n  \"peak_exponent_ci95\": "
      << json_number("%.6g", r.peak_exponent_ci95) << ",\n  \"traces\": [";
    for (std::size_t i = 0; i < r.curves.size(); ++i) {
      const auto &c = r.curves[i];
      o << (i ? ",\n" : "\n") << "    {\"file\": " << json_string(c.name) << ", \"v0\": " << json_number("%.10g", c.v0)
        << ", \"k_z\": " << json_number("%.6g", c.k_z) << ", \"peak\": " << json_number("%.6g", c.peak)
        << ", \"crossed\": " << (c.crossed ? "true" : "false") << ", \"t_star\": " << json_number("%.4g", c.t_star)
        << "}";
    }
    o << "\n  ]\n}\n";
    std::printf("wrote %s\n", json.c_str());
  }
  return problems.empty() ? 0 : 1;
}
