// granpen analysis: granpen flow's files (see flow_tables.h).
#include "flow_tables.h"

#include "json_text.h"
#include "paper_values.h"

#include <cmath>
#include <sstream>

namespace granpen {

namespace {

// %.10g; non-finite as nan in a table, 0 (or null where a value may be undefined) in JSON
std::string csv_num(double v) { return std::isfinite(v) ? json_number("%.10g", v) : std::string("nan"); }
Json js(double v) { return json_rounded("%.10g", v); }
Json js_or_null(double v) { return std::isfinite(v) ? js(v) : Json(); }

Json fit_json(const ExpFit &f, double D)
{
  return {{"ok", f.ok}, {"A", js(f.A)}, {"A_se", js(f.A_se)}, {"lambda", js(f.lambda)}, {"lambda_se", js(f.lambda_se)},
          {"lambda_D", js(f.lambda / D)}, {"lambda_D_se", js(f.lambda_se / D)}, {"n", f.n}, {"zmin", js(f.zmin)},
          {"zmax", js(f.zmax)}, {"note", f.note}};
}

Json parameters_json(const FlowStudyParams &p, const FlowProvenance &how)
{
  const FlowGrid &grid = p.grid;
  return {{"D", js(p.D)}, {"D_source", how.D_source}, {"R", js(0.5 * p.D)}, {"d_g", js(p.d_g)},
          {"d_g_source", how.d_g_source}, {"rho_g", js(p.rho_g)}, {"rho_g_source", how.rho_g_source},
          {"v0", js_or_null(p.v0)}, {"v0_source", how.v0_source}, {"g", js_or_null(p.g)}, {"g_source", how.g_source},
          {"z_s", js(p.z_s)}, {"z_s_source", how.z_s_source}, {"rod_type", how.rod_type},
          {"masses", how.mass_column ? "column mass" : "rho_g 4/3 pi r^3"}, {"voronoi", how.voronoi},
          {"stress", how.stress}, {"periodic", how.periodic},
          {"grid", {{"rmin", 0}, {"rmax", js(grid.rmax)}, {"dr", js(grid.dr)}, {"nr", grid.nr}, {"zlo", js(grid.zlo)},
                    {"zhi", js(grid.zhi)}, {"dz", js(grid.dz)}, {"nz", grid.nz}, {"frame", "tip"}}},
          {"profile_radius", js(p.profile_radius)}, {"strip", {js(p.strip1), js(p.strip2)}},
          {"annulus", {js(p.ann1), js(p.ann2)}}, {"annulus_top", js(p.ann_top)}, {"edge", {js(p.edge_wr), js(p.edge_wz)}}};
}

Json frame_json(const FlowFrameRecord &r, bool phi_vor)
{
  Json f = {{"timestep", r.timestep}, {"where", r.where}, {"grains", r.grains}, {"rod_atoms", r.rod_atoms},
            {"tip", js(r.tip)}, {"z_tip", js(r.z_tip)}, {"t_tilde", js_or_null(r.t_tilde)},
            {"edge", {{"bins", r.edge.bins}, {"I", js(r.edge.I)}, {"phi", js(phi_vor ? r.edge.phi_voronoi : r.edge.phi_centre)},
                      {"gammadot", js(r.edge.gammadot)}, {"p", js(r.edge.p)}}}};
  if (r.annulus)
    f["annulus"] = {{"grains", js(r.ann.samples)}, {"phi", js(r.ann_phi)}, {"vr", js(r.ann.vr)}, {"vz", js(r.ann.vz)},
                    {"T", js(r.ann.T)}};
  return f;
}

std::string fields_csv(const FlowFields &F)
{
  std::ostringstream o;
  o << "r,z,count,phi,phi_centre,vr,vz,T,gammadot,p,I\n";
  for (const auto &b : F.bins)
    o << csv_num(b.r) << ',' << csv_num(b.z) << ',' << csv_num(b.count) << ',' << csv_num(b.phi_voronoi) << ','
      << csv_num(b.phi_centre) << ',' << csv_num(b.vr) << ',' << csv_num(b.vz) << ',' << csv_num(b.T) << ','
      << csv_num(b.gammadot) << ',' << csv_num(b.p) << ',' << csv_num(b.I) << '\n';
  return o.str();
}

std::string below_csv(const FlowSummary &s)
{
  std::ostringstream o;
  o << "z,vz,vz_se,phi\n";
  for (const auto &b : s.below)
    if (b.samples > 0)
      o << csv_num(b.z) << ',' << csv_num(b.vz) << ',' << csv_num(b.vz_se) << ','
        << csv_num(s.below_voronoi ? b.phi_voronoi : b.phi_centre) << '\n';
  return o.str();
}

std::string small_tables_csv(const char *header, const std::vector<std::vector<double>> &columns)
{
  std::ostringstream o;
  o << header << '\n';
  for (std::size_t k = 0; !columns.empty() && k < columns[0].size(); ++k)
    for (std::size_t c = 0; c < columns.size(); ++c) o << csv_num(columns[c][k]) << (c + 1 < columns.size() ? ',' : '\n');
  return o.str();
}

std::string annulus_csv(const std::vector<FlowFrameRecord> &frames)
{
  std::ostringstream o;
  o << "t_tilde,z_tip,phi,vz,T\n";
  for (const auto &r : frames)
    if (r.annulus)
      o << csv_num(r.t_tilde) << ',' << csv_num(r.z_tip) << ',' << csv_num(r.ann_phi) << ',' << csv_num(r.ann.vz) << ','
        << csv_num(r.ann.T) << '\n';
  return o.str();
}

}    // namespace

Json flow_json(const FlowStudyParams &p, const FlowSummary &s, const std::vector<FlowFrameRecord> &frames,
               const FlowProvenance &how)
{
  const bool phi_vor = s.fields.have_voronoi;
  const LinearFit &e = s.edge_fit;
  Json j;
  j["tool"] = "granpen flow";
  j["units"] = "those of the dump (granpen decks: cgs, cm, g, s)";
  j["inputs"] = {{"dumps", how.dumps}, {"trace", how.trace.empty() ? Json() : Json(how.trace)}, {"frames", frames.size()},
                 {"first_timestep", how.first_step}, {"last_timestep", how.last_step}};
  j["parameters"] = parameters_json(p, how);
  j["fields"] = {{"phi", phi_vor ? "voronoi" : "none (0)"}, {"have_stress", s.fields.have_stress}, {"bins", p.grid.bins()}};
  j["profile_below"] = {{"phi", s.below_voronoi ? "voronoi" : "centre"}, {"lambda_vz", fit_json(s.lambda_vz, p.D)},
                        {"lambda_gammadot", fit_json(s.lambda_gammadot, p.D)}, {"paper_lambda_vz_D", paper::lambda_vz_over_D}};
  j["edge"] = {{"points", s.edge_I.size()}, {"phi", phi_vor ? "voronoi" : "centre"},
               {"fit", {{"ok", s.edge_ok}, {"phi_0", js(e.a)}, {"phi_0_se", js(e.se_a)}, {"slope", js(e.b)},
                        {"slope_se", js(e.se_b)}, {"rms", js(e.rms)}, {"n", e.n}, {"note", s.edge_note}}},
               {"paper", {{"phi_0", paper::edge_phi_0}, {"slope", paper::edge_phi_slope}}}};
  j["strip"] = {{"bins", s.strip.size()}, {"z", "height above the bed surface"}};
  j["surface"] = {{"frames", s.surface_t.size()}, {"crossing_t_tilde", js_or_null(s.surface_crossing)},
                  {"paper_t_tilde", paper::surface_crossing_t_tilde}};
  j["annulus"] = {{"frames", s.annulus_frames}, {"phi", phi_vor ? "voronoi" : "centre"}};
  j["frames"] = Json::array();
  for (const auto &r : frames) j["frames"].push_back(frame_json(r, phi_vor));
  j["notes"] = how.notes;
  return j;
}

std::vector<std::pair<std::string, std::string>> flow_files(const FlowStudyParams &p, const FlowSummary &s,
                                                            const std::vector<FlowFrameRecord> &frames,
                                                            const FlowProvenance &how)
{
  std::vector<double> sz, svz;
  for (const auto &b : s.strip) sz.push_back(b.z), svz.push_back(b.vz);
  return {{"flow.json", json_layout(flow_json(p, s, frames, how), 1)},
          {"flow_fields.csv", fields_csv(s.fields)},
          {"flow_profile_below.csv", below_csv(s)},
          {"flow_edge_phi_I.csv", small_tables_csv("I,phi", {s.edge_I, s.edge_phi})},
          {"flow_strip.csv", small_tables_csv("z,vz", {sz, svz})},
          {"flow_annulus.csv", annulus_csv(frames)},
          {"flow_surface.csv", small_tables_csv("t_tilde,z_tip,vz,grains", {s.surface_t, s.surface_z, s.surface_vz, s.surface_grains})}};
}

}    // namespace granpen
