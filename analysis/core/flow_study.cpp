// granpen analysis: the flow study of a push's frames (see flow_study.h).
#include "flow_study.h"

#include "rod_frame.h"
#include "scaling_laws.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace granpen {

namespace {

// strip bins of dz with an edge at the bed surface, from the box bottom to its top
SliceSpec strip_spec(const FlowStudyParams &p)
{
  const double dz = p.grid.dz, R = 0.5 * p.D;
  const double lo = -std::ceil((p.z_s - p.box_zlo) / dz - 1e-9) * dz;
  const double hi = std::max(std::ceil((p.box_zhi - p.z_s) / dz - 1e-9), 1.0) * dz;
  return SliceSpec{R + p.strip1, R + p.strip2, lo, hi, dz};
}

// gammadot below the face: mass-weighted over the field bins inside the cylinder
ExpFit gammadot_length(const FlowFields &F, double radius)
{
  std::vector<double> gz, gg;
  for (int iz = 0; iz < F.grid.nz; ++iz) {
    double m = 0, s = 0;
    for (int ir = 0; ir < F.grid.nr; ++ir) {
      const FlowBin &b = F.at(ir, iz);
      if (b.r < radius && b.z < 0.0 && b.mass > 0) m += b.mass, s += b.mass * b.gammadot;
    }
    if (m > 0) gz.push_back(F.at(0, iz).z), gg.push_back(s / m);
  }
  return fit_exponential(gz, gg);
}

double given_or(double v, double otherwise) { return std::isfinite(v) ? v : otherwise; }

}    // namespace

double flow_grain_density(const ParamChoice &rho_g, std::string &origin)
{
  return resolve(rho_g, DEFAULT_RHO_G, "default", origin);
}

FlowStudyParams flow_study_params(const FlowParamSources &s, FlowParamOrigins &from)
{
  constexpr double PI = 3.14159265358979323846;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  FlowStudyParams p;
  p.rho_g = flow_grain_density(s.rho_g, from.rho_g);
  if (s.mass && from.rho_g == "default") {
    double m = 0, vol = 0;
    for (std::size_t i = 0; i < s.grains; ++i) m += s.mass[i], vol += 4.0 / 3.0 * PI * std::pow(s.radius[i], 3);
    p.rho_g = m / vol, from.rho_g = "first frame";
  }
  double diameters = 0;
  for (std::size_t i = 0; i < s.grains; ++i) diameters += 2.0 * s.radius[i];
  p.d_g = resolve(s.d_g, diameters / (double) s.grains, "first frame", from.d_g);
  p.D = resolve(s.D, s.rod_D, "rod atoms", from.D);
  if (!std::isfinite(p.D)) throw std::invalid_argument("no rod atoms to measure D from: give --D or --trace");
  p.v0 = resolve(s.v0, nan, "none", from.v0);
  p.g = resolve(s.g, nan, "none", from.g);
  if (!std::isfinite(p.v0) || !std::isfinite(p.g)) from.notes.push_back("t~ undefined: no v0 or g (give --trace, or --v0 and --g)");
  p.z_s = resolve(s.z_s, nan, "first frame", from.z_s);
  if (from.z_s == "first frame") {
    p.z_s = s.measure_z_s();
    from.notes.push_back("bed surface z_s measured in the first frame (timestep " + std::to_string(s.timestep) +
                         "): give --zs or a trace with the surface key when the rod is already in the bed");
  }
  const double rmax = given_or(s.rmax, 0.5 * std::min(s.hi[0] - s.lo[0], s.hi[1] - s.lo[1]));
  p.grid = make_flow_grid(0.0, rmax, given_or(s.dr, p.d_g), s.zlo, s.zhi, given_or(s.dz, p.d_g));
  p.edge_wr = given_or(s.edge_wr, p.grid.dr), p.edge_wz = given_or(s.edge_wz, p.grid.dz);
  p.profile_radius = given_or(s.profile_radius, p.D / 3.0);
  p.strip1 = s.strip1, p.strip2 = s.strip2, p.ann1 = s.ann1, p.ann2 = s.ann2, p.ann_top = s.ann_top;
  p.box_zlo = s.lo[2], p.box_zhi = s.hi[2];
  return p;
}

FlowStudy::FlowStudy(const FlowStudyParams &p)
    : p_(p), total_(p.grid), below_(SliceSpec{0.0, p.profile_radius, p.grid.zlo, 0.0, p.grid.dz}),
      strip_(strip_spec(p))
{
}

const FlowFrameRecord &FlowStudy::add_frame(const GrainArrays &ga, double axis_x, double axis_y, double period_x,
                                            double period_y, double tip, std::size_t rod_atoms, long long timestep,
                                            const std::string &where)
{
  const double R = 0.5 * p_.D, dz = p_.grid.dz;
  AxisFrame tipf;
  tipf.x = axis_x, tipf.y = axis_y, tipf.zref = tip, tipf.period_x = period_x, tipf.period_y = period_y;
  FlowAccumulator one(p_.grid);
  one.add(ga, tipf);
  total_.merge(one);
  FlowFrameRecord rec;
  rec.timestep = timestep;
  rec.where = where;
  rec.tip = tip;
  rec.z_tip = p_.z_s - tip;
  rec.t_tilde = t_tilde(rec.z_tip, p_.v0, p_.g, p_.D);
  rec.rod_atoms = rod_atoms;
  rec.grains = ga.n;
  rec.edge = edge_average(one.fields(p_.d_g, p_.rho_g), R, p_.edge_wr, p_.edge_wz);
  below_.add(ga, tipf);
  AxisFrame lab = tipf;
  lab.zref = p_.z_s;
  strip_.add(ga, lab);
  SliceAccumulator top(SliceSpec{R + p_.strip1, R + p_.strip2, -dz, 0.0, dz});
  top.add(ga, lab);
  rec.surface_grains = (std::size_t) top.bins()[0].samples;
  rec.surface_vz = top.bins()[0].vz;
  const double ztop = p_.z_s - p_.ann_top;
  if (ztop > tip) {
    SliceAccumulator ann(SliceSpec{p_.ann1, p_.ann2, 0.0, ztop - tip, ztop - tip});
    ann.add(ga, tipf);
    rec.ann = ann.bins()[0];
    rec.annulus = rec.ann.samples > 0;
    rec.ann_phi = ann.have_voronoi() ? rec.ann.phi_voronoi : rec.ann.phi_centre;
  }
  records_.push_back(rec);
  return records_.back();
}

FlowSummary FlowStudy::summary() const
{
  FlowSummary s;
  s.fields = total_.fields(p_.d_g, p_.rho_g);
  const bool phi_vor = s.fields.have_voronoi;
  s.below = below_.bins();
  s.below_voronoi = below_.have_voronoi();
  std::vector<double> bz, bv, bse;
  for (const auto &b : s.below)
    if (b.samples >= 2) bz.push_back(b.z), bv.push_back(b.vz), bse.push_back(b.vz_se);
  s.lambda_vz = fit_exponential(bz, bv, bse);
  s.lambda_gammadot = gammadot_length(s.fields, p_.profile_radius);

  for (const auto &r : records_)    // frames with the tip in the bed
    if (r.edge.bins > 0 && r.z_tip > 0.0)
      s.edge_I.push_back(r.edge.I), s.edge_phi.push_back(phi_vor ? r.edge.phi_voronoi : r.edge.phi_centre);
  if (!s.fields.have_stress) s.edge_note = "no stress columns: I is 0";
  else {
    try {
      s.edge_fit = linear_fit(s.edge_I, s.edge_phi);
      s.edge_ok = true;
    } catch (std::invalid_argument &e) {
      s.edge_note = e.what();
    }
  }

  for (const auto &b : strip_.bins())
    if (b.samples > 0) s.strip.push_back(b);
  // the surface flux against t~, over the frames with the tip in the bed
  for (const auto &r : records_)
    if (r.z_tip > 0.0 && r.surface_grains > 0 && std::isfinite(r.t_tilde)) {
      s.surface_t.push_back(r.t_tilde), s.surface_z.push_back(r.z_tip), s.surface_vz.push_back(r.surface_vz);
      s.surface_grains.push_back((double) r.surface_grains);
    }
  s.surface_crossing = last_down_crossing(s.surface_t, s.surface_vz);
  for (const auto &r : records_) s.annulus_frames += r.annulus ? 1 : 0;
  return s;
}

}    // namespace granpen
