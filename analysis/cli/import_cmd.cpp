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
#include "import_options.h"
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

// a CSV field, quoted when it holds a comma, a quote or a line break
std::string csv_field(const std::string &s)
{
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

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

// What import writes passes `check`, always: the staged trace read back by check's own
// reader (streamed) before it takes its name; a rejection names the input and the line.
void refuse_unless_checked(const std::string &in, const std::string &staged)
{
  try {
    granpen::scan_trace(staged);
  } catch (const granpen::InputError &e) {
    std::string why = e.what();
    if (why.compare(0, staged.size(), staged) == 0) why = "the trace's line" + why.substr(staged.size());
    throw granpen::InputError(in + ": the imported trace would not pass granpen check (" + why + "); nothing written");
  }
}

// A line break in a file name would break the trace's header (source = NAME, mapping = NAME).
void refuse_line_breaks(const std::string &path, const char *what)
{
  if (path.find_first_of("\n\r") == std::string::npos) return;
  std::string shown;
  for (char c : path) shown += c == '\n' ? "\\n" : c == '\r' ? "\\r" : std::string(1, c);
  throw granpen::InputError(shown + ": a line break in the " + what +
                            "'s name: it would break the trace's header, where the name is written; rename it");
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
  double v0 = 0.0;                     // the header's: the nominal, else the measured mean
  bool v0_measured = false;            // no nominal given: v0 is the measured mean
  long last_data_line = 0, trailer_line = 0;
  std::string trailer_text;
  std::vector<std::string> warnings;   // printed after every file's report and the table
  granpen::ImportMapping mapping;      // the file's (a GEF file's own)
};

std::string header_text(const Imported &res, const granpen::ImportMapping &m, const Header &hd, int run)
{
  using namespace granpen;
  TraceHeader h;
  h.units = hd.si ? "si" : "cgs";
  h.v0 = res.v0;
  h.D = hd.D;
  h.g = hd.g;
  if (!hd.d_g.empty()) h.extra.emplace_back("d_g", hd.d_g);
  if (!hd.rho_g.empty()) h.extra.emplace_back("rho_g", hd.rho_g);
  if (!hd.mu.empty()) h.extra.emplace_back("mu", hd.mu);
  h.extra.emplace_back("run", std::to_string(run));
  h.extra.emplace_back("source", res.in);
  h.extra.emplace_back("mapping", m.path);
  h.extra.emplace_back("tare", num("%.10g", res.sum.limits.tare));
  h.extra.emplace_back("t_from", m.time_from());
  h.extra.emplace_back("v0_from", res.v0_measured ? "measured" : "nominal");
  const SpeedStats &sp = res.sum.speed;
  if (sp.measured && std::isfinite(sp.mean)) {
    h.extra.emplace_back("v0_measured", num("%.6g", sp.mean));
    h.extra.emplace_back("v0_ripple", num("%.3g", sp.ripple));
  }
  if (!m.rules.has_time) h.columns = {"z", "F"};
  return format_trace_header(h);
}

// One file through the passes; the trace into `staged` unless dry. v0: the nominal speed
// for this file (NaN: the mapping's, else the measured mean).
Imported import_file(const std::string &in, const std::string &out, const granpen::ImportMapping &m,
                     const Header &hd, double v0, int run, bool dry)
{
  using namespace granpen;
  Imported res;
  res.in = in;
  res.out = out;
  res.mapping = m;
  ImportRules rules = m.rules;
  rules.v0 = v0 > 0.0 ? v0 : m.v0 > 0.0 ? m.v0 : NAN;
  std::vector<ImportRow> rows;
  try {
    InstrumentReader pass1(in, m);
    res.layout = pass1.layout();
    PushScan scan(rules);
    while (pass1.next(rows)) scan.add(rows);
    const PushLimits lim = scan.finish();
    res.last_data_line = pass1.last_data_line();
    res.trailer_line = pass1.trailer_line();
    res.trailer_text = pass1.trailer_text();
    if (!rules.has_position && std::isnan(rules.v0))
      throw InputError(in + ": no position column: depth = v0 (t - t_surface) needs --v0 or v0 in the mapping");
    if (!rules.has_time && std::isnan(rules.v0))
      throw InputError(in + ": no time and no speed column: the speed cannot be measured: give --v0, --v0-table or "
                            "v0 in the mapping");
    SpeedRamp ramp;
    ramp.cut_line = lim.end_line;
    ramp.cut_t = lim.t_end;
    if (rules.has_time && (rules.has_position || rules.has_speed)) {
      InstrumentReader pass2(in, m);
      SpeedProfile profile(rules, lim);
      while (pass2.next(rows)) profile.add(rows);
      ramp = profile.finish();
    }
    // pass 3: the statistics (the measured mean and ripple go into the header)
    std::vector<TracePoint> points;
    TraceBuilder builder(rules, lim, ramp);
    InstrumentReader pass3(in, m);
    while (pass3.next(rows)) {
      builder.add(rows, points);
      points.clear();
    }
    res.sum = builder.finish(points);
    points.clear();
    res.v0_measured = std::isnan(rules.v0);
    res.v0 = res.v0_measured ? res.sum.speed.mean : rules.v0;
    if (!(res.v0 > 0.0)) throw InputError(in + ": no speed could be measured: give --v0 or v0 in the mapping");
    if (res.sum.points < 10)
      throw InputError(in + ": only " + std::to_string(res.sum.points) + " trace rows after the import (a trace needs 10)");
    res.header = header_text(res, m, hd, run);
    // every number of the header through the checks `granpen check` makes of it
    check_trace_header(res.header, in + " (its trace's header)");
    if (dry) return res;
    // pass 4: the trace, now that its header is known
    res.staged.reset(new StagedFile(out));
    res.staged->write(res.header);
    TraceBuilder again(rules, lim, ramp);
    InstrumentReader pass4(in, m);
    std::string text;
    auto write_points = [&]() {
      text.clear();
      for (const auto &p : points)
        text += rules.has_time ? format_trace_row({p.t, p.z, p.F}) : format_trace_row({p.z, p.F});
      points.clear();
      res.staged->write(text);
    };
    while (pass4.next(rows)) {
      again.add(rows, points);
      write_points();
    }
    again.finish(points);
    write_points();
    res.staged->close();
    refuse_unless_checked(in, res.staged->temporary());
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
  if (r.trailer_line)
    std::printf("  data end at line %ld; from line %ld on, not data rows: '%s'\n", r.last_data_line, r.trailer_line,
                r.trailer_text.c_str());
  if (m.time_source == granpen::ImportMapping::TimeSource::depth_over_speed)
    std::printf("  t = the integral of dz / v over the rows (a depth-sampled log)\n");
  if (!m.rules.has_time) std::printf("  no time and no speed column: the trace has no t (t_from = none)\n");
  std::printf("  tare %.6g %s; surface %s; cut %zu rows after line %ld\n", s.limits.tare, F,
              m.rules.surface_given ? "given" : ("at contact, line " + std::to_string(s.limits.onset_line)).c_str(),
              s.rows_cut, s.ramp.cut_line);
  if (s.speed.measured && std::isfinite(s.speed.mean))
    std::printf("  speed %.6g %s/s (%s), ripple %.3g%%, within %.3g%% of the mean from depth %.4g %s\n", s.speed.mean, L,
                r.v0_measured ? "v0 = this mean" : ("nominal v0 " + num("%.6g", r.v0)).c_str(), 100.0 * s.speed.ripple,
                100.0 * m.rules.speed_tolerance, s.ramp.ramp_depth, L);
  if (dry && !s.speed.profile.empty() && std::isfinite(s.speed.mean)) {
    // the speed against depth, to tell a drift from a stop at a glance
    std::printf("  speed against depth (the push at speed in %zu equal times; each + or - is 1%% of the mean):\n",
                s.speed.profile.size());
    for (const auto &sg : s.speed.profile) {
      const double off = 100.0 * (sg.speed - s.speed.mean) / s.speed.mean;
      std::printf("    z %8.4g..%-8.4g %s %-10.6g %+6.2f%% %s\n", sg.z_from, sg.z_to, L, sg.speed, off,
                  std::string(std::min(20, (int) std::lround(std::fabs(off))), off < 0 ? '-' : '+').c_str());
    }
  }
  if (dry) std::printf("%s  ... %zu rows\n", r.header.c_str(), s.points);
}

// the warnings of one file, each "FILE: what"
std::vector<std::string> speed_warnings(const Imported &r, const granpen::ImportRules &rules)
{
  std::vector<std::string> w;
  const auto &sp = r.sum.speed;
  const std::string tol = num("%g", 100.0 * rules.speed_tolerance);
  if (!sp.measured) return w;
  if (!std::isfinite(sp.mean)) {
    w.push_back(r.in + ": the rod never moves at a steady speed (within " + tol + "%)");
    return w;
  }
  if (!sp.constant)
    w.push_back(r.in + ": speed not constant within " + tol + "%: ripple " + num("%.3g", 100.0 * sp.ripple) +
                "%, a stretch " + num("%.3g", 100.0 * sp.worst) + "% off the mean " + num("%.6g", sp.mean) +
                " (a drift: kept, not cut)");
  // the speed rule cuts a deceleration; a large cut is a slow stop or a second speed
  const double pushed = (double) (r.sum.rows_pushed + r.sum.rows_cut_by_speed);
  if (r.sum.rows_cut_by_speed > 0.05 * pushed)
    w.push_back(r.in + ": the speed rule cut " + std::to_string(r.sum.rows_cut_by_speed) + " rows of the push (" +
                num("%.3g", 100.0 * r.sum.rows_cut_by_speed / pushed) +
                "%): a slow stop, or a second speed at the end");
  if (r.sum.ramp.ramp_depth > 0.0)
    w.push_back(r.in + ": the rod reaches its steady speed only at depth " + num("%.4g", r.sum.ramp.ramp_depth) +
                ", below the surface (the rows above it ramp up)");
  if (!r.v0_measured && std::fabs(sp.mean - r.v0) > rules.speed_tolerance * r.v0)
    w.push_back(r.in + ": measured speed " + num("%.6g", sp.mean) + " is " + num("%.3g", 100.0 * (sp.mean - r.v0) / r.v0) +
                "% off the nominal v0 " + num("%.6g", r.v0));
  return w;
}

// one line a file: the table printed after the reports and written as CSV beside the traces
std::string summary_csv(const std::vector<Imported> &done)
{
  std::string o = "file,trace,rows_read,rows_kept,rows_cut,data_end_line,trailer_line,v0,v0_from,v0_measured,ripple,warnings\n";
  for (const auto &r : done) {
    const auto &sp = r.sum.speed;
    const bool measured = sp.measured && std::isfinite(sp.mean);
    o += csv_field(r.in) + "," + csv_field(std::filesystem::path(r.out).filename().string()) + "," +
         std::to_string(r.sum.rows_read) + "," + std::to_string(r.sum.rows_pushed) + "," + std::to_string(r.sum.rows_cut) +
         "," + std::to_string(r.last_data_line) + "," + std::to_string(r.trailer_line) + "," + num("%.6g", r.v0) + "," +
         (r.v0_measured ? "measured," : "nominal,") + (measured ? num("%.6g", sp.mean) : "") + "," +
         (measured ? num("%.3g", sp.ripple) : "") + "," + std::to_string(r.warnings.size()) + "\n";
  }
  return o;
}

void print_summary_table(const std::vector<Imported> &done, bool si)
{
  const char *V = si ? "m/s" : "cm/s";
  std::printf("\n%-28s %9s %7s %6s %12s %12s %7s %8s\n", "file", "rows kept", "cut", "end", (std::string("v0 ") + V).c_str(),
              "measured", "ripple", "warnings");
  for (const auto &r : done) {
    std::string name = std::filesystem::path(r.in).filename().string();
    if (name.size() > 28) name = name.substr(0, 25) + "...";
    const auto &sp = r.sum.speed;
    const bool measured = sp.measured && std::isfinite(sp.mean);
    std::printf("%-28s %9zu %7zu %6s %12s %12s %7s %8zu\n", name.c_str(), r.sum.rows_pushed, r.sum.rows_cut,
                r.trailer_line ? std::to_string(r.last_data_line).c_str() : "eof",
                (num("%.5g", r.v0) + (r.v0_measured ? " m" : " n")).c_str(), measured ? num("%.5g", sp.mean).c_str() : "-",
                measured ? (num("%.2f", 100.0 * sp.ripple) + "%").c_str() : "-", r.warnings.size());
  }
  std::printf("(v0: n nominal, m measured mean; end: the last data line, before a trailer)\n");
}

}    // namespace

int granpen::cli::run_import(const ImportOptions &o)
{
  const std::vector<std::string> &inputs = o.inputs;
  const std::string &mapping_path = o.mapping, &out_dir = o.out_dir;
  const bool dry = o.dry_run;
  Header hd;
  hd.si = o.si, hd.D = o.D, hd.g = o.g, hd.v0 = o.v0;
  hd.d_g = o.d_g, hd.rho_g = o.rho_g, hd.mu = o.mu;
  // --mapping gef: a named layout, each file's mapping from its own GEF header
  const bool gef = mapping_path == "gef" && !std::filesystem::exists(mapping_path);
  const ImportMapping given = gef ? ImportMapping() : read_import_mapping(mapping_path, hd.si);
  auto mapping_for = [&](const std::string &in) {
    ImportMapping mm = gef ? parse_import_mapping(gef_mapping_text(in), in + " (its GEF header)", hd.si) : given;
    if (gef) mm.path = "gef";
    if (o.window > 0.0) {
      if (!mm.rules.has_time)
        throw InputError((gef ? in : mapping_path) + ": --window needs a time: no time column, sample_rate or speed column");
      mm.rules.window = o.window;
    }
    if (o.speed_tolerance > 0.0) mm.rules.speed_tolerance = o.speed_tolerance;
    if (o.end_tolerance > 0.0) mm.rules.end_tolerance = o.end_tolerance;
    return mm;
  };
  std::map<std::string, double> table;
  if (!o.v0_table.empty()) table = read_v0_table(o.v0_table, hd.si);
  const auto files = input_files(inputs);
  std::vector<std::string> all_inputs = files;
  if (!gef) all_inputs.push_back(mapping_path);
  if (!o.v0_table.empty()) all_inputs.push_back(o.v0_table);
  std::map<std::string, std::string> outputs;    // output -> its input
  struct Planned {
    std::string in, out;
    double v0;
  };
  std::vector<Planned> plan;
  if (!gef) refuse_line_breaks(mapping_path, "mapping");
  for (const auto &in : files) {
    refuse_line_breaks(in, "input");
    std::error_code same_ec;
    if (!o.v0_table.empty() && std::filesystem::equivalent(in, o.v0_table, same_ec)) continue;    // the table in the folder
    const std::string out = (std::filesystem::path(out_dir) / (std::filesystem::path(in).stem().string() + ".csv")).string();
    if (outputs.count(out))
      throw UsageError(in + " and " + outputs[out] + " would both be written as " + out + ": rename one");
    outputs[out] = in;
    refuse_overwriting_inputs(out, "--out", all_inputs);
    const double v0 = table.empty() ? hd.v0 : nominal_v0(table, in);
    if (!(v0 > 0.0) && !table.empty())
      throw InputError(o.v0_table + ": no line for " + in + " (its file name or its name without the extension)");
    plan.push_back({in, out, v0});
  }
  const std::string summary_path = (std::filesystem::path(out_dir) / kImportSummaryName).string();
  refuse_overwriting_inputs(summary_path, "--out", all_inputs);
  std::error_code ec;
  // the folders this run makes, deepest first (--out a/b/c may make a and a/b too)
  std::vector<std::filesystem::path> made_dirs;
  for (std::filesystem::path p = std::filesystem::absolute(out_dir, ec).lexically_normal();
       !dry && !p.empty() && !std::filesystem::exists(p, ec) && p != p.parent_path(); p = p.parent_path())
    made_dirs.push_back(p);
  if (!dry) make_output_dir(out_dir);
  std::vector<Imported> done;
  int run = o.first_run;
  try {
    for (const auto &p : plan) done.push_back(import_file(p.in, p.out, mapping_for(p.in), hd, p.v0, run++, dry));
  } catch (...) {
    done.clear();    // the staged traces' temporaries removed
    for (const auto &d : made_dirs) std::filesystem::remove(d, ec);    // the folders this run made, now empty
    throw;
  }
  // every file imported: now, and only now, the traces take their names
  for (auto &r : done)
    if (r.staged) r.staged->rename();
  for (auto &r : done) {
    r.warnings = speed_warnings(r, r.mapping.rules);
    report(r, r.mapping, hd.si, dry);
  }
  if (done.size() > 1) print_summary_table(done, hd.si);
  if (!dry) write_file_atomic(summary_path, summary_csv(done));
  std::printf("granpen import: %zu trace%s %s %s%s\n", done.size(), done.size() == 1 ? "" : "s",
              dry ? "would be written to" : "written to", out_dir.c_str(),
              dry ? "" : (" (the table: " + summary_path + ")").c_str());
  std::fflush(stdout);
  for (const auto &r : done)
    for (const auto &w : r.warnings) std::fprintf(stderr, "granpen import: warning: %s\n", w.c_str());
  return EXIT_OK;
}

int granpen::cli::import(int argc, char **argv) { return run_parsed(parse_import, run_import, argc, argv); }
