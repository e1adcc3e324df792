// granpen plot KIND INPUTS... --out DIR: the paper's figure types as gnuplot scripts
// with their data beside them, run to PNG and SVG (io/figures.h, io/plot_writer.h):
// parse, make the figures (read; run the study: ratio and peak core/collapse_study.h, force
// and kz core/fit_study.h, flow core/flow_table_study.h; draw), write KIND.json.
#include "atomic_file.h"
#include "plot_options.h"
#include "collapse_study.h"
#include "collapse_tables.h"
#include "ensemble_groups.h"
#include "ensemble_tables.h"
#include "figures.h"
#include "fit_study.h"
#include "flow_table_study.h"
#include "json_writer.h"
#include "subcommands.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;


// Problems, notes and each figure's outcome on the terminal; the number that failed.
int report_figures(const granpen::figures::Run &run)
{
  for (const auto &p : run.problems) std::fprintf(stderr, "granpen plot: %s\n", p.c_str());
  for (const auto &n : run.notes) std::printf("note: %s\n", n.c_str());
  int failed = 0;
  for (const auto &f : run.figures) {
    if (!f.ok()) {
      ++failed;
      std::fprintf(stderr, "granpen plot: %s\n", f.error.c_str());
    } else if (f.ran) {
      std::printf("wrote %s and %s (script %s, data %s)\n", f.png.c_str(), f.svg.c_str(), f.script.c_str(), f.data.c_str());
    } else {
      std::printf("wrote %s and %s (not run: --no-run)\n", f.script.c_str(), f.data.c_str());
    }
  }
  return failed;
}

// DIR/KIND.json: the figures and the numbers drawn
granpen::Json plot_record(const std::string &kind, const granpen::figures::Run &run)
{
  granpen::Json j;
  j["tool"] = "granpen plot";
  j["kind"] = kind;
  j["out"] = run.opt.out;
  j["figures"] = granpen::Json::array();
  for (const auto &f : run.figures)
    j["figures"].push_back({{"name", fs::path(f.script).stem().string()}, {"script", f.script}, {"data", f.data},
                            {"png", f.png}, {"svg", f.svg}, {"made", f.ran}, {"error", f.error}});
  j["numbers"] = run.numbers;
  j["problems"] = run.problems;
  j["notes"] = run.notes;
  return j;
}

// --ensemble: the runs of each (v0, g, D) averaged; a group that cannot be, a problem of the run
std::vector<granpen::TraceGroup> averaged_groups(const std::vector<granpen::figures::TraceIn> &traces,
                                                 granpen::figures::Run &run)
{
  std::vector<granpen::Trace> tr;
  for (const auto &t : traces) tr.push_back(t.tr);
  return granpen::cli::averaged_groups(tr, run.opt.ens, run.problems);
}

// force and kz: the fit study of the traces (kind: the window of the figure), or with
// --ensemble of their groups' means (kz: and of each run on its mean's bins)
void fitted(const std::vector<std::string> &inputs, granpen::figures::Run &run, granpen::figures::FitKind kind)
{
  using namespace granpen;
  const auto traces = figures::load_traces(inputs, run);
  if (traces.empty()) return;
  const bool ens = run.opt.ensemble;
  std::vector<TraceGroup> groups;
  if (ens) groups = averaged_groups(traces, run);
  FitStages st;
  st.fits = !ens, st.ensemble_fits = ens, st.run_fits = ens && kind == figures::FitKind::kz;
  FitStudyParams sp;
  sp.boot = run.opt.boot;
  const FitStudy s = run_fit_study(ens ? std::vector<FitStudyTrace>() : figures::fit_study_traces(traces, run.opt, kind),
                                   figures::fit_study_ensembles(groups, run.opt, kind), sp, st);
  for (const auto &f : s.fits)    // arrays the fit refuses: the command's error, as the kernel's
    if (f.refused) throw std::invalid_argument(f.why);
  if (kind == figures::FitKind::peak) figures::plot_force(traces, groups, s, run);
  else figures::plot_kz(traces, groups, s, run);
}

// flow: the tables of granpen flow read, the flow table study's fits of them, the figures
void flow_figures(const std::vector<std::string> &inputs, granpen::figures::Run &run)
{
  const granpen::figures::FlowFitTables t = granpen::figures::read_flow_fit_tables(inputs[0], run.opt);
  granpen::figures::plot_flow(inputs, t, granpen::run_flow_table_study(t.columns), run);
}

// momentum: the drag table read, F compared with mu g M (core), the figures
void momentum_figures(const std::vector<std::string> &inputs, granpen::figures::Run &run)
{
  const granpen::figures::MomentumDragTable t = granpen::figures::read_momentum_drag_table(inputs[0], run.opt);
  granpen::figures::plot_momentum(inputs, t, granpen::compare_drag(t.mu_g_M, t.F), run);
}

// the study's traces, named by their files
std::vector<granpen::CollapseTrace> study_traces(const std::vector<granpen::figures::TraceIn> &traces,
                                                 const granpen::DepthTerm &dt)
{
  std::vector<granpen::Trace> tr;
  for (const auto &t : traces) tr.push_back(t.tr);
  auto out = granpen::collapse_traces(tr, dt);
  for (std::size_t i = 0; i < out.size(); ++i) out[i].name = traces[i].file;
  return out;
}

// ratio: the collapse of the traces, or with --ensemble of their groups' means
void ratio(const std::vector<std::string> &inputs, granpen::figures::Run &run)
{
  using namespace granpen;
  const auto traces = figures::load_traces(inputs, run);
  const DepthTerm dt = figures::depth_term_of(run.opt);
  const bool ens = run.opt.ensemble;
  std::vector<TraceGroup> groups;
  if (ens) groups = averaged_groups(traces, run);
  CollapseStages st;
  st.collapse = !ens, st.ensembles = ens;
  const CollapseStudy s = run_collapse_study(ens ? std::vector<CollapseTrace>() : study_traces(traces, dt),
                                             collapse_ensemble_inputs(groups, dt),
                                             collapse_study_params(run.opt.collapse, dt, run.opt.boot), st);
  figures::plot_ratio(traces, groups, s, run);
}

// peak: the peaks of every trace, and with --ensemble those of the groups' means
void peak(const std::vector<std::string> &inputs, granpen::figures::Run &run)
{
  using namespace granpen;
  const auto traces = figures::load_traces(inputs, run);
  if (traces.empty()) return;
  const DepthTerm dt = figures::depth_term_of(run.opt);
  const CollapseStudyParams sp = collapse_study_params(run.opt.collapse, dt, run.opt.boot);
  CollapseStages st;
  st.collapse = false, st.peaks = true;
  const CollapseStudy s = run_collapse_study(study_traces(traces, dt), {}, sp, st);
  if (s.refused) {
    run.problems.push_back(s.refusal);
    return;
  }
  std::vector<TraceGroup> groups;
  CollapseStudy es;
  if (run.opt.ensemble) {
    groups = averaged_groups(traces, run);
    CollapseStages est;
    est.collapse = false, est.ensemble_peaks = true;
    es = run_collapse_study({}, collapse_ensemble_inputs(groups, dt), sp, est);
    if (es.refused) throw std::invalid_argument(es.refusal);
  }
  figures::plot_peak(traces, s.peaks, groups, run.opt.ensemble ? &es : nullptr, run);
}

}    // namespace

int granpen::cli::run_plot(const PlotOptions &po)
{
  using namespace granpen::figures;
  Run run;
  run.opt = po.figures;
  const Options &o = run.opt;
  const std::string &kind = po.kind;
  const std::vector<std::string> &inputs = po.inputs;
  // DIR/KIND.json must not be one of the inputs (plot flow DIR --out DIR: DIR/flow.json)
  std::vector<std::string> input_files;
  for (const auto &in : inputs) {
    std::error_code ec;
    if (fs::is_directory(in, ec))
      for (const auto &e : fs::directory_iterator(in, ec)) input_files.push_back(e.path().string());
    else input_files.push_back(in);
  }
  refuse_overwriting_inputs((fs::path(o.out) / (kind + ".json")).string(), "--out", input_files);

  if (kind == "force") fitted(inputs, run, FitKind::peak);
  else if (kind == "ratio") ratio(inputs, run);
  else if (kind == "peak") peak(inputs, run);
  else if (kind == "kz") fitted(inputs, run, FitKind::kz);
  else if (kind == "flow") flow_figures(inputs, run);
  else if (kind == "momentum") momentum_figures(inputs, run);
  else if (kind == "parting") plot_parting(inputs, run);
  else plot_scaling(inputs, run);

  const int failed = report_figures(run);
  if (run.figures.empty()) {    // nothing is created for inputs that could not be read
    std::fprintf(stderr, "granpen plot: no figure made\n");
    return EXIT_FAILED;
  }
  make_output_dir(o.out);
  const std::string jpath = (fs::path(o.out) / (kind + ".json")).string();
  write_json(jpath, plot_record(kind, run), 1);
  std::printf("wrote %s\n", jpath.c_str());
  return (failed || !run.problems.empty()) ? EXIT_FAILED : EXIT_OK;
}

int granpen::cli::plot(int argc, char **argv) { return run_parsed(parse_plot, run_plot, argc, argv); }
