// granpen analysis: granpen fit's per-trace fit and files (see fit_tables.h).
#include "fit_tables.h"

#include "json_text.h"
#include "scaling_laws.h"
#include "trace_reader.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace granpen {

namespace {

// s as a whole finite number (strtod; trailing text, overflow or underflow: false)
bool number_arg(const std::string &s, double &v)
{
  char *end = nullptr;
  errno = 0;
  v = std::strtod(s.c_str(), &end);
  return !s.empty() && end && *end == '\0' && errno != ERANGE && std::isfinite(v);
}

const double DEFAULT_DG = 0.4;

// header value: returns false (message set) when present but not a number
bool header_value(const Trace &tr, const char *key, double fallback, double &out,
                  std::string &src, std::string &message)
{
  auto it = tr.keys.find(key);
  if (it == tr.keys.end()) {
    out = fallback;
    src = "default";
    return true;
  }
  if (!number_arg(it->second.c_str(), out)) {    // c_str(): up to a NUL byte, as fit always read it
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

Json fit_json(const FitResult &r)
{
  const TraceFit &f = r.fit;
  const auto n = [](double v) { return json_rounded("%.10g", v); };
  Json t;
  t["file"] = r.file, t["v0"] = n(r.v0), t["D"] = n(r.D), t["g"] = n(r.g);
  t["mu"] = n(r.mu), t["mu_source"] = r.mu_src, t["rho_g"] = n(r.rho_g), t["rho_g_source"] = r.rho_src;
  t["d_g"] = n(r.d_g), t["d_g_source"] = r.dg_src;
  t["zlo"] = n(f.zlo), t["zhi"] = n(f.zhi), t["n_window"] = f.n_window, t["z_first"] = n(f.z_first);
  t["z_last"] = n(f.z_last);
  t["slope_ok"] = f.slope_ok, t["k_z"] = n(f.k_z), t["k_z_se"] = n(f.k_z_se), t["intercept"] = n(f.intercept);
  t["intercept_se"] = n(f.intercept_se), t["rms"] = n(f.rms);
  t["alpha_ok"] = f.alpha_ok, t["alpha"] = n(f.alpha), t["alpha_se"] = n(f.alpha_se), t["k_z0"] = n(f.k_z0);
  t["k_z0_se"] = n(f.k_z0_se), t["alpha0"] = n(f.alpha0), t["alpha0_se"] = n(f.alpha0_se);
  t["quad_ok"] = f.quad_ok, t["quad_a"] = n(f.quad_a), t["quad_a_se"] = n(f.quad_a_se), t["quad_b"] = n(f.quad_b);
  t["quad_b_se"] = n(f.quad_b_se), t["alpha_a"] = n(f.alpha_a), t["alpha_a_se"] = n(f.alpha_a_se);
  t["beta_b"] = n(f.beta_b), t["beta_b_se"] = n(f.beta_b_se);
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
Json results_json(const std::vector<FitResult> &results, const std::vector<FitFailure> &failures, double zmin,
                  double zmax, double tmin)
{
  const auto n = [](double v) { return json_rounded("%.10g", v); };
  Json j;
  j["tool"] = "granpen fit";
  j["units"] = {{"z", "cm"}, {"F", "dyne"}, {"k_z", "dyne/cm"}, {"v0", "cm/s"}, {"g", "cm/s^2"}, {"rho_g", "g/cm^3"},
                {"wavelength", "cm"}};
  j["window"] = {{"zmin", tmin > 0 ? Json() : n(zmin)}, {"tmin", tmin > 0 ? n(tmin) : Json()},
                 {"zmax", std::isfinite(zmax) ? n(zmax) : Json()}};
  j["traces"] = Json::array();
  for (const auto &r : results) j["traces"].push_back(fit_json(r));
  j["errors"] = Json::array();
  for (const auto &f : failures) j["errors"].push_back({{"file", f.file}, {"message", f.message}});
  return j;
}

std::string results_csv(const std::vector<FitResult> &results)
{
  std::ostringstream o;
  o << "file,v0,D,g,mu,mu_source,rho_g,rho_g_source,d_g,d_g_source,zlo,zhi,n_window,z_first,z_last,"
       "slope_ok,k_z,k_z_se,intercept,intercept_se,rms,alpha_ok,alpha,alpha_se,"
       "peak_ok,peak_F,peak_z,wavelength_ok,wavelength,wavelength_d_g,spectrum_length,power_fraction,"
       "k_z0,k_z0_se,alpha0,alpha0_se,quad_ok,quad_a,quad_a_se,quad_b,quad_b_se,alpha_a,alpha_a_se,beta_b,beta_b_se\n";
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
      << n(f.alpha0) << ',' << n(f.alpha0_se) << ',' << f.quad_ok << ',' << n(f.quad_a) << ',' << n(f.quad_a_se) << ','
      << n(f.quad_b) << ',' << n(f.quad_b_se) << ',' << n(f.alpha_a) << ',' << n(f.alpha_a_se) << ',' << n(f.beta_b) << ','
      << n(f.beta_b_se) << '\n';
  }
  return o.str();
}

}    // namespace

FitTraceRead read_fit_trace(const std::string &file, const FitWindow &w)
{
  FitTraceRead out;
  FitResult &r = out.result;
  r.file = file;
  const Trace tr = to_cgs(read_trace(file));
  std::string msg;
  if (!header_value(tr, "mu", DEFAULT_MU, r.mu, r.mu_src, msg) ||
      !header_value(tr, "rho_g", DEFAULT_RHO_G, r.rho_g, r.rho_src, msg) ||
      !header_value(tr, "d_g", DEFAULT_DG, r.d_g, r.dg_src, msg))
    throw InputError(msg);
  if (w.mu > 0) r.mu = w.mu, r.mu_src = "option";
  if (w.rho_g > 0) r.rho_g = w.rho_g, r.rho_src = "option";
  r.v0 = tr.v0, r.D = tr.D, r.g = tr.g;
  TraceFitParams &p = out.trace.params;
  // a t~ window: z at least this trace's depth of that t~
  p.zlo = w.tmin > 0 ? depth_at_t_tilde(w.tmin, tr.v0, tr.g, tr.D) : w.zmin;
  p.zhi = w.zmax;
  p.v0 = tr.v0, p.D = tr.D, p.g = tr.g;
  p.mu = r.mu, p.rho_g = r.rho_g, p.d_g = r.d_g;
  p.shorten_window = true;    // a window beyond the data: its deeper half, with a note
  out.trace.name = file, out.trace.z = tr.z, out.trace.F = tr.F;
  return out;
}

Json fit_results_json(const std::vector<FitResult> &results, const std::vector<FitFailure> &failures, const FitWindow &w)
{
  return results_json(results, failures, w.zmin, w.zmax, w.tmin);
}

std::string fit_results_csv(const std::vector<FitResult> &results) { return results_csv(results); }

}    // namespace granpen
