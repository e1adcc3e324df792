// granpen analysis: a calibration sweep folder read and written (see calibration_sweep.h).
#include "calibration_sweep.h"

#include "bed_info.h"
#include "json_text.h"
#include "json_writer.h"
#include "plot_writer.h"
#include "scaling_laws.h"
#include "trace_reader.h"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cmath>
#include <filesystem>
#include <map>
#include <utility>

namespace granpen {

namespace {

namespace fs = std::filesystem;

// s as a whole finite number (strtod; trailing text, overflow or underflow: false)
bool number_arg(const std::string &s, double &v)
{
  char *end = nullptr;
  errno = 0;
  v = std::strtod(s.c_str(), &end);
  return !s.empty() && end && *end == '\0' && errno != ERANGE && std::isfinite(v);
}

std::string num(double v) { return json_number("%.10g", v); }


std::string csv_field(const std::string &s)
{
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string o = "\"";
  for (char c : s) o += (c == '"') ? std::string("\"\"") : std::string(1, c);
  return o + "\"";
}

// markdown cell text: no pipes or line breaks
std::string md_cell(std::string s)
{
  for (char &c : s)
    if (c == '|' || c == '\n' || c == '\r') c = ' ';
  return s;
}

std::vector<std::string> files_with(const fs::path &dir, const std::string &ext, std::string &err)
{
  std::vector<std::string> out;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    err = dir.string() + ": no such folder";
    return out;
  }
  for (const auto &e : fs::directory_iterator(dir, ec))
    if (e.path().extension() == ext && e.is_regular_file(ec)) out.push_back(e.path().string());
  if (ec) err = dir.string() + ": cannot list folder: " + ec.message();
  std::sort(out.begin(), out.end());
  return out;
}

std::string pm(const Stat &s, const char *mf, const char *sf)
{
  if (!s.n) return "-";
  return json_number(mf, s.mean) + " +- " + json_number(sf, s.sd);
}

std::string markdown(const std::vector<CalibrationRow> &rows, double zmin, double zmax)
{
  std::string o = "| mu | n beds | phi_0 (mean +- sd) | n pushes | v0 (cm/s) | k_z (dyne/cm, mean +- sd) | "
                  "alpha (mean +- sd) |\n|---:|---:|---|---:|---:|---|---|\n";
  for (const auto &r : rows)
    o += "| " + json_number("%g", r.mu) + " | " + std::to_string(r.phi_0.n) + " | " + pm(r.phi_0, "%.4f", "%.4f") +
         " | " + std::to_string(r.k_z.n) + " | " + (r.pushes.empty() ? std::string("-") : json_number("%g", r.v0)) +
         " | " + pm(r.k_z, "%.4g", "%.2g") + " | " + pm(r.alpha, "%.3g", "%.2g") + " |\n";
  o += "\nk_z: slope of F on z over z = " + json_number("%g", zmin) + ".." + json_number("%g", zmax) +
       " cm; alpha = k_z / (mu rho_g g D^2); sd over beds/pushes (n - 1).\n";
  return o;
}

std::string csv_table(const std::vector<CalibrationRow> &rows)
{
  std::string o = "mu,n_beds,phi_0_mean,phi_0_sd,n_pushes,v0,k_z_mean,k_z_sd,alpha_mean,alpha_sd\n";
  for (const auto &r : rows)
    o += num(r.mu) + "," + std::to_string(r.phi_0.n) + "," + num(r.phi_0.mean) + "," + num(r.phi_0.sd) + "," +
         std::to_string(r.k_z.n) + "," + num(r.v0) + "," + num(r.k_z.mean) + "," + num(r.k_z.sd) + "," +
         num(r.alpha.mean) + "," + num(r.alpha.sd) + "\n";
  return o;
}

Json json_table(const std::vector<CalibrationRow> &rows, const std::string &sweep, double zmin,
                         double zmax, const std::vector<std::string> &problems)
{
  const auto n = [](double v) { return json_rounded("%.10g", v); };
  const auto stat = [&](const Stat &s) { return Json{{"n", s.n}, {"mean", n(s.mean)}, {"sd", n(s.sd)}}; };
  Json j;
  j["tool"] = "granpen calibration";
  j["sweep"] = sweep;
  j["units"] = {{"k_z", "dyne/cm"}, {"v0", "cm/s"}, {"z", "cm"}};
  j["window"] = {{"zmin", n(zmin)}, {"zmax", n(zmax)}};
  j["sd"] = "sample standard deviation (n - 1), 0 for one value";
  j["rows"] = Json::array();
  for (const auto &r : rows) {
    Json row = {{"mu", n(r.mu)}, {"v0", n(r.v0)}, {"phi_0", stat(r.phi_0)}, {"k_z", stat(r.k_z)},
                         {"alpha", stat(r.alpha)}, {"beds", Json::array()}, {"pushes", Json::array()}};
    for (const auto &b : r.beds) row["beds"].push_back({{"name", b.name}, {"seed", n(b.seed)}, {"phi_0", n(b.phi_0)}});
    for (const auto &p : r.pushes)
      row["pushes"].push_back({{"trace", p.name}, {"bed", p.bed}, {"seed", n(p.seed)}, {"k_z", n(p.k_z)}, {"alpha", n(p.alpha)}});
    j["rows"].push_back(row);
  }
  j["problems"] = problems;
  return j;
}

}    // namespace

CalibrationSweep read_calibration_sweep(const std::string &sweep)
{
  CalibrationSweep sw;
  // beds
  std::string err;
  sw.info_files = files_with(fs::path(sweep) / "beds", ".info", err);
  if (!err.empty()) sw.problems.push_back(err);
  std::map<std::string, CalibrationBed> bed_by_name;
  for (const auto &f : sw.info_files) {
    try {
      const BedInfo info = read_bed_info(f);
      CalibrationBed b;
      b.name = info.name;
      b.mu = info.mu;
      b.seed = info.seed;
      b.phi_0 = info.phi_0;
      sw.beds.push_back(b);
      bed_by_name[b.name] = b;
    } catch (InputError &e) {
      sw.problems.push_back(e.what());
    }
  }

  // pushes
  err.clear();
  sw.trace_files = files_with(fs::path(sweep) / "traces", ".csv", err);
  if (!err.empty()) sw.problems.push_back(err);
  for (const auto &f : sw.trace_files) {
    try {
      const Trace tr = to_cgs(read_trace(f));
      CalibrationPush p;
      p.name = fs::path(f).filename().string();
      p.v0 = tr.v0;
      const CalibrationBed *bed = nullptr;
      auto bk = tr.keys.find("bed");
      if (bk != tr.keys.end()) {
        p.bed = bed_name(bk->second);
        auto it = bed_by_name.find(p.bed);
        if (it != bed_by_name.end()) bed = &it->second;
        else sw.notes.push_back(f + ": bed '" + p.bed + "' has no beds/" + p.bed + ".info");
      } else {
        sw.notes.push_back(f + ": no 'bed' header key");
      }
      auto key = [&](const char *k, double &v) {
        auto it = tr.keys.find(k);
        if (it == tr.keys.end()) return false;
        if (it->second.find('\0') != std::string::npos || !number_arg(it->second, v))    // nor with a NUL byte in it
          throw InputError(f + ": header key " + k + " = '" + it->second + "' is not a number");
        return true;
      };
      if (!key("mu", p.mu)) {
        if (!bed) throw InputError(f + ": no header key mu and no known bed to take it from");
        p.mu = bed->mu;
      }
      if (!key("seed", p.seed) && bed) p.seed = bed->seed;
      if (bed && std::fabs(bed->mu - p.mu) > 1e-9 * std::fabs(p.mu))
        sw.notes.push_back(f + ": pushed at mu = " + json_number("%g", p.mu) + " into bed '" + p.bed + "' poured at mu = " +
                        json_number("%g", bed->mu) + " (grouped by the push's mu)");
      double rho_g = DEFAULT_RHO_G;
      if (!key("rho_g", rho_g))
        sw.notes.push_back(f + ": no rho_g header key; alpha uses rho_g = " + json_number("%g", rho_g) + " g/cm^3");

      CalibrationTrace t;
      t.push = p;
      t.z = tr.z, t.F = tr.F, t.D = tr.D, t.g = tr.g, t.rho_g = rho_g;
      t.d_g = 0.4;
      key("d_g", t.d_g);
      sw.pushes.push_back(std::move(t));
      sw.push_files.push_back(f);
      sw.problems_at.push_back(sw.problems.size()), sw.notes_at.push_back(sw.notes.size());
    } catch (std::exception &e) {
      sw.problems.push_back(e.what());
    }
  }

  return sw;
}

void calibration_messages(const CalibrationSweep &sw, const CalibrationStudy &st, std::vector<std::string> &problems,
                          std::vector<std::string> &notes)
{
  problems = sw.problems, notes = sw.notes;
  // from the last push back, so that the earlier positions stay valid
  for (std::size_t i = std::min(sw.pushes.size(), st.fits.size()); i-- > 0;) {
    const CalibrationFitOutcome &o = st.fits[i];
    const std::string &f = sw.push_files[i];
    if (!o.ok) problems.insert(problems.begin() + sw.problems_at[i], o.refused ? o.why : f + ": " + o.why);
    else if (!o.alpha_ok) notes.insert(notes.begin() + sw.notes_at[i], f + ": alpha undefined, counted as 0");
  }
}

std::string calibration_markdown(const std::vector<CalibrationRow> &rows, double zmin, double zmax)
{
  return markdown(rows, zmin, zmax);
}

std::vector<std::pair<std::string, std::string>> calibration_files(const std::vector<CalibrationRow> &rows,
                                                                   const std::string &sweep, double zmin, double zmax,
                                                                   const std::vector<std::string> &problems,
                                                                   const std::string &out_dir)
{
  const fs::path od(out_dir);
  const std::string title = "# Friction calibration: " + md_cell(sweep) + "\n\n";
  return {{(od / "calibration.csv").string(), csv_table(rows)},
          {(od / "calibration.json").string(), json_layout(json_table(rows, sweep, zmin, zmax, problems), 1)},
          {(od / "calibration.md").string(), title + markdown(rows, zmin, zmax)}};
}

namespace {

// the mu axis: the rows' range padded by a tenth (or 0.05 about a single mu)
void mu_axis(const std::vector<CalibrationRow> &rows, SeriesPanel &p)
{
  if (rows.empty()) return;
  double lo = rows.front().mu, hi = lo;
  for (const auto &r : rows) lo = std::min(lo, r.mu), hi = std::max(hi, r.mu);
  const double pad = hi > lo ? 0.1 * (hi - lo) : std::max(0.05, 0.1 * std::fabs(lo));
  p.xmin = lo - pad, p.xmax = hi + pad;
  p.xlabel = "grain friction coefficient μ";
  p.extra = "set offsets 0, 0, graph 0.05, graph 0.05\n";
}

PlotSeries points(const std::string &title, const std::string &colour, int type, double size)
{
  PlotSeries s;
  s.style = "points", s.title = title, s.colour = colour, s.point_type = type, s.point_size = size;
  return s;
}

}    // namespace

std::vector<PlotFiles> calibration_figures(const std::vector<CalibrationRow> &rows)
{
  // phi_0: each bed, and the mean +- sd of each mu (every row of a mu holds its beds)
  SeriesPanel a;
  mu_axis(rows, a);
  a.ylabel = "packing fraction φ_0";
  PlotSeries mean = points("mean ± sd over seeds", "#1f77b4", 7, 1.5), beds = points("each seed's bed", "#555555", 6, 1.2);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const CalibrationRow &r = rows[i];
    if (i > 0 && r.mu == rows[i - 1].mu) continue;
    for (const auto &b : r.beds) beds.x.push_back(b.mu), beds.y.push_back(b.phi_0);
    if (r.phi_0.n) mean.x.push_back(r.mu), mean.y.push_back(r.phi_0.mean), mean.y_err.push_back(r.phi_0.sd);
  }
  a.series = {mean, beds};
  SeriesFigure phi;
  phi.name = "calibration_phi0", phi.title = "Bed packing fraction against friction", phi.width = 1000, phi.height = 600;
  phi.about = "granpen calibration: the packing fraction phi_0 of each poured bed against the grain friction mu,\n"
              "and the mean +- sample sd over the beds of each mu.";
  phi.panels = {a};

  // k_z: per v0 the mean +- sd of each mu, and each push
  SeriesPanel b;
  mu_axis(rows, b);
  b.ylabel = "k_z (dyne/cm)";
  std::vector<double> v0s;
  for (const auto &r : rows)
    if (!r.pushes.empty() && std::find(v0s.begin(), v0s.end(), r.v0) == v0s.end()) v0s.push_back(r.v0);
  for (std::size_t i = 0; i < v0s.size(); ++i) {
    const std::string colour = plot_colour((int) i);
    PlotSeries m = points("v_0 = " + json_number("%g", v0s[i]) + " cm/s: mean ± sd over seeds", colour, 7, 1.5);
    PlotSeries each = points("each seed's push", colour, 6, 1.2);
    for (const auto &r : rows) {
      if (r.pushes.empty() || r.v0 != v0s[i]) continue;
      m.x.push_back(r.mu), m.y.push_back(r.k_z.mean), m.y_err.push_back(r.k_z.sd);
      for (const auto &p : r.pushes) each.x.push_back(p.mu), each.y.push_back(p.k_z);
    }
    b.series.push_back(m), b.series.push_back(each);
  }
  SeriesFigure kz;
  kz.name = "calibration_kz", kz.title = "Depth term k_z against friction", kz.width = 1000, kz.height = 600;
  kz.about = "granpen calibration: the depth term k_z of each push against the grain friction mu, per v0,\n"
             "and the mean +- sample sd over the pushes of each mu.";
  kz.panels = {b};
  return {series_figure(phi), series_figure(kz)};
}

}    // namespace granpen
