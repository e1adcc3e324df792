// granpen fit TRACE...: the paper's observables of each force trace: the depth term
// k_z and alpha, the transient peak, the fluctuation wavelength (core/trace_fit.h).
#include "args.h"
#include "atomic_file.h"
#include "command.h"
#include "json_text.h"
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
#include <string>
#include <vector>

using granpen::json_number;
using granpen::json_string;

namespace {

namespace fs = std::filesystem;
using granpen::TraceFit;

const char *HELP =
    "usage: granpen fit TRACE... [--zmin Z | --tmin T] [--zmax Z] [--mu MU] [--rho RHO] [--json FILE] [--csv FILE]\n"
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
    "options:\n"
    "  --zmin Z    window start, cm (default 3, the paper's z >= 3 cm)\n"
    "  --tmin T    window start by t~ = (z/v0) sqrt(g/D) instead: z >= T v0 sqrt(D/g) per\n"
    "              trace (the deep regime is t~ > 1)\n"
    "  --zmax Z    window end, cm (default: the deepest depth of each trace)\n"
    "  --mu MU     grain friction for alpha (default: header key mu, else 0.3)\n"
    "  --rho RHO   grain density for alpha, g/cm^3 (default: header key rho_g, else 3.0)\n"
    "              d_g comes from header key d_g, else 0.4 cm; the summary says which\n"
    "              values were defaults\n"
    "  --json FILE write the results as JSON (units cgs; undefined values are 0 with a\n"
    "              false *_ok flag; unreadable traces under \"errors\")\n"
    "  --csv FILE  write one CSV row per fitted trace\n"
    "Exit status: 0 when every trace was read, 1 when a trace (or an output file) failed,\n"
    "2 for a usage error. Quantities that cannot be fitted (e.g. a window without data)\n"
    "are reported as undefined and do not change the exit status.\n";

const double DEFAULT_MU = 0.3, DEFAULT_RHO = 3.0, DEFAULT_DG = 0.4;

struct Result {
  std::string file;
  double v0 = 0, D = 0, g = 0;
  double mu = 0, rho_g = 0, d_g = 0;
  std::string mu_src, rho_src, dg_src;    // "option", "header" or "default"
  TraceFit fit;
};

struct Failure {
  std::string file, message;
};

// header value: returns false (message set) when present but not a number
bool header_value(const granpen::Trace &tr, const char *key, double fallback, double &out,
                  std::string &src, std::string &message)
{
  auto it = tr.keys.find(key);
  if (it == tr.keys.end()) {
    out = fallback;
    src = "default";
    return true;
  }
  if (!granpen::cli::number_arg(it->second.c_str(), out)) {    // c_str(): up to a NUL byte, as fit always read it
    message = tr.path + ": header key " + key + " = '" + it->second + "' is not a number";
    return false;
  }
  src = "header";
  return true;
}



std::string num(double v) { return granpen::json_number("%.10g", v); }

std::string csv_field(const std::string &s)
{
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string o = "\"";
  for (char c : s) o += (c == '"') ? std::string("\"\"") : std::string(1, c);
  return o + "\"";
}

std::string window_text(double zlo, double zhi)
{
  return std::isfinite(zhi) ? json_number("%g", zlo) + ".." + json_number("%g", zhi) + " cm" : "z >= " + json_number("%g", zlo) + " cm";
}

void print_result(const Result &r)
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

granpen::Json fit_json(const Result &r)
{
  const TraceFit &f = r.fit;
  const auto n = [](double v) { return granpen::json_rounded("%.10g", v); };
  granpen::Json t;
  t["file"] = r.file, t["v0"] = n(r.v0), t["D"] = n(r.D), t["g"] = n(r.g);
  t["mu"] = n(r.mu), t["mu_source"] = r.mu_src, t["rho_g"] = n(r.rho_g), t["rho_g_source"] = r.rho_src;
  t["d_g"] = n(r.d_g), t["d_g_source"] = r.dg_src;
  t["zlo"] = n(f.zlo), t["zhi"] = n(f.zhi), t["n_window"] = f.n_window, t["z_first"] = n(f.z_first);
  t["z_last"] = n(f.z_last);
  t["slope_ok"] = f.slope_ok, t["k_z"] = n(f.k_z), t["k_z_se"] = n(f.k_z_se), t["intercept"] = n(f.intercept);
  t["intercept_se"] = n(f.intercept_se), t["rms"] = n(f.rms);
  t["alpha_ok"] = f.alpha_ok, t["alpha"] = n(f.alpha), t["alpha_se"] = n(f.alpha_se), t["k_z0"] = n(f.k_z0);
  t["k_z0_se"] = n(f.k_z0_se), t["alpha0"] = n(f.alpha0), t["alpha0_se"] = n(f.alpha0_se);
  t["peak_ok"] = f.peak_ok, t["n_peak"] = f.n_peak, t["peak_zmax"] = n(f.peak_zmax), t["peak_F"] = n(f.peak_F);
  t["peak_z"] = n(f.peak_z);
  t["wavelength_ok"] = f.wavelength_ok, t["wavelength"] = n(f.wavelength), t["wavelength_d_g"] = n(f.wavelength_dg);
  t["spectrum"] = {{"dz", n(f.spectrum.dz)}, {"n", f.spectrum.n}, {"length", n(f.spectrum.length)},
                   {"bin", f.spectrum.bin}, {"power_fraction", n(f.spectrum.power_fraction)},
                   {"lowest_bin", f.spectrum.lowest_bin}};
  t["notes"] = f.notes;
  return t;
}

// every result, units cgs; undefined values 0 with a false *_ok flag
granpen::Json results_json(const std::vector<Result> &results, const std::vector<Failure> &failures, double zmin,
                           double zmax, double tmin)
{
  const auto n = [](double v) { return granpen::json_rounded("%.10g", v); };
  granpen::Json j;
  j["tool"] = "granpen fit";
  j["units"] = {{"z", "cm"}, {"F", "dyne"}, {"k_z", "dyne/cm"}, {"v0", "cm/s"}, {"g", "cm/s^2"}, {"rho_g", "g/cm^3"},
                {"wavelength", "cm"}};
  j["window"] = {{"zmin", tmin > 0 ? granpen::Json() : n(zmin)}, {"tmin", tmin > 0 ? n(tmin) : granpen::Json()},
                 {"zmax", std::isfinite(zmax) ? n(zmax) : granpen::Json()}};
  j["traces"] = granpen::Json::array();
  for (const auto &r : results) j["traces"].push_back(fit_json(r));
  j["errors"] = granpen::Json::array();
  for (const auto &f : failures) j["errors"].push_back({{"file", f.file}, {"message", f.message}});
  return j;
}

std::string results_csv(const std::vector<Result> &results)
{
  std::ostringstream o;
  o << "file,v0,D,g,mu,mu_source,rho_g,rho_g_source,d_g,d_g_source,zlo,zhi,n_window,z_first,z_last,"
       "slope_ok,k_z,k_z_se,intercept,intercept_se,rms,alpha_ok,alpha,alpha_se,"
       "peak_ok,peak_F,peak_z,wavelength_ok,wavelength,wavelength_d_g,spectrum_length,power_fraction,"
       "k_z0,k_z0_se,alpha0,alpha0_se\n";
  for (const auto &r : results) {
    const TraceFit &f = r.fit;
    const auto n = [](double v) { return num(v); };
    o << csv_field(r.file) << ',' << n(r.v0) << ',' << n(r.D) << ',' << n(r.g) << ',' << n(r.mu) << ','
      << r.mu_src << ',' << n(r.rho_g) << ',' << r.rho_src << ',' << n(r.d_g) << ',' << r.dg_src << ','
      << n(f.zlo) << ',' << n(f.zhi) << ',' << f.n_window << ',' << n(f.z_first) << ',' << n(f.z_last) << ','
      << f.slope_ok << ',' << n(f.k_z) << ',' << n(f.k_z_se) << ',' << n(f.intercept) << ','
      << n(f.intercept_se) << ',' << n(f.rms) << ',' << f.alpha_ok << ',' << n(f.alpha) << ','
      << n(f.alpha_se) << ',' << f.peak_ok << ',' << n(f.peak_F) << ',' << n(f.peak_z) << ','
      << f.wavelength_ok << ',' << n(f.wavelength) << ',' << n(f.wavelength_dg) << ','
      << n(f.spectrum.length) << ',' << n(f.spectrum.power_fraction) << ',' << n(f.k_z0) << ',' << n(f.k_z0_se) << ','
      << n(f.alpha0) << ',' << n(f.alpha0_se) << '\n';
  }
  return o.str();
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
  auto *zmin_opt = cmd.number("--zmin", zmin, "window start, cm");
  auto *tmin_opt = app.add_option("--tmin", tmin, "window start by t~")->check(positive_number());
  cmd.number("--zmax", zmax, "window end, cm");
  auto *mu = app.add_option("--mu", mu_opt, "grain friction for alpha")->check(positive_number());
  auto *rho = app.add_option("--rho", rho_opt, "grain density for alpha, g/cm^3")->check(positive_number());
  app.add_option("--json", json_path, "write the results as JSON")->check(CLI::Validator(
      [](std::string &v) { return v.empty() ? std::string("needs a file name") : std::string(); }, "FILE"));
  app.add_option("--csv", csv_path, "write one CSV row per trace")->check(CLI::Validator(
      [](std::string &v) { return v.empty() ? std::string("needs a file name") : std::string(); }, "FILE"));
  if (!cmd.parse(argc, argv)) return EXIT_OK;
  const bool have_mu = mu->count() > 0, have_rho = rho->count() > 0;
  if (zmin_opt->count() > 0 && tmin_opt->count() > 0) throw UsageError("give --zmin or --tmin, not both");
  if (!(tmin_opt->count() > 0) && !(zmin < zmax)) throw UsageError("--zmin must be below --zmax");

  std::vector<Result> results;
  std::vector<Failure> failures;

  std::vector<std::string> problems;
  const std::vector<std::string> files = expand_trace_paths(inputs, problems);
  for (const auto &m : problems) failures.push_back({m.substr(0, m.find(": ")), m});
  for (const auto &f : failures) std::fprintf(stderr, "granpen fit: %s\n", f.message.c_str());
  for (const auto &o : {std::make_pair("--json", json_path), std::make_pair("--csv", csv_path)})
    if (!o.second.empty()) refuse_overwriting_inputs(o.second, o.first, files);

  std::printf("granpen fit: window %s; %zu trace%s\n",
              tmin > 0 ? ("t~ >= " + json_number("%g", tmin) + (std::isfinite(zmax) ? ", z <= " + json_number("%g", zmax) + " cm" : std::string())).c_str()
                       : window_text(zmin, zmax).c_str(), files.size(),
              files.size() == 1 ? "" : "s");
  for (const auto &file : files) {
    Result r;
    r.file = file;
    try {
      const Trace tr = to_cgs(read_trace(file));
      std::string msg;
      if (!header_value(tr, "mu", DEFAULT_MU, r.mu, r.mu_src, msg) ||
          !header_value(tr, "rho_g", DEFAULT_RHO, r.rho_g, r.rho_src, msg) ||
          !header_value(tr, "d_g", DEFAULT_DG, r.d_g, r.dg_src, msg))
        throw InputError(msg);
      if (have_mu) r.mu = mu_opt, r.mu_src = "option";
      if (have_rho) r.rho_g = rho_opt, r.rho_src = "option";
      r.v0 = tr.v0;
      r.D = tr.D;
      r.g = tr.g;
      TraceFitParams p;
      // a t~ window: z >= t~ v0 sqrt(D / g), this trace's depth of that t~
      p.zlo = tmin > 0 ? tmin * tr.v0 * std::sqrt(tr.D / tr.g) : zmin;
      p.zhi = zmax;
      p.v0 = tr.v0;
      p.D = tr.D;
      p.g = tr.g;
      p.mu = r.mu;
      p.rho_g = r.rho_g;
      p.d_g = r.d_g;
      r.fit = fit_trace(tr.z, tr.F, p);
    } catch (std::exception &e) {
      std::fprintf(stderr, "granpen fit: %s\n", e.what());
      failures.push_back({file, e.what()});
      continue;
    }
    print_result(r);
    results.push_back(r);
  }

  int status = failures.empty() ? 0 : 1;
  if (!failures.empty())
    std::printf("granpen fit: %zu input%s failed (see above)\n", failures.size(), failures.size() == 1 ? "" : "s");
  if (!json_path.empty()) {
    write_json(json_path, results_json(results, failures, zmin, zmax, tmin), 1);
    std::printf("wrote %s\n", json_path.c_str());
  }
  if (!csv_path.empty()) {
    write_file_atomic(csv_path, results_csv(results));
    std::printf("wrote %s\n", csv_path.c_str());
  }
  return status;
}
