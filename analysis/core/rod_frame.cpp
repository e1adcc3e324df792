/* ----------------------------------------------------------------------
   granpen analysis: the rod and the bed surface in one frame (rod_frame.h).
------------------------------------------------------------------------- */

#include "rod_frame.h"

#include "bed_surface.h"
#include "rod_shape.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace granpen {

RodPosition find_rod(const double *x, const double *y, const double *z, const double *radius,
                     const double *type, std::size_t n, int rod_type, double period_x, double period_y)
{
  RodPosition rod;
  std::vector<std::size_t> atoms;
  for (std::size_t i = 0; i < n; ++i)
    if (std::lround(type[i]) == rod_type) atoms.push_back(i);
  if (atoms.empty()) return rod;
  const RodImageFrame frame{x[atoms[0]], y[atoms[0]], period_x, period_y};
  RodAxisSums sums = rod_axis_start();
  for (std::size_t i : atoms) rod_axis_add(sums, frame, x[i], y[i]);
  double axis_x, axis_y;
  rod_axis(sums, frame, axis_x, axis_y);
  RodExtent extent = rod_extent_start();
  for (std::size_t i : atoms) rod_extent_add(extent, frame, axis_x, axis_y, x[i], y[i], z[i], radius[i]);
  const RodShapeXY shape = rod_shape(sums, extent, frame);
  rod.found = true;
  rod.atoms = atoms.size();
  rod.axis_x = shape.axis_x;
  rod.axis_y = shape.axis_y;
  rod.tip = shape.tip;
  rod.diameter = shape.diameter;
  return rod;
}

double bed_surface(const double *x, const double *y, const double *z, const double *radius,
                   const char *skip, std::size_t n, double xlo, double xhi, double ylo, double yhi,
                   int ncolumns, int &nempty)
{
  SurfaceGrid grid{xlo, xhi, ylo, yhi, std::max(1, ncolumns)};
  std::vector<double> colmax((std::size_t) grid.n * grid.n, EMPTY_COLUMN);
  std::vector<double> gx, gy, top;
  gx.reserve(n);
  gy.reserve(n);
  top.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (skip && skip[i]) continue;
    gx.push_back(x[i]);
    gy.push_back(y[i]);
    top.push_back(z[i] + radius[i]);
  }
  column_max_tops(grid, gx.data(), gy.data(), top.data(), gx.size(), colmax);
  return surface_from_columns(colmax, nempty);
}

}    // namespace granpen
