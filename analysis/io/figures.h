// granpen analysis: the figure kinds of granpen plot, each a function from its inputs
// (traces, or the tables of granpen flow and granpen momentum) to figures written by
// io/plot_writer and the numbers drawn (figures_trace.cpp: force, ratio, peak, kz;
// figures_flow.cpp: flow and momentum; figures_scaling.cpp: scaling; figures_parting.cpp:
// parting). They draw the results
// they are given: ratio and peak those of core/collapse_study.h, force and kz those of
// core/fit_study.h, flow those of core/flow_table_study.h (the CLI runs the studies).
#ifndef GRANPEN_FIGURES_H
#define GRANPEN_FIGURES_H

#include "collapse.h"
#include "collapse_study.h"
#include "collapse_tables.h"
#include "ensemble_tables.h"
#include "ensemble_average.h"
#include "ensemble_fit.h"
#include "fit_study.h"
#include "flow_table_study.h"
#include "momentum_classes.h"
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

// The fit study's inputs: each trace (or with --ensemble each group's mean) with the window of
// its kind: peak (force: the peaks, trace_fit's default window) or kz (the k_z window,
// shortened onto the data, as granpen fit).
enum class FitKind { peak, kz };
TraceFitParams fit_params_of(const Options &o, FitKind w, double v0, double D, double g);
std::vector<FitStudyTrace> fit_study_traces(const std::vector<TraceIn> &traces, const Options &o, FitKind w);
std::vector<FitStudyEnsemble> fit_study_ensembles(const std::vector<TraceGroup> &groups, const Options &o, FitKind w);

// F against z of the traces: per v0 the mean and range of its runs (or every run) with each
// run's peak (the study's stage fits, kind peak), or with --ensemble each group's mean with
// the peak of its fit (stage ensemble_fits; groups[i] is the study's ensemble i).
void plot_force(const std::vector<TraceIn> &traces, const std::vector<TraceGroup> &groups, const FitStudy &st, Run &run);
// The ratio of the study's collapse: of the traces (stage collapse; the depth terms' notes
// worded here) or, with --ensemble, of the groups' means (stage ensembles). A refused study
// is a problem of the run.
void plot_ratio(const std::vector<TraceIn> &traces, const std::vector<TraceGroup> &groups, const CollapseStudy &s,
                Run &run);
// The peaks of every trace (the study's stage peaks) and with --ensemble those of the
// groups' means (ens_study: a study of the groups that ran stage ensemble_peaks; null: none).
void plot_peak(const std::vector<TraceIn> &traces, const CollapseResult &peaks, const std::vector<TraceGroup> &groups,
               const CollapseStudy *ens_study, Run &run);
// k_z against v0: each trace's (stage fits, kind kz), or with --ensemble each group's mean's
// with its se over runs (stage ensemble_fits) and each run's (stage run_fits).
void plot_kz(const std::vector<TraceIn> &traces, const std::vector<TraceGroup> &groups, const FitStudy &st, Run &run);

// granpen plot flow's tables that the flow table study fits (core/flow_table_study.h): the
// profile below the face and phi against I at the edge, read from DIR; what reading them
// noted or found wrong is kept with each and told when it is drawn, so that the run's notes
// keep the figures' order.
struct FlowFitTable {
  bool read = false;    // there, with its columns
  std::string path;
  double D = 0.0;       // the profile's rod diameter (--D, flow.json, a header key, else 2)
  std::vector<std::string> notes, problems;
};
struct FlowFitTables {
  FlowFitTable profile, edge;
  FlowTableColumns columns;          // the study's input
  std::vector<double> profile_phi;   // the profile's phi (drawn, not fitted)
};
FlowFitTables read_flow_fit_tables(const std::string &dir, const Options &o);
// The figures of DIR (inputs[0]): heat maps, the profile and the edge (drawn with the study's
// fits of t), strip, annulus, surface.
void plot_flow(const std::vector<std::string> &inputs, const FlowFitTables &t, const FlowTableStudy &st, Run &run);
// granpen plot momentum's drag table (t~, F, mu g M), read from DIR, with what reading it
// noted or found wrong (told when it is drawn); the CLI compares F with mu g M
// (core/momentum_classes.h compare_drag) and hands the comparison to plot_momentum.
struct MomentumDragTable {
  bool read = false;    // there, with its columns
  std::string path;
  std::vector<double> t_tilde, F, mu_g_M;
  std::vector<std::string> notes, problems;
};
MomentumDragTable read_momentum_drag_table(const std::string &dir, const Options &o);
// The figures of DIR (inputs[0]): the classes against t~, and F against mu g M with cmp.
void plot_momentum(const std::vector<std::string> &inputs, const MomentumDragTable &t, const DragComparison &cmp, Run &run);
void plot_scaling(const std::vector<std::string> &inputs, Run &run);
// granpen parting's JSON files (figures_parting.cpp): each pair's ratio against time after
// contact, the threshold's band, each parting marked.
void plot_parting(const std::vector<std::string> &inputs, Run &run);

// A power of ten for an axis of values up to maxabs: factor 10^e (e >= 3, else 1)
// and the unit text, e.g. "10^{5} dyne".
struct AxisScale {
  double factor = 1.0;
  std::string unit;
};
AxisScale axis_scale(double maxabs, const std::string &unit);

std::string fmt(const char *f, double v);    // printf one number
std::string literal_text(const std::string &s);    // drawn as written: enhanced-text specials escaped
Json num(const char *f, double v);           // a JSON number rounded as printf's f would (json_rounded)
std::string sci(double v);                   // 2.94×10^{4} (enhanced text); plain below 1e4
// labelled tics of a log axis over [lo, hi] at 1, 2, 5 x 10^e (only 10^e when that
// makes more than 9), labels 10^{e} style or plain %g
std::string log_tics(const char *axis, double lo, double hi, bool plain = false);

}    // namespace figures
}    // namespace granpen

#endif
