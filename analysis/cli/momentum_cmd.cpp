// granpen momentum DUMP... --trace TRACE: the grains' upward momentum by vertical-speed
// class in each dump frame (the paper's "Temporal Flows", compute momentum/vbin's classes),
// M_slow and M(v_z > v0/320) against t~ and depth, and the drag F of the trace against
// mu g M(v_z > v0/320) (core/momentum_classes.h).
#include "dump_cmd_common.h"
#include "json_text.h"
#include "momentum_classes.h"
#include "rod_frame.h"
#include "subcommands.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

using granpen::json_number;
using granpen::json_string;

namespace {

using namespace granpen;
using namespace granpen::cli;

const char *HELP =
    "usage: granpen momentum DUMP... --trace TRACE [--out DIR] [options]\n"
    "Sorts the grains outside the rod (r > R = D/2) of each frame of LAMMPS text dumps\n"
    "(dump custom, plain or gzip; columns id type x y z vx vy vz radius, optional mass) by\n"
    "their upward velocity v_z relative to v0, as compute momentum/vbin does:\n"
    "  fast          v_z >= v0/10\n"
    "  intermediate  v0/80 <= v_z < v0/10\n"
    "  slow          v0/320 < v_z < v0/80\n"
    "  noise         v0/640 < v_z <= v0/320\n"
    "and sums per class the count and the upward momentum sum m v_z; M_slow is the mass of\n"
    "the slow class, M_move that of every grain with v_z > v0/320. Against the drag F of the\n"
    "trace at the frame's time: F = k mu g M_move fitted through the origin (the paper's 1:1\n"
    "line is k = 1) and the mean ratio F / (mu g M_move), over the frames with the rod in the\n"
    "bed (z_tip > 0) and M_move > 0.\n"
    "The rod is found in each frame from its atoms (axis = mean x, y; tip = lowest z - radius);\n"
    "its depth is z_tip = z_s - tip with z_s the trace's surface key, and\n"
    "t~ = (z_tip / v0) sqrt(g / D). F is the trace's at the frame's depth (the first time the\n"
    "tip reached it; linear interpolation), or with --push-step at t = (timestep - N) dt.\n"
    "Outputs in DIR (default .): momentum.json (per frame and the fit, with errors),\n"
    "momentum_classes.csv (t_tilde,z_tip,class,count,p_up), momentum_drag.csv\n"
    "(t_tilde,z_tip,F,mu_g_M).\n"
    "options:\n"
    "  --trace FILE          force trace of the push (required): v0, D, g, mu, rho_g, surface, dt\n"
    "  --out DIR             output folder (made if missing; default .)\n"
    "  --thresholds F1 F2 F3 F4  class bounds as fractions of v0 (default 1/10 1/80 1/320\n"
    "                        1/640), > 0 and decreasing; M_move then counts v_z > F3 v0\n"
    "  --mthreshold F        M_move counts v_z > F v0 instead\n"
    "  --mu MU               friction for mu g M (default: trace header mu, else 0.3)\n"
    "  --rod-type N          atom type of the rod (default 2); every other atom is a grain\n"
    "  --axis X Y            fixed rod axis; --tip Z fixed tip height (dumps without rod atoms)\n"
    "  --D D                 rod diameter (default: the trace's)\n"
    "  --rho RHO             grain density for masses without a mass column (default: trace\n"
    "                        header rho_g, else 3.0)\n"
    "  --zs Z                bed surface (default: the trace's surface key, else measured in the\n"
    "                        first frame as compute bed/surface does)\n"
    "  --push-step N         timestep at which the push began: match the trace by time\n"
    "  --dt DT               timestep size for --push-step (default: the trace's dt key)\n"
    "  --periodic AXES       periodic box directions among x, y: xy (default), x, y or none\n"
    "Units are the dump's and the trace's (cgs for granpen's decks). Progress goes to stderr.\n"
    "Exit status: 0 on success, 1 for unreadable input (the message names file and line;\n"
    "no output is written), 2 for a usage error.\n";

const Usage usage_error{"momentum", HELP};

struct FrameRecord {
  long long timestep = 0;
  std::string where;
  double tip = 0, z_tip = 0, t = 0, t_tilde = 0, F = 0, mu_g_M = 0;
  bool matched = false;
  MomentumTally tally;
};

std::string jnum(double v) { return std::isfinite(v) ? js(v) : std::string("null"); }

}    // namespace

int granpen::cli::momentum(int argc, char **argv)
{
  Command cmd("momentum", HELP);
  static const std::vector<OptionSpec> spec = {
      {"--trace", 1, "force trace of the push (required)"}, {"--out", 1, "output folder"},
      {"--thresholds", 4, "class bounds F1 F2 F3 F4 as fractions of v0"}, {"--mthreshold", 1, "M_move counts v_z > F v0"},
      {"--mu", 1, "friction for mu g M"}, {"--rod-type", 1, "atom type of the rod"}, {"--axis", 2, "fixed rod axis X Y"},
      {"--tip", 1, "fixed tip height"}, {"--D", 1, "rod diameter"}, {"--rho", 1, "grain density"},
      {"--zs", 1, "bed surface"}, {"--push-step", 1, "timestep at which the push began"},
      {"--dt", 1, "timestep size for --push-step"}, {"--periodic", 1, "xy, x, y or none"}};
  ParsedArgs args;
  if (!parse_table(cmd, spec, "dumps", argc, argv, args)) return EXIT_OK;
  std::string msg;
  if (args.positional.empty()) return usage_error("no dump given");
  if (!args.has("--trace")) return usage_error("--trace TRACE is required (v0, D, g and the drag come from it)");
  if (!args.read_numbers({"--trace", "--out", "--periodic", "--push-step"}, msg) ||
      !args.positive({"--D", "--rho", "--dt", "--mthreshold"}, msg))
    return usage_error(msg);
  double mu_opt = 0.0;
  if (args.number("--mu", mu_opt) && !(mu_opt >= 0.0)) return usage_error("--mu must be >= 0");
  RodOptions ro;
  if (!read_rod_options(args, ro, msg)) return usage_error(msg);
  long long push_step = 0;
  const bool by_time = args.has("--push-step");
  if (by_time && !integer_arg(args.value("--push-step", ""), push_step))
    return usage_error("--push-step '" + args.value("--push-step", "") + "' is not an integer");
  const std::string out_dir = args.value("--out", ".");
  if (out_dir.empty()) return usage_error("--out needs a folder");
  refuse_outputs_over_inputs(out_dir, {"momentum.json", "momentum_classes.csv", "momentum_drag.csv"}, args);
  const std::string periodic = args.value("--periodic", "xy");
  bool px, py;
  if (!periodic_axes(periodic, px, py)) return usage_error("--periodic must be xy, x, y or none");

  std::vector<std::string> notes;
  try {
    const TraceHeader th = load_trace(args.value("--trace", ""));
    const Trace &tr = th.trace;
    MomentumClasses classes;
    std::string class_src = "paper (v0/10, v0/80, v0/320, v0/640)";
    try {
      if (args.numbers.count("--thresholds")) {
        double f[MOMENTUM_NCLASS];
        for (int k = 0; k < MOMENTUM_NCLASS; ++k) f[k] = args.numbers.at("--thresholds")[k];
        double mf = 0.0;
        args.number("--mthreshold", mf);
        classes = momentum_classes(tr.v0, f, mf);
        class_src = "option";
      } else {
        classes = momentum_classes(tr.v0);
        double mf;
        if (args.number("--mthreshold", mf)) classes.vmove = mf * tr.v0;
      }
    } catch (std::invalid_argument &e) {
      return usage_error(e.what());
    }
    double mu = 0.3;
    std::string mu_src = "default";
    if (args.has("--mu")) mu = mu_opt, mu_src = "option";
    else if (th.have_mu) mu = th.mu, mu_src = "trace";
    double D = tr.D;
    std::string D_src = "trace";
    if (args.number("--D", D)) D_src = "option";
    const double R = 0.5 * D;
    double rho = 3.0;
    std::string rho_src = "default";
    if (args.number("--rho", rho)) rho_src = "option";
    else if (th.have_rho) rho = th.rho_g, rho_src = "trace";
    double dt = 0.0;
    if (by_time) {
      if (!args.number("--dt", dt)) {
        if (!th.have_dt) return usage_error("--push-step needs --dt (the trace has no dt key)");
        dt = th.dt;
      }
    }

    DumpReader reader(args.positional);
    report_progress(reader, "granpen momentum");
    DumpFrame frame;
    if (!reader.next(frame)) throw InputError(args.positional[0] + ": no frames");
    ColumnChoice cols;
    cols.mass = frame.has("mass");
    if (!cols.mass && rho_src == "default") notes.push_back("masses from rho_g = 3 (default): no mass column, no rho_g");
    GrainFrame g;
    extract_frame(frame, ro, cols, rho, px, py, g);
    double zs = 0.0;
    std::string zs_src = "option";
    if (!args.number("--zs", zs)) {
      if (th.have_surface) zs = th.surface, zs_src = "trace";
      else {
        const auto &X = frame.col("x"), &Y = frame.col("y"), &Z = frame.col("z"), &Rr = frame.col("radius");
        int nempty = 0;
        zs = bed_surface(X.data(), Y.data(), Z.data(), Rr.data(), g.is_rod.data(), X.size(), frame.lo[0],
                         frame.hi[0], frame.lo[1], frame.hi[1], 4, nempty);
        zs_src = "first frame";
        notes.push_back("bed surface measured in the first frame: the trace has no surface key");
      }
    }

    std::vector<FrameRecord> records;
    bool first = true;
    std::size_t unmatched = 0;
    do {
      if (!first) extract_frame(frame, ro, cols, rho, px, py, g);
      first = false;
      FrameRecord r;
      r.timestep = frame.timestep;
      r.where = g.where;
      r.tip = g.tip;
      r.z_tip = zs - g.tip;
      r.t_tilde = t_tilde(r.z_tip, tr.v0, tr.g, D);
      r.tally = tally_momentum(classes, g.x.data(), g.y.data(), g.vz.data(), g.mass.data(), g.grains(), g.axis_x,
                               g.axis_y, R, g.period_x, g.period_y);
      r.mu_g_M = mu * tr.g * r.tally.M_move;
      double pos;
      if (by_time) {
        r.t = (double) (frame.timestep - push_step) * dt;
        pos = locate_first(tr.t, r.t);
      } else {
        pos = locate_first(tr.z, r.z_tip);
        r.t = value_at(tr.t, pos);
      }
      r.F = value_at(tr.F, pos);
      r.matched = std::isfinite(r.F);
      if (!r.matched) ++unmatched;
      records.push_back(r);
    } while (reader.next(frame));
    if (unmatched)
      notes.push_back(std::to_string(unmatched) + " frame(s) outside the trace's " +
                      (by_time ? "time" : "depth") + " range: F undefined");

    std::vector<double> x, y;
    for (const auto &r : records)
      if (r.matched && r.z_tip > 0.0) x.push_back(r.mu_g_M), y.push_back(r.F);
    const DragComparison dc = compare_drag(x, y);

    std::ostringstream cls_csv, drag_csv, json;
    cls_csv << "t_tilde,z_tip,class,count,p_up\n";
    drag_csv << "t_tilde,z_tip,F,mu_g_M\n";
    for (const auto &r : records) {
      for (int k = 0; k < MOMENTUM_NCLASS; ++k)
        cls_csv << csv_num(r.t_tilde) << ',' << csv_num(r.z_tip) << ',' << MOMENTUM_CLASS_NAMES[k] << ','
                << csv_num(r.tally.count[k]) << ',' << csv_num(r.tally.p_up[k]) << '\n';
      drag_csv << csv_num(r.t_tilde) << ',' << csv_num(r.z_tip) << ',' << csv_num(r.F) << ',' << csv_num(r.mu_g_M)
               << '\n';
    }
    json << "{\n  \"tool\": \"granpen momentum\",\n"
         << "  \"units\": \"those of the dump and the trace (granpen decks: cgs: cm, g, s, dyne)\",\n"
         << "  \"inputs\": {\"dumps\": [";
    for (std::size_t k = 0; k < args.positional.size(); ++k) json << (k ? ", " : "") << json_string(args.positional[k]);
    json << "], \"trace\": " << json_string(tr.path) << ", \"frames\": " << records.size() << "},\n"
         << "  \"parameters\": {\"v0\": " << js(tr.v0) << ", \"g\": " << js(tr.g) << ", \"D\": " << js(D)
         << ", \"D_source\": " << json_string(D_src) << ", \"R\": " << js(R) << ", \"mu\": " << js(mu)
         << ", \"mu_source\": " << json_string(mu_src) << ", \"rho_g\": " << js(rho) << ", \"rho_g_source\": "
         << json_string(rho_src) << ", \"masses\": " << json_string(cols.mass ? "column mass" : "rho_g 4/3 pi r^3")
         << ",\n    \"z_s\": " << js(zs) << ", \"z_s_source\": " << json_string(zs_src)
         << ", \"match\": " << json_string(by_time ? "time" : "depth");
    if (by_time) json << ", \"push_step\": " << push_step << ", \"dt\": " << js(dt);
    json << ", \"rod_type\": " << ro.rod_type << ", \"periodic\": " << json_string(periodic) << ",\n"
         << "    \"classes\": {\"source\": " << json_string(class_src) << ", \"names\": [";
    for (int k = 0; k < MOMENTUM_NCLASS; ++k) json << (k ? ", " : "") << json_string(MOMENTUM_CLASS_NAMES[k]);
    json << "], \"bounds\": [";
    for (int k = 0; k < MOMENTUM_NCLASS; ++k) json << (k ? ", " : "") << js(classes.bound[k]);
    json << "], \"v_move\": " << js(classes.vmove) << "}},\n"
         << "  \"drag\": {\"ok\": " << (dc.ok ? "true" : "false") << ", \"n\": " << dc.n
         << ", \"k\": " << js(dc.fit.b) << ", \"k_se\": " << js(dc.fit.se_b) << ", \"rms\": " << js(dc.fit.rms)
         << ", \"ratio_mean\": " << js(dc.ratio_mean) << ", \"ratio_se\": " << js(dc.ratio_se)
         << ", \"note\": " << json_string(dc.note) << ", \"paper\": \"F about equal to mu g M (1:1)\"},\n"
         << "  \"frames\": [";
    for (std::size_t k = 0; k < records.size(); ++k) {
      const FrameRecord &r = records[k];
      json << (k ? ",\n" : "\n") << "    {\"timestep\": " << r.timestep << ", \"where\": " << json_string(r.where)
           << ", \"t\": " << jnum(r.t) << ", \"t_tilde\": " << jnum(r.t_tilde) << ", \"z_tip\": " << js(r.z_tip)
           << ", \"selected\": " << r.tally.selected << ", \"classes\": [";
      for (int c = 0; c < MOMENTUM_NCLASS; ++c)
        json << (c ? ", " : "") << "{\"count\": " << js(r.tally.count[c]) << ", \"mass\": " << js(r.tally.mass[c])
             << ", \"p_up\": " << js(r.tally.p_up[c]) << "}";
      json << "], \"M_slow\": " << js(r.tally.M_slow) << ", \"M_move\": " << js(r.tally.M_move)
           << ", \"mu_g_M\": " << js(r.mu_g_M) << ", \"F\": " << jnum(r.F) << "}";
    }
    json << (records.empty() ? "],\n" : "\n  ],\n") << "  \"notes\": [";
    for (std::size_t k = 0; k < notes.size(); ++k) json << (k ? ", " : "") << json_string(notes[k]);
    json << "]\n}\n";

    std::printf("granpen momentum: %zu frames of %zu dump%s; v0 = %g, D = %g (%s), g = %g, mu = %g (%s), z_s = %.4g (%s), "
                "F matched by %s\n",
                records.size(), args.positional.size(), args.positional.size() == 1 ? "" : "s", tr.v0, D,
                D_src.c_str(), tr.g, mu, mu_src.c_str(), zs, zs_src.c_str(), by_time ? "time" : "depth");
    std::printf("  %10s %8s %8s %8s %8s %8s %10s %10s %10s %10s\n", "timestep", "z_tip", "t~", "fast", "interm",
                "slow", "M_slow", "M_move", "mu_g_M", "F");
    const std::size_t step = records.size() > 20 ? (records.size() + 19) / 20 : 1;
    for (std::size_t k = 0; k < records.size(); ++k) {
      if (k % step && k + 1 != records.size()) continue;
      const FrameRecord &r = records[k];
      std::printf("  %10lld %8.4g %8.4g %8.0f %8.0f %8.0f %10.4g %10.4g %10.4g %10.4g\n", r.timestep, r.z_tip,
                  r.t_tilde, r.tally.count[0], r.tally.count[1], r.tally.count[2], r.tally.M_slow, r.tally.M_move,
                  r.mu_g_M, r.F);
    }
    if (dc.ok)
      std::printf("  drag: F = (%.4g +- %.2g) mu g M(v_z > %g) over %zu frames; mean F / (mu g M) = %.4g +- %.2g "
                  "(paper: 1:1)\n",
                  dc.fit.b, dc.fit.se_b, classes.vmove, dc.n, dc.ratio_mean, dc.ratio_se);
    else
      std::printf("  drag: F against mu g M undefined (%s)\n", dc.note.c_str());
    for (const auto &n : notes) std::printf("  note: %s\n", n.c_str());

    const std::vector<std::pair<std::string, std::string>> files = {
        {"momentum.json", json.str()}, {"momentum_classes.csv", cls_csv.str()}, {"momentum_drag.csv", drag_csv.str()}};
    if (!write_outputs(out_dir, files, msg)) {
      std::fprintf(stderr, "granpen momentum: %s\n", msg.c_str());
      return 1;
    }
    std::printf("wrote %s/{momentum.json, momentum_classes.csv, momentum_drag.csv}\n", out_dir.c_str());
  } catch (std::exception &e) {    // InputError names file:line
    std::fprintf(stderr, "granpen momentum: %s\n", e.what());
    return 1;
  }
  return 0;
}
