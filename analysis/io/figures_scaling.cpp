// granpen analysis: the figure of granpen plot scaling TABLE (figures.h): quantities
// measured at several grain size ratios D/d_g (or box widths), each in its own panel with the
// paper's value, to show whether a difference from the paper closes, stays or grows with the
// table's axis: its column D_over_dg, or box_cm for the box series.
#include "figures.h"

#include "csv_table.h"
#include "errors.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace granpen {
namespace figures {

namespace {

// the axes a table may have (its x column), with their axis labels
struct Axis {
  const char *column, *label;
};
constexpr Axis kAxes[] = {{"D_over_dg", "D/d_g"}, {"box_cm", "box width (cm)"}};

// one series of a quantity (the table's column series: e.g. the grains the boxes were filled
// with), its measured points in the table's order
struct Line {
  std::size_t series = 0;    // index into the table's series, in order of first appearance
  std::vector<double> ratio, value, error;
};

struct Quantity {
  std::string name, label, unit;
  std::vector<Line> lines;              // in order of first appearance within the quantity
  std::vector<double> ratios_listed;    // every row's D/d_g, measured or not (the x range)
  double paper = NAN, paper_error = 0.0;
  bool measured() const
  {
    return std::any_of(lines.begin(), lines.end(), [](const Line &l) { return !l.ratio.empty(); });
  }
};

// How each series is drawn, in order: red is the paper's, so it is not among them; the
// words name the look in the figure's title, which is the legend
struct SeriesLook {
  int colour, point_type;
  const char *words;
};
constexpr SeriesLook kLooks[] = {{0, 7, "blue circles"},     {2, 5, "green squares"}, {3, 9, "orange triangles"},
                                 {4, 13, "purple diamonds"}, {5, 11, "brown triangles"}};
constexpr std::size_t kMaxSeries = sizeof kLooks / sizeof kLooks[0];

// a number rounded as printf's f would, null when not finite (not measured, no paper value)
Json num_or_null(const char *f, double v) { return std::isfinite(v) ? num(f, v) : Json(nullptr); }

// the quantities of the table in the order of their first row; a problem of the run (named
// file:line) for a row that contradicts an earlier one's paper value
std::vector<Quantity> quantities_of(const CsvTable &t, const Axis &axis, std::vector<std::string> &series, Run &run)
{
  const auto names = t.text("quantity");
  const auto ratio = t.numbers(axis.column, false), value = t.numbers("value"), error = t.numbers("error");
  const auto paper = t.has("paper") ? t.numbers("paper") : std::vector<double>(names.size(), NAN);
  const auto paper_err = t.has("paper_error") ? t.numbers("paper_error") : std::vector<double>(names.size(), NAN);
  const auto unit = t.has("unit") ? t.text("unit") : std::vector<std::string>(names.size());
  const auto label = t.has("label") ? t.text("label") : std::vector<std::string>(names.size());
  const auto series_of = t.has("series") ? t.text("series") : std::vector<std::string>(names.size());
  std::vector<Quantity> q;
  std::map<std::string, std::size_t> at;
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::string where = t.path + ":" + std::to_string(t.lines[i]);
    if (names[i].empty()) {
      run.problems.push_back(where + ": no quantity name");
      continue;
    }
    if (!(ratio[i] > 0)) {
      run.problems.push_back(where + ": " + axis.column + " must be positive");
      continue;
    }
    auto it = at.find(names[i]);
    if (it == at.end()) {
      it = at.emplace(names[i], q.size()).first;
      q.push_back(Quantity{names[i], label[i].empty() ? literal_text(names[i]) : label[i], unit[i], {}, {}, NAN, 0.0});
    }
    // the row's series: a new name takes the next look, up to as many as there are looks
    auto named = std::find(series.begin(), series.end(), series_of[i]);
    if (named == series.end()) {
      if (series.size() == kMaxSeries) {
        run.problems.push_back(where + ": series \"" + series_of[i] + "\" is one more than the " + std::to_string(kMaxSeries) +
                               " a figure can tell apart");
        continue;
      }
      named = series.insert(series.end(), series_of[i]);
    }
    const std::size_t k = (std::size_t) (named - series.begin());
    Quantity &x = q[it->second];
    if (std::isfinite(paper[i])) {
      if (std::isfinite(x.paper) && x.paper != paper[i])
        run.problems.push_back(where + ": paper value " + fmt("%g", paper[i]) + " of " + x.name + " differs from " +
                               fmt("%g", x.paper) + " given above");
      x.paper = paper[i];
      if (std::isfinite(paper_err[i])) x.paper_error = std::fabs(paper_err[i]);
    }
    x.ratios_listed.push_back(ratio[i]);
    auto line = std::find_if(x.lines.begin(), x.lines.end(), [&](const Line &l) { return l.series == k; });
    if (line == x.lines.end()) line = x.lines.insert(x.lines.end(), Line{k, {}, {}, {}});
    if (!std::isfinite(value[i])) continue;    // a ratio not measured (yet): no point
    line->ratio.push_back(ratio[i]), line->value.push_back(value[i]);
    line->error.push_back(std::isfinite(error[i]) ? std::fabs(error[i]) : 0.0);
  }
  return q;
}

}    // namespace

void plot_scaling(const std::vector<std::string> &inputs, Run &run)
{
  CsvTable t;
  std::vector<Quantity> qs;
  std::vector<std::string> series;    // the table's series in order of first appearance
  Axis axis = kAxes[0];
  try {
    t = read_csv_table(inputs[0], {"quantity", "value", "error"});
    const Axis *found = nullptr;
    for (const Axis &a : kAxes)
      if (t.has(a.column)) {
        if (found) throw InputError(inputs[0] + ": both " + found->column + " and " + a.column + " columns: one axis per table");
        found = &a;
      }
    if (!found) throw InputError(inputs[0] + ": no axis column (D_over_dg or box_cm)");
    axis = *found;
    if (t.rows.empty()) {
      run.problems.push_back(inputs[0] + ": no rows");
      return;
    }
    qs = quantities_of(t, axis, series, run);
  } catch (InputError &e) {
    run.problems.push_back(e.what());
    return;
  }
  std::vector<SeriesPanel> panels;
  Json numbers = Json::array();
  // the paper's own ratio (or box), marked on every panel when the table says it
  // (# paper_D_over_dg = R, # paper_box_cm = B)
  double paper_ratio = NAN;
  try {
    paper_ratio = t.key_number(std::string("paper_") + axis.column, NAN);
  } catch (InputError &e) {
    run.problems.push_back(e.what());
  }
  // one x range for every panel: every listed ratio (measured or still to come) and the paper's
  double rmin = std::isfinite(paper_ratio) ? paper_ratio : INFINITY, rmax = std::isfinite(paper_ratio) ? paper_ratio : -INFINITY;
  for (const auto &q : qs)
    for (double r : q.ratios_listed) rmin = std::min(rmin, r), rmax = std::max(rmax, r);
  // a margin of half a unit of D/d_g either side, so that no point sits on the frame
  const double xmin = std::floor(rmin - 0.5), xmax = std::ceil(rmax + 0.5);
  const bool named_series = t.has("series");
  // with more than one series, each drawn a little aside (1.2% of the x range apart), so that
  // two series measured in the same box do not hide each other's bars; JSON keeps the true x
  const double dodge = series.size() > 1 ? 0.012 * (xmax - xmin) : 0.0;
  for (const auto &q : qs) {
    if (!q.measured()) {
      run.notes.push_back(q.name + ": no measured value in " + t.path + ": its panel left out");
      continue;
    }
    SeriesPanel p;
    Json pts = Json::array();
    for (const Line &l : q.lines) {
      if (l.ratio.empty()) continue;    // this series not measured for this quantity (yet)
      // points in order of D/d_g, joined, so that the trend reads left to right
      std::vector<std::size_t> o(l.ratio.size());
      for (std::size_t i = 0; i < o.size(); ++i) o[i] = i;
      std::sort(o.begin(), o.end(), [&](std::size_t a, std::size_t b) { return l.ratio[a] < l.ratio[b]; });
      PlotSeries s;
      s.style = "linespoints", s.title = named_series ? series[l.series] : "granpen";
      s.colour = plot_colour(kLooks[l.series].colour), s.point_type = kLooks[l.series].point_type;
      const double aside = dodge * ((double) l.series - 0.5 * (double) (series.size() - 1));
      for (std::size_t i : o) {
        s.x.push_back(l.ratio[i] + aside), s.y.push_back(l.value[i]), s.y_err.push_back(l.error[i]);
        // distance from the paper's value in combined standard errors (NaN without one)
        const double sig = std::sqrt(l.error[i] * l.error[i] + q.paper_error * q.paper_error);
        const double z = std::isfinite(q.paper) && sig > 0 ? (l.value[i] - q.paper) / sig : NAN;
        Json pt = {{axis.column, num("%.6g", l.ratio[i])}, {"value", num("%.6g", l.value[i])},
                   {"error", num("%.6g", l.error[i])}, {"sigmas_from_paper", num_or_null("%.4g", z)}};
        if (named_series) pt["series"] = series[l.series];
        pts.push_back(pt);
      }
      p.series.push_back(s);
    }
    // the paper's value in the title rather than a legend, which would cover points or the line
    p.title = q.label + (std::isfinite(q.paper) ? "   (paper: " + fmt("%g", q.paper) +
                                                      (q.paper_error > 0 ? " ± " + fmt("%g", q.paper_error) : "") + ")"
                                                : "   (no paper value)");
    p.xlabel = axis.label;
    // a long label is the panel's title already: on the y axis it would be cut at the frame
    const std::string y_name = q.label.size() <= 36 ? q.label : q.unit.empty() ? "value" : "";
    p.ylabel = q.unit.empty() ? y_name : (y_name.empty() ? q.unit : y_name + " (" + q.unit + ")");
    p.key = "off";
    p.xmin = xmin, p.xmax = xmax;
    // a y range holding the points, their bars and the paper's value (and band) with a margin
    // of 8%, so that the paper's line never lies on the frame
    double ylo = INFINITY, yhi = -INFINITY;
    for (const PlotSeries &s : p.series)
      for (std::size_t i = 0; i < s.y.size(); ++i) ylo = std::min(ylo, s.y[i] - s.y_err[i]), yhi = std::max(yhi, s.y[i] + s.y_err[i]);
    if (std::isfinite(q.paper)) ylo = std::min(ylo, q.paper - q.paper_error), yhi = std::max(yhi, q.paper + q.paper_error);
    const double pad = yhi > ylo ? 0.08 * (yhi - ylo) : 0.1 * std::max(std::fabs(yhi), 1e-12);
    p.ymin = ylo - pad, p.ymax = yhi + pad;
    if (std::isfinite(paper_ratio)) {
      PlotVLine v;
      v.x = paper_ratio, v.label = "paper";
      p.vlines.push_back(v);
    }
    if (std::isfinite(q.paper)) {
      if (q.paper_error > 0) {
        PlotHBand b;
        b.lo = q.paper - q.paper_error, b.hi = q.paper + q.paper_error;
        b.title = "paper: " + fmt("%g", q.paper) + " ± " + fmt("%g", q.paper_error);
        b.colour = "#d62728";
        p.hbands.push_back(b);
      }
      PlotGuide g;
      g.expression = gp_number(q.paper);
      g.title = q.paper_error > 0 ? "" : "paper: " + fmt("%g", q.paper);
      g.colour = "#d62728";
      p.guides.push_back(g);
    }
    panels.push_back(p);
    numbers.push_back({{"quantity", q.name}, {"paper", num_or_null("%.6g", q.paper)}, {"paper_error", num_or_null("%.6g", std::isfinite(q.paper) ? q.paper_error : NAN)},
                       {"points", pts}});
  }
  run.numbers["quantities"] = numbers;
  if (panels.empty()) {
    run.problems.push_back(t.path + ": no quantity has a measured value");
    return;
  }
  SeriesFigure f;
  f.name = "scaling";
  // the axis in words: "the grain size ratio D/d_g", "the box width"
  const bool by_ratio = std::string(axis.column) == "D_over_dg";
  const std::string axis_words = by_ratio ? "the grain size ratio D/d_g" : "the box width";
  const std::string paper_axis = by_ratio ? "D/d_g" : "box";
  // the legend is the title: one key per panel would repeat it and cover points
  std::string granpen = "granpen (blue, ± its error)";
  if (named_series) {
    granpen = "granpen ± its error: ";
    for (std::size_t k = 0; k < series.size(); ++k)
      granpen += (k ? ", " : "") + (series[k].empty() ? std::string("(no series)") : literal_text(series[k])) + " (" +
                 kLooks[k].words + ")";
    granpen += ";\n";
  } else {
    granpen += ", ";
  }
  f.title = "Against " + axis_words + ": " + granpen + "the paper's value (red; shaded: its error)" +
            std::string(std::isfinite(paper_ratio) ? ", the paper's " + paper_axis + " (dotted)" : "");
  f.about = "granpen plot scaling: each quantity of " + t.path + " against " + (by_ratio ? "D/d_g" : "the box width") +
            " with its error bars, and the paper's value (a red line, with its band when it has an error)" +
            (std::isfinite(paper_ratio) ? "; the dotted line: the paper's own " + paper_axis + "." : ".") +
            (dodge > 0 ? " Each series is drawn " + fmt("%.2g", dodge) + " aside of the next in x, so that bars at one x stay apart." : "");
  f.columns = panels.size() > 1 ? 2 : 1;
  const int rows = (int) ((panels.size() + f.columns - 1) / f.columns);
  f.width = f.columns == 1 ? 800 : 1300, f.height = 120 + 380 * rows;
  f.panels = std::move(panels);
  run.make(series_figure(f));
}

}    // namespace figures
}    // namespace granpen
