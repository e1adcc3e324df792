// granpen analysis: the figure of granpen plot parting JSON... (figures.h): two pushes' drag
// ratio in windows of time after contact, as granpen parting wrote it (--json), one curve per
// pair, the band of the threshold about 1, and each pair's parting marked.
#include "figures.h"

#include "errors.h"
#include "json_path.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace granpen {
namespace figures {

namespace {

// a member of a parting JSON as a number; InputError naming the file and member
double number_at(const Json &j, const char *key, const std::string &path)
{
  if (!j.contains(key) || !j[key].is_number()) throw InputError(path + ": no number '" + key + "' (not granpen parting --json output)");
  return j[key].get<double>();
}

}    // namespace

void plot_parting(const std::vector<std::string> &inputs, Run &run)
{
  SeriesPanel p;
  Json numbers = Json::array();
  double threshold = NAN, tend = 0, tlate = 0;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const std::string &path = inputs[i];
    PlotSeries s, mark;
    Json row;
    try {
      const Json j = read_json_file(path);
      if (!j.contains("windows") || !j["windows"].is_array()) throw InputError(path + ": no 'windows' (not granpen parting --json output)");
      const double thr = number_at(j, "threshold", path);
      if (std::isfinite(threshold) && thr != threshold)
        throw InputError(path + ": threshold " + fmt("%g", thr) + ", not the " + fmt("%g", threshold) + " of the files before it");
      threshold = thr;
      for (const auto &w : j["windows"]) {
        if (!w.is_object() || !w.contains("ratio") || w["ratio"].is_null()) continue;    // no ratio: no point
        const double lo = number_at(w, "t_lo_ms", path), hi = number_at(w, "t_hi_ms", path), r = number_at(w, "ratio", path);
        s.x.push_back(0.5 * (lo + hi)), s.y.push_back(r);
        tend = std::max(tend, hi);
      }
      const bool parted = j.contains("parted") && j["parted"].is_boolean() && j["parted"].get<bool>();
      const std::string stem = std::filesystem::path(path).stem().string();
      s.title = literal_text(stem) + (parted ? ": parts at " + fmt("%g", number_at(j, "t_part_ms", path)) + " ms" : ": does not part");
      s.style = "linespoints", s.colour = plot_colour(int(i)), s.point_type = 7, s.point_size = 0.7, s.line_width = 1.5;
      row = {{"file", path}, {"parted", parted}, {"t_part_ms", parted ? num("%.6g", number_at(j, "t_part_ms", path)) : Json(nullptr)}};
      if (parted) {
        // the parting: an open circle on the curve, at the window where it begins
        const double t = number_at(j, "t_part_ms", path), r = number_at(j, "ratio_at_part", path);
        const double w = number_at(j, "window_ms", path);
        mark.x = {t + 0.5 * w}, mark.y = {r};
        tlate = std::max(tlate, t + w);
        mark.style = "points", mark.colour = s.colour, mark.point_type = 6, mark.point_size = 2.2, mark.title = "";
      }
    } catch (InputError &e) {
      run.problems.push_back(e.what());
      continue;
    }
    if (s.x.empty()) {
      run.notes.push_back(path + ": no window with a ratio: left out");
      continue;
    }
    p.series.push_back(s);
    if (!mark.x.empty()) p.series.push_back(mark);
    numbers.push_back(row);
  }
  run.numbers["pairs"] = numbers;
  if (p.series.empty()) {
    run.problems.push_back("no parting to draw");
    return;
  }
  PlotHBand b;
  b.lo = 1 - threshold, b.hi = 1 + threshold;
  b.title = "within ±" + fmt("%g", 100 * threshold) + "%";
  p.hbands.push_back(b);
  PlotGuide one;    // the line A / B = 1, the library's grey dashes, no key entry
  one.expression = "1";
  p.guides.push_back(one);
  p.xlabel = "time after contact (ms)";
  p.ylabel = "drag A / B, mean per window";
  // to three times the latest parting (the echo has come and gone; a slow pair's later
  // windows would squeeze the partings into the left edge), or to the data's end
  p.xmin = 0, p.xmax = tlate > 0 ? std::min(tend, 3 * tlate) : tend;
  double rlo = 1 - threshold, rhi = 1 + threshold;
  for (const auto &s : p.series)
    for (std::size_t k = 0; k < s.x.size(); ++k)
      if (s.x[k] <= p.xmax) rlo = std::min(rlo, s.y[k]), rhi = std::max(rhi, s.y[k]);
  const double pad = 0.05 * (rhi - rlo);
  p.ymin = rlo - pad, p.ymax = rhi + pad;
  p.key = "column";
  SeriesFigure f;
  f.name = "parting";
  f.title = "When two pushes part: A / B in windows after contact (open circle: the parting)";
  f.about = "granpen plot parting: the ratio of two pushes' mean drag in windows of time after contact, one curve per "
            "granpen parting --json file, the band of its threshold about 1, and each pair's parting (the first of its "
            "windows in a row beyond the threshold) as an open circle.";
  f.width = 1300, f.height = 620;
  f.grid_width = 0.64;    // the key column: room for "bench_12_20_s11_v280: parts at 4 ms"
  f.panels = {p};
  run.make(series_figure(f));
}

}    // namespace figures
}    // namespace granpen
