// granpen analysis: the figure kinds of granpen plot, each a function from its inputs
// (traces, or the tables of granpen flow and granpen momentum) to figures written by
// io/plot_writer and the numbers drawn (figures_trace.cpp: force, ratio, peak, kz;
// figures_flow.cpp: flow and momentum; figures_scaling.cpp: scaling). ratio and peak draw
// the results of core/collapse_study.h they are given (the CLI runs the study).
#ifndef GRANPEN_FIGURES_H
#define GRANPEN_FIGURES_H

#include "collapse.h"
#include "collapse_study.h"
#include "collapse_tables.h"
#include "ensemble_tables.h"
#include "ensemble_average.h"
#include "ensemble_fit.h"
#include "json_writer.h"
#include "plot_writer.h"

#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace granpen {
namespace figures {

struct Options {
  std::string out;              // --out DIR
  bool run = true;              // --no-run: scripts and data only
  bool each = false;            // force: every run instead of mean and band
  double kz_zmin = 3.0, kz_zmax = INFINITY;    // k_z window (cm), as granpen fit / collapse
  double alpha = 0.0, mu = 0.0, rho = 0.0;     // ratio: F_z from alpha, as granpen collapse
  CollapseParams collapse;      // --band, --tbin, --zmin
  double D = 0.0;               // flow: rod diameter when the tables do not say (cm)
  bool ensemble = false;        // force, ratio, peak, kz: runs of one (v0, g, D) averaged
  EnsembleParams ens;           // its bins
  BootstrapParams boot;         // its uncertainties
};

// What one invocation made: the figures' outcomes, problems with the inputs (each a
// line naming the file), notes, and the kind's numbers (a JSON object).
struct Run {
  Options opt;
  std::vector<PlotResult> figures;
  std::vector<std::string> problems, notes;
  Json numbers = Json::object();
  void make(const PlotFiles &f)
  {
    figures.push_back(write_plot(opt.out, f, opt.run));
    notes.insert(notes.end(), f.notes.begin(), f.notes.end());
  }
  // a series figure: its name, title, the about text of its script, size in pixels, the
  // panels, and the screen fraction of their grid (the rest: the key column)
  void make_series(const std::string &name, const std::string &title, const std::string &about, int width, int height,
                   std::vector<SeriesPanel> panels, double grid_width = 1.0)
  {
    SeriesFigure f;
    f.name = name, f.title = title, f.about = about, f.width = width, f.height = height;
    f.panels = std::move(panels), f.grid_width = grid_width;
    make(series_figure(f));
  }
};

// A trace of the figures: its file, its legend label ("seed 1", "run 2" or the file's
// stem), the trace in cgs.
struct TraceIn {
  std::string file, label;
  Trace tr;
};
// The traces of the inputs (files or folders); each one unreadable a problem of the run.
std::vector<TraceIn> load_traces(const std::vector<std::string> &inputs, Run &run);
// The depth term of ratio (the k_z window, or alpha with mu and rho), as granpen collapse's.
DepthTerm depth_term_of(const Options &o);

void plot_force(const std::vector<std::string> &inputs, Run &run);
// The ratio of the study's collapse: of the traces (stage collapse; the depth terms' notes
// worded here) or, with --ensemble, of the groups' means (stage ensembles). A refused study
// is a problem of the run.
void plot_ratio(const std::vector<TraceIn> &traces, const std::vector<TraceGroup> &groups, const CollapseStudy &s,
                Run &run);
// The peaks of every trace (the study's stage peaks) and with --ensemble those of the
// groups' means (ens_study: a study of the groups that ran stage ensemble_peaks; null: none).
void plot_peak(const std::vector<TraceIn> &traces, const CollapseResult &peaks, const std::vector<TraceGroup> &groups,
               const CollapseStudy *ens_study, Run &run);
void plot_kz(const std::vector<std::string> &inputs, Run &run);
void plot_flow(const std::vector<std::string> &inputs, Run &run);
void plot_momentum(const std::vector<std::string> &inputs, Run &run);
void plot_scaling(const std::vector<std::string> &inputs, Run &run);

// A power of ten for an axis of values up to maxabs: factor 10^e (e >= 3, else 1)
// and the unit text, e.g. "10^{5} dyne".
struct AxisScale {
  double factor = 1.0;
  std::string unit;
};
AxisScale axis_scale(double maxabs, const std::string &unit);

std::string fmt(const char *f, double v);    // printf one number
Json num(const char *f, double v);           // a JSON number rounded as printf's f would (json_rounded)
std::string sci(double v);                   // 2.94×10^{4} (enhanced text); plain below 1e4
// labelled tics of a log axis over [lo, hi] at 1, 2, 5 x 10^e (only 10^e when that
// makes more than 9), labels 10^{e} style or plain %g
std::string log_tics(const char *axis, double lo, double hi, bool plain = false);

}    // namespace figures
}    // namespace granpen

#endif
