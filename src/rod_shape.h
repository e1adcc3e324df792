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
   GRANPEN package: the shape of a rod measured from its atoms, as fix
   rod/drive, compute rod/drag and granpen flow / momentum (analysis/core
   rod_frame) all take it: the axis is the mean x, y of the atoms' centres
   taken as offsets (nearest periodic image) from one reference atom, so a
   rod across a periodic boundary stays whole; the diameter is
   D = 2 max(r_xy + radius) about that axis (nearest image); the tip is the
   lowest point, min(z - radius).
   Two passes over the atoms, each a sum that combines across MPI ranks:
   rod_axis_add (MPI_SUM of RodAxisSums), then rod_extent_add (MPI_MAX of
   RodExtent). Pure C++11: no LAMMPS type, no I/O.
------------------------------------------------------------------------- */

#ifndef LMP_ROD_SHAPE_H
#define LMP_ROD_SHAPE_H

namespace granpen {

// The reference atom's x, y and the box's periods (0: not periodic in that direction).
struct RodImageFrame {
  double x0, y0;
  double period_x, period_y;
};

// count, then the sums of the offsets dx, dy from the reference (3 doubles: MPI_SUM).
struct RodAxisSums {
  double v[3];
};

// max(r_xy + radius), max(-(z - radius)) (2 doubles: MPI_MAX; -(tip) so both are maxima).
struct RodExtent {
  double v[2];
};

struct RodShapeXY {
  double count = 0.0;
  double axis_x = 0.0, axis_y = 0.0;
  double diameter = 0.0;
  double tip = 0.0;
};

RodAxisSums rod_axis_start();
void rod_axis_add(RodAxisSums &s, const RodImageFrame &f, double x, double y);
// The axis of the summed atoms (the reference itself when there is none).
void rod_axis(const RodAxisSums &s, const RodImageFrame &f, double &axis_x, double &axis_y);

RodExtent rod_extent_start();
void rod_extent_add(RodExtent &e, const RodImageFrame &f, double axis_x, double axis_y, double x, double y,
                    double z, double radius);

// The shape from the combined sums and extent (all zero when count is 0).
RodShapeXY rod_shape(const RodAxisSums &s, const RodExtent &e, const RodImageFrame &f);

}    // namespace granpen

#endif
