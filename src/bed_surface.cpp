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
   GRANPEN package: bed surface height from column maxima.
------------------------------------------------------------------------- */

#include "bed_surface.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace granpen {

int column_of(const SurfaceGrid &g, double x, double y)
{
  int ix = static_cast<int>(std::floor((x - g.xlo) / (g.xhi - g.xlo) * g.n));
  int iy = static_cast<int>(std::floor((y - g.ylo) / (g.yhi - g.ylo) * g.n));
  ix = std::min(std::max(ix, 0), g.n - 1);
  iy = std::min(std::max(iy, 0), g.n - 1);
  return iy * g.n + ix;
}

void column_max_tops(const SurfaceGrid &g, const double *x, const double *y, const double *top,
                     std::size_t count, std::vector<double> &colmax)
{
  for (std::size_t i = 0; i < count; ++i) {
    int c = column_of(g, x[i], y[i]);
    if (top[i] > colmax[c]) colmax[c] = top[i];
  }
}

double surface_from_columns(const std::vector<double> &colmax, int &nempty)
{
  double sum = 0.0;
  int nfull = 0;
  nempty = 0;
  for (double h : colmax) {
    if (h <= EMPTY_COLUMN) {
      ++nempty;
    } else {
      sum += h;
      ++nfull;
    }
  }
  return nfull ? sum / nfull : std::numeric_limits<double>::quiet_NaN();
}

}    // namespace granpen
