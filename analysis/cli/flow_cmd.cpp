// granpen flow DUMP...: the flow around the rod from LAMMPS dumps of the grains and the
// rod: azimuthal (r, z) fields in the tip frame, the profile below the rod face with its
// exponential length, phi against I at the rod edge, the near-shaft strip and the
// annulus r = 2-3 cm against t~ (core/flow_fields.h, core/voronoi_volumes.h).
#include "atomic_file.h"
#include "dump_cmd_common.h"
#include "flow_options.h"
#include "flow_fields.h"
#include "flow_study.h"
#include "flow_tables.h"
#include "json_text.h"
#include "paper_values.h"
#include "rod_frame.h"
#include "subcommands.h"
#include "text_util.h"
#include "voronoi_volumes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

using granpen::json_number;

namespace {

using namespace granpen;
using namespace granpen::cli;

constexpr double PI = 3.14159265358979323846;


const char *const OUTPUTS[] = {"flow.json", "flow_fields.csv", "flow_profile_below.csv", "flow_edge_phi_I.csv",
                               "flow_strip.csv", "flow_annulus.csv", "flow_surface.csv"};

// The columns to read, from the first frame: Voronoi volumes (or voro++) and stresses.
struct Columns {
  ColumnChoice choice;
  bool voro = false;
};
Columns choose_columns(const DumpFrame &frame, const FlowOptions &o, FlowProvenance &how)
{
  Columns c;
  c.choice.mass = frame.has("mass");
  if (o.voronoi == "auto") {
    if (frame.has("c_vor[1]")) c.choice.voronoi = "c_vor[1]";
    else c.voro = true;
  } else if (o.voronoi == "voro++") {
    c.voro = true;
  } else if (o.voronoi != "none") {
    if (!frame.has(o.voronoi))
      throw InputError(file_line(frame.file, frame.line) + ": frame has no column " + o.voronoi + " (--voronoi)");
    c.choice.voronoi = o.voronoi;
  }
  how.voronoi = c.voro ? (o.rod_cells ? "voro++ (the rod's spheres as neighbours)" : "voro++")
                       : c.choice.voronoi.empty() ? "none" : "column " + c.choice.voronoi;
  if (o.stress != "none") {
    const std::string id = o.stress == "auto" ? "stress" : o.stress;
    bool all = true;
    for (int k = 0; k < 3; ++k) {
      c.choice.stress[k] = "c_" + id + "[" + std::to_string(k + 1) + "]";
      all = all && frame.has(c.choice.stress[k]);
    }
    if (!all) {
      if (o.stress != "auto")
        throw InputError(file_line(frame.file, frame.line) + ": frame has no columns c_" + id + "[1..3] (--stress " + id + ")");
      for (auto &s : c.choice.stress) s.clear();
    }
  }
  how.stress = c.choice.stress[0].empty() ? "none" : "columns c_" + (o.stress == "auto" ? std::string("stress") : o.stress) + "[1..3]";
  if (c.choice.stress[0].empty()) how.notes.push_back("no per-atom stress columns: p and I are 0");
  return c;
}

// Where the study's parameters may come from: the options, the trace header, the first frame.
FlowParamSources parameter_sources(const DumpFrame &frame, const GrainFrame &g, const PushTrace &th,
                                   const FlowOptions &o, bool mass_column)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  FlowParamSources s;
  s.D = {o.D, th.present ? th.trace.D : nan};
  s.d_g = {o.d_g, th.have_dg ? th.d_g : nan};
  s.rho_g = {o.rho_g, th.have_rho ? th.rho_g : nan};
  s.v0 = {o.v0, th.present ? th.trace.v0 : nan};
  s.g = {o.g, th.present ? th.trace.g : nan};
  s.z_s = {o.z_s, th.have_surface ? th.surface : nan};
  s.radius = g.radius.data(), s.mass = mass_column ? g.mass.data() : nullptr, s.grains = g.grains();
  if (g.rod.found) s.rod_D = g.rod.diameter;
  for (int d = 0; d < 3; ++d) s.lo[d] = frame.lo[d], s.hi[d] = frame.hi[d];
  s.timestep = frame.timestep;
  s.measure_z_s = [&frame, &g] { return frame_bed_surface(frame, g); };
  s.dr = o.dr, s.dz = o.dz, s.rmax = o.rmax, s.profile_radius = o.profile_radius;
  s.edge_wr = o.edge_wr, s.edge_wz = o.edge_wz;
  s.zlo = o.zlo, s.zhi = o.zhi;
  s.strip1 = o.strip1, s.strip2 = o.strip2, s.ann1 = o.ann1, s.ann2 = o.ann2, s.ann_top = o.ann_top;
  return s;
}

// The study's parameters (core/flow_study.h's flow_study_params), their origins in how.
FlowStudyParams resolve_parameters(const DumpFrame &frame, const GrainFrame &g, const PushTrace &th,
                                   const FlowOptions &o, FlowProvenance &how)
{
  const FlowParamSources s = parameter_sources(frame, g, th, o, how.mass_column);
  if (!std::isfinite(s.D.option) && !std::isfinite(s.D.trace) && !g.rod.found)
    throw InputError(g.where + ": no rod atoms to measure D from: give --D or --trace");
  FlowParamOrigins from;
  FlowStudyParams p;
  try {
    p = flow_study_params(s, from);
  } catch (std::invalid_argument &e) {
    throw UsageError(e.what());
  }
  how.D_source = from.D, how.d_g_source = from.d_g, how.rho_g_source = from.rho_g;
  how.v0_source = from.v0, how.g_source = from.g, how.z_s_source = from.z_s;
  how.notes.insert(how.notes.end(), from.notes.begin(), from.notes.end());
  return p;
}

// g.vor from voro++ on the frame's box; cells that could not be made are counted
void tessellate(const DumpFrame &frame, const FlowOptions &o, GrainFrame &g, std::size_t &missing)
{
  VoronoiBox box;
  for (int d = 0; d < 3; ++d) box.lo[d] = frame.lo[d], box.hi[d] = frame.hi[d];
  box.periodic[0] = o.px, box.periodic[1] = o.py, box.periodic[2] = false;
  VoronoiInfo info;
  try {
    if (o.rod_cells && !g.rod_x.empty())
      g.vor = voronoi_volumes_among(g.x.data(), g.y.data(), g.z.data(), g.radius.data(), g.grains(), g.rod_x.data(),
                                    g.rod_y.data(), g.rod_z.data(), g.rod_radius.data(), g.rod_x.size(), box, &info);
    else
      g.vor = voronoi_volumes(g.x.data(), g.y.data(), g.z.data(), g.radius.data(), g.grains(), box, nullptr, &info);
  } catch (std::invalid_argument &e) {
    throw InputError(g.where + ": " + e.what());
  }
  g.have_vor = true;
  missing += info.missing;
}

std::string fit_text(const ExpFit &f, double D)
{
  if (!f.ok) return "undefined (" + f.note + ")";
  return json_number("%.3g", f.lambda) + " +- " + json_number("%.2g", f.lambda_se) + " = " +
         json_number("%.3g", f.lambda / D) + " +- " + json_number("%.2g", f.lambda_se / D) + " D (" +
         std::to_string(f.n) + " bins, z " + json_number("%.3g", f.zmin) + ".." + json_number("%.3g", f.zmax) + ")";
}

void print_summary(const FlowStudyParams &p, const FlowSummary &s, const std::vector<FlowFrameRecord> &frames,
                   const FlowProvenance &how)
{
  const FlowGrid &grid = p.grid;
  std::printf("granpen flow: %zu frames (timesteps %lld..%lld) of %zu dump%s, %zu grains in the last\n", frames.size(),
              how.first_step, how.last_step, how.dumps.size(), how.dumps.size() == 1 ? "" : "s", frames.back().grains);
  std::printf("  rod D = %g cm (%s), d_g = %g (%s), rho_g = %g (%s), z_s = %.4g (%s), v0 = %g (%s), g = %g (%s)\n", p.D,
              how.D_source.c_str(), p.d_g, how.d_g_source.c_str(), p.rho_g, how.rho_g_source.c_str(), p.z_s,
              how.z_s_source.c_str(), p.v0, how.v0_source.c_str(), p.g, how.g_source.c_str());
  std::printf("  fields: %d x %d bins (dr %.4g, dz %.4g; z %g..%g from the tip), phi: %s, stress: %s\n", grid.nr, grid.nz,
              grid.dr, grid.dz, grid.zlo, grid.zhi, how.voronoi.c_str(), how.stress.c_str());
  std::printf("  below the rod (r < %.3g): lambda_vz = %s (paper: %.2f D +- %.2f)\n", p.profile_radius,
              fit_text(s.lambda_vz, p.D).c_str(), paper::lambda_vz_over_D, paper::lambda_vz_over_D_error);
  std::printf("  below the rod: lambda_gammadot = %s\n", fit_text(s.lambda_gammadot, p.D).c_str());
  const LinearFit &e = s.edge_fit;
  if (s.edge_ok)
    std::printf("  rod edge: phi = %.4g +- %.2g + (%.4g +- %.2g) I over %zu frames (paper: %.2f %c %.2f I)\n", e.a,
                e.se_a, e.b, e.se_b, e.n, paper::edge_phi_0, paper::edge_phi_slope < 0 ? '-' : '+',
                std::fabs(paper::edge_phi_slope));
  else
    std::printf("  rod edge: %zu frames, phi(I) fit undefined (%s)\n", s.edge_I.size(), s.edge_note.c_str());
  std::printf("  strip %g-%g from the shaft: %zu bins; annulus r %g-%g: %zu frames\n", p.strip1, p.strip2,
              s.strip.size(), p.ann1, p.ann2, s.annulus_frames);
  if (std::isfinite(s.surface_crossing))
    std::printf("  surface flux (top layer of the strip): up to down at t~ = %.3f over %zu frames (paper: 1)\n",
                s.surface_crossing, s.surface_t.size());
  else
    std::printf("  surface flux (top layer of the strip): no change from up to down over %zu frames\n",
                s.surface_t.size());
  for (const auto &n : how.notes) std::printf("  note: %s\n", n.c_str());
}

}    // namespace

int granpen::cli::run_flow(const FlowOptions &o)
{
  FlowProvenance how;
  begin_dump_command(o, std::vector<const char *>(std::begin(OUTPUTS), std::end(OUTPUTS)), how);
  PushTrace th;
  if (!o.trace.empty()) th = load_push_trace(o.trace), how.trace = th.trace.path;

  DumpReader reader(o.dumps);
  DumpFrame frame;
  first_frame(reader, o.dumps, frame, "granpen flow");
  const Columns cols = choose_columns(frame, o, how);
  how.mass_column = cols.choice.mass;
  std::string rho_source;
  const double rho = flow_grain_density({o.rho_g, th.have_rho ? th.rho_g : NAN}, rho_source);
  GrainFrame g;
  extract_frame(frame, o.rod, cols.choice, rho, o.px, o.py, g);
  if (g.grains() == 0) throw InputError(g.where + ": frame has no grains (atoms not of the rod type)");
  const FlowStudyParams params = resolve_parameters(frame, g, th, o, how);

  FlowStudy study(params);
  std::size_t voro_missing = 0;
  bool extracted = true;    // g holds the first frame
  do {
    if (!o.selected(frame.timestep)) {
      extracted = false;
      continue;
    }
    if (!extracted) extract_frame(frame, o.rod, cols.choice, params.rho_g, o.px, o.py, g);
    extracted = false;
    if (study.frames().empty()) how.first_step = frame.timestep;
    how.last_step = frame.timestep;
    if (cols.voro) tessellate(frame, o, g, voro_missing);
    study.add_frame(g.arrays(), g.axis_x, g.axis_y, g.period_x, g.period_y, g.tip, g.rod.atoms, frame.timestep, g.where);
  } while (reader.next(frame));
  if (study.frames().empty())
    throw InputError(o.dumps[0] + ": no frame with a timestep in " + o.steps + " (--steps)");
  if (voro_missing) how.notes.push_back(std::to_string(voro_missing) + " grain cells could not be computed (volume 0)");

  const FlowSummary summary = study.summary();
  print_summary(params, summary, study.frames(), how);
  std::string msg;
  if (!write_outputs(o.out_dir, flow_files(params, summary, study.frames(), how), msg))
    throw OutputError(msg);
  std::printf("wrote %s/{flow.json, flow_fields.csv, flow_profile_below.csv, flow_edge_phi_I.csv, "
              "flow_strip.csv, flow_annulus.csv, flow_surface.csv}\n", o.out_dir.c_str());
  return EXIT_OK;
}

int granpen::cli::flow(int argc, char **argv) { return run_parsed(parse_flow, run_flow, argc, argv); }
