// granpen import FILE... --mapping MAP --out DIR: a lab's instrument files (force, and
// displacement or time, in the instrument's own columns, units and layout) written as
// granpen-trace v1 files, one per run, in one folder. The file is streamed three times
// (pass 1: tare, contact, end of push; pass 2: the speed profile; pass 3: the trace), so
// memory does not grow with its length; every trace is staged under a temporary name and
// renamed only when every file has been imported.
#include "atomic_file.h"
#include "import_mapping.h"
#include "instrument_import.h"
#include "instrument_reader.h"
#include "staged_file.h"
#include "options.h"
#include "subcommands.h"
#include "text_util.h"
#include "trace_files.h"
#include "trace_reader.h"
#include "trace_writer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace {


std::string num(const char *f, double v) { return granpen::printf_number(f, v); }

// the inputs as files: a folder stands for its regular files (not hidden), sorted
std::vector<std::string> input_files(const std::vector<std::string> &inputs)
{
  std::vector<std::string> problems;
  auto files = granpen::expand_paths(
      inputs,
      [](const std::filesystem::directory_entry &e) {
        std::error_code ec;
        return e.is_regular_file(ec) && e.path().filename().string()[0] != '.';
      },
      "an empty folder", problems);
  if (!problems.empty()) throw granpen::InputError(problems.front());
  return files;
}

// ImportRejected from the kernels as "FILE:LINE: what" (or "FILE: what")
[[noreturn]] void rethrow_at(const std::string &file, const granpen::ImportRejected &e)
{
  if (e.line > 0) granpen::fail_at(file, e.line, e.what());
  throw granpen::InputError(file + ": " + e.what());
}

struct Header {
  bool si = false;
  double D = 0.0, g = 0.0, v0 = 0.0;
  std::string d_g, rho_g, mu;
};

struct Imported {
  std::string in, out;
  std::unique_ptr<granpen::StagedFile> staged;
  granpen::ImportSummary sum;
  std::string layout, header;
  double v0 = 0.0;
  bool v0_measured = false;
};

// One file through the three passes; the trace into `staged` unless dry.
Imported import_file(const std::string &in, const std::string &out, const granpen::ImportMapping &m,
                     const Header &hd, int run, bool dry)
{
  using namespace granpen;
  Imported res;
  res.in = in;
  res.out = out;
  ImportRules rules = m.rules;
  rules.v0 = hd.v0 > 0.0 ? hd.v0 : m.v0 > 0.0 ? m.v0 : NAN;
  std::vector<ImportRow> rows;
  PushLimits lim;
  SpeedRamp ramp;
  try {
    InstrumentReader pass1(in, m);
    res.layout = pass1.layout();
    PushScan scan(rules);
    while (pass1.next(rows)) scan.add(rows);
    lim = scan.finish();
    if (!rules.has_position && std::isnan(rules.v0))
      throw InputError(in + ": no position column: depth = v0 (t - t_surface) needs --v0 or v0 in the mapping");
    if (rules.has_position || rules.has_speed) {
      InstrumentReader pass2(in, m);
      SpeedProfile profile(rules, lim);
      while (pass2.next(rows)) profile.add(rows);
      ramp = profile.finish();
    } else {
      ramp.cut_line = lim.end_line;
      ramp.cut_t = lim.t_end;
    }
    // v0: the nominal speed given, else the measured mean
    res.v0 = rules.v0;
    res.v0_measured = std::isnan(res.v0);
    TraceBuilder builder(rules, lim, ramp);
    InstrumentReader pass3(in, m);
    std::vector<TracePoint> points;
    std::string text;
    auto write_points = [&]() {
      text.clear();
      for (const auto &p : points) text += format_trace_row({p.t, p.z, p.F});
      points.clear();
      if (res.staged) res.staged->write(text);
    };
    if (res.v0_measured) {
      // the measured mean at speed is known only after pass 3: the header waits for it
      while (pass3.next(rows)) {
        builder.add(rows, points);
        points.clear();
      }
      res.sum = builder.finish(points);
      points.clear();
      res.v0 = res.sum.speed.mean;
      if (!(res.v0 > 0.0)) throw InputError(in + ": no speed could be measured: give --v0 or v0 in the mapping");
    }
    TraceHeader h;
    h.units = hd.si ? "si" : "cgs";
    h.v0 = res.v0;
    h.D = hd.D;
    h.g = hd.g;
    if (!hd.d_g.empty()) h.extra.emplace_back("d_g", hd.d_g);
    if (!hd.rho_g.empty()) h.extra.emplace_back("rho_g", hd.rho_g);
    if (!hd.mu.empty()) h.extra.emplace_back("mu", hd.mu);
    h.extra.emplace_back("run", std::to_string(run));
    h.extra.emplace_back("source", in);
    h.extra.emplace_back("mapping", m.path);
    h.extra.emplace_back("tare", num("%.10g", lim.tare));
    res.header = format_trace_header(h);
    if (!dry) {
      res.staged.reset(new StagedFile(out));
      res.staged->write(res.header);
    }
    if (res.v0_measured) {
      // second reading of pass 3, now that the header is written
      TraceBuilder again(rules, lim, ramp);
      InstrumentReader pass4(in, m);
      while (pass4.next(rows)) {
        again.add(rows, points);
        write_points();
      }
      again.finish(points);
    } else {
      while (pass3.next(rows)) {
        builder.add(rows, points);
        write_points();
      }
      res.sum = builder.finish(points);
    }
    write_points();
    if (res.sum.points < 10)
      throw InputError(in + ": only " + std::to_string(res.sum.points) + " trace rows after the import (a trace needs 10)");
    if (res.staged) res.staged->close();
  } catch (const ImportRejected &e) {
    rethrow_at(in, e);
  }
  return res;
}

void report(const Imported &r, const granpen::ImportMapping &m, bool si, bool dry)
{
  const auto &s = r.sum;
  const char *L = si ? "m" : "cm", *F = si ? "N" : "dyne";
  std::printf("granpen import: %s -> %s%s: %s; %zu rows read, %zu trace rows, z = %.4g to %.4g %s\n", r.in.c_str(),
              r.out.c_str(), dry ? " (dry run)" : "", r.layout.c_str(), s.rows_read, s.points, s.z_first, s.z_last, L);
  std::printf("  tare %.6g %s; surface %s; cut %zu rows after line %ld\n", s.limits.tare, F,
              m.rules.surface_given ? "given" : ("at contact, line " + std::to_string(s.limits.onset_line)).c_str(),
              s.rows_cut, s.ramp.cut_line);
  if (s.speed.measured && std::isfinite(s.speed.mean))
    std::printf("  speed %.6g %s/s (%s), ripple %.3g%%, within %.3g%% of the mean from depth %.4g %s\n", s.speed.mean, L,
                r.v0_measured ? "v0 = this mean" : ("nominal v0 " + num("%.6g", r.v0)).c_str(), 100.0 * s.speed.ripple,
                100.0 * m.rules.speed_tolerance, s.ramp.ramp_depth, L);
  if (dry) std::printf("%s  ... %zu rows\n", r.header.c_str(), s.points);
}

void warn_speed(const Imported &r, const granpen::ImportRules &rules)
{
  const auto &sp = r.sum.speed;
  if (!sp.measured) return;
  if (!std::isfinite(sp.mean)) {
    std::fprintf(stderr, "granpen import: warning: %s: the rod never moves at a steady speed (within %g%%)\n",
                 r.in.c_str(), 100.0 * rules.speed_tolerance);
    return;
  }
  if (!sp.constant)
    std::fprintf(stderr,
                 "granpen import: warning: %s: speed not constant within %g%%: ripple %.3g%%, a stretch %.3g%% off "
                 "the mean %.6g\n",
                 r.in.c_str(), 100.0 * rules.speed_tolerance, 100.0 * sp.ripple, 100.0 * sp.worst, sp.mean);
  // the speed rule cuts a deceleration; a large cut is a slow stop or a second speed
  if (r.sum.rows_cut_by_speed > 0.05 * (double) (r.sum.rows_pushed + r.sum.rows_cut_by_speed))
    std::fprintf(stderr, "granpen import: warning: %s: the speed rule cut %zu rows of the push (%.3g%%): a slow stop, "
                 "or a second speed at the end\n", r.in.c_str(), r.sum.rows_cut_by_speed,
                 100.0 * r.sum.rows_cut_by_speed / (double) (r.sum.rows_pushed + r.sum.rows_cut_by_speed));
  if (r.sum.ramp.ramp_depth > 0.0)
    std::fprintf(stderr, "granpen import: warning: %s: the rod reaches its steady speed only at depth %.4g, below the "
                 "surface (the rows above it ramp up)\n", r.in.c_str(), r.sum.ramp.ramp_depth);
  if (!r.v0_measured && std::fabs(sp.mean - r.v0) > rules.speed_tolerance * r.v0)
    std::fprintf(stderr, "granpen import: warning: %s: measured speed %.6g is %.3g%% off the nominal v0 %.6g\n",
                 r.in.c_str(), sp.mean, 100.0 * (sp.mean - r.v0) / r.v0, r.v0);
}

}    // namespace

int granpen::cli::run_import(const ImportOptions &o)
{
  const std::vector<std::string> &inputs = o.inputs;
  const std::string &mapping_path = o.mapping, &out_dir = o.out_dir;
  const double window = o.window;
  const bool dry = o.dry_run;
  Header hd;
  hd.si = o.si, hd.D = o.D, hd.g = o.g, hd.v0 = o.v0;
  hd.d_g = o.d_g, hd.rho_g = o.rho_g, hd.mu = o.mu;
  ImportMapping m = read_import_mapping(mapping_path, hd.si);
  if (window > 0.0) m.rules.window = window;
  const auto files = input_files(inputs);
  std::vector<std::string> all_inputs = files;
  all_inputs.push_back(mapping_path);
  std::map<std::string, std::string> outputs;    // output -> its input
  std::vector<std::pair<std::string, std::string>> plan;
  for (const auto &in : files) {
    const std::string out = (std::filesystem::path(out_dir) / (std::filesystem::path(in).stem().string() + ".csv")).string();
    if (outputs.count(out))
      throw UsageError(in + " and " + outputs[out] + " would both be written as " + out + ": rename one");
    outputs[out] = in;
    refuse_overwriting_inputs(out, "--out", all_inputs);
    plan.emplace_back(in, out);
  }
  std::error_code ec;
  const bool made_dir = !dry && !std::filesystem::exists(out_dir, ec);
  if (!dry) make_output_dir(out_dir);
  std::vector<Imported> done;
  int run = o.first_run;
  try {
    for (const auto &p : plan) done.push_back(import_file(p.first, p.second, m, hd, run++, dry));
  } catch (...) {
    done.clear();    // the staged traces' temporaries removed
    if (made_dir) std::filesystem::remove(out_dir, ec);    // the folder this run made, now empty
    throw;
  }
  // every file imported: now, and only now, the traces take their names
  for (auto &r : done)
    if (r.staged) r.staged->rename();
  for (const auto &r : done) {
    report(r, m, hd.si, dry);
    warn_speed(r, m.rules);
  }
  std::printf("granpen import: %zu trace%s %s %s\n", done.size(), done.size() == 1 ? "" : "s",
              dry ? "would be written to" : "written to", out_dir.c_str());
  return EXIT_OK;
}
