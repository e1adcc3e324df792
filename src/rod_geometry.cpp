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
   GRANPEN package: geometry of a rod built from overlapping spheres.
------------------------------------------------------------------------- */

#include "rod_geometry.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace granpen {

static constexpr double TWO_PI = 6.283185307179586;
static constexpr double TINY = 1.0e-9;

int ring_count(double r, double spacing)
{
  if (r < TINY) return 1;
  int n = static_cast<int>(std::lround(TWO_PI * r / spacing));
  return n < 1 ? 1 : n;
}

std::vector<double> disc_radii(double rshell, double spacing)
{
  // stop half a spacing inside the shell ring, which closes the disc
  std::vector<double> radii;
  for (int j = 0; j * spacing <= rshell - 0.5 * spacing + TINY; ++j) radii.push_back(j * spacing);
  return radii;
}

static void add_ring(std::vector<RodSphere> &out, double r, double z, int layer, double spacing, double phase)
{
  int n = ring_count(r, spacing);
  for (int k = 0; k < n; ++k) {
    double a = (TWO_PI * k) / n + phase;
    out.push_back({r * std::cos(a), r * std::sin(a), z, layer});
  }
}

// ring_count in double: no int overflow for any radius and spacing
static double ring_count_real(double r, double spacing)
{
  if (r < TINY) return 1.0;
  const double n = std::round(TWO_PI * r / spacing);
  return n < 1.0 ? 1.0 : n;
}

static void check_spec(const RodSpec &s)
{
  if (!(s.sphere > 0.0)) throw std::invalid_argument("rod sphere diameter must be > 0");
  if (!(s.spacing > 0.0)) throw std::invalid_argument("rod sphere spacing must be > 0");
  if (!(s.diameter > s.sphere))
    throw std::invalid_argument("rod diameter must exceed the sphere diameter");
  if (!(s.length >= s.sphere))
    throw std::invalid_argument("rod length must be at least one sphere diameter");
  if (s.spacing > s.sphere)
    throw std::invalid_argument("rod spacing larger than the sphere diameter leaves gaps");
  if (!std::isfinite(s.diameter) || !std::isfinite(s.length))
    throw std::invalid_argument("rod diameter and length must be finite");
}

double rod_sphere_count(const RodSpec &s)
{
  check_spec(s);
  const double rshell = 0.5 * (s.diameter - s.sphere);
  const double nlayers = std::floor((s.length - s.sphere) / s.spacing + TINY) + 1.0;
  // rings of one disc layer: radii 0, spacing, ... up to rshell - spacing / 2
  const double nradii = std::floor((rshell - 0.5 * s.spacing) / s.spacing + TINY) + 1.0;
  double disc = 0.0;
  if (nradii > 1.0e6) {
    disc = 0.5 * TWO_PI * nradii * nradii;    // far beyond any bound: the sum's leading term
  } else {
    for (double j = 0; j < nradii; j += 1.0) disc += ring_count_real(j * s.spacing, s.spacing);
  }
  return nlayers * ring_count_real(rshell, s.spacing) + (s.filled ? nlayers : 1.0) * disc;
}

std::vector<RodSphere> build_rod(const RodSpec &s)
{
  const double count = rod_sphere_count(s);    // checks the spec
  if (count > MAX_ROD_SPHERES)
    throw std::invalid_argument("the rod would have " + std::to_string(static_cast<long long>(std::min(count, 9.0e18))) +
                                " spheres, more than the " + std::to_string(static_cast<long long>(MAX_ROD_SPHERES)) +
                                " a rod may have (check D, length and spacing)");

  const double rshell = 0.5 * (s.diameter - s.sphere);
  const int nlayers = static_cast<int>(std::floor((s.length - s.sphere) / s.spacing + TINY)) + 1;
  const std::vector<double> disc = disc_radii(rshell, s.spacing);

  std::vector<RodSphere> out;
  for (int layer = 0; layer < nlayers; ++layer) {
    const double z = 0.5 * s.sphere + layer * s.spacing;
    const int nring = ring_count(rshell, s.spacing);
    const double phase = (layer % 2) ? 0.5 * TWO_PI / nring : 0.0;
    add_ring(out, rshell, z, layer, s.spacing, phase);
    if (layer == 0 || s.filled)
      for (double r : disc) add_ring(out, r, z, layer, s.spacing, 0.0);
  }
  return out;
}

}    // namespace granpen
