/* ----------------------------------------------------------------------
   granpen analysis: the rod and the bed surface in one frame (rod_frame.h).
------------------------------------------------------------------------- */

#include "rod_frame.h"

#include "bed_surface.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace granpen {

namespace {
double nearest(double d, double period)
{
  return period > 0.0 ? d - period * std::round(d / period) : d;
}
}    // namespace

RodPosition find_rod(const double *x, const double *y, const double *z, const double *radius,
                     const double *type, std::size_t n, int rod_type, double period_x, double period_y)
{
  RodPosition rod;
  double x0 = 0.0, y0 = 0.0, sx = 0.0, sy = 0.0;
  std::vector<std::size_t> atoms;
  for (std::size_t i = 0; i < n; ++i) {
    if (std::lround(type[i]) != rod_type) continue;
    if (atoms.empty()) x0 = x[i], y0 = y[i];
    atoms.push_back(i);
    sx += nearest(x[i] - x0, period_x);
    sy += nearest(y[i] - y0, period_y);
  }
  if (atoms.empty()) return rod;
  rod.found = true;
  rod.atoms = atoms.size();
  rod.axis_x = x0 + sx / (double) atoms.size();
  rod.axis_y = y0 + sy / (double) atoms.size();
  rod.tip = std::numeric_limits<double>::infinity();
  double rmax = 0.0;
  for (std::size_t i : atoms) {
    rod.tip = std::min(rod.tip, z[i] - radius[i]);
    const double dx = nearest(x[i] - rod.axis_x, period_x), dy = nearest(y[i] - rod.axis_y, period_y);
    rmax = std::max(rmax, std::sqrt(dx * dx + dy * dy) + radius[i]);
  }
  rod.diameter = 2.0 * rmax;
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

double t_tilde(double z, double v0, double g, double D)
{
  if (!(v0 > 0.0 && g > 0.0 && D > 0.0) || !std::isfinite(v0) || !std::isfinite(g) || !std::isfinite(D))
    return std::numeric_limits<double>::quiet_NaN();
  return z / v0 * std::sqrt(g / D);
}

}    // namespace granpen
