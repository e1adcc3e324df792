// granpen fit TRACE...: the paper's observables of each force trace: the depth term
// k_z and alpha, the transient peak, the fluctuation wavelength (core/trace_fit.h).
#include "args.h"
#include "ensemble_args.h"
#include "ensemble_tables.h"
#include "atomic_file.h"
#include "subcommand.h"
#include "json_text.h"
#include "fit_tables.h"
#include "json_writer.h"
#include "trace_files.h"
#include "subcommands.h"
#include "trace_fit.h"
#include "trace_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <limits>
#include <map>
#include <string>
#include <vector>

using granpen::json_number;
using granpen::json_string;

namespace {

namespace fs = std::filesystem;
using granpen::FitResult;
using granpen::TraceFit;

const char *HELP =
    "usage: granpen fit TRACE... [--zmin Z | --tmin T] [--zmax Z] [--mu MU] [--rho RHO] [--json FILE] [--csv FILE]\n"
    "                [--ensemble [--ensemble-bin W] [--bootstrap B] [--ensemble-csv FILE]]\n"
    "Fits each force trace (granpen-trace v1; SI traces are converted to cgs). A folder\n"
    "argument stands for every *.csv in it. Per trace:\n"
    "  k_z    slope of F on z over the window (linear least squares), with its standard error\n"
    "  alpha  k_z / (mu rho_g g D^2), the paper's depth-term prefactor (35 +- 5 at 40 cm/s)\n"
    "  k_z0, alpha0  the same through the origin, F = k_z0 z (the paper's form F_z = k_z z;\n"
    "         in --csv and --json): the depth term granpen collapse --alpha takes\n"
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

std::string pm(const granpen::Estimate &e, const char *f)
{
  std::string t = json_number(f, e.value);
  return e.se_ok ? t + " +- " + json_number("%.2g", e.se) : t;
}

// the ensemble's line: the fit of its mean with standard errors over runs
void print_ensemble(const granpen::TraceGroup &g, const granpen::EnsembleFit &e)
{
  std::puts(granpen::ensemble_summary(g).c_str());
  const TraceFit &f = e.fit;
  std::string line = "  mean:";
  if (e.k_z.ok)
    line += " k_z = " + pm(e.k_z, "%.4g") + " dyne/cm (z " + json_number("%.3g", f.z_first) + ".." +
            json_number("%.3g", f.z_last) + " cm, " + std::to_string(f.n_window) + " bins)";
  else line += " k_z undefined";
  line += e.alpha.ok ? ", alpha = " + pm(e.alpha, "%.3g") : ", alpha undefined";
  if (e.peak_F.ok) line += ", peak F = " + pm(e.peak_F, "%.4g") + " dyne at z = " + pm(e.peak_z, "%.3g") + " cm";
  else line += ", peak undefined";
  line += e.wavelength.ok ? ", wavelength = " + pm(e.wavelength, "%.3g") + " cm" : ", wavelength undefined";
  std::puts(line.c_str());
  if (e.resamples > 0)
    std::printf("  (+-: standard error over the %zu runs, bootstrap of %d resamples)\n", e.runs, e.resamples);
  for (const auto &n : f.notes) std::printf("  note: %s\n", n.c_str());
}

std::string window_text(double zlo, double zhi)
{
  return std::isfinite(zhi) ? json_number("%g", zlo) + ".." + json_number("%g", zhi) + " cm" : "z >= " + json_number("%g", zlo) + " cm";
}

void print_result(const FitResult &r)
{
  const TraceFit &f = r.fit;
  std::string line = r.file + ": v0 = " + json_number("%g", r.v0) + " cm/s";
  if (f.slope_ok)
    line += ", k_z = " + json_number("%.4g", f.k_z) + " +- " + json_number("%.2g", f.k_z_se) + " dyne/cm (z " +
            json_number("%.3g", f.z_first) + ".." + json_number("%.3g", f.z_last) + " cm, " + std::to_string(f.n_window) + " rows)";
  else
    line += ", k_z undefined";
  if (f.alpha_ok) line += ", alpha = " + json_number("%.3g", f.alpha) + " +- " + json_number("%.2g", f.alpha_se);
  else line += ", alpha undefined";
  if (f.peak_ok)
    line += ", peak F = " + json_number("%.4g", f.peak_F) + " dyne at z = " + json_number("%.3g", f.peak_z) + " cm";
  else line += ", peak undefined";
  if (f.wavelength_ok)
    line += ", wavelength = " + json_number("%.3g", f.wavelength) + " cm (" + json_number("%.3g", f.wavelength_dg) + " d_g, " +
            json_number("%.0f", 100.0 * f.spectrum.power_fraction) + "% of the power)";
  else line += ", wavelength undefined";
  std::puts(line.c_str());

  std::vector<std::string> defs;
  if (r.mu_src == "default") defs.push_back("mu = " + json_number("%g", r.mu));
  if (r.rho_src == "default") defs.push_back("rho_g = " + json_number("%g", r.rho_g) + " g/cm^3");
  if (r.dg_src == "default") defs.push_back("d_g = " + json_number("%g", r.d_g) + " cm");
  if (!defs.empty()) {
    std::string d = "  defaults used (not in the header):";
    for (std::size_t i = 0; i < defs.size(); ++i) d += (i ? ", " : " ") + defs[i];
    std::puts(d.c_str());
  }
  for (const auto &n : f.notes) std::printf("  note: %s\n", n.c_str());
}

// --ensemble: the runs read again, grouped by (v0, g, D), averaged and fitted with the
// window and mu, rho_g, d_g of each group's first run; JSON of each into out
std::vector<granpen::TraceGroup> fit_ensembles(const std::vector<FitResult> &results,
                                               const granpen::cli::EnsembleOptions &ens, granpen::Json &out)
{
  using namespace granpen;
  std::vector<std::string> files, problems;
  std::map<std::string, const FitResult *> by_file;
  for (const auto &r : results) files.push_back(r.file), by_file[r.file] = &r;
  auto groups = group_traces(read_traces(files, problems));
  average_groups(groups, ens.mean, problems);
  for (const auto &p : problems) std::printf("granpen fit: %s\n", p.c_str());
  for (const auto &g : groups) {
    const EnsembleFit e = fit_ensemble(g.mean, by_file.at(g.traces.front().path)->fit.params, ens.boot);
    print_ensemble(g, e);
    out.push_back(ensemble_fit_json(g, e));
  }
  return groups;
}

}    // namespace

int granpen::cli::fit(int argc, char **argv)
{
  Command cmd("fit", HELP);
  double zmin = 3.0, zmax = std::numeric_limits<double>::infinity();
  double mu_opt = 0.0, rho_opt = 0.0, tmin = -1.0;
  std::string json_path, csv_path;
  std::vector<std::string> inputs;
  auto &app = cmd.app;
  app.add_option("traces", inputs, "trace files, or folders of them")->required();
  auto *zmin_opt = cmd.number("--zmin", zmin, "window start, cm (default 3, the paper's z >= 3 cm)")->type_name("Z");
  auto *tmin_opt = app.add_option("--tmin", tmin, "window start by t~ = (z/v0) sqrt(g/D) instead: z >= T v0 sqrt(D/g)\n"
                                                  "per trace (the deep regime is t~ > 1)")
                       ->check(positive_number())->type_name("T");
  cmd.number("--zmax", zmax, "window end, cm (default: the deepest depth of each trace)")->type_name("Z");
  auto *mu = app.add_option("--mu", mu_opt, "grain friction for alpha (default: header key mu, else 0.3)")
                 ->check(positive_number())->type_name("MU");
  auto *rho = app.add_option("--rho", rho_opt, "grain density for alpha, g/cm^3 (default: header key rho_g,\n"
                                               "else 3.0); d_g comes from header key d_g, else 0.4 cm;\n"
                                               "the summary says which values were defaults")
                  ->check(positive_number())->type_name("RHO");
  app.add_option("--json", json_path, "write the results as JSON (units cgs; undefined values are 0\n"
                                      "with a false *_ok flag; unreadable traces under \"errors\")")
      ->check(file_name())->type_name("FILE");
  app.add_option("--csv", csv_path, "write one CSV row per fitted trace")->check(file_name())->type_name("FILE");
  EnsembleOptions ens;
  ens.add_to(cmd);
  std::string ens_csv;
  app.add_option("--ensemble-csv", ens_csv, "--ensemble: write the mean curves (v0, g, D, runs, z, F_mean, F_se, F_sd)")
      ->check(file_name())->type_name("FILE");
  if (!cmd.parse(argc, argv)) return EXIT_OK;
  ens.check();
  if (!ens.on && !ens_csv.empty()) throw UsageError("--ensemble-csv needs --ensemble");
  const bool have_mu = mu->count() > 0, have_rho = rho->count() > 0;
  if (zmin_opt->count() > 0 && tmin_opt->count() > 0) throw UsageError("give --zmin or --tmin, not both");
  if (!(tmin_opt->count() > 0) && !(zmin < zmax)) throw UsageError("--zmin must be below --zmax");

  std::vector<FitResult> results;
  std::vector<FitFailure> failures;

  std::vector<std::string> problems;
  const std::vector<std::string> files = expand_trace_paths(inputs, problems);
  for (const auto &m : problems) failures.push_back({m.substr(0, m.find(": ")), m});
  for (const auto &f : failures) std::fprintf(stderr, "granpen fit: %s\n", f.message.c_str());
  for (const auto &o : {std::make_pair("--json", json_path), std::make_pair("--csv", csv_path),
                        std::make_pair("--ensemble-csv", ens_csv)})
    if (!o.second.empty()) refuse_overwriting_inputs(o.second, o.first, files);

  std::printf("granpen fit: window %s; %zu trace%s\n",
              tmin > 0 ? ("t~ >= " + json_number("%g", tmin) + (std::isfinite(zmax) ? ", z <= " + json_number("%g", zmax) + " cm" : std::string())).c_str()
                       : window_text(zmin, zmax).c_str(), files.size(),
              files.size() == 1 ? "" : "s");
  FitWindow w;
  w.zmin = zmin, w.zmax = zmax, w.tmin = tmin;
  w.mu = have_mu ? mu_opt : 0.0, w.rho_g = have_rho ? rho_opt : 0.0;
  for (const auto &file : files) {
    try {
      results.push_back(fit_trace_file(file, w));
    } catch (std::exception &e) {    // one bad trace: the others are still fitted
      std::fprintf(stderr, "granpen fit: %s\n", user_text(e).c_str());
      failures.push_back({file, user_text(e)});
      continue;
    }
    print_result(results.back());
  }

  Json ensembles = Json::array();
  std::vector<TraceGroup> groups;
  if (ens.on) groups = fit_ensembles(results, ens, ensembles);

  int status = failures.empty() ? 0 : 1;
  if (!failures.empty())
    std::printf("granpen fit: %zu input%s failed (see above)\n", failures.size(), failures.size() == 1 ? "" : "s");
  if (!json_path.empty()) {
    Json j = fit_results_json(results, failures, w);
    if (ens.on) j["ensembles"] = ensembles;
    write_json(json_path, j, 1);
    std::printf("wrote %s\n", json_path.c_str());
  }
  if (!csv_path.empty()) {
    write_file_atomic(csv_path, fit_results_csv(results));
    std::printf("wrote %s\n", csv_path.c_str());
  }
  if (!ens_csv.empty()) {
    write_file_atomic(ens_csv, ensemble_curves_csv(groups));
    std::printf("wrote %s\n", ens_csv.c_str());
  }
  return status;
}
