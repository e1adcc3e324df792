// granpen analysis: ensembles of trace files (see ensemble_tables.h).
#include "ensemble_tables.h"

#include "errors.h"
#include "json_text.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <tuple>

namespace granpen {

namespace {

double key6(double v)
{
  if (!(v != 0.0) || !std::isfinite(v)) return v;
  const double e = std::pow(10.0, std::floor(std::log10(std::fabs(v))) - 5);
  return std::round(v / e) * e;
}

std::string g3(double v) { return json_number("%g", v); }

// a trace's grains: d_g, rho_g and mu (cgs, 6 significant digits), "" for a key not given
std::string material_of(const Trace &t)
{
  std::string s;
  for (const char *k : {"d_g", "rho_g", "mu"}) {
    const double v = t.number(k, NAN);
    s += std::string(s.empty() ? "" : ", ") + k + " = " + (std::isnan(v) ? std::string("not given") : g3(key6(v)));
  }
  return s;
}

// An ensemble averages runs of one material: the fits take mu, rho_g and d_g from the
// group's first run, so runs of other grains in the group would be averaged in silently.
void refuse_mixed_materials(const TraceGroup &g)
{
  const std::string first = material_of(g.traces.front());
  for (const auto &t : g.traces) {
    const std::string other = material_of(t);
    if (other != first)
      throw InputError("--ensemble: " + g.traces.front().path + " (" + first + ") and " + t.path + " (" + other +
                       ") are runs of one case (" + g.label() +
                       ") but of different grains: an ensemble averages runs of one material; give each material's "
                       "runs in a command of its own");
  }
}

}    // namespace

std::string TraceGroup::label() const
{
  std::string s = "v0 = " + g3(v0) + " cm/s";
  if (v0_tolerance > 0.0 && v0_max > v0_min)
    s += " (runs at " + g3(v0_min) + ".." + g3(v0_max) + " cm/s, grouped within " + g3(100.0 * v0_tolerance) + "%)";
  return s + ", g = " + g3(g) + " cm/s^2, D = " + g3(D) + " cm";
}

std::vector<Trace> read_traces(const std::vector<std::string> &files, std::vector<std::string> &problems)
{
  std::vector<Trace> out;
  for (const auto &f : files) {
    try {
      out.push_back(to_cgs(read_trace(f)));
    } catch (InputError &e) {
      problems.push_back(e.what());
    }
  }
  return out;
}

std::vector<TraceGroup> group_traces(const std::vector<Trace> &traces, double v0_tolerance)
{
  std::map<std::tuple<double, double, double>, TraceGroup> m;    // (g, D, v0)
  for (const auto &t : traces) {
    TraceGroup &g = m[{key6(t.g), key6(t.D), key6(t.v0)}];
    if (g.traces.empty()) g.v0 = t.v0, g.g = t.g, g.D = t.D, g.v0_min = g.v0_max = t.v0;
    g.traces.push_back(t);
  }
  std::vector<TraceGroup> out;
  for (auto &kv : m) {
    TraceGroup &next = kv.second;
    // sorted by (g, D, v0): a group within the tolerance of the slowest run of the one
    // before (same g and D) joins it
    if (v0_tolerance > 0.0 && !out.empty()) {
      TraceGroup &prev = out.back();
      if (key6(prev.g) == key6(next.g) && key6(prev.D) == key6(next.D) &&
          next.v0_max <= prev.v0_min * (1.0 + v0_tolerance)) {
        for (auto &t : next.traces) prev.traces.push_back(std::move(t));
        prev.v0_max = next.v0_max;
        double sum = 0.0;
        for (const auto &t : prev.traces) sum += t.v0;
        prev.v0 = sum / (double) prev.traces.size();
        continue;
      }
    }
    next.v0_tolerance = v0_tolerance;
    out.push_back(std::move(next));
  }
  for (const auto &g : out) refuse_mixed_materials(g);
  return out;
}

std::vector<EnsembleRuns> ensemble_runs(const std::vector<TraceGroup> &groups)
{
  std::vector<EnsembleRuns> out;
  for (const auto &g : groups) {
    EnsembleRuns e;
    e.name = g.label();
    for (const auto &t : g.traces) e.z.push_back(t.z), e.F.push_back(t.F);
    out.push_back(std::move(e));
  }
  return out;
}

void keep_averaged(std::vector<TraceGroup> &groups, const EnsembleAveraging &a, const EnsembleParams &p,
                   std::vector<std::string> &problems)
{
  // a given bin too fine for the runs' depths: the option named
  if (a.bin_too_fine && a.too_fine < groups.size())
    throw InputError("--ensemble-bin " + json_number("%g", p.bin) + " cm makes " +
                     json_number("%.3g", (a.z_hi - a.z_lo) / p.bin) + " bins over z = " + json_number("%.4g", a.z_lo) +
                     ".." + json_number("%.4g", a.z_hi) + " cm of ensemble " + groups[a.too_fine].label() +
                     ", more than " + std::to_string(kMaxEnsembleBins) + ": give a wider bin");
  std::vector<TraceGroup> kept;
  for (std::size_t i = 0; i < groups.size() && i < a.ensembles.size(); ++i) {
    TraceGroup &g = groups[i];
    if (a.ensembles[i].ok) {
      g.mean = a.ensembles[i].mean;
      kept.push_back(std::move(g));
    } else {
      problems.push_back("ensemble " + g.label() + " (" + std::to_string(g.traces.size()) + " runs): " +
                         a.ensembles[i].why + "; left out");
    }
  }
  groups = std::move(kept);
}

std::string ensemble_summary(const TraceGroup &g)
{
  const EnsembleMean &m = g.mean;
  std::string s = "ensemble " + g.label() + ": " + std::to_string(m.runs) + (m.runs == 1 ? " run" : " runs") +
                  ", bins of " + json_number("%.3g", m.bin) + " cm over z = " + json_number("%.3g", m.z_first) +
                  ".." + json_number("%.3g", m.z_last) + " cm";
  if (m.runs > 1) s += ", aligned at the mean force onset z = " + json_number("%.3f", m.alignment.reference) +
                       " cm (origins moved by up to " + json_number("%.3f", m.alignment.max_shift) + " cm)";
  if (m.runs == 1) s += " (one run: no run-to-run band, no uncertainties)";
  for (const auto &n : m.notes) s += "\n  note: " + n;
  return s;
}

std::string ensemble_curves_csv(const std::vector<TraceGroup> &groups)
{
  std::string o = "v0,g,D,runs,z,F_mean,F_se,F_sd\n";
  const auto n = [](double v) { return json_number("%.10g", v); };
  for (const auto &g : groups)
    for (std::size_t k = 0; k < g.mean.z.size(); ++k)
      o += n(g.v0) + "," + n(g.g) + "," + n(g.D) + "," + std::to_string(g.mean.n[k]) + "," + n(g.mean.z[k]) + "," +
           n(g.mean.mean[k]) + "," + n(g.mean.se[k]) + "," + n(g.mean.sd[k]) + "\n";
  return o;
}

Json estimate_json(const Estimate &e)
{
  const auto n = [](double v) { return json_rounded("%.10g", v); };
  return {{"ok", e.ok}, {"value", n(e.value)}, {"se_ok", e.se_ok}, {"se", n(e.se)}, {"ci95", n(e.ci95)},
          {"defined", e.defined}};
}

Json ensemble_json(const TraceGroup &g)
{
  const auto n = [](double v) { return json_rounded("%.10g", v); };
  const EnsembleMean &m = g.mean;
  Json j;
  j["v0"] = n(g.v0), j["g"] = n(g.g), j["D"] = n(g.D), j["runs"] = m.runs;
  if (g.v0_tolerance > 0.0) j["v0_min"] = n(g.v0_min), j["v0_max"] = n(g.v0_max), j["v0_tolerance"] = n(g.v0_tolerance);
  j["files"] = Json::array();
  for (std::size_t i = 0; i < g.traces.size(); ++i)
    j["files"].push_back({{"file", g.traces[i].path}, {"onset", i < m.alignment.onset.size() && std::isfinite(m.alignment.onset[i]) ? n(m.alignment.onset[i]) : Json()},
                          {"shift", n(i < m.alignment.shift.size() ? m.alignment.shift[i] : 0.0)}});
  j["reference_onset"] = n(m.alignment.reference);
  j["max_shift"] = n(m.alignment.max_shift);
  j["bin"] = n(m.bin), j["z_first"] = n(m.z_first), j["z_last"] = n(m.z_last), j["bins"] = m.z.size();
  j["notes"] = m.notes;
  return j;
}

Json ensemble_fit_json(const TraceGroup &g, const EnsembleFit &f)
{
  const auto n = [](double v) { return json_rounded("%.10g", v); };
  Json j = ensemble_json(g);
  j["resamples"] = f.resamples;
  j["zlo"] = n(f.fit.zlo), j["zhi"] = n(f.fit.zhi), j["window_shortened"] = f.fit.window_shortened;
  j["n_window"] = f.fit.n_window;
  for (const auto &[name, e] : {std::make_pair("k_z", &f.k_z), std::make_pair("intercept", &f.intercept),
                                std::make_pair("alpha", &f.alpha), std::make_pair("k_z0", &f.k_z0),
                                std::make_pair("alpha0", &f.alpha0), std::make_pair("peak_F", &f.peak_F),
                                std::make_pair("peak_z", &f.peak_z), std::make_pair("wavelength", &f.wavelength)})
    j[name] = estimate_json(*e);
  for (const auto &note : f.fit.notes) j["notes"].push_back(note);
  return j;
}

Json ensemble_collapse_json(const std::vector<TraceGroup> &groups, const EnsembleCollapse &c)
{
  const auto n = [](double v) { return json_rounded("%.10g", v); };
  Json j;
  j["resamples"] = c.resamples, j["usable_resamples"] = c.usable;
  j["ensembles"] = Json::array();
  for (std::size_t i = 0; i < groups.size() && i < c.result.curves.size(); ++i) {
    Json e = ensemble_json(groups[i]);
    e["k_z"] = estimate_json(c.k_z[i]);
    e["peak"] = estimate_json(c.peak[i]);
    e["peak_z"] = n(c.result.curves[i].peak_z);
    e["crossed"] = c.result.curves[i].crossed;
    e["t_star"] = estimate_json(c.t_star[i]);
    j["ensembles"].push_back(e);
  }
  j["t_star_mean"] = estimate_json(c.t_star_mean);
  j["n_crossed"] = c.result.n_crossed;
  j["t_star_ensemble"] = estimate_json(c.t_star_ensemble);
  j["spread_z"] = estimate_json(c.spread_z);
  j["spread_t"] = estimate_json(c.spread_t);
  j["peak_exponent"] = estimate_json(c.peak_exponent);
  j["peak_prefactor"] = n(c.result.peak_law.prefactor);
  return j;
}

std::string ensemble_collapse_csv_rows(const std::vector<TraceGroup> &groups, const EnsembleCollapse &c)
{
  std::string o;
  for (std::size_t i = 0; i < groups.size() && i < c.result.curves.size(); ++i) {
    const auto &g = groups[i];
    const auto &cv = c.result.curves[i];
    const std::string name = "ensemble v0=" + g3(g.v0) + " g=" + g3(g.g) + " D=" + g3(g.D) +
                             " runs=" + std::to_string(g.mean.runs);
    for (std::size_t k = 0; k < cv.t.size(); ++k)
      o += name + "," + json_number("%.10g", g.v0) + "," + json_number("%.10g", g.g) + "," + json_number("%.10g", g.D) +
           "," + json_number("%.6g", cv.t[k]) + "," + json_number("%.6g", cv.ratio[k]) + "\n";
  }
  return o;
}

}    // namespace granpen
