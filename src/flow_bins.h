/* -*- c++ -*- ----------------------------------------------------------
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
   GRANPEN package: the flow fields about the rod, binned in (r, z), as pure
   kernels (no LAMMPS type, no I/O). Written once, called by compute
   flow/azimuthal (one frame, sums reduced over MPI ranks) and by the
   post-processor's analysis/core/flow_fields (frames of a dump, pooled).

   - the grid: nr = round((rmax - rmin) / dr), nz = round((zhi - zlo) / dz)
     whole bins (dr, dz then adjusted), each count checked as a double
     against FLOW_MAX_BINS before it is cast or allocated;
   - the sums of one grain into its bin (FlowSum slots);
   - the bin moments from the sums: count, mass, phi (centre-assigned),
     phi_voronoi, mass-weighted v_r, v_z, v_theta, the granular temperature
     T = (<|v|^2> - v_r^2 - v_z^2 - v_theta^2) / 3, p = -sum tr(S_i) / (3 V_bin)
     and sigma_zz = -sum S_zz,i / V_bin from per-grain stress x volume S_i;
   - the shear rate
       gammadot = sqrt(1/2 (dvr/dr - dvz/dz)^2 + 1/2 (dvr/dz + dvz/dr)^2)
     by centred differences of bin means between the bins' mass-weighted mean
     positions (exact for a linear field; one-sided at edges and next to empty
     bins), and the inertial number I = gammadot d_g / sqrt(p / rho_g), 0 where
     p <= 0 (paper: "Inertial Number").
   C++11, like the rest of src/ (the package route compiles it into LAMMPS).
------------------------------------------------------------------------- */

#ifndef LMP_FLOW_BINS_H
#define LMP_FLOW_BINS_H

#include <cstddef>
#include <vector>

namespace granpen {

// The most bins a grid may have, in all and along each axis: about 350 MB in compute
// flow/azimuthal (its array and two sum buffers), 250 MB in the post-processor.
const double FLOW_MAX_BINS = 1.0e6;

struct FlowGrid {
  double rmin, rmax, dr, zlo, zhi, dz;
  int nr, nz;
  FlowGrid() : rmin(0.0), rmax(0.0), dr(0.0), zlo(0.0), zhi(0.0), dz(0.0), nr(0), nz(0) {}
  int bins() const { return nr * nz; }
};

// How the caller calls the bin widths in its messages ("dr"/"dz" in the post-processor,
// "rbin"/"zbin" in the compute), and what it puts before them.
struct FlowGridNames {
  const char *prefix, *dr, *dz;
  FlowGridNames() : prefix("flow grid: "), dr("dr"), dz("dz") {}
  FlowGridNames(const char *p, const char *r, const char *z) : prefix(p), dr(r), dz(z) {}
};

// The grid of whole bins over rmin <= r < rmax, zlo <= z < zhi. Throws
// std::invalid_argument for dr, dz <= 0, rmin < 0, rmax <= rmin, zhi <= zlo, bins larger
// than their range, or more than FLOW_MAX_BINS bins.
FlowGrid make_flow_grid(double rmin, double rmax, double dr, double zlo, double zhi, double dz,
                        const FlowGridNames &names = FlowGridNames());

// round(span / width) as a whole number of bins, at least 1 when at_least_one; the count
// is checked as a double against FLOW_MAX_BINS before the cast. Throws
// std::invalid_argument naming `what` (e.g. "slice dz") beyond it or for width <= 0.
int whole_bin_count(double span, double width, const char *what, bool at_least_one);

// d minus the nearest multiple of period (0: not periodic): the offset to the nearest
// image of the axis.
double nearest_image(double d, double period);

// Bin iz * nr + ir of a grain at (r, z), or -1 outside the grid.
int flow_bin_of(const FlowGrid &g, double r, double z);

// Sums per bin (FLOW_NSUM doubles a bin): VOL_VOR is the grain volume of the grains that
// have a Voronoi cell, so that phi_voronoi pools only frames that had one.
enum FlowSum {
  FS_COUNT, FS_MASS, FS_VOL, FS_MVR, FS_MVZ, FS_MVT, FS_MV2, FS_VOL_VOR, FS_VOR, FS_TRS, FS_SZZ,
  FS_MR, FS_MZ, FLOW_NSUM
};

// One grain into the sums of its bin: (dx, dy) its offset from the axis (nearest image), z
// its height in the grid's frame. voronoi: its cell volume, stress: S_xx, S_yy, S_zz
// (stress x volume); either may be null.
void add_grain_to_bin(double *sums, double dx, double dy, double z, double vx, double vy, double vz,
                      double radius, double mass, const double *voronoi, const double *stress);

double sphere_volume(double radius);

// T from the sums of m |v|^2 and m over the bin and its mean velocity (0 for an empty
// bin; never negative: a rigid motion's round-off is clipped).
double granular_temperature(double mv2, double mass, double vr, double vz, double vtheta);

// I = gammadot d_g / sqrt(p / rho_g), 0 where p <= 0.
double inertial_number(double gammadot, double p, double d_g, double rho_g);

struct FlowBin {
  double r, z;               // bin centre
  double count, mass;        // per frame
  double phi_centre, phi_voronoi;
  double vr, vz, vtheta, T;
  double p, sigma_zz;
  double gammadot, I;
  double rbar, zbar;         // mass-weighted mean position (the bin centre when empty)
  FlowBin()
      : r(0), z(0), count(0), mass(0), phi_centre(0), phi_voronoi(0), vr(0), vz(0), vtheta(0), T(0),
        p(0), sigma_zz(0), gammadot(0), I(0), rbar(0), zbar(0)
  {
  }
};

// The volume of a ring r1 <= r < r2 of height dz: pi (r2^2 - r1^2) dz.
double ring_volume(double r1, double r2, double dz);

// The moments of one ring of volume `volume` from its FLOW_NSUM sums pooled over `frames`
// frames: count, mass and phi_centre means per frame; phi_voronoi when `voronoi`; v_r, v_z,
// v_theta and T mass-weighted (0 for an empty ring); p and sigma_zz means over the
// stress_frames that had stress (0 without); rbar, zbar mass-weighted (row.r and row.z,
// set by the caller, when empty). gammadot and I are left as they are.
void bin_moments(const double *sums, double volume, double frames, double stress_frames, bool voronoi,
                 FlowBin &row);

// The bins' moments from sums pooled over `frames` frames (grid.bins() * FLOW_NSUM
// doubles): counts, mass, phi and p are means per frame (p over the stress_frames that
// had stress; 0 without), velocities and T mass-weighted over every sample; phi_voronoi
// only when `voronoi` (every frame had cell volumes). Then gammadot and I.
std::vector<FlowBin> flow_bins_from_sums(const FlowGrid &grid, const double *sums, double frames,
                                         double stress_frames, bool voronoi, double d_g, double rho_g);

// gammadot and I of every occupied bin (count > 0) from the bins' v_r, v_z, rbar, zbar
// and p; empty bins keep 0.
void shear_rate_and_inertial_number(const FlowGrid &grid, std::vector<FlowBin> &bins, double d_g,
                                    double rho_g);

}    // namespace granpen

#endif
