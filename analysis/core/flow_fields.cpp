/* ----------------------------------------------------------------------
   granpen analysis: flow fields about the rod (flow_fields.h). The binning,
   the means and the shear rate follow src/compute_flow_azimuthal.cpp line by
   line, so that one frame gives the compute's numbers to round-off.
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

constexpr double PI = 3.14159265358979323846;
enum { A_COUNT, A_MASS, A_VOL, A_MVR, A_MVZ, A_MVT, A_MV2, A_VOLV, A_VOR, A_TRS, A_SZZ, A_MR, A_MZ, NACC };
enum { S_COUNT, S_MASS, S_VOL, S_MVR, S_MVZ, S_MVT, S_MV2, S_MVZ2, S_VOLV, S_VOR, NSACC };

std::string num(double v)
{
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}

double nearest(double d, double period)
{
  return period > 0.0 ? d - period * std::round(d / period) : d;
}

double sphere_volume(double r) { return 4.0 / 3.0 * PI * r * r * r; }

void check_frame(const GrainArrays &g)
{
  if (g.n && (!g.x || !g.y || !g.z || !g.vx || !g.vy || !g.vz || !g.radius || !g.mass))
    throw std::invalid_argument("flow fields: a grain array (x y z vx vy vz radius mass) is missing");
  if (g.n && (g.sxx || g.syy || g.szz) && !(g.sxx && g.syy && g.szz))
    throw std::invalid_argument("flow fields: stress needs all of sxx, syy, szz");
}

}    // namespace

FlowGrid make_flow_grid(double rmin, double rmax, double dr, double zlo, double zhi, double dz)
{
  if (!(dr > 0.0)) throw std::invalid_argument("flow grid: dr must be > 0, got " + num(dr));
  if (!(dz > 0.0)) throw std::invalid_argument("flow grid: dz must be > 0, got " + num(dz));
  if (!(rmin >= 0.0)) throw std::invalid_argument("flow grid: rmin must be >= 0, got " + num(rmin));
  if (!(rmax > rmin)) throw std::invalid_argument("flow grid: rmax " + num(rmax) + " must exceed rmin " + num(rmin));
  if (!(zhi > zlo)) throw std::invalid_argument("flow grid: zhi " + num(zhi) + " must exceed zlo " + num(zlo));
  FlowGrid g;
  g.rmin = rmin;
  g.rmax = rmax;
  g.zlo = zlo;
  g.zhi = zhi;
  g.nr = static_cast<int>(std::lround((rmax - rmin) / dr));
  g.nz = static_cast<int>(std::lround((zhi - zlo) / dz));
  if (g.nr < 1 || g.nz < 1)
    throw std::invalid_argument("flow grid: bins larger than their range: dr " + num(dr) + " over " +
                                num(rmax - rmin) + ", dz " + num(dz) + " over " + num(zhi - zlo));
  g.dr = (rmax - rmin) / g.nr;
  g.dz = (zhi - zlo) / g.nz;
  return g;
}

// ------------------------------------------------------------------ fields

FlowAccumulator::FlowAccumulator(const FlowGrid &grid) : grid_(grid)
{
  if (grid.nr < 1 || grid.nz < 1 || !(grid.dr > 0.0) || !(grid.dz > 0.0))
    throw std::invalid_argument("flow fields: grid without bins (use make_flow_grid)");
  acc_.assign((std::size_t) grid.bins() * NACC, 0.0);
}

void FlowAccumulator::add(const GrainArrays &g, const AxisFrame &a)
{
  check_frame(g);
  const FlowGrid &G = grid_;
  const bool stress = g.sxx != nullptr;
  for (std::size_t i = 0; i < g.n; ++i) {
    const double dx = nearest(g.x[i] - a.x, a.period_x), dy = nearest(g.y[i] - a.y, a.period_y);
    const double r = std::sqrt(dx * dx + dy * dy);
    const double z = g.z[i] - a.zref;
    if (r < G.rmin || r >= G.rmax || z < G.zlo || z >= G.zhi) continue;
    const int ir = std::min(G.nr - 1, static_cast<int>((r - G.rmin) / G.dr));
    const int iz = std::min(G.nz - 1, static_cast<int>((z - G.zlo) / G.dz));
    double *acc = &acc_[((std::size_t) iz * G.nr + ir) * NACC];
    const double m = g.mass[i];
    const double c = r > 0.0 ? dx / r : 1.0, s = r > 0.0 ? dy / r : 0.0;
    const double vx = g.vx[i], vy = g.vy[i], vz = g.vz[i];
    const double vr = vx * c + vy * s, vt = -vx * s + vy * c;
    const double vol = sphere_volume(g.radius[i]);
    acc[A_COUNT] += 1.0;
    acc[A_MASS] += m;
    acc[A_VOL] += vol;
    acc[A_MVR] += m * vr;
    acc[A_MVZ] += m * vz;
    acc[A_MVT] += m * vt;
    acc[A_MV2] += m * (vx * vx + vy * vy + vz * vz);
    if (g.voronoi) {
      acc[A_VOLV] += vol;
      acc[A_VOR] += g.voronoi[i];
    }
    if (stress) {
      acc[A_TRS] += g.sxx[i] + g.syy[i] + g.szz[i];
      acc[A_SZZ] += g.szz[i];
    }
    acc[A_MR] += m * r;
    acc[A_MZ] += m * z;
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
  const FlowGrid &G = grid_;
  FlowFields f;
  f.grid = G;
  f.frames = frames_;
  f.have_voronoi = frames_ > 0 && voronoi_frames_ == frames_;
  f.have_stress = frames_ > 0 && stress_frames_ == frames_;
  f.bins.resize((std::size_t) G.bins());
  const double nf = frames_ > 0 ? (double) frames_ : 1.0;
  const double nfs = stress_frames_ > 0 ? (double) stress_frames_ : 1.0;
  for (int iz = 0; iz < G.nz; ++iz)
    for (int ir = 0; ir < G.nr; ++ir) {
      const std::size_t b = (std::size_t) iz * G.nr + ir;
      const double *g = &acc_[b * NACC];
      FlowBin &row = f.bins[b];
      const double r1 = G.rmin + ir * G.dr, r2 = r1 + G.dr;
      const double vbin = PI * (r2 * r2 - r1 * r1) * G.dz;
      const double M = g[A_MASS];
      row.r = 0.5 * (r1 + r2);
      row.z = G.zlo + (iz + 0.5) * G.dz;
      row.count = g[A_COUNT] / nf;
      row.mass = M / nf;
      row.phi_centre = g[A_VOL] / (vbin * nf);
      row.phi_voronoi = (f.have_voronoi && g[A_VOR] > 0.0) ? g[A_VOLV] / g[A_VOR] : 0.0;
      row.vr = M > 0.0 ? g[A_MVR] / M : 0.0;
      row.vz = M > 0.0 ? g[A_MVZ] / M : 0.0;
      row.vtheta = M > 0.0 ? g[A_MVT] / M : 0.0;
      row.T = M > 0.0 ? (g[A_MV2] / M - row.vr * row.vr - row.vz * row.vz - row.vtheta * row.vtheta) / 3.0 : 0.0;
      if (row.T < 0.0) row.T = 0.0;    // round-off of a rigid motion
      row.p = stress_frames_ > 0 ? -g[A_TRS] / (3.0 * vbin * nfs) : 0.0;
      row.sigma_zz = stress_frames_ > 0 ? -g[A_SZZ] / (vbin * nfs) : 0.0;
      row.rbar = M > 0.0 ? g[A_MR] / M : row.r;
      row.zbar = M > 0.0 ? g[A_MZ] / M : row.z;
    }

  // shear rate: centred differences over the neighbouring bins' mean positions (exact
  // for a linear field), one-sided at the edges and next to empty bins
  auto occupied = [&](int b) { return b >= 0 && acc_[(std::size_t) b * NACC + A_COUNT] > 0.0; };
  auto derivative = [&](int b, int bm, int bp, bool vz, bool along_r) {
    const int lo = occupied(bm) ? bm : b, hi = occupied(bp) ? bp : b;
    const FlowBin &L = f.bins[(std::size_t) lo], &H = f.bins[(std::size_t) hi];
    const double cl = along_r ? L.rbar : L.zbar, ch = along_r ? H.rbar : H.zbar;
    if (lo == hi || ch == cl) return 0.0;
    return ((vz ? H.vz : H.vr) - (vz ? L.vz : L.vr)) / (ch - cl);
  };
  for (int iz = 0; iz < G.nz; ++iz)
    for (int ir = 0; ir < G.nr; ++ir) {
      const int b = iz * G.nr + ir;
      FlowBin &row = f.bins[(std::size_t) b];
      if (!occupied(b)) continue;
      const int rm = ir > 0 ? b - 1 : -1, rp = ir < G.nr - 1 ? b + 1 : -1;
      const int zm = iz > 0 ? b - G.nr : -1, zp = iz < G.nz - 1 ? b + G.nr : -1;
      const double dvr_dr = derivative(b, rm, rp, false, true), dvz_dz = derivative(b, zm, zp, true, false);
      const double dvr_dz = derivative(b, zm, zp, false, false), dvz_dr = derivative(b, rm, rp, true, true);
      const double a = dvr_dr - dvz_dz, c = dvr_dz + dvz_dr;
      row.gammadot = std::sqrt(0.5 * a * a + 0.5 * c * c);
      row.I = row.p > 0.0 ? row.gammadot * d_g / std::sqrt(row.p / rho_g) : 0.0;
    }
  return f;
}

// ------------------------------------------------------------------ slices

SliceAccumulator::SliceAccumulator(const SliceSpec &s) : spec_(s)
{
  if (!(s.r1 >= 0.0) || !(s.r2 > s.r1))
    throw std::invalid_argument("slice: needs 0 <= r1 < r2, got " + num(s.r1) + " and " + num(s.r2));
  if (!(s.zhi > s.zlo)) throw std::invalid_argument("slice: zhi " + num(s.zhi) + " must exceed zlo " + num(s.zlo));
  if (!(s.dz > 0.0)) throw std::invalid_argument("slice: dz must be > 0, got " + num(s.dz));
  nz_ = std::max(1, static_cast<int>(std::lround((s.zhi - s.zlo) / s.dz)));
  spec_.dz = (s.zhi - s.zlo) / nz_;
  acc_.assign((std::size_t) nz_ * NSACC, 0.0);
}

void SliceAccumulator::add(const GrainArrays &g, const AxisFrame &a)
{
  check_frame(g);
  const SliceSpec &S = spec_;
  for (std::size_t i = 0; i < g.n; ++i) {
    const double dx = nearest(g.x[i] - a.x, a.period_x), dy = nearest(g.y[i] - a.y, a.period_y);
    const double r = std::sqrt(dx * dx + dy * dy);
    const double z = g.z[i] - a.zref;
    if (r < S.r1 || r >= S.r2 || z < S.zlo || z >= S.zhi) continue;
    const int iz = std::min(nz_ - 1, static_cast<int>((z - S.zlo) / S.dz));
    double *acc = &acc_[(std::size_t) iz * NSACC];
    const double m = g.mass[i];
    const double c = r > 0.0 ? dx / r : 1.0, s = r > 0.0 ? dy / r : 0.0;
    const double vx = g.vx[i], vy = g.vy[i], vz = g.vz[i];
    const double vol = sphere_volume(g.radius[i]);
    acc[S_COUNT] += 1.0;
    acc[S_MASS] += m;
    acc[S_VOL] += vol;
    acc[S_MVR] += m * (vx * c + vy * s);
    acc[S_MVZ] += m * vz;
    acc[S_MVT] += m * (-vx * s + vy * c);
    acc[S_MV2] += m * (vx * vx + vy * vy + vz * vz);
    acc[S_MVZ2] += m * vz * vz;
    if (g.voronoi) {
      acc[S_VOLV] += vol;
      acc[S_VOR] += g.voronoi[i];
    }
  }
  ++frames_;
  if (g.voronoi) ++voronoi_frames_;
}

std::vector<SliceBin> SliceAccumulator::bins() const
{
  std::vector<SliceBin> out((std::size_t) nz_);
  const double nf = frames_ > 0 ? (double) frames_ : 1.0;
  const double ring = PI * (spec_.r2 * spec_.r2 - spec_.r1 * spec_.r1) * spec_.dz;
  for (int iz = 0; iz < nz_; ++iz) {
    const double *g = &acc_[(std::size_t) iz * NSACC];
    SliceBin &b = out[(std::size_t) iz];
    const double M = g[S_MASS], n = g[S_COUNT];
    b.z = spec_.zlo + (iz + 0.5) * spec_.dz;
    b.samples = n;
    b.count = n / nf;
    b.phi_centre = g[S_VOL] / (ring * nf);
    b.phi_voronoi = (have_voronoi() && g[S_VOR] > 0.0) ? g[S_VOLV] / g[S_VOR] : 0.0;
    if (!(M > 0.0)) continue;
    b.vr = g[S_MVR] / M;
    b.vz = g[S_MVZ] / M;
    b.vtheta = g[S_MVT] / M;
    b.T = std::max(0.0, (g[S_MV2] / M - b.vr * b.vr - b.vz * b.vz - b.vtheta * b.vtheta) / 3.0);
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
