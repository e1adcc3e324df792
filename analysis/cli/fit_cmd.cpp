// granpen fit TRACE...: the paper's observables of each force trace: the depth term
// k_z and alpha, the transient peak, the fluctuation wavelength: read (io/fit_tables.h),
// fit (core/fit_study.h), print and write.
#include "fit_options.h"
#include "ensemble_groups.h"
#include "ensemble_tables.h"
#include "fit_study.h"
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
#include <stdexcept>
#include <string>
#include <vector>

using granpen::json_number;
using granpen::json_string;

namespace {

namespace fs = std::filesystem;
using granpen::FitResult;
using granpen::TraceFit;


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
  auto groups = cli::averaged_groups(read_traces(files, problems), ens.mean, problems);
  for (const auto &p : problems) std::printf("granpen fit: %s\n", p.c_str());
  std::vector<FitStudyEnsemble> means;
  for (const auto &g : groups) means.push_back({g.label(), g.mean, by_file.at(g.traces.front().path)->fit.params});
  FitStages st;
  st.fits = false, st.ensemble_fits = true;
  FitStudyParams sp;
  sp.boot = ens.boot;
  const FitStudy s = run_fit_study({}, means, sp, st);
  for (std::size_t i = 0; i < groups.size(); ++i) {
    print_ensemble(groups[i], s.ensembles[i]);
    out.push_back(ensemble_fit_json(groups[i], s.ensembles[i]));
  }
  return groups;
}

}    // namespace

int granpen::cli::run_fit(const FitOptions &o)
{
  const FitWindow &w = o.window;
  const double zmin = w.zmin, zmax = w.zmax, tmin = w.tmin;
  const std::string &json_path = o.json, &csv_path = o.csv;
  const std::vector<std::string> &inputs = o.traces;
  const EnsembleOptions &ens = o.ensemble;
  const std::string &ens_csv = o.ensemble_csv;
  std::vector<FitResult> results;
  std::vector<FitFailure> failures;

  std::vector<std::string> problems;
  const std::vector<std::string> files = expand_trace_paths(inputs, problems);
  for (const auto &m : problems) failures.push_back({m.substr(0, m.find(": ")), m});
  for (const auto &f : failures) std::fprintf(stderr, "granpen fit: %s\n", f.message.c_str());
  const std::vector<std::pair<std::string, std::string>> outputs = {
      {"--json", json_path}, {"--csv", csv_path}, {"--ensemble-csv", ens_csv}};
  refuse_shared_outputs(outputs);
  for (const auto &o : outputs)
    if (!o.second.empty()) refuse_overwriting_inputs(o.second, o.first, files);

  std::printf("granpen fit: window %s; %zu trace%s\n",
              tmin > 0 ? ("t~ >= " + json_number("%g", tmin) + (std::isfinite(zmax) ? ", z <= " + json_number("%g", zmax) + " cm" : std::string())).c_str()
                       : window_text(zmin, zmax).c_str(), files.size(),
              files.size() == 1 ? "" : "s");
  std::vector<FitStudyTrace> read;
  for (const auto &file : files) {
    try {
      FitTraceRead r = read_fit_trace(file, w);
      results.push_back(std::move(r.result));
      read.push_back(std::move(r.trace));
    } catch (std::exception &e) {    // one bad trace: the others are still fitted
      std::fprintf(stderr, "granpen fit: %s\n", user_text(e).c_str());
      failures.push_back({file, user_text(e)});
    }
  }
  const FitStudy s = run_fit_study(read, {}, {}, FitStages{});
  std::vector<FitResult> fitted;
  for (std::size_t i = 0; i < results.size(); ++i) {
    if (s.fits[i].refused) {    // arrays the fit refuses: a failure of that file, as one unread
      const std::string why = user_text(std::invalid_argument(s.fits[i].why));
      std::fprintf(stderr, "granpen fit: %s\n", why.c_str());
      failures.push_back({results[i].file, why});
      continue;
    }
    results[i].fit = s.fits[i].fit;
    print_result(results[i]);
    fitted.push_back(results[i]);
  }
  results = std::move(fitted);

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

int granpen::cli::fit(int argc, char **argv) { return run_parsed(parse_fit, run_fit, argc, argv); }
