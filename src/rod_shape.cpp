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
   GRANPEN package: the shape of a rod from its atoms (rod_shape.h).
------------------------------------------------------------------------- */

#include "rod_shape.h"

#include "flow_bins.h"    // nearest_image

#include <cmath>
#include <limits>

namespace granpen {

RodAxisSums rod_axis_start() { return RodAxisSums{{0.0, 0.0, 0.0}}; }

void rod_axis_add(RodAxisSums &s, const RodImageFrame &f, double x, double y)
{
  s.v[0] += 1.0;
  s.v[1] += nearest_image(x - f.x0, f.period_x);
  s.v[2] += nearest_image(y - f.y0, f.period_y);
}

void rod_axis(const RodAxisSums &s, const RodImageFrame &f, double &axis_x, double &axis_y)
{
  axis_x = f.x0 + (s.v[0] > 0.0 ? s.v[1] / s.v[0] : 0.0);
  axis_y = f.y0 + (s.v[0] > 0.0 ? s.v[2] / s.v[0] : 0.0);
}

RodExtent rod_extent_start()
{
  const double lowest = -std::numeric_limits<double>::max();
  return RodExtent{{0.0, lowest}};
}

void rod_extent_add(RodExtent &e, const RodImageFrame &f, double axis_x, double axis_y, double x, double y,
                    double z, double radius)
{
  const double dx = nearest_image(x - axis_x, f.period_x), dy = nearest_image(y - axis_y, f.period_y);
  const double r = std::sqrt(dx * dx + dy * dy) + radius;
  if (r > e.v[0]) e.v[0] = r;
  if (-(z - radius) > e.v[1]) e.v[1] = -(z - radius);
}

RodShapeXY rod_shape(const RodAxisSums &s, const RodExtent &e, const RodImageFrame &f)
{
  RodShapeXY shape;
  if (!(s.v[0] > 0.0)) return shape;
  shape.count = s.v[0];
  rod_axis(s, f, shape.axis_x, shape.axis_y);
  shape.diameter = 2.0 * e.v[0];
  shape.tip = -e.v[1];
  return shape;
}

}    // namespace granpen
