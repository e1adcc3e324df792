// granpen analysis: granpen collapse's files (see collapse_tables.h).
#include "collapse_tables.h"

#include "json_text.h"
#include "scaling_laws.h"
#include "trace_reader.h"

#include <utility>

namespace granpen {

double alpha_depth_term(const DepthTerm &dt, const Trace &tr)
{
  const double mu = dt.mu > 0 ? dt.mu : tr.number("mu", DEFAULT_MU);
  const double rho = dt.rho_g > 0 ? dt.rho_g : tr.number("rho_g", DEFAULT_RHO_G);
  return k_z_from_alpha(dt.alpha, mu, rho, tr.g, tr.D);
}

std::vector<CollapseTrace> collapse_traces(const std::vector<Trace> &traces, const DepthTerm &dt)
{
  std::vector<CollapseTrace> out;
  for (const auto &tr : traces) {
    CollapseTrace c;
    c.name = tr.path, c.z = tr.z, c.F = tr.F, c.v0 = tr.v0, c.D = tr.D, c.g = tr.g;
    if (dt.alpha > 0.0) c.k_z_given = true, c.k_z_fixed = alpha_depth_term(dt, tr);
    out.push_back(std::move(c));
  }
  return out;
}

std::vector<CollapseEnsemble> collapse_ensemble_inputs(const std::vector<TraceGroup> &groups, const DepthTerm &dt)
{
  std::vector<CollapseEnsemble> out;
  for (const auto &g : groups) {
    CollapseEnsemble c;
    c.name = g.label(), c.v0 = g.v0, c.D = g.D, c.g = g.g, c.mean = g.mean;
    if (dt.alpha > 0.0) c.k_z_given = true, c.k_z_fixed = alpha_depth_term(dt, g.traces.front());
    out.push_back(std::move(c));
  }
  return out;
}

CollapseStudyParams collapse_study_params(const CollapseParams &p, const DepthTerm &dt, const BootstrapParams &b)
{
  CollapseStudyParams s;
  s.collapse = p, s.kz_zmin = dt.kz_zmin, s.kz_zmax = dt.kz_zmax, s.boot = b;
  return s;
}

std::string collapse_curves_csv(const CollapseResult &r)
{
  std::string o = "trace,v0,g,D,t_tilde,F_over_Fz\n";
  for (const auto &c : r.curves)
    for (std::size_t k = 0; k < c.t.size(); ++k)
      o += c.name + "," + json_number("%.10g", c.v0) + "," + json_number("%.10g", c.g) + "," +
           json_number("%.10g", c.D) + "," + json_number("%.6g", c.t[k]) + "," + json_number("%.6g", c.ratio[k]) + "\n";
  return o;
}

Json collapse_json(const CollapseResult &r, const CollapseParams &p)
{
  Json j;
  j["tool"] = "granpen collapse";
  j["band"] = json_rounded("%g", p.band);
  j["t_star_mean"] = json_rounded("%.6g", r.t_star_mean);
  j["t_star_sd"] = json_rounded("%.6g", r.t_star_sd);
  j["n_crossed"] = r.n_crossed;
  j["spread_z"] = json_rounded("%.6g", r.spread_z);
  j["spread_t"] = json_rounded("%.6g", r.spread_t);
  j["ensemble_crossed"] = r.ens_crossed;
  j["t_star_ensemble"] = json_rounded("%.6g", r.t_star_ensemble);
  j["peak_exponent"] = json_rounded("%.6g", r.peak_law.exponent);
  j["peak_exponent_ci95"] = json_rounded("%.6g", r.peak_law.exponent_ci95);
  if (r.peak_law.two_term_ok) {
    Json t{{"linear", json_rounded("%.6g", r.peak_law.linear)}, {"linear_se", json_rounded("%.6g", r.peak_law.linear_se)},
           {"quadratic", json_rounded("%.6g", r.peak_law.quadratic)},
           {"quadratic_se", json_rounded("%.6g", r.peak_law.quadratic_se)}};
    if (r.peak_law.crossover_ok) {
      t["crossover_speed"] = json_rounded("%.6g", r.peak_law.crossover_speed);
      t["crossover_speed_se"] = json_rounded("%.6g", r.peak_law.crossover_speed_se);
    }
    j["peak_two_term"] = t;
  }
  j["traces"] = Json::array();
  for (const auto &c : r.curves)
    j["traces"].push_back({{"file", c.name}, {"v0", json_rounded("%.10g", c.v0)}, {"k_z", json_rounded("%.6g", c.k_z)},
                           {"peak", json_rounded("%.6g", c.peak)}, {"crossed", c.crossed},
                           {"t_star", json_rounded("%.4g", c.t_star)}});
  return j;
}

}    // namespace granpen
