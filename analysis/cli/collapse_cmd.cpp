// granpen collapse TRACE-OR-FOLDER...: F/F_z against t~ = (z/v0) sqrt(g/D) over a set of
// traces, the crossover t~*, the collapse quality and the peak law (core/collapse.h).
#include "atomic_file.h"
#include "options.h"
#include "collapse.h"
#include "json_text.h"
#include "collapse_tables.h"
#include "json_writer.h"
#include "subcommands.h"
#include "trace_fit.h"
#include "trace_files.h"
#include "trace_reader.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

using granpen::json_number;

int granpen::cli::run_collapse(const CollapseOptions &o)
{
  const std::string &csv = o.csv, &json = o.json;
  const CollapseParams &p = o.params;
  std::vector<std::string> problems;
  const auto files = expand_trace_paths(o.traces, problems);
  const std::vector<CollapseInput> in = read_collapse_inputs(files, o.depth, problems);

  for (const auto &output : {std::make_pair("--csv", csv), std::make_pair("--json", json)})
    if (!output.second.empty()) refuse_overwriting_inputs(output.second, output.first, files);
  for (const auto &m : problems) std::fprintf(stderr, "granpen collapse: %s\n", m.c_str());
  if (in.empty()) {
    std::fprintf(stderr, "granpen collapse: no usable trace\n");
    return 1;
  }

  const CollapseResult r = granpen::collapse(in, p);
  std::printf("granpen collapse: %zu traces, band 1 +- %g, t~ bins of %g\n", r.curves.size(), p.band, p.tbin);
  for (const auto &c : r.curves)
    std::printf("  %s: v0 = %g cm/s, g = %g, D = %g, k_z = %.4g dyne/cm, peak %.4g dyne at z = %.3g cm, t~* = %s\n",
                c.name.c_str(), c.v0, c.g, c.D, c.k_z, c.peak, c.peak_z,
                c.crossed ? json_number("%.2f", c.t_star).c_str() : "not reached");
  std::printf("crossover: t~* = %.2f +- %.2f over %d of %zu traces (paper: 1)\n", r.t_star_mean, r.t_star_sd,
              r.n_crossed, r.curves.size());
  if (r.ens_crossed)
    std::printf("ensemble crossover: the mean of F/F_z over the traces stays within 1 +- %g from t~* = %.2f "
                "(bins with at least %d traces)\n",
                p.band, r.t_star_ensemble, std::min<int>(p.min_curves, static_cast<int>(r.curves.size())));
  else
    std::printf("ensemble crossover: the mean of F/F_z over the traces does not stay within 1 +- %g\n", p.band);
  std::printf("collapse quality: spread of F/F_z across traces %.3f against z, %.3f against t~ (ratio %.2f)\n",
              r.spread_z, r.spread_t, r.spread_z > 0 ? r.spread_t / r.spread_z : 0.0);
  if (r.peak_ok)
    std::printf("peak law: peak ~ v0^%.2f +- %.2f (95%%; paper: 2)\n", r.peak_exponent, r.peak_exponent_ci95);
  else
    std::printf("peak law: needs at least 3 traces over 2 or more speeds\n");

  if (!csv.empty()) {
    write_file_atomic(csv, collapse_curves_csv(r));
    std::printf("wrote %s\n", csv.c_str());
  }
  if (!json.empty()) {
    write_json(json, collapse_json(r, p), 1);
    std::printf("wrote %s\n", json.c_str());
  }
  return problems.empty() ? 0 : 1;
}
