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
   GRANPEN package: vertical-speed classes (momentum_class_limits.h).
------------------------------------------------------------------------- */

#include "momentum_class_limits.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace granpen {

const char *const MOMENTUM_CLASS_NAMES[MOMENTUM_NCLASS] = {"fast", "intermediate", "slow", "noise"};

namespace {
// the paper's class bounds as divisors of v0: fast >= v0/10 > intermediate >= v0/80 >
// slow > v0/320 >= noise > v0/640; M_move counts v_z > v0/320
const double DEFAULT_DIV[MOMENTUM_NCLASS] = {10.0, 80.0, 320.0, 640.0};
const double MOVE_DIV = 320.0;
}    // namespace

MomentumClasses momentum_classes(double v0) { return momentum_classes(v0, nullptr, 0.0); }

MomentumClasses momentum_classes(double v0, const double *frac, double mfrac)
{
  if (!(v0 > 0.0) || !std::isfinite(v0)) throw std::invalid_argument("momentum classes: v0 must be > 0");
  if (frac)
    for (int k = 0; k < MOMENTUM_NCLASS; ++k)
      if (!(frac[k] > 0.0) || !std::isfinite(frac[k]) || (k > 0 && !(frac[k] < frac[k - 1])))
        throw std::invalid_argument("momentum classes: thresholds must be > 0 and strictly decreasing");
  if (!(mfrac >= 0.0) || !std::isfinite(mfrac))
    throw std::invalid_argument("momentum classes: mthreshold must be > 0");
  MomentumClasses c;
  c.v0 = v0;
  for (int k = 0; k < MOMENTUM_NCLASS; ++k) c.bound[k] = frac ? v0 * frac[k] : v0 / DEFAULT_DIV[k];
  if (mfrac > 0.0) c.vmove = v0 * mfrac;
  else c.vmove = frac ? c.bound[2] : v0 / MOVE_DIV;
  return c;
}

int momentum_class(const MomentumClasses &c, double vz)
{
  if (vz >= c.bound[0]) return 0;
  if (vz >= c.bound[1]) return 1;
  if (vz > c.bound[2]) return 2;
  if (vz > c.bound[3]) return 3;
  return -1;
}

std::vector<double> momentum_log_edges(double v0, int n, double fmin, double fmax)
{
  if (!(v0 > 0.0) || !std::isfinite(v0)) throw std::invalid_argument("momentum classes: v0 must be > 0");
  if (n < 1 || n > MOMENTUM_MAX_LOG_CLASSES)
    throw std::invalid_argument("momentum classes: logbins N must be 1 to " + std::to_string(MOMENTUM_MAX_LOG_CLASSES));
  if (!(fmin > 0.0 && fmin < fmax) || !std::isfinite(fmax))
    throw std::invalid_argument("momentum classes: logbins needs 0 < fmin < fmax");
  std::vector<double> edges(n + 1);
  const double q = std::pow(fmax / fmin, 1.0 / n);
  for (int k = 0; k < n; k++) edges[k] = v0 * (fmin * std::pow(q, k));
  edges[n] = v0 * fmax;
  return edges;
}

int momentum_log_class(const std::vector<double> &edges, double vz)
{
  const int n = static_cast<int>(edges.size()) - 1;
  if (n < 1 || !(vz >= edges[0] && vz < edges[n])) return -1;
  // class k covers [edges[k], edges[k+1]): estimate, then settle on the stored edges
  const double span = std::log(edges[n] / edges[0]);
  int k = static_cast<int>(std::floor(n * std::log(vz / edges[0]) / span));
  if (k < 0) k = 0;
  if (k > n - 1) k = n - 1;
  while (k > 0 && vz < edges[k]) k--;
  while (k < n - 1 && vz >= edges[k + 1]) k++;
  return n - 1 - k;
}

}    // namespace granpen
