// granpen plot KIND INPUTS... --out DIR: the paper's figure types as gnuplot scripts
// with their data beside them, run to PNG and SVG (io/figures.h, io/plot_writer.h):
// parse, make the figures, write KIND.json.
#include "atomic_file.h"
#include "plot_options.h"
#include "figures.h"
#include "json_writer.h"
#include "subcommands.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
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

  if (kind == "force") plot_force(inputs, run);
  else if (kind == "ratio") plot_ratio(inputs, run);
  else if (kind == "peak") plot_peak(inputs, run);
  else if (kind == "kz") plot_kz(inputs, run);
  else if (kind == "flow") plot_flow(inputs, run);
  else if (kind == "momentum") plot_momentum(inputs, run);
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
