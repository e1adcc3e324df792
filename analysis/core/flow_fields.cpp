/* ----------------------------------------------------------------------
   granpen analysis: flow fields about the rod (flow_fields.h). The binning,
   the sums, the means and the shear rate are src/flow_bins.h's kernels, the
   ones compute flow/azimuthal calls: one frame gives the compute's numbers
   but for the order of summation over MPI ranks.
------------------------------------------------------------------------- */

#include "flow_fields.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace granpen {

namespace {

// a slice's sums: the flow sums of its bin, then m v_z^2 (for the standard error of v_z)
constexpr int S_MVZ2 = FLOW_NSUM, NSACC = FLOW_NSUM + 1;

std::string num(double v)
{
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}

void check_frame(const GrainArrays &g)
{
  if (g.n && (!g.x || !g.y || !g.z || !g.vx || !g.vy || !g.vz || !g.radius || !g.mass))
    throw std::invalid_argument("flow fields: a grain array (x y z vx vy vz radius mass) is missing");
  if (g.n && (g.sxx || g.syy || g.szz) && !(g.sxx && g.syy && g.szz))
    throw std::invalid_argument("flow fields: stress needs all of sxx, syy, szz");
}

}    // namespace

// ------------------------------------------------------------------ fields

FlowAccumulator::FlowAccumulator(const FlowGrid &grid) : grid_(grid)
{
  if (grid.nr < 1 || grid.nz < 1 || !(grid.dr > 0.0) || !(grid.dz > 0.0))
    throw std::invalid_argument("flow fields: grid without bins (use make_flow_grid)");
  acc_.assign((std::size_t) grid.bins() * FLOW_NSUM, 0.0);
}

void FlowAccumulator::add(const GrainArrays &g, const AxisFrame &a)
{
  check_frame(g);
  const bool stress = g.sxx != nullptr;
  for (std::size_t i = 0; i < g.n; ++i) {
    const double dx = nearest_image(g.x[i] - a.x, a.period_x), dy = nearest_image(g.y[i] - a.y, a.period_y);
    const double z = g.z[i] - a.zref;
    const int b = flow_bin_of(grid_, std::sqrt(dx * dx + dy * dy), z);
    if (b < 0) continue;
    const double s[3] = {stress ? g.sxx[i] : 0.0, stress ? g.syy[i] : 0.0, stress ? g.szz[i] : 0.0};
    add_grain_to_bin(&acc_[(std::size_t) b * FLOW_NSUM], dx, dy, z, g.vx[i], g.vy[i], g.vz[i], g.radius[i],
                     g.mass[i], g.voronoi ? &g.voronoi[i] : nullptr, stress ? s : nullptr);
  }
  ++frames_;
  if (g.voronoi) ++voronoi_frames_;
  if (stress) ++stress_frames_;
}

void FlowAccumulator::merge(const FlowAccumulator &o)
{
  const FlowGrid &a = grid_, &b = o.grid_;
  if (a.nr != b.nr || a.nz != b.nz || a.rmin != b.rmin || a.rmax != b.rmax || a.zlo != b.zlo || a.zhi != b.zhi)
    throw std::invalid_argument("flow fields: merging accumulators of different grids");
  for (std::size_t k = 0; k < acc_.size(); ++k) acc_[k] += o.acc_[k];
  frames_ += o.frames_;
  voronoi_frames_ += o.voronoi_frames_;
  stress_frames_ += o.stress_frames_;
}

FlowFields FlowAccumulator::fields(double d_g, double rho_g) const
{
  if (!(d_g > 0.0) || !(rho_g > 0.0))
    throw std::invalid_argument("flow fields: d_g and rho_g must be > 0, got " + num(d_g) + " and " + num(rho_g));
  FlowFields f;
  f.grid = grid_;
  f.frames = frames_;
  f.have_voronoi = frames_ > 0 && voronoi_frames_ == frames_;
  f.have_stress = frames_ > 0 && stress_frames_ == frames_;
  f.bins = flow_bins_from_sums(grid_, acc_.data(), frames_, stress_frames_, f.have_voronoi, d_g, rho_g);
  return f;
}

// ------------------------------------------------------------------ slices

SliceAccumulator::SliceAccumulator(const SliceSpec &s) : spec_(s)
{
  if (!(s.r1 >= 0.0) || !(s.r2 > s.r1))
    throw std::invalid_argument("slice: needs 0 <= r1 < r2, got " + num(s.r1) + " and " + num(s.r2));
  if (!(s.zhi > s.zlo)) throw std::invalid_argument("slice: zhi " + num(s.zhi) + " must exceed zlo " + num(s.zlo));
  if (!(s.dz > 0.0)) throw std::invalid_argument("slice: dz must be > 0, got " + num(s.dz));
  nz_ = whole_bin_count(s.zhi - s.zlo, s.dz, "slice: dz", true);
  spec_.dz = (s.zhi - s.zlo) / nz_;
  acc_.assign((std::size_t) nz_ * NSACC, 0.0);
}

void SliceAccumulator::add(const GrainArrays &g, const AxisFrame &a)
{
  check_frame(g);
  const SliceSpec &S = spec_;
  for (std::size_t i = 0; i < g.n; ++i) {
    const double dx = nearest_image(g.x[i] - a.x, a.period_x), dy = nearest_image(g.y[i] - a.y, a.period_y);
    const double r = std::sqrt(dx * dx + dy * dy);
    const double z = g.z[i] - a.zref;
    if (r < S.r1 || r >= S.r2 || z < S.zlo || z >= S.zhi) continue;
    const int iz = std::min(nz_ - 1, static_cast<int>((z - S.zlo) / S.dz));
    double *acc = &acc_[(std::size_t) iz * NSACC];
    add_grain_to_bin(acc, dx, dy, z, g.vx[i], g.vy[i], g.vz[i], g.radius[i], g.mass[i],
                     g.voronoi ? &g.voronoi[i] : nullptr, nullptr);
    acc[S_MVZ2] += g.mass[i] * g.vz[i] * g.vz[i];
  }
  ++frames_;
  if (g.voronoi) ++voronoi_frames_;
}

std::vector<SliceBin> SliceAccumulator::bins() const
{
  std::vector<SliceBin> out((std::size_t) nz_);
  const double ring = ring_volume(spec_.r1, spec_.r2, spec_.dz);
  for (int iz = 0; iz < nz_; ++iz) {
    const double *g = &acc_[(std::size_t) iz * NSACC];
    SliceBin &b = out[(std::size_t) iz];
    const double M = g[FS_MASS], n = g[FS_COUNT];
    FlowBin m;    // the ring's moments, as the flow bins' (no stress in a slice)
    m.z = b.z = spec_.zlo + (iz + 0.5) * spec_.dz;
    bin_moments(g, ring, (double) frames_, 0.0, have_voronoi(), m);
    b.samples = n;
    b.count = m.count;
    b.phi_centre = m.phi_centre;
    b.phi_voronoi = m.phi_voronoi;
    b.vr = m.vr, b.vz = m.vz, b.vtheta = m.vtheta, b.T = m.T;
    if (!(M > 0.0)) continue;
    const double var = std::max(0.0, g[S_MVZ2] / M - b.vz * b.vz);
    b.vz_se = n >= 2.0 ? std::sqrt(var / (n - 1.0)) : 0.0;
  }
  return out;
}

// ------------------------------------------------------------------ fits

ExpFit fit_exponential(const std::vector<double> &z, const std::vector<double> &v, const std::vector<double> &se)
{
  ExpFit f;
  if (z.size() != v.size() || (!se.empty() && se.size() != v.size())) {
    f.note = "arrays of different lengths";
    return f;
  }
  double vmax = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i)
    if (std::isfinite(v[i]) && std::isfinite(z[i]) && std::fabs(v[i]) > std::fabs(vmax)) vmax = v[i];
  if (vmax == 0.0) {
    f.note = "no nonzero value";
    return f;
  }
  const double sign = vmax > 0.0 ? 1.0 : -1.0;
  std::vector<double> X, Y, W;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!std::isfinite(v[i]) || !std::isfinite(z[i]) || !(sign * v[i] > 0.0)) continue;
    const double e = se.empty() ? 0.0 : se[i];
    if (!se.empty() && !(std::fabs(v[i]) > 2.0 * e)) continue;
    X.push_back(z[i]);
    Y.push_back(std::log(std::fabs(v[i])));
    W.push_back(e > 0.0 ? (v[i] / e) * (v[i] / e) : v[i] * v[i]);
  }
  f.n = X.size();
  if (f.n < 3) {
    f.note = std::to_string(f.n) + " usable points (of one sign, |v| > 2 se), at least 3 needed";
    return f;
  }
  // weights relative to their mean (only relative weights matter; s^2 scales the errors)
  double sw = 0.0;
  for (double w : W) sw += w;
  for (double &w : W) w *= (double) f.n / sw;
  double S = 0, Sx = 0, Sy = 0;
  for (std::size_t i = 0; i < f.n; ++i) {
    S += W[i];
    Sx += W[i] * X[i];
    Sy += W[i] * Y[i];
  }
  const double xb = Sx / S, yb = Sy / S;
  double Sxx = 0, Sxy = 0;
  for (std::size_t i = 0; i < f.n; ++i) {
    Sxx += W[i] * (X[i] - xb) * (X[i] - xb);
    Sxy += W[i] * (X[i] - xb) * (Y[i] - yb);
  }
  f.zmin = *std::min_element(X.begin(), X.end());
  f.zmax = *std::max_element(X.begin(), X.end());
  if (!(Sxx > 0.0)) {
    f.note = "no spread in z";
    return f;
  }
  const double b = Sxy / Sxx, a = yb - b * xb;
  double chi2 = 0.0;
  for (std::size_t i = 0; i < f.n; ++i) {
    const double r = Y[i] - a - b * X[i];
    chi2 += W[i] * r * r;
  }
  const double s2 = chi2 / (double) (f.n - 2);
  const double se_b = std::sqrt(s2 / Sxx), se_a = std::sqrt(s2 * (1.0 / S + xb * xb / Sxx));
  if (!(b > 0.0)) {
    f.note = "the values do not decay away from the face (slope of ln|v| on z is " + num(b) + ")";
    return f;
  }
  f.ok = true;
  f.lambda = 1.0 / b;
  f.lambda_se = se_b / (b * b);
  f.A = sign * std::exp(a);
  f.A_se = std::fabs(f.A) * se_a;
  return f;
}

std::vector<LocalExpFit> local_exponential_fits(const std::vector<double> &z, const std::vector<double> &v,
                                                const std::vector<double> &se, double width)
{
  std::vector<LocalExpFit> out;
  if (z.size() != v.size() || (!se.empty() && se.size() != v.size()) || !(width > 0.0) || !std::isfinite(width))
    return out;
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < z.size(); ++i)
    if (std::isfinite(z[i])) order.push_back(i);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return z[a] < z[b]; });
  if (order.empty()) return out;
  const double ztop = z[order.back()], tol = 1e-9 * std::max(1.0, width);    // printed bin centres
  for (std::size_t a = 0; a < order.size(); ++a) {
    const double lo = z[order[a]];
    if (lo + width > ztop + tol) break;
    std::vector<double> wz, wv, ws;
    for (std::size_t b = a; b < order.size() && z[order[b]] <= lo + width + tol; ++b) {
      wz.push_back(z[order[b]]), wv.push_back(v[order[b]]);
      if (!se.empty()) ws.push_back(se[order[b]]);
    }
    out.push_back({lo, lo + width, fit_exponential(wz, wv, ws)});
  }
  return out;
}

EdgeAverage edge_average(const FlowFields &f, double R, double wr, double wz)
{
  EdgeAverage e;
  for (const FlowBin &b : f.bins) {
    if (std::fabs(b.r - R) > wr || std::fabs(b.z) > wz || !(b.mass > 0.0)) continue;
    ++e.bins;
    e.mass += b.mass;
    e.phi_centre += b.mass * b.phi_centre;
    e.phi_voronoi += b.mass * b.phi_voronoi;
    e.I += b.mass * b.I;
    e.gammadot += b.mass * b.gammadot;
    e.p += b.mass * b.p;
  }
  if (e.mass > 0.0) {
    e.phi_centre /= e.mass;
    e.phi_voronoi /= e.mass;
    e.I /= e.mass;
    e.gammadot /= e.mass;
    e.p /= e.mass;
  }
  return e;
}

double last_down_crossing(const std::vector<double> &t, const std::vector<double> &v)
{
  double at = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 0; i + 1 < std::min(t.size(), v.size()); ++i)
    if (v[i] > 0.0 && v[i + 1] <= 0.0) at = t[i] + v[i] / (v[i] - v[i + 1]) * (t[i + 1] - t[i]);
  return at;
}

}    // namespace granpen
