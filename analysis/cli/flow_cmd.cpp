// granpen flow DUMP...: the flow around the rod from LAMMPS dumps of the grains and the
// rod: azimuthal (r, z) fields in the tip frame, the profile below the rod face with its
// exponential length, phi against I at the rod edge, the near-shaft strip and the
// annulus r = 2-3 cm against t~ (core/flow_fields.h, core/voronoi_volumes.h).
#include "dump_cmd_common.h"
#include "flow_fields.h"
#include "json_text.h"
#include "linear_fit.h"
#include "rod_frame.h"
#include "subcommands.h"
#include "text_util.h"
#include "voronoi_volumes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using granpen::json_number;
using granpen::json_string;

namespace {

using namespace granpen;
using namespace granpen::cli;

constexpr double PI = 3.14159265358979323846;

const char *HELP =
    "usage: granpen flow DUMP... [--trace TRACE] [--out DIR] [options]\n"
    "The flow of the grains around the rod from LAMMPS text dumps (dump custom, plain or\n"
    "gzip; columns id type x y z vx vy vz radius, optional mass, a Voronoi volume and a\n"
    "per-atom stress), as compute flow/azimuthal defines it (docs/postprocess.md):\n"
    "  fields   (r, z) bins about the rod axis, z from the rod tip (negative below it),\n"
    "           pooled over the frames: count, phi (Voronoi), phi_centre, v_r, v_z, T,\n"
    "           shear rate gammadot, pressure p, inertial number I = gammadot d_g / sqrt(p/rho_g)\n"
    "  below    v_z and phi against z in the cylinder r < D/3 below the rod face, with the\n"
    "           exponential fit v_z ~ A exp(z / lambda) (paper: lambda_vz = 0.98 D +- 0.15)\n"
    "  edge     per frame with the tip in the bed, phi and I of the bins at the rod's bottom\n"
    "           edge (r = R, z = 0), and the fit phi = phi_0 + b I (paper: phi = 0.57 - 0.35 I)\n"
    "  strip    v_z against height above the bed surface, 0.5 to 1.5 cm from the shaft\n"
    "  surface  per frame, v_z of the strip's top grain layer (one dz below the surface)\n"
    "           against t~, and the t~ where it last turns from up to down (paper: 1)\n"
    "  annulus  per frame, phi, v_z and T for r = 2 to 3 cm between 0.5 cm below the bed\n"
    "           surface and the tip, against t~ = (z_tip / v0) sqrt(g / D)\n"
    "The rod is found in each frame from its atoms: axis = mean x, y, tip = lowest z - radius.\n"
    "Outputs in DIR (default .): flow.json (every fitted number with its error),\n"
    "flow_fields.csv (r,z,count,phi,phi_centre,vr,vz,T,gammadot,p,I),\n"
    "flow_profile_below.csv (z,vz,vz_se,phi), flow_edge_phi_I.csv (I,phi),\n"
    "flow_strip.csv (z,vz), flow_annulus.csv (t_tilde,z_tip,phi,vz,T),\n"
    "flow_surface.csv (t_tilde,z_tip,vz,grains).\n"
    "options:\n"
    "  --trace FILE       the push's force trace: v0, D, g, d_g, rho_g and the bed surface\n"
    "                     (key surface) from its header\n"
    "  --out DIR          output folder (made if missing; default .)\n"
    "  --rod-type N       atom type of the rod (default 2); every other atom is a grain\n"
    "  --axis X Y         fixed rod axis instead of the rod atoms' mean x, y\n"
    "  --tip Z            fixed tip height instead of the rod atoms' lowest point\n"
    "  --D D              rod diameter (default: trace header, else measured from the rod atoms\n"
    "                     as fix rod/drive does: 2 max(r_xy + radius))\n"
    "  --dg D             grain diameter for I and the default bins (default: trace header,\n"
    "                     else the mean grain diameter of the first frame)\n"
    "  --rho RHO          grain density for I and for masses without a mass column\n"
    "                     (default: trace header rho_g, else 3.0)\n"
    "  --v0 V --g G       push speed and gravity for t~ (default: trace header)\n"
    "  --zs Z             bed surface height (default: trace header key surface, else measured\n"
    "                     in the first frame as compute bed/surface does)\n"
    "  --dr DR --dz DZ    bin sizes (default d_g), rounded to whole bins as the compute does\n"
    "  --rmax R           outer radius of the bins (default half the smaller box width)\n"
    "  --zlo Z --zhi Z    bin range about the tip (default -4 and 6)\n"
    "  --voronoi WHAT     auto (default: column c_vor[1] if the dump has it, else voro++),\n"
    "                     a column name, voro++ (tessellate each frame, as compute\n"
    "                     flow/azimuthal voronoi voro++ does) or none\n"
    "  --rod-cells        with voro++: the rod's spheres take part in the tessellation, so\n"
    "                     that the grains' cells end at the rod surface instead of reaching\n"
    "                     into the rod (phi next to the rod; the compute does not do this)\n"
    "  --stress WHAT      auto (default: columns c_stress[1..3] if present), a compute ID\n"
    "                     (columns c_ID[1] c_ID[2] c_ID[3] of compute stress/atom), or none\n"
    "  --periodic AXES    periodic box directions among x, y: xy (default), x, y or none\n"
    "  --profile-radius R cylinder radius of the profile below the rod (default D/3)\n"
    "  --strip A B        strip distances from the shaft surface (default 0.5 1.5)\n"
    "  --annulus R1 R2    annulus radii (default 2 3)\n"
    "  --annulus-top H    the annulus starts H below the bed surface (default 0.5)\n"
    "  --edge WR WZ       edge bins: centres within WR of r = R and WZ of z = 0 (default:\n"
    "                     one bin size each)\n"
    "  --steps A[:B]      only the frames with timesteps A to B (either may be left out)\n"
    "Units are the dump's (cgs for granpen's decks). Progress goes to stderr.\n"
    "Exit status: 0 on success, 1 for unreadable input (the message names file and line;\n"
    "no output is written), 2 for a usage error.\n";

const Usage usage_error{"flow", HELP};

struct FrameRecord {
  long long timestep = 0;
  std::string where;
  double tip = 0, z_tip = 0, t_tilde = 0;
  std::size_t rod_atoms = 0, grains = 0;
  EdgeAverage edge;
  bool annulus = false;
  SliceBin ann;
  double ann_phi = 0;
  double surface_vz = 0;    // the near-shaft strip's top grain layer (dz below z_s)
  std::size_t surface_grains = 0;
};

std::string fit_json(const ExpFit &f, double D)
{
  std::ostringstream o;
  o << "{\"ok\": " << (f.ok ? "true" : "false") << ", \"A\": " << js(f.A) << ", \"A_se\": " << js(f.A_se)
    << ", \"lambda\": " << js(f.lambda) << ", \"lambda_se\": " << js(f.lambda_se)
    << ", \"lambda_D\": " << js(f.lambda / D) << ", \"lambda_D_se\": " << js(f.lambda_se / D)
    << ", \"n\": " << f.n << ", \"zmin\": " << js(f.zmin) << ", \"zmax\": " << js(f.zmax)
    << ", \"note\": " << json_string(f.note) << "}";
  return o.str();
}

std::string fit_text(const ExpFit &f, double D)
{
  if (!f.ok) return "undefined (" + f.note + ")";
  return json_number("%.3g", f.lambda) + " +- " + json_number("%.2g", f.lambda_se) + " = " +
         json_number("%.3g", f.lambda / D) + " +- " + json_number("%.2g", f.lambda_se / D) + " D (" +
         std::to_string(f.n) + " bins, z " + json_number("%.3g", f.zmin) + ".." + json_number("%.3g", f.zmax) + ")";
}

}    // namespace

int granpen::cli::flow(int argc, char **argv)
{
  Command cmd("flow", HELP);
  static const std::vector<OptionSpec> spec = {
      {"--trace", 1, "the push's force trace"}, {"--out", 1, "output folder"}, {"--rod-type", 1, "atom type of the rod"},
      {"--axis", 2, "fixed rod axis X Y"}, {"--tip", 1, "fixed tip height"}, {"--D", 1, "rod diameter"},
      {"--dg", 1, "grain diameter"}, {"--rho", 1, "grain density"}, {"--v0", 1, "push speed"}, {"--g", 1, "gravity"},
      {"--zs", 1, "bed surface height"}, {"--dr", 1, "radial bin size"}, {"--dz", 1, "vertical bin size"},
      {"--rmax", 1, "outer radius of the bins"}, {"--zlo", 1, "bin range below the tip"},
      {"--zhi", 1, "bin range above the tip"}, {"--voronoi", 1, "auto, a column, voro++ or none"},
      {"--stress", 1, "auto, a compute ID or none"}, {"--periodic", 1, "xy, x, y or none"},
      {"--profile-radius", 1, "cylinder radius of the profile below the rod"}, {"--strip", 2, "strip distances A B"},
      {"--annulus", 2, "annulus radii R1 R2"}, {"--annulus-top", 1, "annulus starts H below the surface"},
      {"--edge", 2, "edge bin widths WR WZ"}, {"--steps", 1, "frames with timesteps A[:B]"},
      {"--rod-cells", 0, "with voro++: the rod's spheres take part in the tessellation"}};
  ParsedArgs args;
  if (!parse_table(cmd, spec, "dumps", argc, argv, args)) return EXIT_OK;
  std::string msg;
  if (args.positional.empty()) return usage_error("no dump given");

  if (!args.read_numbers({"--trace", "--out", "--voronoi", "--stress", "--periodic", "--steps"}, msg) ||
      !args.positive({"--D", "--dg", "--rho", "--v0", "--g", "--dr", "--dz", "--rmax", "--profile-radius"}, msg))
    return usage_error(msg);
  const auto &num = args.numbers;

  RodOptions ro;
  if (!read_rod_options(args, ro, msg)) return usage_error(msg);
  const std::string out_dir = args.value("--out", ".");
  if (out_dir.empty()) return usage_error("--out needs a folder");
  refuse_outputs_over_inputs(out_dir, {"flow.json", "flow_fields.csv", "flow_profile_below.csv", "flow_edge_phi_I.csv", "flow_strip.csv", "flow_annulus.csv", "flow_surface.csv"}, args);
  const std::string vor_opt = args.value("--voronoi", "auto");
  const bool rod_cells = args.has("--rod-cells");
  const std::string stress_opt = args.value("--stress", "auto");
  const std::string periodic = args.value("--periodic", "xy");
  bool px, py;
  if (!periodic_axes(periodic, px, py)) return usage_error("--periodic must be xy, x, y or none");
  double strip1 = 0.5, strip2 = 1.5, ann1 = 2.0, ann2 = 3.0, ann_top = 0.5, zlo = -4.0, zhi = 6.0;
  if (num.count("--strip")) strip1 = num.at("--strip")[0], strip2 = num.at("--strip")[1];
  if (num.count("--annulus")) ann1 = num.at("--annulus")[0], ann2 = num.at("--annulus")[1];
  if (!(strip1 >= 0 && strip2 > strip1)) return usage_error("--strip needs 0 <= A < B");
  if (!(ann1 >= 0 && ann2 > ann1)) return usage_error("--annulus needs 0 <= R1 < R2");
  args.number("--annulus-top", ann_top);
  args.number("--zlo", zlo);
  args.number("--zhi", zhi);
  if (!(zhi > zlo)) return usage_error("--zhi must exceed --zlo");
  if (!(zlo < 0.0)) return usage_error("--zlo must be below 0 (the profile below the rod needs bins below the tip)");

  long long step_lo = std::numeric_limits<long long>::min(), step_hi = std::numeric_limits<long long>::max();
  if (args.has("--steps")) {
    const std::string t = args.value("--steps", "");
    const auto colon = t.find(':');
    const std::string a = t.substr(0, colon), b = colon == std::string::npos ? a : t.substr(colon + 1);
    if ((!a.empty() && !integer_arg(a, step_lo)) || (!b.empty() && !integer_arg(b, step_hi)) || (a.empty() && b.empty()))
      return usage_error("--steps '" + t + "' is not FIRST[:LAST] (timesteps)");
    if (step_hi < step_lo) return usage_error("--steps '" + t + "': LAST is before FIRST");
  }
  auto selected = [&](long long step) { return step >= step_lo && step <= step_hi; };

  std::vector<std::string> notes;
  try {
    TraceHeader th;
    if (args.has("--trace")) th = load_trace(args.value("--trace", ""));

    DumpReader reader(args.positional);
    report_progress(reader, "granpen flow");
    DumpFrame frame;
    if (!reader.next(frame)) throw InputError(args.positional[0] + ": no frames");

    // columns, from the first frame
    ColumnChoice cols;
    cols.mass = frame.has("mass");
    std::string vor_source, stress_source;
    bool voro = false;
    if (vor_opt == "auto") {
      if (frame.has("c_vor[1]")) cols.voronoi = "c_vor[1]";
      else voro = true;
    } else if (vor_opt == "voro++") {
      voro = true;
    } else if (vor_opt != "none") {
      if (!frame.has(vor_opt))
        throw InputError(file_line(frame.file, frame.line) + ": frame has no column " + vor_opt +
                         " (--voronoi)");
      cols.voronoi = vor_opt;
    }
    vor_source = voro ? (rod_cells ? "voro++ (the rod's spheres as neighbours)" : "voro++")
                      : cols.voronoi.empty() ? "none" : "column " + cols.voronoi;
    if (stress_opt != "none") {
      const std::string id = stress_opt == "auto" ? "stress" : stress_opt;
      bool all = true;
      for (int k = 0; k < 3; ++k) {
        cols.stress[k] = "c_" + id + "[" + std::to_string(k + 1) + "]";
        all = all && frame.has(cols.stress[k]);
      }
      if (!all) {
        if (stress_opt != "auto")
          throw InputError(file_line(frame.file, frame.line) + ": frame has no columns c_" + id +
                           "[1..3] (--stress " + id + ")");
        for (auto &s : cols.stress) s.clear();
      }
    }
    stress_source = cols.stress[0].empty() ? "none" : "columns c_" + (stress_opt == "auto" ? std::string("stress") : stress_opt) + "[1..3]";
    if (cols.stress[0].empty()) notes.push_back("no per-atom stress columns: p and I are 0");

    // parameters: option, trace header, or the first frame
    GrainFrame g;
    double rho = 3.0;
    std::string rho_src = "default";
    if (args.number("--rho", rho)) rho_src = "option";
    else if (th.have_rho) rho = th.rho_g, rho_src = "trace";
    extract_frame(frame, ro, cols, rho, px, py, g);
    if (g.grains() == 0) throw InputError(g.where + ": frame has no grains (atoms not of the rod type)");
    if (cols.mass && rho_src == "default") {
      double m = 0, vol = 0;
      for (std::size_t i = 0; i < g.grains(); ++i) m += g.mass[i], vol += 4.0 / 3.0 * PI * std::pow(g.radius[i], 3);
      rho = m / vol, rho_src = "first frame";
    }
    double d_g = 0.0;
    std::string dg_src = "option";
    if (!args.number("--dg", d_g)) {
      if (th.have_dg) d_g = th.d_g, dg_src = "trace";
      else {
        double s = 0;
        for (double r : g.radius) s += 2.0 * r;
        d_g = s / (double) g.grains(), dg_src = "first frame";
      }
    }
    double D = 0.0;
    std::string D_src = "option";
    if (!args.number("--D", D)) {
      if (th.present) D = th.trace.D, D_src = "trace";
      else if (g.rod.found) D = g.rod.diameter, D_src = "rod atoms";
      else throw InputError(g.where + ": no rod atoms to measure D from: give --D or --trace");
    }
    const double R = 0.5 * D;
    double v0 = std::numeric_limits<double>::quiet_NaN(), gacc = v0;
    std::string v0_src = "none", g_src = "none";
    if (args.number("--v0", v0)) v0_src = "option";
    else if (th.present) v0 = th.trace.v0, v0_src = "trace";
    if (args.number("--g", gacc)) g_src = "option";
    else if (th.present) gacc = th.trace.g, g_src = "trace";
    if (!std::isfinite(v0) || !std::isfinite(gacc)) notes.push_back("t~ undefined: no v0 or g (give --trace, or --v0 and --g)");
    double zs = 0.0;
    std::string zs_src = "option";
    if (!args.number("--zs", zs)) {
      if (th.have_surface) zs = th.surface, zs_src = "trace";
      else {
        std::vector<double> X = frame.col("x"), Y = frame.col("y"), Z = frame.col("z"), Rr = frame.col("radius");
        int nempty = 0;
        zs = bed_surface(X.data(), Y.data(), Z.data(), Rr.data(), g.is_rod.data(), X.size(), frame.lo[0],
                         frame.hi[0], frame.lo[1], frame.hi[1], 4, nempty);
        zs_src = "first frame";
        notes.push_back("bed surface z_s measured in the first frame (timestep " + std::to_string(frame.timestep) +
                        "): give --zs or a trace with the surface key when the rod is already in the bed");
      }
    }

    double dr = d_g, dz = d_g, rmax = 0.5 * std::min(frame.hi[0] - frame.lo[0], frame.hi[1] - frame.lo[1]);
    args.number("--dr", dr);
    args.number("--dz", dz);
    args.number("--rmax", rmax);
    FlowGrid grid;
    try {
      grid = make_flow_grid(0.0, rmax, dr, zlo, zhi, dz);
    } catch (std::invalid_argument &e) {
      return usage_error(e.what());
    }
    double wr = grid.dr, wz = grid.dz;
    if (num.count("--edge")) wr = num.at("--edge")[0], wz = num.at("--edge")[1];
    double prof_r = D / 3.0;
    args.number("--profile-radius", prof_r);

    FlowAccumulator total(grid);
    SliceAccumulator below(SliceSpec{0.0, prof_r, grid.zlo, 0.0, grid.dz});
    // strip bins of dz with an edge at the bed surface, from the box bottom to its top
    const double strip_lo = -std::ceil((zs - frame.lo[2]) / grid.dz - 1e-9) * grid.dz;
    const double strip_hi = std::max(std::ceil((frame.hi[2] - zs) / grid.dz - 1e-9), 1.0) * grid.dz;
    SliceAccumulator strip(SliceSpec{R + strip1, R + strip2, strip_lo, strip_hi, grid.dz});
    std::vector<FrameRecord> records;
    std::size_t voro_missing = 0;
    long long first_step = 0, last_step = 0;
    bool extracted = true;    // g holds the first frame

    do {
      if (!selected(frame.timestep)) {
        extracted = false;
        continue;
      }
      if (!extracted) extract_frame(frame, ro, cols, rho, px, py, g);
      extracted = false;
      if (records.empty()) first_step = frame.timestep;
      last_step = frame.timestep;
      if (voro) {
        VoronoiBox box;
        for (int d = 0; d < 3; ++d) box.lo[d] = frame.lo[d], box.hi[d] = frame.hi[d];
        box.periodic[0] = px, box.periodic[1] = py, box.periodic[2] = false;
        VoronoiInfo info;
        try {
          if (rod_cells && !g.rod_x.empty()) {
            g.vor = voronoi_volumes_among(g.x.data(), g.y.data(), g.z.data(), g.radius.data(), g.grains(),
                                          g.rod_x.data(), g.rod_y.data(), g.rod_z.data(), g.rod_radius.data(),
                                          g.rod_x.size(), box, &info);
          } else {
            g.vor = voronoi_volumes(g.x.data(), g.y.data(), g.z.data(), g.radius.data(), g.grains(), box, nullptr,
                                    &info);
          }
        } catch (std::invalid_argument &e) {
          throw InputError(g.where + ": " + e.what());
        }
        g.have_vor = true;
        voro_missing += info.missing;
      }
      const GrainArrays ga = g.arrays();
      AxisFrame tipf;
      tipf.x = g.axis_x, tipf.y = g.axis_y, tipf.zref = g.tip, tipf.period_x = g.period_x, tipf.period_y = g.period_y;
      FlowAccumulator one(grid);
      one.add(ga, tipf);
      total.merge(one);
      FrameRecord rec;
      rec.timestep = frame.timestep;
      rec.where = g.where;
      rec.tip = g.tip;
      rec.z_tip = zs - g.tip;
      rec.t_tilde = t_tilde(rec.z_tip, v0, gacc, D);
      rec.rod_atoms = g.rod.atoms;
      rec.grains = g.grains();
      rec.edge = edge_average(one.fields(d_g, rho), R, wr, wz);
      below.add(ga, tipf);
      AxisFrame lab = tipf;
      lab.zref = zs;
      strip.add(ga, lab);
      {
        SliceAccumulator top(SliceSpec{R + strip1, R + strip2, -grid.dz, 0.0, grid.dz});
        top.add(ga, lab);
        rec.surface_grains = (std::size_t) top.bins()[0].samples;
        rec.surface_vz = top.bins()[0].vz;
      }
      const double ztop = zs - ann_top;
      if (ztop > g.tip) {
        SliceAccumulator ann(SliceSpec{ann1, ann2, 0.0, ztop - g.tip, ztop - g.tip});
        ann.add(ga, tipf);
        rec.ann = ann.bins()[0];
        rec.annulus = rec.ann.samples > 0;
        rec.ann_phi = ann.have_voronoi() ? rec.ann.phi_voronoi : rec.ann.phi_centre;
      }
      records.push_back(rec);
    } while (reader.next(frame));
    if (records.empty())
      throw InputError(args.positional[0] + ": no frame with a timestep in " + args.value("--steps", "") + " (--steps)");
    if (voro_missing) notes.push_back(std::to_string(voro_missing) + " grain cells could not be computed (volume 0)");

    // ---- results
    const FlowFields F = total.fields(d_g, rho);
    const bool phi_vor = F.have_voronoi;
    const auto below_bins = below.bins();
    std::vector<double> bz, bv, bse;
    for (const auto &b : below_bins)
      if (b.samples >= 2) bz.push_back(b.z), bv.push_back(b.vz), bse.push_back(b.vz_se);
    const ExpFit fit_vz = fit_exponential(bz, bv, bse);
    // gammadot below the face: mass-weighted over the field bins inside the cylinder
    std::vector<double> gz, gg;
    for (int iz = 0; iz < grid.nz; ++iz) {
      double m = 0, s = 0;
      for (int ir = 0; ir < grid.nr; ++ir) {
        const FlowBin &b = F.at(ir, iz);
        if (b.r < prof_r && b.z < 0.0 && b.mass > 0) m += b.mass, s += b.mass * b.gammadot;
      }
      if (m > 0) gz.push_back(F.at(0, iz).z), gg.push_back(s / m);
    }
    const ExpFit fit_gd = fit_exponential(gz, gg);

    std::vector<double> eI, ephi;
    for (const auto &r : records)    // frames with the tip in the bed
      if (r.edge.bins > 0 && r.z_tip > 0.0)
        eI.push_back(r.edge.I), ephi.push_back(phi_vor ? r.edge.phi_voronoi : r.edge.phi_centre);
    LinearFit edge_fit;
    bool edge_ok = false;
    std::string edge_note;
    if (!F.have_stress) edge_note = "no stress columns: I is 0";
    else {
      try {
        edge_fit = linear_fit(eI, ephi);
        edge_ok = true;
      } catch (std::invalid_argument &e) {
        edge_note = e.what();
      }
    }

    // ---- tables
    std::ostringstream fields_csv, below_csv, edge_csv, strip_csv, ann_csv, surf_csv, json;
    fields_csv << "r,z,count,phi,phi_centre,vr,vz,T,gammadot,p,I\n";
    for (const auto &b : F.bins)
      fields_csv << csv_num(b.r) << ',' << csv_num(b.z) << ',' << csv_num(b.count) << ',' << csv_num(b.phi_voronoi)
                 << ',' << csv_num(b.phi_centre) << ',' << csv_num(b.vr) << ',' << csv_num(b.vz) << ','
                 << csv_num(b.T) << ',' << csv_num(b.gammadot) << ',' << csv_num(b.p) << ',' << csv_num(b.I) << '\n';
    below_csv << "z,vz,vz_se,phi\n";
    for (const auto &b : below_bins)
      if (b.samples > 0)
        below_csv << csv_num(b.z) << ',' << csv_num(b.vz) << ',' << csv_num(b.vz_se) << ','
                  << csv_num(below.have_voronoi() ? b.phi_voronoi : b.phi_centre) << '\n';
    edge_csv << "I,phi\n";
    for (std::size_t k = 0; k < eI.size(); ++k) edge_csv << csv_num(eI[k]) << ',' << csv_num(ephi[k]) << '\n';
    strip_csv << "z,vz\n";
    std::size_t strip_rows = 0;
    for (const auto &b : strip.bins())
      if (b.samples > 0) strip_csv << csv_num(b.z) << ',' << csv_num(b.vz) << '\n', ++strip_rows;
    // the surface flux against t~, over the frames with the tip in the bed, and where it
    // turns from up to down
    surf_csv << "t_tilde,z_tip,vz,grains\n";
    std::vector<double> st, sv;
    for (const auto &r : records)
      if (r.z_tip > 0.0 && r.surface_grains > 0 && std::isfinite(r.t_tilde)) {
        surf_csv << csv_num(r.t_tilde) << ',' << csv_num(r.z_tip) << ',' << csv_num(r.surface_vz) << ','
                 << r.surface_grains << '\n';
        st.push_back(r.t_tilde), sv.push_back(r.surface_vz);
      }
    const double surf_cross = last_down_crossing(st, sv);
    ann_csv << "t_tilde,z_tip,phi,vz,T\n";
    std::size_t ann_rows = 0;
    for (const auto &r : records)
      if (r.annulus)
        ann_csv << csv_num(r.t_tilde) << ',' << csv_num(r.z_tip) << ',' << csv_num(r.ann_phi) << ','
                << csv_num(r.ann.vz) << ',' << csv_num(r.ann.T) << '\n', ++ann_rows;

    json << "{\n  \"tool\": \"granpen flow\",\n"
         << "  \"units\": \"those of the dump (granpen decks: cgs, cm, g, s)\",\n"
         << "  \"inputs\": {\"dumps\": [";
    for (std::size_t k = 0; k < args.positional.size(); ++k) json << (k ? ", " : "") << json_string(args.positional[k]);
    json << "], \"trace\": " << (th.present ? json_string(th.trace.path) : std::string("null"))
         << ", \"frames\": " << records.size() << ", \"first_timestep\": " << first_step
         << ", \"last_timestep\": " << last_step << "},\n"
         << "  \"parameters\": {\"D\": " << js(D) << ", \"D_source\": " << json_string(D_src) << ", \"R\": " << js(R)
         << ", \"d_g\": " << js(d_g) << ", \"d_g_source\": " << json_string(dg_src) << ", \"rho_g\": " << js(rho)
         << ", \"rho_g_source\": " << json_string(rho_src) << ",\n    \"v0\": "
         << (std::isfinite(v0) ? js(v0) : "null") << ", \"v0_source\": " << json_string(v0_src)
         << ", \"g\": " << (std::isfinite(gacc) ? js(gacc) : "null") << ", \"g_source\": " << json_string(g_src)
         << ", \"z_s\": " << js(zs) << ", \"z_s_source\": " << json_string(zs_src) << ",\n    \"rod_type\": "
         << ro.rod_type << ", \"masses\": " << json_string(cols.mass ? "column mass" : "rho_g 4/3 pi r^3")
         << ", \"voronoi\": " << json_string(vor_source) << ", \"stress\": " << json_string(stress_source)
         << ", \"periodic\": " << json_string(periodic) << ",\n    \"grid\": {\"rmin\": 0, \"rmax\": "
         << js(grid.rmax) << ", \"dr\": " << js(grid.dr) << ", \"nr\": " << grid.nr << ", \"zlo\": " << js(grid.zlo)
         << ", \"zhi\": " << js(grid.zhi) << ", \"dz\": " << js(grid.dz) << ", \"nz\": " << grid.nz
         << ", \"frame\": \"tip\"},\n    \"profile_radius\": " << js(prof_r) << ", \"strip\": [" << js(strip1)
         << ", " << js(strip2) << "], \"annulus\": [" << js(ann1) << ", " << js(ann2)
         << "], \"annulus_top\": " << js(ann_top) << ", \"edge\": [" << js(wr) << ", " << js(wz) << "]},\n"
         << "  \"fields\": {\"phi\": " << json_string(phi_vor ? "voronoi" : "none (0)")
         << ", \"have_stress\": " << (F.have_stress ? "true" : "false") << ", \"bins\": " << grid.bins() << "},\n"
         << "  \"profile_below\": {\"phi\": " << json_string(below.have_voronoi() ? "voronoi" : "centre")
         << ", \"lambda_vz\": " << fit_json(fit_vz, D) << ",\n    \"lambda_gammadot\": " << fit_json(fit_gd, D)
         << ", \"paper_lambda_vz_D\": 0.98},\n"
         << "  \"edge\": {\"points\": " << eI.size() << ", \"phi\": " << json_string(phi_vor ? "voronoi" : "centre")
         << ", \"fit\": {\"ok\": " << (edge_ok ? "true" : "false") << ", \"phi_0\": " << js(edge_fit.a)
         << ", \"phi_0_se\": " << js(edge_fit.se_a) << ", \"slope\": " << js(edge_fit.b)
         << ", \"slope_se\": " << js(edge_fit.se_b) << ", \"rms\": " << js(edge_fit.rms)
         << ", \"n\": " << edge_fit.n << ", \"note\": " << json_string(edge_note)
         << "}, \"paper\": {\"phi_0\": 0.57, \"slope\": -0.35}},\n"
         << "  \"strip\": {\"bins\": " << strip_rows << ", \"z\": \"height above the bed surface\"},\n"
         << "  \"surface\": {\"frames\": " << st.size() << ", \"crossing_t_tilde\": "
         << (std::isfinite(surf_cross) ? js(surf_cross) : "null") << ", \"paper_t_tilde\": 1},\n"
         << "  \"annulus\": {\"frames\": " << ann_rows << ", \"phi\": "
         << json_string(phi_vor ? "voronoi" : "centre") << "},\n  \"frames\": [";
    for (std::size_t k = 0; k < records.size(); ++k) {
      const FrameRecord &r = records[k];
      json << (k ? ",\n" : "\n") << "    {\"timestep\": " << r.timestep << ", \"where\": " << json_string(r.where)
           << ", \"grains\": " << r.grains << ", \"rod_atoms\": " << r.rod_atoms << ", \"tip\": " << js(r.tip)
           << ", \"z_tip\": " << js(r.z_tip) << ", \"t_tilde\": " << (std::isfinite(r.t_tilde) ? js(r.t_tilde) : "null")
           << ", \"edge\": {\"bins\": " << r.edge.bins << ", \"I\": " << js(r.edge.I)
           << ", \"phi\": " << js(phi_vor ? r.edge.phi_voronoi : r.edge.phi_centre)
           << ", \"gammadot\": " << js(r.edge.gammadot) << ", \"p\": " << js(r.edge.p) << "}";
      if (r.annulus)
        json << ", \"annulus\": {\"grains\": " << js(r.ann.samples) << ", \"phi\": " << js(r.ann_phi)
             << ", \"vr\": " << js(r.ann.vr) << ", \"vz\": " << js(r.ann.vz) << ", \"T\": " << js(r.ann.T) << "}";
      json << "}";
    }
    json << (records.empty() ? "],\n" : "\n  ],\n") << "  \"notes\": [";
    for (std::size_t k = 0; k < notes.size(); ++k) json << (k ? ", " : "") << json_string(notes[k]);
    json << "]\n}\n";

    // ---- summary
    std::printf("granpen flow: %zu frames (timesteps %lld..%lld) of %zu dump%s, %zu grains in the last\n",
                records.size(), first_step, last_step, args.positional.size(), args.positional.size() == 1 ? "" : "s",
                records.back().grains);
    std::printf("  rod D = %g cm (%s), d_g = %g (%s), rho_g = %g (%s), z_s = %.4g (%s), v0 = %g (%s), g = %g (%s)\n", D,
                D_src.c_str(), d_g, dg_src.c_str(), rho, rho_src.c_str(), zs, zs_src.c_str(), v0, v0_src.c_str(),
                gacc, g_src.c_str());
    std::printf("  fields: %d x %d bins (dr %.4g, dz %.4g; z %g..%g from the tip), phi: %s, stress: %s\n", grid.nr,
                grid.nz, grid.dr, grid.dz, grid.zlo, grid.zhi, vor_source.c_str(), stress_source.c_str());
    std::printf("  below the rod (r < %.3g): lambda_vz = %s (paper: 0.98 D +- 0.15)\n", prof_r,
                fit_text(fit_vz, D).c_str());
    std::printf("  below the rod: lambda_gammadot = %s\n", fit_text(fit_gd, D).c_str());
    if (edge_ok)
      std::printf("  rod edge: phi = %.4g +- %.2g + (%.4g +- %.2g) I over %zu frames (paper: 0.57 - 0.35 I)\n",
                  edge_fit.a, edge_fit.se_a, edge_fit.b, edge_fit.se_b, edge_fit.n);
    else
      std::printf("  rod edge: %zu frames, phi(I) fit undefined (%s)\n", eI.size(), edge_note.c_str());
    std::printf("  strip %g-%g from the shaft: %zu bins; annulus r %g-%g: %zu frames\n", strip1, strip2, strip_rows,
                ann1, ann2, ann_rows);
    if (std::isfinite(surf_cross))
      std::printf("  surface flux (top layer of the strip): up to down at t~ = %.3f over %zu frames (paper: 1)\n",
                  surf_cross, st.size());
    else
      std::printf("  surface flux (top layer of the strip): no change from up to down over %zu frames\n", st.size());
    for (const auto &n : notes) std::printf("  note: %s\n", n.c_str());

    std::vector<std::pair<std::string, std::string>> files = {
        {"flow.json", json.str()},          {"flow_fields.csv", fields_csv.str()},
        {"flow_profile_below.csv", below_csv.str()}, {"flow_edge_phi_I.csv", edge_csv.str()},
        {"flow_strip.csv", strip_csv.str()}, {"flow_annulus.csv", ann_csv.str()},
        {"flow_surface.csv", surf_csv.str()}};
    if (!write_outputs(out_dir, files, msg)) {
      std::fprintf(stderr, "granpen flow: %s\n", msg.c_str());
      return 1;
    }
    std::printf("wrote %s/{flow.json, flow_fields.csv, flow_profile_below.csv, flow_edge_phi_I.csv, "
                "flow_strip.csv, flow_annulus.csv, flow_surface.csv}\n", out_dir.c_str());
  } catch (std::exception &e) {    // InputError names file:line
    std::fprintf(stderr, "granpen flow: %s\n", e.what());
    return 1;
  }
  return 0;
}
