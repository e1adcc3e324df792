// granpen analysis: the figures of granpen plot flow DIR and granpen plot momentum DIR,
// from the tables written by granpen flow --out DIR and granpen momentum (figures.h). The fits drawn are the
// library's, as the tables' writers use them: the flow table study's (core/flow_table_study.h,
// run by the CLI on the tables read here) and core/momentum_classes.h compare_drag (also the
// CLI's: the drag figure draws the comparison it is given).
#include "figures.h"

#include "csv_table.h"
#include "flow_fields.h"
#include "json_path.h"
#include "json_text.h"
#include "momentum_classes.h"
#include "paper_values.h"
#include "errors.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace granpen {
namespace figures {

namespace {

namespace fs = std::filesystem;

// the table DIR/NAME, or false (with a note) when the file does not exist
bool open_table(const std::string &dir, const std::string &name, const std::vector<std::string> &required, Run &run,
                CsvTable &t)
{
  const fs::path p = fs::path(dir) / name;
  std::error_code ec;
  if (!fs::exists(p, ec)) {
    run.notes.push_back(p.string() + " not found: its figure skipped");
    return false;
  }
  try {
    t = read_csv_table(p.string(), required);
    if (t.rows.empty()) {
      run.problems.push_back(p.string() + ": no rows");
      return false;
    }
    return true;
  } catch (InputError &e) {
    run.problems.push_back(e.what());
    return false;
  }
}

// open_table, then `columns` takes its columns out of t; false (the error a problem of the
// run) when a column does not read
bool read_table(const std::string &dir, const std::string &name, const std::vector<std::string> &required, Run &run,
                CsvTable &t, const std::function<void()> &columns)
{
  if (!open_table(dir, name, required, run, t)) return false;
  try {
    columns();
    return true;
  } catch (InputError &e) {
    run.problems.push_back(e.what());
    return false;
  }
}

double quantile(std::vector<double> v, double q)
{
  v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); }), v.end());
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  const double pos = q * (v.size() - 1);
  const std::size_t k = static_cast<std::size_t>(pos);
  return k + 1 < v.size() ? v[k] + (pos - k) * (v[k + 1] - v[k]) : v.back();
}

// sorted distinct values (within a tolerance of the spread)
std::vector<double> distinct(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  const double tol = v.empty() ? 0.0 : 1e-9 * std::max(1.0, v.back() - v.front());
  std::vector<double> out;
  for (double x : v)
    if (out.empty() || x - out.back() > tol) out.push_back(x);
  return out;
}

int find_index(const std::vector<double> &grid, double x)
{
  auto it = std::lower_bound(grid.begin(), grid.end(), x - 1e-9 * std::max(1.0, std::fabs(x)));
  return it == grid.end() ? (int) grid.size() - 1 : (int) (it - grid.begin());
}

// a number of DIR/flow.json's "parameters" (granpen flow writes D, the annulus radii, ...),
// NaN when the file, the key or the number is absent; index picks an element of an array
double flow_parameter(const std::string &dir, const std::string &key, int index = -1)
{
  const fs::path file = fs::path(dir) / "flow.json";
  if (!fs::is_regular_file(file)) return NAN;
  try {
    const Json doc = read_json_file(file.string());
    const auto p = doc.find("parameters");
    if (p == doc.end() || !p->is_object()) return NAN;
    const auto k = p->find(key);
    if (k == p->end()) return NAN;
    const Json *v = &*k;
    if (index >= 0) {
      if (!v->is_array() || (std::size_t) index >= v->size()) return NAN;
      v = &(*v)[(std::size_t) index];
    }
    return v->is_number() ? v->get<double>() : NAN;
  } catch (const InputError &) {
    return NAN;    // not JSON: as absent (the figure then says where D came from)
  }
}

// the rod diameter: --D, else granpen flow's flow.json, else a `# D = ` header key,
// else 2 cm (with a note)
double rod_diameter(const std::string &dir, const CsvTable &t, Run &run)
{
  if (run.opt.D > 0) return run.opt.D;
  const double j = flow_parameter(dir, "D");
  if (j > 0) return j;
  const double h = t.key_number("D", 0.0);
  if (h > 0) return h;
  run.notes.push_back(t.path + ": rod diameter neither in " + dir + "/flow.json nor in a header: D = 2 cm assumed (--D)");
  return 2.0;
}

// the t~ column, or z_tip when t~ is undefined throughout (granpen flow without v0 or g)
bool time_axis(const CsvTable &t, std::vector<double> &x, std::string &label, Run &run)
{
  x = t.numbers("t_tilde");
  if (std::any_of(x.begin(), x.end(), [](double v) { return std::isfinite(v); })) {
    label = "t̃ = (z / v_0) √(g / D)";
    return true;
  }
  if (!t.has("z_tip")) return false;
  x = t.numbers("z_tip");
  label = "rod tip depth z_{tip} (cm)";
  run.notes.push_back(t.path + ": t_tilde undefined (nan): drawn against z_tip");
  return false;
}

const char *VIRIDIS = "set palette defined (0 \"#440154\", 0.25 \"#3b528b\", 0.5 \"#21918c\", 0.75 \"#5ec962\", 1 \"#fde725\")\n";
const char *DIVERGING = "set palette defined (-1 \"#2166ac\", -0.5 \"#92c5de\", 0 \"#f7f7f7\", 0.5 \"#f4a582\", 1 \"#b2182b\")\n";
const char *MAGMA = "set palette defined (0 \"#000004\", 0.25 \"#51127c\", 0.5 \"#b73779\", 0.75 \"#fc8961\", 1 \"#fcfdbf\")\n";

// ---------------------------------------------------------------- heatmaps

void flow_heatmaps(const std::string &dir, Run &run)
{
  CsvTable t;
  std::vector<double> r, z, count, phi, vz, gd, I;
  const auto columns = [&] {
    r = t.numbers("r", false), z = t.numbers("z", false), count = t.numbers("count");
    phi = t.numbers("phi"), vz = t.numbers("vz"), gd = t.numbers("gammadot"), I = t.numbers("I");
  };
  if (!read_table(dir, "flow_fields.csv", {"r", "z", "count", "phi", "vz", "gammadot", "I"}, run, t, columns)) return;
  const double D = rod_diameter(dir, t, run), R = 0.5 * D;
  const auto rs = distinct(r), zs = distinct(z);
  const std::size_t nr = rs.size(), nz = zs.size();
  if (nr < 2 || nz < 2) {
    run.problems.push_back(t.path + ": the (r, z) grid needs at least 2 values of each (has " + std::to_string(nr) + " x " +
                           std::to_string(nz) + ")");
    return;
  }
  const double dr = (rs.back() - rs.front()) / (nr - 1), dz = (zs.back() - zs.front()) / (nz - 1);
  // grid [iz][ir] -> row, empty bins NaN
  std::vector<int> at(nr * nz, -1);
  for (std::size_t i = 0; i < r.size(); ++i) at[find_index(zs, z[i]) * nr + find_index(rs, r[i])] = (int) i;
  PlotBlock blk;
  blk.title = "flow fields on the (r, z) grid, z from the rod tip; empty bins (count 0) NaN; scans of r separated by blank lines";
  blk.columns = {"r", "z", "phi", "vz", "gammadot", "I", "count"};
  std::vector<double> fphi, fvz, fgd, fI;
  for (std::size_t iz = 0; iz < nz; ++iz) {
    if (iz) blk.rows.push_back({});
    for (std::size_t ir = 0; ir < nr; ++ir) {
      const int i = at[iz * nr + ir];
      const bool full = i >= 0 && count[i] > 0;
      auto val = [&](const std::vector<double> &v) { return full ? v[i] : NAN; };
      blk.rows.push_back({rs[ir], zs[iz], val(phi), val(vz), val(gd), val(I), i >= 0 ? count[i] : 0.0});
      if (full) fphi.push_back(phi[i]), fvz.push_back(std::fabs(vz[i])), fgd.push_back(gd[i]), fI.push_back(I[i]);
    }
  }
  if (fphi.empty()) {
    run.problems.push_back(t.path + ": every bin is empty (count 0)");
    return;
  }
  const double x0 = rs.front() - 0.5 * dr, x1 = rs.back() + 0.5 * dr;
  const double y0 = zs.front() - 0.5 * dz, y1 = zs.back() + 0.5 * dz;
  PlotFiles f;
  f.name = "flow_heatmaps";
  f.about = "granpen plot flow: heatmaps of " + t.path + " in (r, z - z_tip), the rod (r < R = " + fmt("%g", R) +
            " cm, z > 0) in grey;\ncolour ranges: phi from the 2nd to the 99th percentile of the filled bins, v_z symmetric "
            "about 0,\ngamma-dot and I on log scales over three decades below their 99th percentile.";
  f.add_block(blk);
  std::ostringstream b;
  // four in a row for a tall domain, else two by two
  const bool row = (y1 - y0) > (x1 - x0);
  f.width = row ? 1700 : 1200, f.height = row ? 600 : 1000;
  b << "set multiplot layout " << (row ? "1,4" : "2,2") << " title " << gp_quote("Flow around the rod (" + fmt("%g", nr) + " x " + fmt("%g", nz) + " bins)")
    << " font \",14\"\n";
  struct Field {
    const char *title, *cblabel;    // units in the title: a colour-bar label would crowd the next panel
    int col;
    std::string palette, range;
    bool log;
  };
  const double plo = quantile(fphi, 0.02), phi_hi = quantile(fphi, 0.99);
  const double vmax = std::max(1e-12, quantile(fvz, 0.99));
  auto positive = [](std::vector<double> v) {
    v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !(x > 0); }), v.end());
    return v;
  };
  const auto gpos = positive(fgd), ipos = positive(fI);
  const double gtop = quantile(gpos, 0.99), itop = quantile(ipos, 0.99);
  std::vector<Field> fields = {
      {"(a) packing fraction φ", "", 3, VIRIDIS, "[" + gp_number(plo) + ":" + gp_number(phi_hi > plo ? phi_hi : plo + 0.01) + "]", false},
      {"(b) vertical velocity v_z (cm/s; > 0 up)", "", 4, DIVERGING, "[" + gp_number(-vmax) + ":" + gp_number(vmax) + "]", false},
      {"(c) shear rate γ̇ (1/s)", "", 5, MAGMA, gpos.empty() ? "[*:*]" : "[" + gp_number(gtop / 1e3) + ":" + gp_number(gtop) + "]", !gpos.empty()},
      {"(d) inertial number I", "", 6, MAGMA, ipos.empty() ? "[*:*]" : "[" + gp_number(itop / 1e3) + ":" + gp_number(itop) + "]", !ipos.empty()},
  };
  for (const auto &fd : fields) {
    b << "\n# ---- " << fd.title << "\n"
      << "unset logscale cb\nunset object\nunset label\n"
      << "set title " << gp_quote(fd.title) << "\n"
      << "set xlabel \"r (cm)\"\nset ylabel \"z − z_{tip} (cm)\"\nunset cblabel\n"
      << "set size ratio -1\nset xrange [" << gp_number(x0) << ":" << gp_number(x1) << "]\nset yrange ["
      << gp_number(y0) << ":" << gp_number(y1) << "]\nset tics out\nset key off\n"
      << fd.palette << "set cbrange " << fd.range << "\n" << (fd.log ? "set logscale cb\nset format cb \"10^{%T}\"\n" : "set format cb \"%g\"\n");
    if (y1 > 0)
      b << "set object 1 rectangle from first 0, first 0 to first " << gp_number(std::min(R, x1)) << ", first " << gp_number(y1)
        << " front fillcolor rgb \"#707070\" fillstyle solid 1.0 border lc rgb \"black\"\n"
        << "set label 1 \"rod\" at first " << gp_number(0.5 * std::min(R, x1)) << ", first " << gp_number(0.5 * y1)
        << " center front textcolor rgb \"white\"\n";
    else
      b << "set label 1 \"rod tip above (z = 0)\" at graph 0.02, graph 0.96 left front\n";
    b << "plot data index 0 using 1:2:" << fd.col << " with image notitle\n";
  }
  b << "unset multiplot\n";
  f.body = b.str();
  run.make(f);
  run.numbers["fields"] = {{"bins_r", nr}, {"bins_z", nz}, {"D", num("%g", D)},
                           {"phi_range", {num("%.4g", plo), num("%.4g", phi_hi)}}, {"vz_abs_p99", num("%.4g", vmax)}};
}

// ---------------------------------------------------------------- profile below the face

// what reading a table noted or found wrong, told now (as it was read, in the figures' order)
void tell(const FlowFitTable &t, Run &run)
{
  run.notes.insert(run.notes.end(), t.notes.begin(), t.notes.end());
  run.problems.insert(run.problems.end(), t.problems.begin(), t.problems.end());
}

// the paper's lambda_vz / D as "0.98 ± 0.15", the unit after each number
std::string paper_lambda_text(const std::string &unit)
{
  return fmt("%.2f", paper::lambda_vz_over_D) + unit + " ± " + fmt("%.2f", paper::lambda_vz_over_D_error);
}

// "φ = a − b I" with FORMAT for the two numbers
std::string phi_of_I_text(double a, double b, const char *format)
{
  return "φ = " + fmt(format, a) + (b < 0 ? " − " : " + ") + fmt(format, std::fabs(b)) + " I";
}

// panel (c) of the profile figure and its JSON: the local decay length lambda / D of each
// window of the profile (flow table study, stage 2), against the window's middle, beside the
// single fit's and the paper's band (paper_values.h)
SeriesPanel local_panel(const std::vector<LocalExpFit> &local, const ExpFit &fit, double D, double width, Json &out)
{
  SeriesPanel c;
  c.title = "(c) local decay length, windows of " + fmt("%.2g", width) + " cm";
  c.xlabel = "z − z_{tip} (cm; the window's middle)";
  c.ylabel = "λ / D";
  c.key = "top left Left reverse";
  PlotHBand papers;
  papers.lo = paper::lambda_vz_over_D - paper::lambda_vz_over_D_error;
  papers.hi = paper::lambda_vz_over_D + paper::lambda_vz_over_D_error;
  papers.title = "paper: " + paper_lambda_text("");
  c.hbands.push_back(papers);
  PlotSeries pts;
  pts.style = "points", pts.title = "λ / D of each window ± standard error", pts.colour = plot_colour(0);
  Json windows = Json::array();
  double lo = INFINITY, hi = -INFINITY, at_hi = NAN;
  int not_fitted = 0;
  for (const LocalExpFit &w : local) {
    Json j = {{"z_lo", num("%.6g", w.z_lo)}, {"z_hi", num("%.6g", w.z_hi)}, {"ok", w.fit.ok}};
    if (w.fit.ok) {
      const double r = w.fit.lambda / D;
      j["lambda"] = num("%.6g", w.fit.lambda), j["lambda_se"] = num("%.6g", w.fit.lambda_se);
      j["lambda_over_D"] = num("%.6g", r), j["n"] = w.fit.n;
      pts.x.push_back(0.5 * (w.z_lo + w.z_hi)), pts.y.push_back(r), pts.y_err.push_back(w.fit.lambda_se / D);
      lo = std::min(lo, r);
      if (r > hi) hi = r, at_hi = 0.5 * (w.z_lo + w.z_hi);
    } else {
      j["note"] = w.fit.note;
      ++not_fitted;
    }
    windows.push_back(j);
  }
  c.series.push_back(pts);
  if (fit.ok) {
    PlotGuide all;
    all.expression = fmt("%.6g", fit.lambda / D), all.title = "the single fit: " + fmt("%.2f", fit.lambda / D);
    c.guides.push_back(all);
  }
  c.ymin = 0.0;
  c.ymax = std::max(1.3, std::isfinite(hi) ? 1.15 * hi : 0.0);
  if (!local.empty())    // the z axis of panels (a) and (b), whole cm
    c.xmin = std::floor(local.front().z_lo), c.xmax = std::ceil(local.back().z_hi);
  out = {{"width", num("%.6g", width)}, {"windows", windows}, {"not_fitted", not_fitted}};
  if (!pts.x.empty())
    out["lambda_over_D_min"] = num("%.6g", lo), out["lambda_over_D_max"] = num("%.6g", hi),
    out["z_at_max"] = num("%.6g", at_hi);
  return c;
}

void flow_profile(const FlowFitTables &tables, const ExpFit &fit, const std::vector<LocalExpFit> &local, Run &run)
{
  tell(tables.profile, run);
  if (!tables.profile.read) return;
  const std::string &path = tables.profile.path;
  const std::vector<double> &z = tables.columns.z, &vz = tables.columns.vz, &se = tables.columns.vz_se;
  const std::vector<double> &phi = tables.profile_phi;
  const double D = tables.profile.D;
  SeriesPanel a, b;
  a.title = "(a) |v_z| below the face";
  a.xlabel = b.xlabel = "z − z_{tip} (cm; below the rod face)";
  a.ylabel = "|v_z| (cm/s)";
  a.logy = true;
  a.key = "top left Left reverse";    // |v_z| decays away from the face (z = 0, at the right)
  b.title = "(b) packing fraction below the face";
  b.ylabel = "φ";
  b.key = "off";
  PlotSeries s, sp;
  s.style = "points", s.title = "|v_z| ± standard error", s.colour = plot_colour(0);
  for (std::size_t i = 0; i < z.size(); ++i)
    if (std::isfinite(vz[i]) && vz[i] != 0) s.x.push_back(z[i]), s.y.push_back(std::fabs(vz[i])), s.y_err.push_back(se[i]);
  sp.style = "linespoints", sp.colour = plot_colour(2), sp.point_size = 1.0;
  for (std::size_t i = 0; i < z.size(); ++i) sp.x.push_back(z[i]), sp.y.push_back(phi[i]);
  a.series.push_back(s);
  b.series.push_back(sp);
  double vlo = INFINITY, vhi = 0;
  for (std::size_t i = 0; i < s.y.size(); ++i) vlo = std::min(vlo, s.y[i]), vhi = std::max(vhi, s.y[i] + s.y_err[i]);
  if (vhi > 0) {
    a.ymin = vlo / 1.5, a.ymax = vhi * 1.5;
    a.extra = log_tics("y", a.ymin, a.ymax, true);
  }
  std::string title = "Flow below the rod face";
  Json profile = {{"fit_ok", false}, {"note", fit.note}};
  if (fit.ok) {
    PlotSeries line;
    line.colour = "#000000";
    line.title = "fit |v_z| = " + fmt("%.3g", std::fabs(fit.A)) + " exp(z/λ), λ = " + fmt("%.3g", fit.lambda) + " ± " +
                 fmt("%.2g", fit.lambda_se) + " cm";
    for (int k = 0; k <= 100; ++k) {
      const double x = fit.zmin + (fit.zmax - fit.zmin) * k / 100.0;
      line.x.push_back(x), line.y.push_back(std::fabs(fit.A) * std::exp(x / fit.lambda));
    }
    a.series.push_back(line);
    title += ": λ_{vz} = " + fmt("%.3g", fit.lambda) + " cm = " + fmt("%.2f", fit.lambda / D) + " D (paper: " + paper_lambda_text(" D") + ")";
    profile = {{"fit_ok", true}, {"A", num("%.6g", fit.A)}, {"lambda", num("%.6g", fit.lambda)},
               {"lambda_se", num("%.6g", fit.lambda_se)}, {"lambda_over_D", num("%.6g", fit.lambda / D)}, {"n", fit.n}};
  } else {
    run.notes.push_back(path + ": no exponential fit: " + fit.note);
    title += " (no exponential fit: " + fit.note + ")";
  }
  std::vector<SeriesPanel> panels = {a, b};
  if (tables.columns.local_width > 0.0) {
    Json lj;
    panels.push_back(local_panel(local, fit, D, tables.columns.local_width, lj));
    profile["local"] = lj;
  }
  run.make_series("flow_profile",
                  title,
                  "granpen plot flow: v_z and phi below the rod face (" + path +
                  "), |v_z| on a log axis with the weighted\nexponential fit of the library (fit_exponential, as granpen flow)" +
                      (panels.size() > 2 ? "; (c) the same fit over each window of D/2 (local_exponential_fits)." : "."),
                  panels.size() > 2 ? 1900 : 1300, 560, panels);
  run.numbers["profile"] = profile;
}

// ---------------------------------------------------------------- phi against I at the edge

void flow_phi_I(const FlowFitTables &tables, const EdgeLine &e, Run &run)
{
  tell(tables.edge, run);
  if (!tables.edge.read) return;
  SeriesPanel p;
  p.xlabel = "inertial number I";
  p.ylabel = "packing fraction φ at the rod edge (r = R)";
  p.key = "outside right top Left reverse";
  p.xmin = 0;
  PlotSeries s;
  s.style = "points", s.title = "this run", s.colour = plot_colour(0);
  const std::vector<double> &x = e.I;
  s.x = e.I, s.y = e.phi;
  p.series.push_back(s);
  PlotGuide papers;
  papers.expression = gp_number(paper::edge_phi_0) + (paper::edge_phi_slope < 0 ? " - " : " + ") +
                      gp_number(std::fabs(paper::edge_phi_slope)) + "*x";
  papers.title = "paper: " + phi_of_I_text(paper::edge_phi_0, paper::edge_phi_slope, "%.2f");
  papers.colour = "#d62728";
  p.guides.push_back(papers);
  Json edge = {{"n", x.size()}};
  std::string title = "Packing fraction against inertial number at the rod edge";
  if (e.ok) {
    const LinearFit &lf = e.fit;
    PlotGuide g;
    g.expression = gp_number(lf.a) + " + " + gp_number(lf.b) + "*x";
    g.title = "fit: " + phi_of_I_text(lf.a, lf.b, "%.3f");
    g.colour = "#000000", g.dash = 1;
    p.guides.push_back(g);
    edge.update({{"fit_ok", true}, {"intercept", num("%.6g", lf.a)}, {"intercept_se", num("%.6g", lf.se_a)},
                 {"slope", num("%.6g", lf.b)}, {"slope_se", num("%.6g", lf.se_b)}});
    title += ": fit φ(0) = " + fmt("%.3f", lf.a) + " ± " + fmt("%.3f", lf.se_a) + ", slope " + fmt("%.2f", lf.b) +
             " ± " + fmt("%.2f", lf.se_b);
  } else {
    edge["fit_ok"] = false;
  }
  run.make_series("flow_phi_I",
                  title,
                  "granpen plot flow: phi against I at the rod's bottom edge (" + tables.edge.path +
                  "), the paper's line phi = 0.57 - 0.35 I and a least-squares line.",
                  1100, 620, {p});
  run.numbers["edge"] = edge;
}

// ---------------------------------------------------------------- near-shaft strip

void flow_strip(const std::string &dir, Run &run)
{
  CsvTable t;
  std::vector<double> z, vz;
  const auto columns = [&] { z = t.numbers("z", false), vz = t.numbers("vz"); };
  if (!read_table(dir, "flow_strip.csv", {"z", "vz"}, run, t, columns)) return;
  SeriesPanel p;
  p.xlabel = "v_z of the strip (cm/s; > 0 up)";
  p.ylabel = "z − z_s (cm; height above the bed surface)";
  p.key = "off";
  PlotVLine zero;
  zero.x = 0, zero.label = "v_z = 0";
  p.vlines.push_back(zero);
  PlotSeries s;
  s.style = "linespoints", s.colour = plot_colour(0), s.point_size = 0.9;
  for (std::size_t i = 0; i < z.size(); ++i) s.x.push_back(vz[i]), s.y.push_back(z[i]);
  p.series.push_back(s);
  run.make_series("flow_strip",
                  "Vertical velocity of the near-shaft strip against depth",
                  "granpen plot flow: v_z of the grains 0.5-1.5 cm from the rod shaft (" + t.path + ") against depth.",
                  800, 700, {p});
}

// ---------------------------------------------------------------- surface flux against t~

void flow_surface(const std::string &dir, Run &run)
{
  CsvTable t;
  std::vector<double> tt, vz;
  const auto columns = [&] { tt = t.numbers("t_tilde"), vz = t.numbers("vz"); };
  if (!read_table(dir, "flow_surface.csv", {"t_tilde", "vz"}, run, t, columns)) return;
  const double cross = last_down_crossing(tt, vz);
  SeriesPanel p;
  p.xlabel = "t̃ = (z/v_0) √(g/D)";
  p.ylabel = "v_z of the surface grains (cm/s; > 0 up)";
  p.key = "bottom left";
  // one label when the two lines nearly coincide (they would overprint)
  const double t_paper = paper::surface_crossing_t_tilde;
  const bool near = std::isfinite(cross) && std::abs(cross - t_paper) < 0.25;
  PlotVLine papers;
  papers.x = t_paper, papers.label = near ? "" : "t̃ = " + fmt("%g", t_paper) + " (paper)";
  p.vlines.push_back(papers);
  if (std::isfinite(cross)) {
    PlotVLine c;
    c.x = cross, c.colour = "#b03030", c.dash = 2;
    c.label = "  up → down at t̃ = " + fmt("%.2f", cross) + (near ? " (paper: " + fmt("%g", t_paper) + ")" : "");
    p.vlines.push_back(c);
  }
  PlotGuide zero;
  zero.expression = "0", zero.title = "", zero.dash = 1, zero.line_width = 1.0;
  p.guides.push_back(zero);
  PlotSeries s;
  s.style = "linespoints", s.colour = plot_colour(0), s.point_size = 0.9, s.title = "top grain layer, 0.5–1.5 cm from the shaft";
  s.x = tt, s.y = vz;
  p.series.push_back(s);
  run.make_series("flow_surface",
                  "Surface flux next to the rod: " +
                  (std::isfinite(cross) ? "turns from up to down at t̃ = " + fmt("%.2f", cross) : std::string("no sign change")),
                  "granpen plot flow: v_z of the near-shaft strip's top grain layer per frame (" + t.path +
                  ") against t~ = (z/v0) sqrt(g/D); the paper sees it cross 0 at t~ = 1.",
                  900, 620, {p});
  run.numbers["surface_crossing_t_tilde"] = std::isfinite(cross) ? num("%.6g", cross) : Json();
}

// ---------------------------------------------------------------- annulus means against t~

void flow_annulus(const std::string &dir, Run &run)
{
  CsvTable t;
  std::vector<double> tt, phi, vz, T;
  std::string xlabel;
  bool tilde = true;
  const auto columns = [&] {
    tilde = time_axis(t, tt, xlabel, run);
    phi = t.numbers("phi"), vz = t.numbers("vz"), T = t.numbers("T");
  };
  if (!read_table(dir, "flow_annulus.csv", {"t_tilde", "phi", "vz", "T"}, run, t, columns)) return;
  const char *titles[] = {"(a) packing fraction φ", "(b) vertical velocity v_z", "(c) granular temperature T"};
  const char *labels[] = {"φ", "v_z (cm/s; > 0 up)", "T (cm^2/s^2)"};
  const std::vector<double> *cols[] = {&phi, &vz, &T};
  SeriesFigure fig;
  fig.name = "flow_annulus";
  const double r1 = flow_parameter(dir, "annulus", 0), r2 = flow_parameter(dir, "annulus", 1);
  const std::string where = std::isfinite(r1) && std::isfinite(r2) ? "r = " + fmt("%g", r1) + "–" + fmt("%g", r2) + " cm"
                                                                   : "r = 2–3 cm (granpen flow's default)";
  fig.title = "Annulus " + where + " about the rod, against " + (tilde ? "rescaled time" : "depth");
  fig.about = "granpen plot flow: means over the annulus (" + t.path + ") against t~ = (z/v0) sqrt(g/D).";
  fig.width = 1500, fig.height = 520;
  for (int k = 0; k < 3; ++k) {
    SeriesPanel p;
    p.title = titles[k];
    p.xlabel = xlabel;
    p.ylabel = labels[k];
    p.key = "off";
    PlotVLine v;
    v.x = 1, v.label = "t̃ = 1";
    if (tilde) p.vlines.push_back(v);
    PlotSeries s;
    s.style = "linespoints", s.colour = plot_colour(k), s.point_size = 0.8;
    s.x = tt, s.y = *cols[k];
    p.series.push_back(s);
    if (k == 1) p.extra = "set xzeroaxis lt 1 lw 1 lc rgb \"#606060\"\n";
    fig.panels.push_back(p);
  }
  run.make(series_figure(fig));
}

// ---------------------------------------------------------------- momentum

struct ClassInfo {
  std::string key, title, colour;
};

std::vector<ClassInfo> class_order(const std::vector<std::string> &names)
{
  static const char *known[] = {"fast", "intermediate", "slow", "noise"};
  static const char *defs[] = {"fast: v_z ≥ v_0/10", "intermediate: v_0/80 ≤ v_z < v_0/10", "slow: v_0/320 < v_z < v_0/80",
                               "noise: v_0/640 < v_z ≤ v_0/320"};
  static const char *colours[] = {"#d62728", "#ff7f0e", "#1f77b4", "#7f7f7f"};
  std::vector<std::string> seen;
  for (const auto &n : names)
    if (std::find(seen.begin(), seen.end(), n) == seen.end()) seen.push_back(n);
  std::vector<ClassInfo> out;
  for (int k = 0; k < 4; ++k)
    for (const auto &s : seen)
      if (s == known[k] || s == std::to_string(k)) out.push_back({s, defs[k], colours[k]});
  int extra = 4;
  for (const auto &s : seen)
    if (std::none_of(out.begin(), out.end(), [&](const ClassInfo &c) { return c.key == s; }))
      out.push_back({s, "class " + s, plot_colour(extra++)});
  return out;
}

void momentum_classes_figure(const std::string &dir, Run &run)
{
  CsvTable t;
  std::vector<double> tt, count, p;
  std::vector<std::string> cls;
  std::string xlabel;
  bool tilde = true;
  const auto columns = [&] {
    tilde = time_axis(t, tt, xlabel, run);
    count = t.numbers("count"), p = t.numbers("p_up"), cls = t.text("class");
  };
  if (!read_table(dir, "momentum_classes.csv", {"t_tilde", "class", "count", "p_up"}, run, t, columns)) return;
  const auto order = class_order(cls);
  SeriesPanel a, b;
  a.title = "(a) upward momentum of each class";
  b.title = "(b) grains in each class";
  a.xlabel = b.xlabel = xlabel;
  a.ylabel = "summed upward momentum Σ m v_z (g cm/s)";
  b.ylabel = "grains";
  a.key = "off";
  b.key = "column";
  PlotVLine v;
  v.x = 1, v.label = "t̃ = 1";
  if (tilde) a.vlines.push_back(v), b.vlines.push_back(v);
  double pmin = INFINITY, pmax = 0, cmin = INFINITY, cmax = 0;
  for (const auto &c : order) {
    PlotSeries sa, sb;
    sa.style = sb.style = "linespoints";
    sa.point_size = sb.point_size = 0.7;
    sa.colour = sb.colour = c.colour;
    sb.title = c.title;
    std::vector<std::pair<double, std::size_t>> rows;
    for (std::size_t i = 0; i < cls.size(); ++i)
      if (cls[i] == c.key) rows.push_back({tt[i], i});
    std::sort(rows.begin(), rows.end());
    for (const auto &r : rows) {
      sa.x.push_back(r.first), sa.y.push_back(p[r.second]);
      sb.x.push_back(r.first), sb.y.push_back(count[r.second]);
      if (p[r.second] > 0) pmin = std::min(pmin, p[r.second]), pmax = std::max(pmax, p[r.second]);
      if (count[r.second] > 0) cmin = std::min(cmin, count[r.second]), cmax = std::max(cmax, count[r.second]);
    }
    a.series.push_back(sa), b.series.push_back(sb);
  }
  // log axes when the classes span more than two decades (zeros then drop out)
  a.logy = pmax > 0 && pmax / pmin > 100;
  b.logy = cmax > 0 && cmax / cmin > 100;
  if (a.logy) a.extra = "set format y \"10^{%T}\"\n";
  if (b.logy) b.extra = "set format y \"10^{%T}\"\n";
  run.make_series("momentum_classes",
                  "Grains moving up, by vertical-speed class (r > R)",
                  "granpen plot momentum: the classes of " + t.path + " against t~; log axes when a quantity spans more "
                  "than two decades\n(then zero values are not drawn).",
                  1500, 600, {a, b}, 0.74);
}

// F against mu g M from the table read (t) and the comparison the CLI made of it (cmp)
void momentum_drag_figure(const MomentumDragTable &t, const DragComparison &cmp, Run &run)
{
  run.notes.insert(run.notes.end(), t.notes.begin(), t.notes.end());
  run.problems.insert(run.problems.end(), t.problems.begin(), t.problems.end());
  if (!t.read) return;
  const std::vector<double> &tt = t.t_tilde, &F = t.F, &M = t.mu_g_M;
  // one unit for both axes (the 1:1 line is then the diagonal of equal numbers); each
  // axis over its own data, so that points far from 1:1 stay readable
  double top = 0, ftop = 0, mtop = 0;
  for (std::size_t i = 0; i < F.size(); ++i) {
    if (std::isfinite(F[i])) ftop = std::max(ftop, std::fabs(F[i]));
    if (std::isfinite(M[i])) mtop = std::max(mtop, std::fabs(M[i]));
  }
  top = std::max(ftop, mtop);
  const AxisScale sc = axis_scale(top, "dyne");
  SeriesPanel p;
  p.xlabel = "μ g M(v_z > v_0/320) (" + sc.unit + ")";
  p.ylabel = "drag force F (" + sc.unit + ")";
  p.xmin = p.ymin = 0;
  p.xmax = mtop > 0 ? 1.05 * mtop / sc.factor : 1;
  p.ymax = ftop > 0 ? 1.05 * ftop / sc.factor : 1;
  PlotSeries before, after;
  before.style = after.style = "points";
  before.title = "t̃ < 1", after.title = "t̃ ≥ 1";
  before.colour = "#ff7f0e", after.colour = "#1f77b4";
  before.point_type = 9, after.point_type = 7;
  for (std::size_t i = 0; i < F.size(); ++i) {
    if (!std::isfinite(F[i]) || !std::isfinite(M[i])) continue;
    PlotSeries &s = tt[i] < 1 ? before : after;
    s.x.push_back(M[i] / sc.factor), s.y.push_back(F[i] / sc.factor);
  }
  p.series = {before, after};
  PlotGuide one;
  one.expression = "x", one.title = "1:1 (paper)", one.colour = "#404040";
  p.guides.push_back(one);
  std::string title = "Drag against μ g M of the moving grains";
  Json drag = {{"ok", cmp.ok}, {"n", cmp.n}};
  if (cmp.ok) {
    PlotGuide g;
    g.expression = gp_number(cmp.fit.b) + "*x";
    g.title = "fit F = k μ g M, k = " + fmt("%.2f", cmp.fit.b) + " ± " + fmt("%.2f", cmp.fit.se_b);
    g.colour = "#000000", g.dash = 1;
    p.guides.push_back(g);
    // the fit's k only: the mean of the ratio (in the JSON) is dominated by the first
    // frames, when few grains move yet, and a title holding both ran off the canvas
    title += ": k = " + fmt("%.2f", cmp.fit.b) + " ± " + fmt("%.2f", cmp.fit.se_b) + " (paper: about 1)";
    drag.update({{"k", num("%.6g", cmp.fit.b)}, {"k_se", num("%.6g", cmp.fit.se_b)}, {"ratio_mean", num("%.6g", cmp.ratio_mean)},
                 {"ratio_se", num("%.6g", cmp.ratio_se)}});
  } else {
    run.notes.push_back(t.path + ": no drag comparison: " + cmp.note);
  }
  run.make_series("momentum_drag",
                  title,
                  "granpen plot momentum: F against mu g M(v_z > v0/320) (" + t.path +
                  "), the 1:1 line and the fit through the origin\n(compare_drag, as granpen momentum).",
                  980, 680, {p});
  run.numbers["drag"] = drag;
}

bool folder_ok(const std::vector<std::string> &inputs, Run &run)
{
  std::error_code ec;
  if (!fs::is_directory(inputs[0], ec)) {
    run.problems.push_back(inputs[0] + ": not a folder");
    return false;
  }
  return true;
}

}    // namespace

FlowFitTables read_flow_fit_tables(const std::string &dir, const Options &o)
{
  FlowFitTables out;
  FlowTableColumns &c = out.columns;
  Run said;    // what reading each table notes or finds wrong, kept with it
  said.opt = o;
  CsvTable t;
  const auto profile = [&] {
    c.z = t.numbers("z", false), c.vz = t.numbers("vz"), c.vz_se = t.numbers("vz_se"), out.profile_phi = t.numbers("phi");
  };
  if (read_table(dir, "flow_profile_below.csv", {"z", "vz", "vz_se", "phi"}, said, t, profile)) {
    out.profile.read = c.has_profile = true;
    out.profile.path = t.path;
    out.profile.D = rod_diameter(dir, t, said);
    c.local_width = 0.5 * out.profile.D;    // the local decay length over windows of R
    for (double &s : c.vz_se)    // an unknown standard error: drawn and weighted as 0
      if (!std::isfinite(s)) s = 0.0;
  }
  out.profile.notes = said.notes, out.profile.problems = said.problems;
  said.notes.clear(), said.problems.clear();
  const auto edge = [&] { c.I = t.numbers("I"), c.phi = t.numbers("phi"); };
  if (read_table(dir, "flow_edge_phi_I.csv", {"I", "phi"}, said, t, edge)) {
    out.edge.read = c.has_edge = true;
    out.edge.path = t.path;
  }
  out.edge.notes = said.notes, out.edge.problems = said.problems;
  return out;
}

void plot_flow(const std::vector<std::string> &inputs, const FlowFitTables &t, const FlowTableStudy &st, Run &run)
{
  if (!folder_ok(inputs, run)) return;
  const std::string &dir = inputs[0];
  flow_heatmaps(dir, run);
  flow_profile(t, st.profile, st.local, run);
  flow_phi_I(t, st.edge, run);
  flow_strip(dir, run);
  flow_annulus(dir, run);
  flow_surface(dir, run);
  if (run.figures.empty() && run.problems.empty())
    run.problems.push_back(dir + ": none of flow_fields.csv, flow_profile_below.csv, flow_edge_phi_I.csv, flow_strip.csv, "
                                 "flow_annulus.csv, flow_surface.csv is there (granpen flow --out writes them)");
}

MomentumDragTable read_momentum_drag_table(const std::string &dir, const Options &o)
{
  MomentumDragTable out;
  Run said;    // what reading the table notes or finds wrong, told when it is drawn
  said.opt = o;
  CsvTable t;
  const auto columns = [&] { out.t_tilde = t.numbers("t_tilde"), out.F = t.numbers("F"), out.mu_g_M = t.numbers("mu_g_M"); };
  if (read_table(dir, "momentum_drag.csv", {"t_tilde", "F", "mu_g_M"}, said, t, columns)) {
    out.read = true;
    out.path = t.path;
  }
  out.notes = said.notes, out.problems = said.problems;
  return out;
}

void plot_momentum(const std::vector<std::string> &inputs, const MomentumDragTable &t, const DragComparison &cmp, Run &run)
{
  if (!folder_ok(inputs, run)) return;
  const std::string &dir = inputs[0];
  momentum_classes_figure(dir, run);
  momentum_drag_figure(t, cmp, run);
  if (run.figures.empty() && run.problems.empty())
    run.problems.push_back(dir + ": neither momentum_classes.csv nor momentum_drag.csv is there");
}

}    // namespace figures
}    // namespace granpen
