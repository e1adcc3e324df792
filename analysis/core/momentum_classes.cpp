/* ----------------------------------------------------------------------
   granpen analysis: momentum by vertical-speed class (momentum_classes.h):
   the classes of src/momentum_class_limits.h, the selection r > R of
   src/compute_momentum_vbin.cpp with LAMMPS's minimum image.
------------------------------------------------------------------------- */

#include "momentum_classes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace granpen {

namespace {
// LAMMPS Domain::minimum_image: one shift by the period when beyond half of it
double minimum_image(double d, double period)
{
  if (period > 0.0 && std::fabs(d) > 0.5 * period) d += d < 0.0 ? period : -period;
  return d;
}
}    // namespace

MomentumTally tally_momentum(const MomentumClasses &c, const double *x, const double *y, const double *vz,
                             const double *mass, std::size_t n, double axis_x, double axis_y, double rmin,
                             double period_x, double period_y)
{
  MomentumTally t;
  const double r2min = rmin * rmin;
  for (std::size_t i = 0; i < n; ++i) {
    const double dx = minimum_image(x[i] - axis_x, period_x), dy = minimum_image(y[i] - axis_y, period_y);
    if (dx * dx + dy * dy <= r2min) continue;
    ++t.selected;
    const double m = mass[i];
    if (vz[i] > c.vmove) t.M_move += m;
    const int k = momentum_class(c, vz[i]);
    if (k < 0) continue;
    t.count[k] += 1.0;
    t.mass[k] += m;
    t.p_up[k] += m * vz[i];
  }
  t.M_slow = t.mass[2];
  return t;
}

double locate_first(const std::vector<double> &x, double x0)
{
  if (!std::isfinite(x0)) return -1.0;
  for (std::size_t i = 0; i + 1 < x.size(); ++i) {
    const double a = x[i], b = x[i + 1];
    if ((a <= x0 && x0 <= b) || (b <= x0 && x0 <= a)) return a == b ? (double) i : (double) i + (x0 - a) / (b - a);
  }
  if (x.size() == 1 && x[0] == x0) return 0.0;
  return -1.0;
}

double value_at(const std::vector<double> &y, double pos)
{
  if (!(pos >= 0.0) || y.empty() || pos > (double) (y.size() - 1)) return std::numeric_limits<double>::quiet_NaN();
  const std::size_t i = (std::size_t) pos;
  if (i + 1 >= y.size()) return y.back();
  const double f = pos - (double) i;
  return y[i] + f * (y[i + 1] - y[i]);
}

DragComparison compare_drag(const std::vector<double> &mu_g_M, const std::vector<double> &F)
{
  DragComparison d;
  if (mu_g_M.size() != F.size()) {
    d.note = "arrays of different lengths";
    return d;
  }
  std::vector<double> x, y;
  for (std::size_t i = 0; i < F.size(); ++i)
    if (mu_g_M[i] > 0.0 && std::isfinite(mu_g_M[i]) && std::isfinite(F[i])) {
      x.push_back(mu_g_M[i]);
      y.push_back(F[i]);
    }
  d.n = x.size();
  if (d.n < 3) {
    d.note = std::to_string(d.n) + " frames with mu g M > 0 and a force, at least 3 needed";
    return d;
  }
  try {
    d.fit = linear_fit_origin(x, y);
  } catch (std::invalid_argument &e) {
    d.note = e.what();
    return d;
  }
  double s = 0.0, s2 = 0.0;
  for (std::size_t i = 0; i < d.n; ++i) {
    const double q = y[i] / x[i];
    s += q;
    s2 += q * q;
  }
  d.ratio_mean = s / (double) d.n;
  const double var = std::max(0.0, (s2 - s * s / (double) d.n) / (double) (d.n - 1));
  d.ratio_se = std::sqrt(var / (double) d.n);
  d.ok = true;
  return d;
}

}    // namespace granpen
