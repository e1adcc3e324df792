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
   GRANPEN package: the paper's scaling relations (scaling_laws.h).
------------------------------------------------------------------------- */

#include "scaling_laws.h"

#include <cmath>
#include <limits>

namespace granpen {

namespace {
bool positive_finite(double v) { return v > 0.0 && std::isfinite(v); }
const double NaN = std::numeric_limits<double>::quiet_NaN();
}    // namespace

double t_tilde(double z, double v0, double g, double D)
{
  if (!positive_finite(v0) || !positive_finite(g) || !positive_finite(D)) return NaN;
  return z / v0 * std::sqrt(g / D);
}

double depth_at_t_tilde(double t, double v0, double g, double D)
{
  if (!positive_finite(v0) || !positive_finite(g) || !positive_finite(D)) return NaN;
  return t * v0 * std::sqrt(D / g);
}

double k_z_from_alpha(double alpha, double mu, double rho_g, double g, double D)
{
  return alpha * mu * rho_g * g * D * D;
}

double peak_regime_end(double D) { return PEAK_END_PER_D * D; }

bool in_peak_regime(double z, double D) { return z > 0.0 && z < peak_regime_end(D); }

}    // namespace granpen
