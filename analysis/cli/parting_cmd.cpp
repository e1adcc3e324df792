// granpen parting A B: when two pushes part (core/trace_parting.h), a line per window and
// the verdict; --json the same as JSON.
#include "atomic_file.h"
#include "errors.h"
#include "json_text.h"
#include "json_writer.h"
#include "parting_options.h"
#include "subcommand.h"
#include "subcommands.h"
#include "trace_parting.h"
#include "trace_reader.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

namespace {

using granpen::json_number;
using granpen::Json;
using granpen::json_rounded;

std::string ms(double s) { return json_number("%.4g", s * 1e3); }

std::string verdict_line(const granpen::Parting &p, const granpen::cli::PartingOptions &o)
{
  const std::string within = "within " + json_number("%.2g", p.largest_before) + " of 1";
  if (!p.parted) {
    const double end = p.windows.empty() ? 0.0 : p.windows.back().t_hi;
    return "not parted over " + std::to_string(p.windows.size()) + " windows (to " + ms(end) + " ms after contact): " + within;
  }
  std::string ratios;
  for (long long k = 0; k < o.sustain; ++k)
    ratios += (k ? ", " : "") + json_number("%.3g", p.windows[p.first + std::size_t(k)].ratio);
  return "parted at " + ms(p.t_part) + " ms after contact (z = " + json_number("%.3g", p.z_part) + " cm in B): A / B = " +
         ratios + "; before it " + within;
}

Json parting_json(const granpen::Parting &p, const granpen::cli::PartingOptions &o)
{
  Json j;
  j["a"] = o.a;
  j["b"] = o.b;
  j["window_ms"] = json_rounded("%.6g", o.window * 1e3);
  j["threshold"] = json_rounded("%.6g", o.threshold);
  j["sustain"] = o.sustain;
  j["contact_a_s"] = json_rounded("%.9g", p.contact_a);
  j["contact_b_s"] = json_rounded("%.9g", p.contact_b);
  j["parted"] = p.parted;
  if (p.parted) {
    j["t_part_ms"] = json_rounded("%.6g", p.t_part * 1e3);
    j["z_part"] = json_rounded("%.6g", p.z_part);
    j["ratio_at_part"] = json_rounded("%.6g", p.windows[p.first].ratio);
  }
  j["largest_before"] = json_rounded("%.6g", p.largest_before);
  Json rows = Json::array();
  for (const auto &w : p.windows) {
    Json r;
    r["t_lo_ms"] = json_rounded("%.6g", w.t_lo * 1e3);
    r["t_hi_ms"] = json_rounded("%.6g", w.t_hi * 1e3);
    r["mean_a"] = json_rounded("%.6g", w.mean_a);
    r["mean_b"] = json_rounded("%.6g", w.mean_b);
    r["ratio"] = std::isfinite(w.ratio) ? json_rounded("%.6g", w.ratio) : Json(nullptr);
    rows.push_back(r);
  }
  j["windows"] = rows;
  return j;
}

}    // namespace

int granpen::cli::run_parting(const PartingOptions &o)
{
  if (!o.json.empty()) refuse_overwriting_inputs(o.json, "--json", {o.a, o.b});
  const Trace a = to_cgs(read_trace(o.a)), b = to_cgs(read_trace(o.b));
  require_t(a, "granpen parting");
  require_t(b, "granpen parting");
  granpen::PartingSettings k;
  k.window = o.window;
  k.threshold = o.threshold;
  k.sustain = int(o.sustain);
  const Parting p = parting_time(a.t, a.F, b.t, b.z, b.F, k);
  for (const auto &[trace, contact] : {std::pair<const Trace *, double>{&a, p.contact_a}, {&b, p.contact_b}})
    if (std::isnan(contact))
      throw InputError(trace->path + ": no contact (F is never above 0): granpen parting reads time after contact");
  std::string text = "# granpen parting: A / B mean drag in windows of " + ms(o.window) + " ms after each trace's contact\n";
  text += "# A: " + o.a + " (contact at t = " + json_number("%.6g", p.contact_a) + " s)\n";
  text += "# B: " + o.b + " (contact at t = " + json_number("%.6g", p.contact_b) + " s)\n";
  text += "t_from_ms\tt_to_ms\tratio\n";
  for (const auto &w : p.windows)
    text += ms(w.t_lo) + "\t" + ms(w.t_hi) + "\t" + (std::isfinite(w.ratio) ? json_number("%.4g", w.ratio) : std::string("-")) + "\n";
  text += verdict_line(p, o) + "\n";
  if (!o.json.empty()) write_json(o.json, parting_json(p, o));
  if (std::fputs(text.c_str(), stdout) == EOF || std::fflush(stdout) != 0) throw OutputError("standard output: write failed");
  return EXIT_OK;
}

int granpen::cli::parting(int argc, char **argv) { return run_parsed(parse_parting, run_parting, argc, argv); }
