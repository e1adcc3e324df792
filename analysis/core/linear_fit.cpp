/* ----------------------------------------------------------------------
   granpen analysis: ordinary least squares (see linear_fit.h).
------------------------------------------------------------------------- */

#include "linear_fit.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace granpen {

namespace {

void check_input(const std::vector<double> &x, const std::vector<double> &y, const char *who)
{
  if (x.size() != y.size())
    throw std::invalid_argument(std::string(who) + ": x and y have different lengths (" +
                                std::to_string(x.size()) + " and " + std::to_string(y.size()) + ")");
  if (x.size() < 3)
    throw std::invalid_argument(std::string(who) + ": " + std::to_string(x.size()) +
                                " points, at least 3 needed");
  for (std::size_t i = 0; i < x.size(); ++i)
    if (!std::isfinite(x[i]) || !std::isfinite(y[i]))
      throw std::invalid_argument(std::string(who) + ": non-finite value at point " + std::to_string(i));
}

// spread below this fraction of the largest |x| counts as none (rounding noise)
double negligible(const std::vector<double> &x)
{
  double m = 0.0;
  for (double v : x) m = std::max(m, std::fabs(v));
  const double tiny = 1e-12 * m;
  return tiny * tiny * (double) x.size();
}

}    // namespace

LinearFit linear_fit(const std::vector<double> &x, const std::vector<double> &y)
{
  check_input(x, y, "linear_fit");
  const std::size_t n = x.size();
  double xbar = 0.0, ybar = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    xbar += x[i];
    ybar += y[i];
  }
  xbar /= (double) n;
  ybar /= (double) n;
  double sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    sxx += (x[i] - xbar) * (x[i] - xbar);
    sxy += (x[i] - xbar) * (y[i] - ybar);
  }
  if (!(sxx > negligible(x))) throw std::invalid_argument("linear_fit: zero spread in x");

  LinearFit f;
  f.n = n;
  f.b = sxy / sxx;
  f.a = ybar - f.b * xbar;
  double ssr = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = y[i] - f.a - f.b * x[i];
    ssr += r * r;
  }
  const double s2 = ssr / (double) (n - 2);
  f.se_b = std::sqrt(s2 / sxx);
  f.se_a = std::sqrt(s2 * (1.0 / (double) n + xbar * xbar / sxx));
  f.rms = std::sqrt(ssr / (double) n);
  return f;
}

LinearFit linear_fit_origin(const std::vector<double> &x, const std::vector<double> &y)
{
  check_input(x, y, "linear_fit_origin");
  const std::size_t n = x.size();
  double sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    sxx += x[i] * x[i];
    sxy += x[i] * y[i];
  }
  if (!(sxx > negligible(x)) || sxx == 0.0)
    throw std::invalid_argument("linear_fit_origin: zero spread in x (every x is 0)");

  LinearFit f;
  f.n = n;
  f.b = sxy / sxx;
  double ssr = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = y[i] - f.b * x[i];
    ssr += r * r;
  }
  f.se_b = std::sqrt(ssr / (double) (n - 1) / sxx);
  f.rms = std::sqrt(ssr / (double) n);
  return f;
}

QuadraticFit quadratic_fit_origin(const std::vector<double> &x, const std::vector<double> &y)
{
  check_input(x, y, "quadratic_fit_origin");
  const std::size_t n = x.size();
  // scaled by the largest |x| so that x^4 sums stay well inside double range
  double m = 0.0;
  for (double v : x) m = std::max(m, std::fabs(v));
  if (!(m > 0.0)) throw std::invalid_argument("quadratic_fit_origin: every x is 0");
  double s2 = 0.0, s3 = 0.0, s4 = 0.0, sy1 = 0.0, sy2 = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double u = x[i] / m;
    s2 += u * u, s3 += u * u * u, s4 += u * u * u * u, sy1 += u * y[i], sy2 += u * u * y[i];
  }
  const double det = s2 * s4 - s3 * s3;
  // det = sum over pairs of u_i^2 u_j^2 (u_i - u_j)^2 / 2: zero unless two distinct nonzero x
  if (!(det > 1e-12 * s2 * s4))
    throw std::invalid_argument("quadratic_fit_origin: fewer than 2 distinct nonzero x");
  const double au = (s4 * sy1 - s3 * sy2) / det, bu = (s2 * sy2 - s3 * sy1) / det;    // in u
  QuadraticFit f;
  f.n = n;
  f.a = au / m;
  f.b = bu / (m * m);
  double ssr = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = y[i] - f.a * x[i] - f.b * x[i] * x[i];
    ssr += r * r;
  }
  const double var = n > 2 ? ssr / (double) (n - 2) : 0.0;
  f.se_a = std::sqrt(var * s4 / det) / m;
  f.se_b = std::sqrt(var * s2 / det) / (m * m);
  f.rms = std::sqrt(ssr / (double) n);
  return f;
}

}    // namespace granpen
