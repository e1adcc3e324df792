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

struct Quantity {
  std::string name, label, unit;
  std::vector<double> ratio, value, error;
  std::vector<double> ratios_listed;    // every row's D/d_g, measured or not (the x range)
  double paper = NAN, paper_error = 0.0;
};

// a number rounded as printf's f would, null when not finite (not measured, no paper value)
Json num_or_null(const char *f, double v) { return std::isfinite(v) ? num(f, v) : Json(nullptr); }

// the quantities of the table in the order of their first row; a problem of the run (named
// file:line) for a row that contradicts an earlier one's paper value
std::vector<Quantity> quantities_of(const CsvTable &t, const Axis &axis, Run &run)
{
  const auto names = t.text("quantity");
  const auto ratio = t.numbers(axis.column, false), value = t.numbers("value"), error = t.numbers("error");
  const auto paper = t.has("paper") ? t.numbers("paper") : std::vector<double>(names.size(), NAN);
  const auto paper_err = t.has("paper_error") ? t.numbers("paper_error") : std::vector<double>(names.size(), NAN);
  const auto unit = t.has("unit") ? t.text("unit") : std::vector<std::string>(names.size());
  const auto label = t.has("label") ? t.text("label") : std::vector<std::string>(names.size());
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
      q.push_back(Quantity{names[i], label[i].empty() ? literal_text(names[i]) : label[i], unit[i], {}, {}, {}, {}, NAN, 0.0});
    }
    Quantity &x = q[it->second];
    if (std::isfinite(paper[i])) {
      if (std::isfinite(x.paper) && x.paper != paper[i])
        run.problems.push_back(where + ": paper value " + fmt("%g", paper[i]) + " of " + x.name + " differs from " +
                               fmt("%g", x.paper) + " given above");
      x.paper = paper[i];
      if (std::isfinite(paper_err[i])) x.paper_error = std::fabs(paper_err[i]);
    }
    x.ratios_listed.push_back(ratio[i]);
    if (!std::isfinite(value[i])) continue;    // a ratio not measured (yet): no point
    x.ratio.push_back(ratio[i]), x.value.push_back(value[i]);
    x.error.push_back(std::isfinite(error[i]) ? std::fabs(error[i]) : 0.0);
  }
  return q;
}

}    // namespace

void plot_scaling(const std::vector<std::string> &inputs, Run &run)
{
  CsvTable t;
  std::vector<Quantity> qs;
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
    qs = quantities_of(t, axis, run);
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
  for (const auto &q : qs) {
    if (q.ratio.empty()) {
      run.notes.push_back(q.name + ": no measured value in " + t.path + ": its panel left out");
      continue;
    }
    // points in order of D/d_g, joined, so that the trend reads left to right
    std::vector<std::size_t> o(q.ratio.size());
    for (std::size_t i = 0; i < o.size(); ++i) o[i] = i;
    std::sort(o.begin(), o.end(), [&](std::size_t a, std::size_t b) { return q.ratio[a] < q.ratio[b]; });
    PlotSeries s;
    s.style = "linespoints", s.title = "granpen", s.colour = plot_colour(0), s.point_type = 7;
    Json pts = Json::array();
    for (std::size_t i : o) {
      s.x.push_back(q.ratio[i]), s.y.push_back(q.value[i]), s.y_err.push_back(q.error[i]);
      // distance from the paper's value in combined standard errors (NaN without one)
      const double sig = std::sqrt(q.error[i] * q.error[i] + q.paper_error * q.paper_error);
      const double z = std::isfinite(q.paper) && sig > 0 ? (q.value[i] - q.paper) / sig : NAN;
      pts.push_back({{axis.column, num("%.6g", q.ratio[i])}, {"value", num("%.6g", q.value[i])},
                     {"error", num("%.6g", q.error[i])}, {"sigmas_from_paper", num_or_null("%.4g", z)}});
    }
    SeriesPanel p;
    // the paper's value in the title rather than a legend, which would cover points or the line
    p.title = q.label + (std::isfinite(q.paper) ? "   (paper: " + fmt("%g", q.paper) +
                                                      (q.paper_error > 0 ? " ± " + fmt("%g", q.paper_error) : "") + ")"
                                                : "   (no paper value)");
    p.xlabel = axis.label;
    // a long label is the panel's title already: on the y axis it would be cut at the frame
    const std::string y_name = q.label.size() <= 36 ? q.label : q.unit.empty() ? "value" : "";
    p.ylabel = q.unit.empty() ? y_name : (y_name.empty() ? q.unit : y_name + " (" + q.unit + ")");
    p.key = "off";
    // a margin of half a unit of D/d_g either side, so that no point sits on the frame
    p.xmin = std::floor(rmin - 0.5), p.xmax = std::ceil(rmax + 0.5);
    p.series.push_back(s);
    // a y range holding the points, their bars and the paper's value (and band) with a margin
    // of 8%, so that the paper's line never lies on the frame
    double ylo = INFINITY, yhi = -INFINITY;
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
  f.title = "Against " + axis_words + ": granpen (blue, ± its error), the paper's value (red; shaded: its error)" +
            std::string(std::isfinite(paper_ratio) ? ", the paper's " + paper_axis + " (dotted)" : "");
  f.about = "granpen plot scaling: each quantity of " + t.path + " against " + (by_ratio ? "D/d_g" : "the box width") +
            " with its error bars, and the paper's value (a red line, with its band when it has an error)" +
            (std::isfinite(paper_ratio) ? "; the dotted line: the paper's own " + paper_axis + "." : ".");
  f.columns = panels.size() > 1 ? 2 : 1;
  const int rows = (int) ((panels.size() + f.columns - 1) / f.columns);
  f.width = f.columns == 1 ? 800 : 1300, f.height = 120 + 380 * rows;
  f.panels = std::move(panels);
  run.make(series_figure(f));
}

}    // namespace figures
}    // namespace granpen
