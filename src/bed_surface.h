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
   GRANPEN package: the bed surface height z_s, as defined by the bench
   scenario: the mean, over an N x N grid of columns spanning the box in
   x and y, of the highest grain top (z + radius) in each column.
   Pure C++: the per-rank column maxima are combined by the caller with
   MPI_MAX, then surface_from_columns() takes the mean.
------------------------------------------------------------------------- */

#ifndef LMP_BED_SURFACE_H
#define LMP_BED_SURFACE_H

#include <cstddef>
#include <vector>

namespace granpen {

struct SurfaceGrid {
  double xlo, xhi, ylo, yhi;
  int n;    // columns per side
};

// Value of an empty column (no grain seen): below any real height.
constexpr double EMPTY_COLUMN = -1.0e300;

// Column index (0 .. n*n-1) of point (x, y); points on or beyond the edges
// go to the edge column.
int column_of(const SurfaceGrid &grid, double x, double y);

// Raise colmax (size n*n, start at EMPTY_COLUMN) by the grain tops given.
void column_max_tops(const SurfaceGrid &grid, const double *x, const double *y,
                     const double *top, std::size_t count, std::vector<double> &colmax);

// Mean over non-empty columns; nempty gets the number of empty ones.
// Returns NaN when every column is empty.
double surface_from_columns(const std::vector<double> &colmax, int &nempty);

}    // namespace granpen

#endif
