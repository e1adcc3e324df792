/* ----------------------------------------------------------------------
   LAMMPS - Large-scale Atomic/Molecular Massively Parallel Simulator
   https://www.lammps.org/, Sandia National Laboratories
   Steve Plimpton, sjplimp@sandia.gov

   Copyright (2003) Sandia Corporation.  Under the terms of Contract
   DE-AC04-94AL85000 with Sandia Corporation, the U.S. Government retains
   certain rights in this software.  This software is distributed under
   the GNU General Public License.

   See the README file in the top-level LAMMPS directory.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   Contributing author: granpen developers
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   GRANPEN package: flow fields binned in (r, z) (flow_bins.h).
------------------------------------------------------------------------- */

#include "flow_bins.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace granpen {

namespace {

const double PI = 3.14159265358979323846;

// d(col)/d(coord) at bin b from its neighbours bm, bp (-1: none): centred over the
// occupied ones, one-sided next to an edge or an empty bin, 0 with neither
double derivative(const std::vector<FlowBin> &bins, int b, int bm, int bp, bool of_vz, bool along_r)
{
  const bool hm = bm >= 0 && bins[bm].count > 0.0, hp = bp >= 0 && bins[bp].count > 0.0;
  const int lo = hm ? bm : b, hi = hp ? bp : b;
  const FlowBin &L = bins[lo], &H = bins[hi];
  const double cl = along_r ? L.rbar : L.zbar, ch = along_r ? H.rbar : H.zbar;
  if (lo == hi || ch == cl) return 0.0;
  return ((of_vz ? H.vz : H.vr) - (of_vz ? L.vz : L.vr)) / (ch - cl);
}

// v as printf writes it with `format`: the messages say 1e-09, and the limit 1000000
std::string num(double v, const char *format = "%g")
{
  char b[32];
  std::snprintf(b, sizeof b, format, v);
  return b;
}

}    // namespace

int whole_bin_count(double span, double width, const char *what, bool at_least_one)
{
  if (!(width > 0.0)) throw std::invalid_argument(std::string(what) + " must be > 0, got " + num(width));
  const double n = std::round(span / width);    // as lround, but before any cast
  if (!(n <= FLOW_MAX_BINS))
    throw std::invalid_argument(std::string(what) + " " + num(width) + " gives " + num(n) + " bins over the range " +
                                num(span) + ": more than the limit of " + num(FLOW_MAX_BINS, "%.0f") + " bins");
  const int count = static_cast<int>(n);
  return at_least_one ? std::max(1, count) : count;
}

FlowGrid make_flow_grid(double rmin, double rmax, double dr, double zlo, double zhi, double dz,
                        const FlowGridNames &names)
{
  const std::string pre = names.prefix;
  if (!(dr > 0.0)) throw std::invalid_argument(pre + names.dr + " must be > 0, got " + num(dr));
  if (!(dz > 0.0)) throw std::invalid_argument(pre + names.dz + " must be > 0, got " + num(dz));
  if (!(rmin >= 0.0)) throw std::invalid_argument(pre + "rmin must be >= 0, got " + num(rmin));
  if (!(rmax > rmin)) throw std::invalid_argument(pre + "rmax " + num(rmax) + " must exceed rmin " + num(rmin));
  if (!(zhi > zlo)) throw std::invalid_argument(pre + "zhi " + num(zhi) + " must exceed zlo " + num(zlo));
  FlowGrid g;
  g.rmin = rmin;
  g.rmax = rmax;
  g.zlo = zlo;
  g.zhi = zhi;
  g.nr = whole_bin_count(rmax - rmin, dr, (pre + names.dr).c_str(), false);
  g.nz = whole_bin_count(zhi - zlo, dz, (pre + names.dz).c_str(), false);
  if (g.nr < 1 || g.nz < 1)
    throw std::invalid_argument(pre + "bins larger than their range: " + names.dr + " " + num(dr) + " over " +
                                num(rmax - rmin) + ", " + names.dz + " " + num(dz) + " over " + num(zhi - zlo));
  if (!(static_cast<double>(g.nr) * g.nz <= FLOW_MAX_BINS))
    throw std::invalid_argument(pre + names.dr + " " + num(dr) + " and " + names.dz + " " + num(dz) + " give " +
                                num(static_cast<double>(g.nr) * g.nz) + " bins: more than the limit of " +
                                num(FLOW_MAX_BINS, "%.0f"));
  g.dr = (rmax - rmin) / g.nr;    // whole bins over the range
  g.dz = (zhi - zlo) / g.nz;
  return g;
}

double nearest_image(double d, double period)
{
  return period > 0.0 ? d - period * std::round(d / period) : d;
}

int flow_bin_of(const FlowGrid &g, double r, double z)
{
  if (r < g.rmin || r >= g.rmax || z < g.zlo || z >= g.zhi) return -1;
  const int ir = std::min(g.nr - 1, static_cast<int>((r - g.rmin) / g.dr));
  const int iz = std::min(g.nz - 1, static_cast<int>((z - g.zlo) / g.dz));
  return iz * g.nr + ir;
}

double sphere_volume(double radius) { return 4.0 / 3.0 * PI * radius * radius * radius; }

void add_grain_to_bin(double *acc, double dx, double dy, double z, double vx, double vy, double vz,
                      double radius, double m, const double *voronoi, const double *stress)
{
  const double r = std::sqrt(dx * dx + dy * dy);
  const double c = r > 0.0 ? dx / r : 1.0, s = r > 0.0 ? dy / r : 0.0;
  const double vr = vx * c + vy * s, vt = -vx * s + vy * c;
  const double vol = sphere_volume(radius);
  acc[FS_COUNT] += 1.0;
  acc[FS_MASS] += m;
  acc[FS_VOL] += vol;
  acc[FS_MVR] += m * vr;
  acc[FS_MVZ] += m * vz;
  acc[FS_MVT] += m * vt;
  acc[FS_MV2] += m * (vx * vx + vy * vy + vz * vz);
  if (voronoi) {
    acc[FS_VOL_VOR] += vol;
    acc[FS_VOR] += *voronoi;
  }
  if (stress) {
    acc[FS_TRS] += stress[0] + stress[1] + stress[2];
    acc[FS_SZZ] += stress[2];
  }
  acc[FS_MR] += m * r;
  acc[FS_MZ] += m * z;
}

double granular_temperature(double mv2, double mass, double vr, double vz, double vtheta)
{
  if (!(mass > 0.0)) return 0.0;
  const double T = (mv2 / mass - vr * vr - vz * vz - vtheta * vtheta) / 3.0;
  return T < 0.0 ? 0.0 : T;    // round-off of a rigid motion
}

double inertial_number(double gammadot, double p, double d_g, double rho_g)
{
  return p > 0.0 ? gammadot * d_g / std::sqrt(p / rho_g) : 0.0;
}

double ring_volume(double r1, double r2, double dz) { return PI * (r2 * r2 - r1 * r1) * dz; }

void bin_moments(const double *g, double vbin, double frames, double stress_frames, bool voronoi, FlowBin &row)
{
  const double nf = frames > 0.0 ? frames : 1.0;
  const double nfs = stress_frames > 0.0 ? stress_frames : 1.0;
  const double M = g[FS_MASS];
  row.count = g[FS_COUNT] / nf;
  row.mass = M / nf;
  row.phi_centre = g[FS_VOL] / (vbin * nf);
  row.phi_voronoi = (voronoi && g[FS_VOR] > 0.0) ? g[FS_VOL_VOR] / g[FS_VOR] : 0.0;
  row.vr = M > 0.0 ? g[FS_MVR] / M : 0.0;
  row.vz = M > 0.0 ? g[FS_MVZ] / M : 0.0;
  row.vtheta = M > 0.0 ? g[FS_MVT] / M : 0.0;
  row.T = granular_temperature(g[FS_MV2], M, row.vr, row.vz, row.vtheta);
  row.p = stress_frames > 0.0 ? -g[FS_TRS] / (3.0 * vbin * nfs) : 0.0;
  row.sigma_zz = stress_frames > 0.0 ? -g[FS_SZZ] / (vbin * nfs) : 0.0;
  row.rbar = M > 0.0 ? g[FS_MR] / M : row.r;
  row.zbar = M > 0.0 ? g[FS_MZ] / M : row.z;
}

std::vector<FlowBin> flow_bins_from_sums(const FlowGrid &G, const double *sums, double frames,
                                         double stress_frames, bool voronoi, double d_g, double rho_g)
{
  std::vector<FlowBin> bins((std::size_t) G.bins());
  for (int iz = 0; iz < G.nz; ++iz)
    for (int ir = 0; ir < G.nr; ++ir) {
      const std::size_t b = (std::size_t) iz * G.nr + ir;
      const double *g = &sums[b * FLOW_NSUM];
      FlowBin &row = bins[b];
      const double r1 = G.rmin + ir * G.dr, r2 = r1 + G.dr;
      row.r = 0.5 * (r1 + r2);
      row.z = G.zlo + (iz + 0.5) * G.dz;
      bin_moments(g, ring_volume(r1, r2, G.dz), frames, stress_frames, voronoi, row);
    }
  shear_rate_and_inertial_number(G, bins, d_g, rho_g);
  return bins;
}

void shear_rate_and_inertial_number(const FlowGrid &G, std::vector<FlowBin> &bins, double d_g, double rho_g)
{
  for (int iz = 0; iz < G.nz; ++iz)
    for (int ir = 0; ir < G.nr; ++ir) {
      const int b = iz * G.nr + ir;
      FlowBin &row = bins[b];
      if (!(row.count > 0.0)) {
        row.gammadot = row.I = 0.0;
        continue;
      }
      const int rm = ir > 0 ? b - 1 : -1, rp = ir < G.nr - 1 ? b + 1 : -1;
      const int zm = iz > 0 ? b - G.nr : -1, zp = iz < G.nz - 1 ? b + G.nr : -1;
      const double dvr_dr = derivative(bins, b, rm, rp, false, true);
      const double dvz_dz = derivative(bins, b, zm, zp, true, false);
      const double dvr_dz = derivative(bins, b, zm, zp, false, false);
      const double dvz_dr = derivative(bins, b, rm, rp, true, true);
      const double a = dvr_dr - dvz_dz, c = dvr_dz + dvz_dr;
      row.gammadot = std::sqrt(0.5 * a * a + 0.5 * c * c);
      row.I = inertial_number(row.gammadot, row.p, d_g, rho_g);
    }
}

}    // namespace granpen
