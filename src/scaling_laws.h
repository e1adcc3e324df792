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
   GRANPEN package: the paper's scaling relations, each written once. The
   styles (compute rod/drag) and the post-processor (analysis/) call these;
   tests/architecture/scaling_once.sh fails when one is written elsewhere.
   - t~ = (z / v0) sqrt(g / D), the scaled time of the collapse, and its
     inverse, the depth z = t~ v0 sqrt(D / g) of a given t~;
   - F_z = k_z z with k_z = alpha mu rho_g g D^2 (alpha = k_z / k_z(alpha = 1));
   - the peak regime: z <= 0.35 D (0.7 R);
   - the defaults mu and rho_g of a trace that names neither;
   - the bed surface's grid of columns (the bench's definition of z_s).
   Pure C++11: no LAMMPS type, no I/O.
------------------------------------------------------------------------- */

#ifndef LMP_SCALING_LAWS_H
#define LMP_SCALING_LAWS_H

namespace granpen {

// Grain friction and density (g/cm^3) of the bench's beds: what a trace without the header
// keys mu and rho_g was run with.
constexpr double DEFAULT_MU = 0.3;
constexpr double DEFAULT_RHO_G = 3.0;

// The peak regime ends at this fraction of the rod's diameter (0.7 R: the force peak of a
// shallow push lies above it).
constexpr double PEAK_END_PER_D = 0.35;

// Columns per side of the grid whose highest grain tops average to the bed surface z_s
// (the bench's definition: 4 x 4).
constexpr int SURFACE_COLUMNS = 4;

// t~ = (z / v0) sqrt(g / D); NaN unless v0, g and D are positive and finite.
double t_tilde(double z, double v0, double g, double D);

// The depth of a given t~: z = t~ v0 sqrt(D / g); NaN unless v0, g and D are positive and
// finite.
double depth_at_t_tilde(double t, double v0, double g, double D);

// k_z = alpha mu rho_g g D^2: the slope of F_z = k_z z, the depth-linear force (alpha = 1
// gives the scale that divides a fitted k_z into alpha).
double k_z_from_alpha(double alpha, double mu, double rho_g, double g, double D);

// The depth where the peak regime ends: PEAK_END_PER_D D.
double peak_regime_end(double D);

// Whether depth z lies in the peak regime, 0 < z < peak_regime_end(D): the one predicate of
// the fit's peak, the collapse's and the gap's peak regime (the end itself is not in it).
bool in_peak_regime(double z, double D);

}    // namespace granpen

#endif
