// granpen fit TRACE...: the paper's observables of each force trace: the depth term
// k_z and alpha, the transient peak, the fluctuation wavelength (core/trace_fit.h).
#include "args.h"
#include "json_text.h"
#include "trace_files.h"
#include "subcommands.h"
#include "trace_fit.h"
#include "trace_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
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

bool write_json(const std::string &path, const std::vector<Result> &results,
                const std::vector<Failure> &failures, double zmin, double zmax, double tmin)
{
  std::ofstream o(path, std::ios::binary);
  if (!o) return false;
  o << "{\n  \"tool\": \"granpen fit\",\n"
    << "  \"units\": {\"z\": \"cm\", \"F\": \"dyne\", \"k_z\": \"dyne/cm\", \"v0\": \"cm/s\", "
       "\"g\": \"cm/s^2\", \"rho_g\": \"g/cm^3\", \"wavelength\": \"cm\"},\n"
    << "  \"window\": {\"zmin\": " << (tmin > 0 ? std::string("null") : num(zmin))
    << ", \"tmin\": " << (tmin > 0 ? num(tmin) : std::string("null")) << ", \"zmax\": " << (std::isfinite(zmax) ? num(zmax) : std::string("null")) << "},\n"
    << "  \"traces\": [";
  auto b = [](bool v) { return v ? "true" : "false"; };
  for (std::size_t i = 0; i < results.size(); ++i) {
    const Result &r = results[i];
    const TraceFit &f = r.fit;
    o << (i ? ",\n" : "\n") << "    {\"file\": " << json_string(r.file) << ", \"v0\": " << num(r.v0)
      << ", \"D\": " << num(r.D) << ", \"g\": " << num(r.g) << ",\n"
      << "     \"mu\": " << num(r.mu) << ", \"mu_source\": " << json_string(r.mu_src)
      << ", \"rho_g\": " << num(r.rho_g) << ", \"rho_g_source\": " << json_string(r.rho_src)
      << ", \"d_g\": " << num(r.d_g) << ", \"d_g_source\": " << json_string(r.dg_src) << ",\n"
      << "     \"zlo\": " << num(f.zlo) << ", \"zhi\": " << num(f.zhi)
      << ", \"n_window\": " << f.n_window << ", \"z_first\": " << num(f.z_first)
      << ", \"z_last\": " << num(f.z_last) << ",\n"
      << "     \"slope_ok\": " << b(f.slope_ok) << ", \"k_z\": " << num(f.k_z)
      << ", \"k_z_se\": " << num(f.k_z_se) << ", \"intercept\": " << num(f.intercept)
      << ", \"intercept_se\": " << num(f.intercept_se) << ", \"rms\": " << num(f.rms) << ",\n"
      << "     \"alpha_ok\": " << b(f.alpha_ok) << ", \"alpha\": " << num(f.alpha)
      << ", \"alpha_se\": " << num(f.alpha_se) << ", \"k_z0\": " << num(f.k_z0) << ", \"k_z0_se\": " << num(f.k_z0_se)
      << ", \"alpha0\": " << num(f.alpha0) << ", \"alpha0_se\": " << num(f.alpha0_se) << ",\n"
      << "     \"peak_ok\": " << b(f.peak_ok) << ", \"n_peak\": " << f.n_peak
      << ", \"peak_zmax\": " << num(f.peak_zmax) << ", \"peak_F\": " << num(f.peak_F)
      << ", \"peak_z\": " << num(f.peak_z) << ",\n"
      << "     \"wavelength_ok\": " << b(f.wavelength_ok) << ", \"wavelength\": " << num(f.wavelength)
      << ", \"wavelength_d_g\": " << num(f.wavelength_dg) << ", \"spectrum\": {\"dz\": "
      << num(f.spectrum.dz) << ", \"n\": " << f.spectrum.n << ", \"length\": "
      << num(f.spectrum.length) << ", \"bin\": " << f.spectrum.bin
      << ", \"power_fraction\": " << num(f.spectrum.power_fraction)
      << ", \"lowest_bin\": " << b(f.spectrum.lowest_bin) << "},\n"
      << "     \"notes\": [";
    for (std::size_t k = 0; k < f.notes.size(); ++k) o << (k ? ", " : "") << json_string(f.notes[k]);
    o << "]}";
  }
  o << (results.empty() ? "],\n" : "\n  ],\n") << "  \"errors\": [";
  for (std::size_t i = 0; i < failures.size(); ++i)
    o << (i ? ",\n" : "\n") << "    {\"file\": " << json_string(failures[i].file)
      << ", \"message\": " << json_string(failures[i].message) << "}";
  o << (failures.empty() ? "]\n}\n" : "\n  ]\n}\n");
  return (bool) o.flush();
}

bool write_csv(const std::string &path, const std::vector<Result> &results)
{
  std::ofstream o(path, std::ios::binary);
  if (!o) return false;
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
  return (bool) o.flush();
}

const granpen::cli::Usage usage_error{"fit", HELP};

}    // namespace

int granpen::cli::fit(int argc, char **argv)
{
  if (argc < 1) return usage_error.no_arguments();
  double zmin = 3.0, zmax = std::numeric_limits<double>::infinity();
  double mu_opt = 0.0, rho_opt = 0.0, tmin = -1.0;
  bool have_mu = false, have_rho = false, have_zmin = false;
  std::string json_path, csv_path;
  std::vector<std::string> inputs;

  for (int i = 0; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--help" || a == "-h") return usage_error.help_asked();
    if (is_option(a)) {
      std::string name, value;
      const bool inline_value = split_option(a, name, value);
      if (name != "--zmin" && name != "--zmax" && name != "--tmin" && name != "--mu" && name != "--rho" &&
          name != "--json" && name != "--csv")
        return usage_error(unknown_option(name));
      if (!inline_value && !next_value(argc, argv, i, value)) return usage_error(needs_value(name));
      if (name == "--json" || name == "--csv") {
        if (value.empty()) return usage_error(name + " needs a file name");
        (name == "--json" ? json_path : csv_path) = value;
        continue;
      }
      double v;
      if (!number_arg(value, v)) return usage_error(not_a_number(name, value));
      if (name == "--zmin") zmin = v, have_zmin = true;
      else if (name == "--tmin") tmin = v;
      else if (name == "--zmax") zmax = v;
      else if (name == "--mu") mu_opt = v, have_mu = true;
      else rho_opt = v, have_rho = true;
      continue;
    }
    inputs.push_back(a);
  }
  if (inputs.empty()) return usage_error("no trace given");
  if (have_zmin && tmin >= 0) return usage_error("give --zmin or --tmin, not both");
  if (tmin >= 0 && !(tmin > 0)) return usage_error("--tmin must be positive");
  if (tmin < 0 && !(zmin < zmax)) return usage_error("--zmin must be below --zmax");
  if (have_mu && !(mu_opt > 0)) return usage_error("--mu must be positive");
  if (have_rho && !(rho_opt > 0)) return usage_error("--rho must be positive");

  std::vector<Result> results;
  std::vector<Failure> failures;

  std::vector<std::string> problems;
  const std::vector<std::string> files = expand_trace_paths(inputs, problems);
  for (const auto &m : problems) failures.push_back({m.substr(0, m.find(": ")), m});
  for (const auto &f : failures) std::fprintf(stderr, "granpen fit: %s\n", f.message.c_str());

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
    if (write_json(json_path, results, failures, zmin, zmax, tmin)) std::printf("wrote %s\n", json_path.c_str());
    else std::fprintf(stderr, "granpen fit: cannot write %s\n", json_path.c_str()), status = 1;
  }
  if (!csv_path.empty()) {
    if (write_csv(csv_path, results)) std::printf("wrote %s\n", csv_path.c_str());
    else std::fprintf(stderr, "granpen fit: cannot write %s\n", csv_path.c_str()), status = 1;
  }
  return status;
}
