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
#include "subcommand.h"
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

const char *HELP =
    "usage: granpen import FILE-OR-FOLDER... --mapping MAP --out DIR --D D --g G\n"
    "                      [--units cgs|si] [--v0 V] [--window W] [--run N] [--d_g DG]\n"
    "                      [--rho_g RHO] [--mu MU] [--dry-run]\n"
    "Reads instrument files (delimited text or key=value rows, as the mapping MAP says:\n"
    "columns, units, signs, tare, contact threshold or surface, speed checks; see\n"
    "docs/measurements.md) and writes one granpen-trace v1 file per input, DIR/NAME.csv:\n"
    "  t = time since the file's first row, z = depth below the surface (negative before\n"
    "  contact), F = force with the offset of the first tare_rows rows removed.\n"
    "The end of the push is cut by one rule: rows after the rod's furthest advance\n"
    "(standstill, retraction), and rows after the last block of speed_rows rows moving at\n"
    "the mean speed within speed_tolerance (the deceleration and its force spike); without\n"
    "a position, rows after the last at contact force. Each file's cut is reported.\n"
    "A folder stands for every file in it. Runs are numbered from --run in the order given.\n"
    "Nothing is written unless every file imports; --dry-run prints what would be written.\n"
    "Exit status 0, 1 for bad input (named with file and line), 2 for usage.\n";

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

int granpen::cli::import(int argc, char **argv)
{
  Command cmd("import", HELP);
  std::vector<std::string> inputs;
  std::string mapping_path, out_dir, units = "cgs";
  Header hd;
  double window = 0.0;
  int run0 = 1;
  bool dry = false;
  auto &app = cmd.app;
  app.add_option("files", inputs, "instrument files, or folders of them")->required();
  app.add_option("--mapping", mapping_path, "the mapping file (columns, units, signs, rules)")->required()->type_name("MAP");
  app.add_option("--out", out_dir, "the folder the traces go to (made when missing)")->required()->type_name("DIR");
  app.add_option("--units", units, "units of the traces and of --v0, --D, --g (default cgs)")
      ->type_name("UNITS")->check(CLI::IsMember({"cgs", "si"}));
  app.add_option("--v0", hd.v0, "nominal push speed, > 0 (default: the mapping's v0, else the measured mean)")
      ->check(positive_number())->type_name("V");
  app.add_option("--D", hd.D, "rod diameter, > 0")->check(positive_number())->required()->type_name("D");
  app.add_option("--g", hd.g, "gravity, > 0")->check(positive_number())->required()->type_name("G");
  app.add_option("--window", window, "average into windows of W seconds (default: the mapping's window, else none)")
      ->check(positive_number())->type_name("W");
  app.add_option("--run", run0, "the first run number (default 1)")->check(CLI::PositiveNumber)->type_name("N");
  app.add_option("--d_g", hd.d_g, "optional header key d_g")->check(positive_number())->type_name("DG");
  app.add_option("--rho_g", hd.rho_g, "optional header key rho_g")->check(positive_number())->type_name("RHO");
  app.add_option("--mu", hd.mu, "optional header key mu")->check(positive_number())->type_name("MU");
  app.add_flag("--dry-run", dry, "print what would be written; write nothing");
  if (!cmd.parse(argc, argv)) return EXIT_OK;
  hd.si = units == "si";

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
  int run = run0;
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
