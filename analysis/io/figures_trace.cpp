// granpen analysis: the paper's figure types of force traces (force, ratio, peak, kz) as
// gnuplot scripts with their data beside them (io/figures.h, io/plot_writer.h). ratio and
// peak draw the collapse study they are given (core/collapse_study.h, as granpen collapse),
// force and kz the fit study (core/fit_study.h, as granpen fit); the CLI runs the studies.
#include "figures.h"

#include "collapse_tables.h"
#include "ensemble_tables.h"
#include "json_text.h"
#include "scaling_laws.h"
#include "trace_files.h"
#include "trace_reader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace granpen {
namespace figures {

std::string fmt(const char *f, double v) { return json_number(f, v); }
Json num(const char *f, double v) { return json_rounded(f, v); }

AxisScale axis_scale(double maxabs, const std::string &unit)
{
  AxisScale s;
  s.unit = unit;
  if (!(maxabs > 0) || !std::isfinite(maxabs)) return s;
  const int e = static_cast<int>(std::floor(std::log10(maxabs)));
  if (e < 3) return s;
  s.factor = std::pow(10.0, e);
  s.unit = "10^{" + std::to_string(e) + "} " + unit;
  return s;
}

// labelled tics at 1, 2 and 5 x 10^e over [lo, hi] of a log axis (only 10^e when
// that makes more than 9)
std::string log_tics(const char *axis, double lo, double hi, bool plain)
{
  std::vector<std::string> all, decades;
  for (int e = (int) std::floor(std::log10(lo)); e <= (int) std::ceil(std::log10(hi)); ++e)
    for (int m : {1, 2, 5}) {
      const double v = m * std::pow(10.0, e);
      if (v < lo * (1 - 1e-9) || v > hi * (1 + 1e-9)) continue;
      const std::string lab = plain ? fmt("%g", v)
                                    : (m == 1 ? std::string("10^{") : std::to_string(m) + "×10^{") + std::to_string(e) + "}";
      all.push_back(gp_quote(lab) + " " + gp_number(v));
      if (m == 1) decades.push_back(all.back());
    }
  const auto &use = all.size() > 9 && decades.size() >= 2 ? decades : all;
  std::string t = std::string("set ") + axis + "tics (";
  for (std::size_t i = 0; i < use.size(); ++i) t += (i ? ", " : "") + use[i];
  return t + ")\nset m" + axis + "tics 10\n";
}

// text drawn as written: gnuplot's enhanced-text specials escaped (a file's stem, a name)
std::string literal_text(const std::string &s)
{
  std::string out;
  for (char c : s) {
    if (c && std::string("_^@&~{}").find(c) != std::string::npos) out += '\\';
    out += c;
  }
  return out;
}

// a number as 2.94×10^{4} (plain below 1e4)
std::string sci(double v)
{
  if (v == 0 || !std::isfinite(v) || std::fabs(v) < 1e4) return fmt("%.3g", v);
  const int e = (int) std::floor(std::log10(std::fabs(v)));
  return fmt("%.3g", v / std::pow(10.0, e)) + "×10^{" + std::to_string(e) + "}";
}

namespace {

namespace fs = std::filesystem;

}    // namespace

// ---------------------------------------------------------------- traces

std::vector<TraceIn> load_traces(const std::vector<std::string> &inputs, Run &run)
{
  std::vector<std::string> problems;
  const auto files = expand_trace_paths(inputs, problems);
  for (const auto &p : problems) run.problems.push_back(p);
  std::vector<TraceIn> out;
  for (const auto &f : files) {
    try {
      TraceIn t;
      t.file = f;
      t.tr = to_cgs(read_trace(f));
      auto seed = t.tr.keys.find("seed"), r = t.tr.keys.find("run");
      if (seed != t.tr.keys.end()) t.label = "seed " + seed->second;
      else if (r != t.tr.keys.end()) t.label = "run " + r->second;
      else t.label = fs::path(f).stem().string();
      out.push_back(t);
    } catch (std::exception &e) {
      run.problems.push_back(e.what());
    }
  }
  if (out.empty() && run.problems.empty()) run.problems.push_back("no trace given");
  return out;
}

TraceFitParams fit_params_of(const Options &o, FitKind w, double v0, double D, double g)
{
  TraceFitParams fp;
  if (w == FitKind::kz) {
    fp.zlo = o.kz_zmin, fp.zhi = o.kz_zmax;
    fp.shorten_window = true;
  }
  fp.v0 = v0, fp.D = D, fp.g = g;
  return fp;
}

std::vector<FitStudyTrace> fit_study_traces(const std::vector<TraceIn> &traces, const Options &o, FitKind w)
{
  std::vector<FitStudyTrace> out;
  for (const auto &t : traces) {
    FitStudyTrace f;
    f.name = t.file, f.z = t.tr.z, f.F = t.tr.F;
    f.params = fit_params_of(o, w, t.tr.v0, t.tr.D, t.tr.g);
    out.push_back(std::move(f));
  }
  return out;
}

std::vector<FitStudyEnsemble> fit_study_ensembles(const std::vector<TraceGroup> &groups, const Options &o, FitKind w)
{
  std::vector<FitStudyEnsemble> out;
  for (const auto &g : groups) {
    FitStudyEnsemble e;
    e.name = g.label(), e.mean = g.mean;
    e.params = fit_params_of(o, w, g.v0, g.D, g.g);
    out.push_back(std::move(e));
  }
  return out;
}

DepthTerm depth_term_of(const Options &o)
{
  DepthTerm dt;
  dt.kz_zmin = o.kz_zmin, dt.kz_zmax = o.kz_zmax, dt.alpha = o.alpha, dt.mu = o.mu, dt.rho_g = o.rho;
  return dt;
}

namespace {

// a < b with runs of digits compared as numbers ("run 2" < "run 10")
bool natural_less(const std::string &a, const std::string &b)
{
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    if (std::isdigit((unsigned char) a[i]) && std::isdigit((unsigned char) b[j])) {
      std::size_t i2 = i, j2 = j;
      while (i2 < a.size() && std::isdigit((unsigned char) a[i2])) ++i2;
      while (j2 < b.size() && std::isdigit((unsigned char) b[j2])) ++j2;
      const double x = std::stod(a.substr(i, i2 - i)), y = std::stod(b.substr(j, j2 - j));
      if (x != y) return x < y;
      i = i2, j = j2;
    } else {
      if (a[i] != b[j]) return a[i] < b[j];
      ++i, ++j;
    }
  }
  return a.size() - i < b.size() - j;
}

// traces grouped by v0 (ascending): indices into the traces, each group in the natural
// order of the runs' labels (seed 2 before seed 10)
std::vector<std::vector<int>> by_speed(const std::vector<TraceIn> &t)
{
  std::map<double, std::vector<int>> m;
  for (std::size_t i = 0; i < t.size(); ++i) m[t[i].tr.v0].push_back((int) i);
  std::vector<std::vector<int>> g;
  for (auto &kv : m) {
    std::stable_sort(kv.second.begin(), kv.second.end(),
                     [&](int a, int b) { return natural_less(t[a].label, t[b].label); });
    g.push_back(kv.second);
  }
  return g;
}

std::string v0_text(double v0) { return "v_0 = " + fmt("%g", v0) + " cm/s"; }

// What tells curve i from the others of its speed in a legend: its D and g where they differ
// from another's (two pushes of one bed at one speed and two diameters are both "seed 1"),
// then its run label.
std::string run_text(const std::vector<CollapseCurve> &cs, const std::vector<int> &group, int i, const std::string &label)
{
  bool D_differs = false, g_differs = false;
  for (int j : group) D_differs |= cs[j].D != cs[i].D, g_differs |= cs[j].g != cs[i].g;
  std::string s = D_differs ? "D = " + fmt("%g", cs[i].D) + " cm, " : "";
  if (g_differs) s += "g = " + fmt("%g", cs[i].g) + ", ";
  return s + label;
}

// log-axis tics at the given values (and the minor tics gnuplot adds)
std::string value_tics(const char *axis, std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  std::string s = std::string("set ") + axis + "tics (";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + gp_number(v[i]);
  return s + ")\n";
}

bool increasing(const std::vector<double> &z)
{
  for (std::size_t i = 1; i < z.size(); ++i)
    if (!(z[i] > z[i - 1])) return false;
  return z.size() >= 2;
}

double interp(const std::vector<double> &x, const std::vector<double> &y, double xq)
{
  auto it = std::lower_bound(x.begin(), x.end(), xq);
  if (it == x.begin()) return y.front();
  if (it == x.end()) return y.back();
  const std::size_t k = it - x.begin();
  const double f = (xq - x[k - 1]) / (x[k] - x[k - 1]);
  return y[k - 1] + f * (y[k] - y[k - 1]);
}

// the k_z window as text: "z = 1..3 cm" or "z ≥ 3 cm"
std::string window_text(const Options &o)
{
  return std::isfinite(o.kz_zmax) ? "z = " + fmt("%g", o.kz_zmin) + ".." + fmt("%g", o.kz_zmax) + " cm"
                                  : "z ≥ " + fmt("%g", o.kz_zmin) + " cm";
}

}    // namespace

// ---------------------------------------------------------------- force

namespace {

// "" when the peak region earns an enlarged view: some run has at least 5 samples at
// 0 < z < zpeak and the region is less than half the depth drawn (else the main plot shows
// it as large); otherwise why not, for a note.
std::string peak_view_missing(const std::vector<TraceIn> &traces, double zpeak)
{
  std::size_t most = 0;
  double zdeep = -INFINITY;
  for (const auto &t : traces) {
    std::size_t n = 0;
    for (double z : t.tr.z) n += z > 0 && z < zpeak, zdeep = std::max(zdeep, z);
    most = std::max(most, n);
  }
  const std::string region = "the peak region 0 < z < 0.7 R = " + fmt("%.3g", zpeak) + " cm";
  if (most < 5)
    return region + " holds " + std::to_string(most) + " samples of the best-resolved run (5 needed): no enlarged view of it";
  if (zpeak >= 0.5 * zdeep)
    return region + " is half or more of the depth drawn (to " + fmt("%.3g", zdeep) + " cm): no enlarged view of it";
  return "";
}

// The inset below the key column's legend of `lines` lines, the figure made taller (to
// 1000 px at most) until the inset is at least 0.32 of its height; false when it cannot be.
bool place_below_key(SeriesFigure &fig, SeriesPanel &inset, int lines)
{
  for (;;) {
    const double h = key_column_top(fig) - lines * key_line_height(fig.height) - 0.05 - 0.04;
    if (h >= 0.32) {
      inset.at_y = 0.04, inset.at_h = std::min(h, 0.64);
      return true;
    }
    if (fig.height >= 1000) {
      inset.at_y = 0.04, inset.at_h = 0.32;
      return false;
    }
    fig.height = std::min(1000, fig.height + 60);
  }
}

int key_lines(const SeriesPanel &p)
{
  int n = p.key_title.empty() ? 0 : 1 + (int) std::count(p.key_title.begin(), p.key_title.end(), '\n');
  for (const auto &s : p.series) n += !s.title.empty();
  return n;
}

// one series per run of group g (shades of colour); in: their part in the peak region
void each_run(const std::vector<TraceIn> &traces, const std::vector<int> &g, const std::string &colour,
              double factor, double zpeak, SeriesPanel &main, SeriesPanel &inset)
{
  for (std::size_t j = 0; j < g.size(); ++j) {
    const auto &t = traces[g[j]];
    PlotSeries s, in;
    s.title = v0_text(t.tr.v0) + (g.size() > 1 ? ", " + t.label : "");
    s.colour = in.colour = plot_shade(colour, (int) j, (int) g.size());
    s.line_width = in.line_width = g.size() > 1 ? 1.5 : 2.0;
    for (std::size_t k = 0; k < t.tr.z.size(); ++k) {
      s.x.push_back(t.tr.z[k]), s.y.push_back(t.tr.F[k] / factor);
      if (t.tr.z[k] >= -0.15 * zpeak && t.tr.z[k] <= zpeak * 1.05) in.x.push_back(t.tr.z[k]), in.y.push_back(t.tr.F[k] / factor);
    }
    main.series.push_back(s);
    inset.series.push_back(in);
  }
}

// the mean of the runs of g on the first run's depth step, with their min..max range
PlotSeries mean_and_range(const std::vector<TraceIn> &traces, const std::vector<int> &g, double factor)
{
  double z0 = -INFINITY, z1 = INFINITY;
  for (int i : g) z0 = std::max(z0, traces[i].tr.z.front()), z1 = std::min(z1, traces[i].tr.z.back());
  const auto &zr = traces[g[0]].tr.z;
  std::vector<double> dz;
  for (std::size_t k = 1; k < zr.size(); ++k) dz.push_back(zr[k] - zr[k - 1]);
  std::nth_element(dz.begin(), dz.begin() + dz.size() / 2, dz.end());
  const double step = dz[dz.size() / 2];
  PlotSeries s;
  s.title = v0_text(traces[g[0]].tr.v0) + " (" + std::to_string(g.size()) + " runs)";
  for (std::size_t k = 0; z0 + k * step <= z1 + 1e-9 * step; ++k) {
    const double z = z0 + k * step;
    double sum = 0, lo = INFINITY, hi = -INFINITY;
    for (int i : g) {
      const double F = interp(traces[i].tr.z, traces[i].tr.F, z) / factor;
      sum += F, lo = std::min(lo, F), hi = std::max(hi, F);
    }
    s.x.push_back(z), s.y.push_back(sum / g.size()), s.band_lo.push_back(lo), s.band_hi.push_back(hi);
  }
  return s;
}

// a series cut to the inset's depths
PlotSeries inset_part(const PlotSeries &s, double zpeak)
{
  PlotSeries in = s;
  in.title.clear();
  in.x.clear(), in.y.clear(), in.band_lo.clear(), in.band_hi.clear();
  const bool band = s.band_lo.size() == s.x.size();
  for (std::size_t k = 0; k < s.x.size(); ++k)
    if (s.x[k] >= -0.15 * zpeak && s.x[k] <= zpeak * 1.05) {
      in.x.push_back(s.x[k]), in.y.push_back(s.y[k]);
      if (band) in.band_lo.push_back(s.band_lo[k]), in.band_hi.push_back(s.band_hi[k]);
    }
  return in;
}

// --ensemble: the groups of (v0, g, D), averaged; the mean +- se per group and its peak
// (the study's ensemble fit, with its standard error)
void force_ensembles(const std::vector<TraceGroup> &groups, const FitStudy &st, double factor, double zpeak, Run &run,
                     SeriesPanel &main, SeriesPanel &inset, Json &json_runs)
{
  bool several_cases = false;
  for (const auto &g : groups) several_cases |= g.g != groups.front().g || g.D != groups.front().D;
  for (std::size_t gi = 0; gi < groups.size(); ++gi) {
    const auto &g = groups[gi];
    const EnsembleMean &m = g.mean;
    PlotSeries s;
    s.colour = plot_colour((int) gi);
    s.title = v0_text(g.v0) + (several_cases ? ", g = " + fmt("%g", g.g) + ", D = " + fmt("%g", g.D) : std::string()) +
              " (" + std::to_string(m.runs) + (m.runs == 1 ? " run)" : " runs)");
    for (std::size_t k = 0; k < m.z.size(); ++k)
      s.x.push_back(m.z[k]), s.y.push_back(m.mean[k] / factor), s.band_lo.push_back((m.mean[k] - m.se[k]) / factor),
          s.band_hi.push_back((m.mean[k] + m.se[k]) / factor);
    main.series.push_back(s);
    inset.series.push_back(inset_part(s, zpeak));
    const EnsembleFit &e = st.ensembles[gi];
    PlotSeries peak;
    peak.style = "points", peak.colour = s.colour, peak.point_type = 7, peak.point_size = 1.3;
    if (e.peak_F.ok) {
      peak.x.push_back(e.peak_z.value), peak.y.push_back(e.peak_F.value / factor);
      peak.y_err.push_back(e.peak_F.se / factor);
    }
    inset.series.push_back(peak);
    json_runs.push_back({{"v0", num("%.10g", g.v0)}, {"g", num("%.10g", g.g)}, {"D", num("%.10g", g.D)},
                         {"runs", m.runs}, {"max_shift", num("%.4g", m.alignment.max_shift)},
                         {"peak_F", estimate_json(e.peak_F)}, {"peak_z", estimate_json(e.peak_z)}});
    for (const auto &n : m.notes) run.notes.push_back(g.label() + ": " + n);
  }
}

// without --ensemble: per v0, the mean and range of its runs (or every run), the peaks
void force_groups(const std::vector<TraceIn> &traces, const FitStudy &st, double factor, double zpeak, Run &run,
                  SeriesPanel &main, SeriesPanel &inset, Json &json_runs)
{
  const auto groups = by_speed(traces);
  const bool mean_mode = !run.opt.each;
  for (std::size_t gi = 0; gi < groups.size(); ++gi) {
    const auto &g = groups[gi];
    const std::string colour = plot_colour((int) gi);
    const double v0 = traces[g[0]].tr.v0;
    bool can_mean = mean_mode && g.size() > 1;
    for (int i : g) can_mean = can_mean && increasing(traces[i].tr.z);
    if (mean_mode && g.size() > 1 && !can_mean)
      run.notes.push_back(v0_text(v0) + ": depth not increasing in every run; each run drawn");
    // the peaks (the study's fits: trace_fit's definition, as granpen fit and collapse)
    PlotSeries peaks;
    peaks.style = "points", peaks.colour = colour, peaks.point_type = 7, peaks.point_size = 1.3;
    for (int i : g) {
      const auto &t = traces[i];
      const TraceFit &fit = st.fits[i].fit;
      if (fit.peak_ok) peaks.x.push_back(fit.peak_z), peaks.y.push_back(fit.peak_F / factor);
      json_runs.push_back({{"file", t.file}, {"v0", num("%.10g", v0)}, {"peak_F", num("%.6g", fit.peak_F)},
                           {"peak_z", num("%.6g", fit.peak_z)}});
    }
    if (can_mean) {
      PlotSeries s = mean_and_range(traces, g, factor);
      s.colour = colour;
      double deepest = s.x.empty() ? 0 : s.x.back();
      for (int i : g) deepest = std::max(deepest, traces[i].tr.z.back());
      if (!s.x.empty() && deepest > s.x.back() * 1.02 + 1e-9)
        run.notes.push_back(v0_text(v0) + ": the mean stops at z = " + fmt("%.3g", s.x.back()) +
                            " cm, where the shallowest of its runs ends (the deepest reaches " + fmt("%.3g", deepest) + " cm)");
      main.series.push_back(s);
      inset.series.push_back(inset_part(s, zpeak));
    } else {
      each_run(traces, g, colour, factor, zpeak, main, inset);
    }
    inset.series.push_back(peaks);
  }
}

// many runs drawn one by one: one legend entry per v0 ("v_0 = 50 cm/s (3 runs)") instead of per run
void legend_per_speed(SeriesPanel &main)
{
  std::map<std::string, int> runs, seen;
  const auto speed = [](const std::string &t) { return t.substr(0, t.find(',')); };
  for (const auto &s : main.series)
    if (!s.title.empty()) ++runs[speed(s.title)];
  for (auto &s : main.series) {
    if (s.title.empty()) continue;
    const std::string v = speed(s.title);
    s.title = seen[v]++ ? std::string() : v + (runs[v] > 1 ? " (" + std::to_string(runs[v]) + " runs)" : "");
  }
}

}    // namespace

void plot_force(const std::vector<TraceIn> &traces, const std::vector<TraceGroup> &groups, const FitStudy &st, Run &run)
{
  if (traces.empty()) return;
  double Dmax = 0, Fmax = 0;
  for (const auto &t : traces) {
    Dmax = std::max(Dmax, t.tr.D);
    for (double F : t.tr.F) Fmax = std::max(Fmax, std::fabs(F));
  }
  const double zpeak = peak_regime_end(Dmax);
  const AxisScale ys = axis_scale(Fmax, "dyne");
  const std::string no_view = peak_view_missing(traces, zpeak);
  const bool view = no_view.empty();
  if (!view) run.notes.push_back("force: " + no_view);

  SeriesPanel main, inset;
  main.xlabel = "rod tip depth z below the bed surface (cm)";
  main.ylabel = "drag force F (" + ys.unit + ")";
  main.extra = "set offsets 0, 0, graph 0.04, 0\nset autoscale xfix\n";    // x: the depths drawn, no more
  if (view)
    main.extra += "set object 2 rectangle from first 0, graph 0 to first " + gp_number(zpeak) +
                  ", graph 1 behind fillcolor rgb \"#e8e8e8\" fillstyle solid 1.0 noborder\n"
                  "set label 2 \"z < 0.7 R\" at first " + gp_number(0.5 * zpeak) +
                  ", graph 0.975 center textcolor rgb \"#606060\"\n";
  main.key = "column";
  const bool ens = run.opt.ensemble, mean_mode = !run.opt.each;
  main.key_title = ens ? "lines: mean of the runs at each v_0,\naligned at their force onsets\nbands: ± standard error over runs"
                       : mean_mode ? "lines: mean of the runs at each v_0\nbands: their range" : "every run";
  // the peak region, enlarged beside the main plot (an inset over the plot would hide data)
  inset.at_x = 0.655, inset.at_w = 0.335;
  inset.key = "off";
  inset.title = "peak region z < 0.7 R = " + fmt("%.3g", zpeak) + " cm\n(" +
                (ens ? "dots: the mean's peak ± se" : "dots: each run's peak") + ")";
  inset.xlabel = "z (cm)";
  inset.ylabel = "F (" + ys.unit + ")";
  inset.xmin = -0.15 * zpeak, inset.xmax = zpeak;
  inset.ymin = 0;
  inset.extra = "set mxtics 2\nset tics font \",11\"\nset title font \",11\"\nset xlabel font \",11\"\nset ylabel font \",11\"\n";

  Json json_runs = Json::array();
  if (ens) force_ensembles(groups, st, ys.factor, zpeak, run, main, inset, json_runs);
  else force_groups(traces, st, ys.factor, zpeak, run, main, inset, json_runs);
  if (!ens && mean_mode && std::none_of(main.series.begin(), main.series.end(),
                                        [](const PlotSeries &s) { return !s.band_lo.empty(); }))
    main.key_title = "every run (no v_0 has several)";    // no mean, no band to explain
  SeriesFigure fig;
  fig.name = "force";
  fig.title = "Drag force against depth";
  fig.about = "granpen plot force: F against the tip depth z for each v0 (" +
              std::string(ens ? "mean of the runs of each (v0, g, D) aligned at their force onsets, band: +- se over runs"
                          : mean_mode ? "mean of the runs at each v0, band: their min..max" : "every run") +
              "), F in " + ys.unit + (view ? ";\nbeside it, enlarged: the transient peak region 0 < z < 0.7 R, dots at the peaks." : ".");
  fig.width = 1250, fig.height = 720;
  fig.grid_width = view ? 0.64 : 0.7;
  if (view && !place_below_key(fig, inset, key_lines(main)) && !ens && !mean_mode) {
    legend_per_speed(main);    // every run drawn: the legend names the speeds
    run.notes.push_back("force: one legend entry per v0 (shades: its runs), for room");
    fig.height = 720;
    place_below_key(fig, inset, key_lines(main));
  }
  fig.panels = {main};
  if (view) fig.panels.push_back(inset);
  run.make(series_figure(fig));
  run.numbers["F_unit"] = "dyne";
  run.numbers["F_scale"] = num("%g", ys.factor);
  run.numbers["peak_zmax"] = num("%g", zpeak);
  run.numbers["peak_view"] = view;
  run.numbers[ens ? "ensembles" : "runs"] = json_runs;
}

// ---------------------------------------------------------------- ratio

namespace {

// The curves of the ratio figure: one per trace, or with --ensemble one per ensemble (its
// mean, k_z from it) with the run-to-run standard error of each t~ bin (the study's).
struct RatioCurves {
  std::vector<std::string> label;                    // legend detail: "seed 1", "5 runs"
  const std::vector<std::vector<double>> *se = nullptr;    // --ensemble: per curve, per t~ bin
  const EnsembleCollapse *ens = nullptr;             // --ensemble
};

// The study's curves with their labels; the depth terms' notes (a window shortened, a trace
// or ensemble left out) worded as notes of the run. False: none to draw.
bool ratio_curves(const std::vector<TraceIn> &traces, const std::vector<TraceGroup> &groups, const CollapseStudy &s,
                  Run &run, RatioCurves &rc, CollapseResult &r)
{
  if (!run.opt.ensemble) {
    for (std::size_t i = 0; i < traces.size() && i < s.depth.size(); ++i) {
      const TraceIn &t = traces[i];
      const DepthTermOutcome &d = s.depth[i];
      std::string why = d.window_shortened ? t.file + ": " + d.window_note : std::string();
      if (!d.ok)
        why = t.file + ": no positive depth term over the k_z window; left out (use --kz-zmin/--kz-zmax, --alpha or --ensemble)";
      if (!why.empty()) run.notes.push_back(why);
      if (d.ok) rc.label.push_back(t.label);
    }
    if (!s.collapsed) return false;
    r = s.result;
    return true;
  }
  for (std::size_t i : s.ensembles.left_out)
    run.notes.push_back("ensemble " + groups[i].label() + ": no positive depth term on its mean; left out");
  for (std::size_t i : s.ensembles.kept)
    rc.label.push_back(std::to_string(groups[i].mean.runs) + (groups[i].mean.runs == 1 ? " run" : " runs"));
  if (!s.ensembles_done || s.ensembles.kept.empty()) return false;
  rc.ens = &s.ensembles.collapse;
  rc.se = &s.ensembles.ratio_se;
  r = s.ensembles.collapse.result;
  return true;
}

std::string pm_text(const Estimate &e, const char *f)
{
  return fmt(f, e.value) + (e.se_ok ? " ± " + fmt(f, e.se) : std::string());
}

// the crossover and the spread, as granpen collapse reports them
std::string ratio_title(const CollapseResult &r, const RatioCurves &rc, bool ensemble)
{
  const std::string what = ensemble ? " ensembles" : " traces";
  std::string t = "t̃* = " +
                  (!r.n_crossed ? std::string("not reached")
                   : ensemble   ? pm_text(rc.ens->t_star_mean, "%.3g")
                                : fmt("%.3g", r.t_star_mean) + " ± " + fmt("%.2g", r.t_star_sd)) +
                  " (" + std::to_string(r.n_crossed) + " of " + std::to_string(r.curves.size()) + what;
  if (r.curves.size() > 1)
    t += "; their mean: " + (!r.ens_crossed ? std::string("not reached")
                             : ensemble     ? pm_text(rc.ens->t_star_ensemble, "%.3g")
                                            : fmt("%.3g", r.t_star_ensemble));
  t += "), spread ";
  if (ensemble) return t + pm_text(rc.ens->spread_z, "%.3f") + " against z, " + pm_text(rc.ens->spread_t, "%.3f") + " against t̃";
  return t + fmt("%.3f", r.spread_z) + " against z, " + fmt("%.3f", r.spread_t) + " against t̃";
}

}    // namespace

void plot_ratio(const std::vector<TraceIn> &traces, const std::vector<TraceGroup> &groups, const CollapseStudy &s,
                Run &run)
{
  RatioCurves rc;
  CollapseResult r;
  if (!ratio_curves(traces, groups, s, run, rc, r)) {
    run.problems.push_back(s.refused ? s.refusal
                                     : std::string("no usable ") + (run.opt.ensemble ? "ensemble" : "trace") + " for the ratio");
    return;
  }
  // colours: by v0, shades for the runs of one v0
  std::map<double, std::vector<int>> speed;
  for (std::size_t i = 0; i < r.curves.size(); ++i) speed[r.curves[i].v0].push_back((int) i);
  std::vector<std::string> colour(r.curves.size());
  int gi = 0;
  for (auto &kv : speed) {
    for (std::size_t j = 0; j < kv.second.size(); ++j)
      colour[kv.second[j]] = plot_shade(plot_colour(gi), (int) j, (int) kv.second.size());
    ++gi;
  }
  const double band = run.opt.collapse.band;
  SeriesPanel a, b;
  a.title = "(a) against depth";
  a.xlabel = "rod tip depth z (cm)";
  b.title = "(b) against rescaled time";
  b.xlabel = "t̃ = (z / v_0) √(g / D)";
  a.ylabel = b.ylabel = run.opt.alpha > 0 ? "F / F_z   (F_z = α μ ρ_g g D² z)" : "F / F_z   (F_z = k_z z)";
  a.key = "off";
  b.key = "column";
  if (run.opt.ensemble) b.key_title = "bands: ± se over runs";
  PlotHBand hb;
  hb.lo = 1 - band, hb.hi = 1 + band;
  a.hbands.push_back(hb);
  hb.title = "1 ± " + fmt("%g", band);
  b.hbands.push_back(hb);
  PlotVLine v;
  v.x = 1.0, v.label = "t̃ = 1 (paper)";
  b.vlines.push_back(v);
  double ymax = 0, ymin = 0;
  Json json_curves = Json::array();
  // a legend entry per run while it stays readable, else one per speed
  const bool per_run = r.curves.size() <= 12;
  for (auto &kv : speed)
    for (int i : kv.second) {
      const CollapseCurve &c = r.curves[i];
      PlotSeries sa, sb;
      sa.colour = sb.colour = colour[i];
      if (run.opt.ensemble)
        sb.title = v0_text(c.v0) + (kv.second.size() > 1 ? ", g = " + fmt("%g", c.g) + ", D = " + fmt("%g", c.D) : "") +
                   " (" + rc.label[i] + ")";
      else if (per_run)
        sb.title = v0_text(c.v0) + (kv.second.size() > 1 ? ", " + run_text(r.curves, kv.second, i, rc.label[i]) : "");
      else if (i == kv.second.front())
        sb.title = v0_text(c.v0) + " (" + std::to_string(kv.second.size()) + " runs)";
      sa.line_width = sb.line_width = 1.8;
      for (std::size_t k = 0; k < c.t.size(); ++k) {
        sa.x.push_back(depth_at_t_tilde(c.t[k], c.v0, c.g, c.D)), sa.y.push_back(c.ratio[k]);
        sb.x.push_back(c.t[k]), sb.y.push_back(c.ratio[k]);
        ymax = std::max(ymax, c.ratio[k]), ymin = std::min(ymin, c.ratio[k]);
        if (run.opt.ensemble) {    // the run-to-run band
          const double e = (*rc.se)[i][k];
          sa.band_lo.push_back(c.ratio[k] - e), sa.band_hi.push_back(c.ratio[k] + e);
          sb.band_lo.push_back(c.ratio[k] - e), sb.band_hi.push_back(c.ratio[k] + e);
        }
      }
      a.series.push_back(sa);
      b.series.push_back(sb);
      json_curves.push_back({{"file", c.name}, {"v0", num("%.10g", c.v0)}, {"k_z", num("%.6g", c.k_z)},
                             {"crossed", c.crossed}, {"t_star", num("%.4g", c.t_star)}});
    }
  if (r.curves.size() > 1 && !r.ens_t.empty()) {
    // the mean over the runs, where the grain-scale fluctuations of single runs average out
    PlotSeries e;
    e.colour = "#000000";
    e.line_width = 3.0;
    e.title = run.opt.ensemble ? "all ensembles: mean ± se" : "mean of the runs ± se";    // its t̃*: in the title
    e.x = r.ens_t, e.y = r.ens_ratio;
    for (std::size_t k = 0; k < r.ens_t.size(); ++k)
      e.band_lo.push_back(r.ens_ratio[k] - r.ens_se[k]), e.band_hi.push_back(r.ens_ratio[k] + r.ens_se[k]);
    b.series.push_back(e);
  }
  // linear up to 4; beyond, a log axis, so that the early, large ratios of fast pushes
  // stay in view next to the band about 1
  std::string clipped;
  if (ymax > 4.0) {
    double pos = ymax;
    int nonpos = 0;
    for (const auto &c : r.curves)
      for (double y : c.ratio) y > 0 ? (void) (pos = std::min(pos, y)) : (void) ++nonpos;
    const double lo = std::min(0.5, pos / 1.3), hi = ymax * 1.3;
    a.logy = b.logy = true;
    a.ymin = b.ymin = lo, a.ymax = b.ymax = hi;
    a.extra = b.extra = log_tics("y", lo, hi, true);
    if (nonpos) clipped = " (" + std::to_string(nonpos) + " bins with F/F_z <= 0 not drawn on the log axis)";
  } else {
    a.ymin = b.ymin = std::min(0.0, ymin);
  }
  a.extra += "set autoscale xfix\n";
  // t~ over more than 1000 bins (slow pushes, deep soundings): a log axis, so that every
  // speed and the paper's t~ = 1 stay in view and the tic labels do not run together
  double tmax = 0;
  for (const auto &c : r.curves)
    for (double t : c.t) tmax = std::max(tmax, t);
  if (tmax > 1000 * run.opt.collapse.tbin) {
    b.logx = true;
    b.xmin = 0.5 * run.opt.collapse.tbin, b.xmax = tmax * 1.3;
    b.extra += log_tics("x", b.xmin, b.xmax, true);
  }
  SeriesFigure fig;
  fig.name = "ratio";
  fig.title = "F over its depth term F_z" + clipped + ": " + ratio_title(r, rc, run.opt.ensemble);
  fig.about = "granpen plot ratio: the binned F/F_z curves of granpen collapse (bins of t~ of width " +
              fmt("%g", run.opt.collapse.tbin) + ", z >= " + fmt("%g", run.opt.collapse.zmin) +
              " cm), against z (bin centre t~ converted back to z)\nand against t~; the band 1 +- " + fmt("%g", band) +
              "; k_z " +
              (run.opt.alpha > 0 ? "from alpha = " + fmt("%g", run.opt.alpha)
                                 : "fitted over " + window_text(run.opt)) +
              ".";
  fig.width = 1450, fig.height = 620;
  fig.grid_width = 0.76;    // the key column: room for "mean of the runs ± se (t̃* = 1.23)"
  fig.panels = {a, b};
  run.make(series_figure(fig));
  Json &n = run.numbers;
  n["band"] = num("%g", band), n["tbin"] = num("%g", run.opt.collapse.tbin), n["zmin"] = num("%g", run.opt.collapse.zmin);
  n["t_star_mean"] = num("%.6g", r.t_star_mean), n["t_star_sd"] = num("%.6g", r.t_star_sd), n["n_crossed"] = r.n_crossed;
  n["spread_z"] = num("%.6g", r.spread_z), n["spread_t"] = num("%.6g", r.spread_t);
  n["ensemble_crossed"] = r.ens_crossed, n["t_star_ensemble"] = num("%.6g", r.t_star_ensemble);
  n["curves"] = json_curves;
}

// ---------------------------------------------------------------- peak

namespace {

// the ensembles' points with their standard errors, and every run's own peak, small
void ensemble_peak_series(const std::vector<TraceGroup> &groups, const EnsembleCollapse &ec, const CollapseResult &single,
                          SeriesPanel &p)
{
  for (std::size_t i = 0; i < groups.size(); ++i) {
    PlotSeries s;
    s.style = "points", s.colour = plot_colour((int) i), s.point_size = 1.6;
    s.title = v0_text(groups[i].v0) + " (mean of " + std::to_string(groups[i].mean.runs) + " runs ± se)";
    if (ec.peak[i].ok && ec.peak[i].value > 0)
      s.x.push_back(groups[i].v0), s.y.push_back(ec.peak[i].value), s.y_err.push_back(ec.peak[i].se);
    p.series.push_back(s);
  }
  PlotSeries one;
  one.style = "points", one.colour = "#808080", one.point_type = 6, one.point_size = 0.9, one.title = "single runs";
  for (const auto &c : single.curves)
    if (c.peak > 0) one.x.push_back(c.v0), one.y.push_back(c.peak);
  p.series.push_back(one);
}

}    // namespace

void plot_peak(const std::vector<TraceIn> &traces, const CollapseResult &peaks, const std::vector<TraceGroup> &groups,
               const CollapseStudy *ens_study, Run &run)
{
  // the peak law of granpen collapse; peaks and the law do not depend on k_z
  CollapseResult r = peaks;
  std::vector<double> v0s;
  double pmax = 0;
  std::vector<std::string> no_peak;
  for (const auto &c : r.curves) {
    v0s.push_back(c.v0);
    if (!(c.peak > 0.0)) no_peak.push_back(c.name);
    pmax = std::max(pmax, c.peak);
  }
  if (no_peak.size() == 1) run.notes.push_back(no_peak[0] + ": no positive force at 0 < z < 0.7 R: no peak");
  else if (!no_peak.empty())
    run.notes.push_back(std::to_string(no_peak.size()) + " of " + std::to_string(r.curves.size()) +
                        " traces have no positive force at 0 < z < 0.7 R (no peak), e.g. " + no_peak.front() + ", " +
                        no_peak[1] + (no_peak.size() > 2 ? ", ..." : ""));
  SeriesPanel p;
  p.logx = p.logy = true;
  p.xlabel = "rod speed v_0 (cm/s)";
  p.ylabel = "peak force F_{peak} (dyne), max over 0 < z < 0.7 R";
  std::vector<double> vs = v0s;
  std::sort(vs.begin(), vs.end());
  if (!vs.empty()) p.xmin = vs.front() / 1.35, p.xmax = vs.back() * 1.35;
  double pmin = pmax;
  for (const auto &c : r.curves)
    if (c.peak > 0) pmin = std::min(pmin, c.peak);
  if (pmax > 0) p.ymin = pmin / 2.5, p.ymax = pmax * 2.5;
  p.extra = value_tics("x", v0s) + "set mxtics 10\n";
  if (pmax > 0) p.extra += log_tics("y", p.ymin, p.ymax);

  const auto speeds = by_speed(traces);
  PlotBlock points;
  points.title = "peaks: v0 (cm/s), peak F (dyne), its depth (cm)";
  points.columns = {"v0", "peak_F", "peak_z"};
  const bool ens = run.opt.ensemble && ens_study && ens_study->ensemble_peaks_done;
  if (ens) {
    ensemble_peak_series(groups, ens_study->ensemble_peaks, r, p);
    for (const auto &c : r.curves) points.rows.push_back({c.v0, c.peak, c.peak_z});
    r.peak_law = ens_study->ensemble_peak_law;
  }
  for (std::size_t gi = 0; gi < speeds.size() && !ens; ++gi) {
    PlotSeries s;
    s.style = "points", s.colour = plot_colour((int) gi), s.point_size = 1.6;
    s.title = v0_text(traces[speeds[gi][0]].tr.v0) + (speeds[gi].size() > 1 ? " (" + std::to_string(speeds[gi].size()) + " runs)" : "");
    for (int i : speeds[gi]) {
      const auto &c = r.curves[i];
      points.rows.push_back({c.v0, c.peak, c.peak_z});
      if (c.peak > 0) s.x.push_back(c.v0), s.y.push_back(c.peak);
    }
    p.series.push_back(s);
  }
  Json law = {{"peak_ok", false}};
  PlotBlock fitblk;
  fitblk.title = ens ? "peak law (granpen collapse --ensemble): over the ensembles' peaks; se, ci95 from the bootstrap over runs"
                     : "peak law (granpen collapse): F_peak = prefactor * v0^exponent; exponent_ci95 = t95 * se";
  fitblk.columns = {"exponent", "exponent_se", "exponent_ci95", "prefactor", "n"};
  std::string title = "Transient peak against speed";
  if (r.peak_law.ok) {
    const double pref = r.peak_law.prefactor;
    PlotGuide fit;
    fit.expression = gp_number(pref) + "*x**" + gp_number(r.peak_law.exponent);
    fit.title = "fit: F_{peak} ∝ v_0^{" + fmt("%.2f", r.peak_law.exponent) + " ± " + fmt("%.2f", r.peak_law.exponent_ci95) + "} (95%" +
                (ens ? ", over runs)" : ")");
    fit.colour = "#000000", fit.dash = 1, fit.line_width = 2;
    PlotGuide sq;
    sq.expression = gp_number(r.peak_law.v2_prefactor) + "*x**2";
    sq.title = "∝ v_0^2 guide (paper)";
    sq.colour = "#808080", sq.dash = 2;
    p.guides = {fit, sq};
    fitblk.rows.push_back({r.peak_law.exponent, r.peak_law.exponent_se, r.peak_law.exponent_ci95, pref, (double) r.peak_law.points});
    title += ": exponent " + fmt("%.2f", r.peak_law.exponent) + " ± " + fmt("%.2f", r.peak_law.exponent_ci95) + " (95%; paper: 2)";
    law = {{"peak_ok", true}, {"exponent", num("%.10g", r.peak_law.exponent)}, {"exponent_se", num("%.10g", r.peak_law.exponent_se)},
           {"exponent_ci95", num("%.10g", r.peak_law.exponent_ci95)}, {"prefactor", num("%.10g", pref)}, {"n", r.peak_law.points}};
  } else {
    run.notes.push_back("peak law: needs at least 3 peaks over 2 or more speeds; points only");
    title += " (too few speeds for a power law)";
  }
  SeriesFigure fig;
  fig.name = "peak";
  fig.title = title;
  fig.about = "granpen plot peak: the transient peak (max F over 0 < z < 0.7 R) of each trace against v0, log-log;\n"
              "the power law fitted by granpen collapse (least squares of ln F_peak on ln v0) and a v0^2 guide.";
  fig.width = 1050, fig.height = 650;
  fig.panels = {p};
  PlotFiles f = series_figure(fig);
  f.add_block(points);
  f.add_block(fitblk);
  run.make(f);
  run.numbers.update(law);
  Json pts = Json::array();
  for (const auto &c : r.curves)
    pts.push_back({{"file", c.name}, {"v0", num("%.10g", c.v0)}, {"peak_F", num("%.10g", c.peak)}, {"peak_z", num("%.6g", c.peak_z)}});
  run.numbers["peaks"] = pts;
}

// ---------------------------------------------------------------- kz

namespace {

struct K {
  double v0, k, se;
  std::string file, label;
};

// --ensemble: k_z of each ensemble's mean +- its se over runs (one group per ensemble), and
// each run's own k_z in singles (the study's run fits)
void ensemble_kz(const std::vector<TraceGroup> &groups, const FitStudy &st, Run &run, std::vector<std::vector<K>> &per,
                 PlotSeries &singles, Json &json_fits)
{
  for (std::size_t gi = 0; gi < groups.size(); ++gi) {
    const TraceGroup &g = groups[gi];
    const EnsembleFit &e = st.ensembles[gi];
    if (!e.k_z.ok) {
      run.notes.push_back("ensemble " + g.label() + ": k_z undefined on its mean; left out");
      continue;
    }
    if (e.fit.window_shortened) run.notes.push_back("ensemble " + g.label() + ": " + e.fit.notes.front());
    per.push_back({{g.v0, e.k_z.value, e.k_z.se, g.label(), std::to_string(g.mean.runs) + " runs"}});
    Json j = ensemble_json(g);
    j["k_z"] = estimate_json(e.k_z);
    json_fits.push_back(j);
    // each run on the ensemble's aligned bins: their mean is the ensemble's k_z (a linear fit)
    for (const TraceFit &f : st.run_fits[gi])
      if (f.slope_ok) singles.x.push_back(g.v0), singles.y.push_back(f.k_z);
  }
}

}    // namespace

void plot_kz(const std::vector<TraceIn> &traces, const std::vector<TraceGroup> &ensembles, const FitStudy &st, Run &run)
{
  if (traces.empty()) return;
  const auto groups = by_speed(traces);
  std::vector<std::vector<K>> per(groups.size());
  double kmax = 0, sum = 0, sum2 = 0;
  int n = 0;
  std::vector<double> v0s;
  Json json_fits = Json::array();
  PlotSeries singles;    // --ensemble: each run's own k_z, small
  singles.style = "points", singles.colour = "#808080", singles.point_type = 6, singles.point_size = 0.9;
  if (run.opt.ensemble) {
    per.clear();
    ensemble_kz(ensembles, st, run, per, singles, json_fits);
    for (const auto &g : per)
      for (const auto &k : g) {
        kmax = std::max(kmax, std::fabs(k.k) + k.se);
        sum += k.k, sum2 += k.k * k.k, ++n;
        v0s.push_back(k.v0);
      }
    for (double y : singles.y) kmax = std::max(kmax, std::fabs(y));
  }
  for (std::size_t gi = 0; gi < groups.size() && !run.opt.ensemble; ++gi)
    for (int i : groups[gi]) {
      const auto &t = traces[i];
      const TraceFit &fit = st.fits[i].fit;
      if (fit.window_shortened) run.notes.push_back(t.file + ": " + fit.notes.front());
      if (!fit.slope_ok) {
        run.notes.push_back(t.file + ": k_z undefined over the window, left out: " +
                               (fit.notes.empty() ? std::string("no fit") : fit.notes.front()));
        continue;
      }
      per[gi].push_back({t.tr.v0, fit.k_z, fit.k_z_se, t.file, t.label});
      kmax = std::max(kmax, std::fabs(fit.k_z) + fit.k_z_se);
      sum += fit.k_z, sum2 += fit.k_z * fit.k_z, ++n;
      v0s.push_back(t.tr.v0);
      json_fits.push_back({{"file", t.file}, {"v0", num("%.10g", t.tr.v0)}, {"k_z", num("%.10g", fit.k_z)},
                           {"k_z_se", num("%.10g", fit.k_z_se)}, {"z_first", num("%.6g", fit.z_first)},
                           {"z_last", num("%.6g", fit.z_last)}});
    }
  if (n == 0) {
    run.problems.push_back("no trace with k_z over the window " + window_text(run.opt));
    return;
  }
  const AxisScale ys = axis_scale(kmax, "dyne/cm");
  const double mean = sum / n, sd = n > 1 ? std::sqrt(std::max(0.0, (sum2 - n * mean * mean) / (n - 1))) : 0.0;
  SeriesPanel p;
  p.logx = true;
  p.xlabel = "rod speed v_0 (cm/s)";
  p.ylabel = "depth coefficient k_z (" + ys.unit + ")";
  double kmin = 0;
  for (const auto &g : per)
    for (const auto &k : g) kmin = std::min(kmin, k.k - k.se);
  for (double y : singles.y) kmin = std::min(kmin, y);
  p.ymin = kmin < 0 ? 1.1 * kmin / ys.factor : 0.0;    // negative fits are drawn, not cut off
  std::sort(v0s.begin(), v0s.end());
  p.xmin = v0s.front() / 1.35, p.xmax = v0s.back() * 1.35;
  p.extra = value_tics("x", v0s) + "set mxtics 10\nset offsets 0, 0, graph 0.1, 0\n";
  p.key_title = run.opt.ensemble ? "ensemble means ± se over runs;\nopen circles: each run, aligned" : "runs of one v_0 side by side";
  if (kmin < 0) p.extra += "set xzeroaxis lt 1 lw 1 lc rgb \"#606060\"\n";
  PlotHBand hb;
  hb.lo = (mean - sd) / ys.factor, hb.hi = (mean + sd) / ys.factor;
  hb.title = "mean ± sd over the " + std::to_string(n) + (run.opt.ensemble ? " ensembles" : " traces");
  hb.colour = "#606060";
  if (n > 1) p.hbands.push_back(hb);
  PlotGuide mg;
  mg.expression = gp_number(mean / ys.factor);
  mg.title = "mean k_z = " + sci(mean) + " dyne/cm";
  p.guides.push_back(mg);
  for (std::size_t gi = 0; gi < per.size(); ++gi) {
    if (per[gi].empty()) continue;
    PlotSeries s;
    s.style = "points", s.colour = plot_colour((int) gi), s.point_size = 1.4, s.line_width = 1.5;
    s.title = v0_text(per[gi][0].v0) + (run.opt.ensemble ? " (" + per[gi][0].label + ")"
                                        : per[gi].size() > 1 ? " (" + std::to_string(per[gi].size()) + " runs)" : "");
    const std::size_t m = per[gi].size();
    for (std::size_t j = 0; j < m; ++j) {
      const double shift = std::pow(1.04, double(j) - 0.5 * (m - 1));
      s.x.push_back(per[gi][j].v0 * shift), s.y.push_back(per[gi][j].k / ys.factor);
      s.y_err.push_back(per[gi][j].se / ys.factor);
    }
    p.series.push_back(s);
  }
  if (!singles.x.empty()) {
    for (auto &y : singles.y) y /= ys.factor;
    singles.title = "single runs";
    p.series.push_back(singles);
  }
  SeriesFigure fig;
  fig.name = "kz";
  fig.title = "Depth coefficient against speed (fit over " + window_text(run.opt) + "; bars: standard errors" +
              (run.opt.ensemble ? " over runs)" : ")");
  fig.about = "granpen plot kz: k_z of each trace (granpen fit's linear fit of F on z over the window) with its\n"
              "standard error, against v0; runs of one v0 drawn side by side (x scaled by 1.04 per run);\n"
              "k_z in " + ys.unit + ".";
  fig.width = 1050, fig.height = 620;
  fig.panels = {p};
  run.make(series_figure(fig));
  run.numbers["k_z_unit"] = "dyne/cm";
  run.numbers["window"] = {{"zmin", num("%g", run.opt.kz_zmin)},
                           {"zmax", std::isfinite(run.opt.kz_zmax) ? num("%g", run.opt.kz_zmax) : Json()}};
  run.numbers["k_z_mean"] = num("%.10g", mean), run.numbers["k_z_sd"] = num("%.10g", sd);
  run.numbers["fits"] = json_fits;
}

}    // namespace figures
}    // namespace granpen
