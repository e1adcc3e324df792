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

}    // namespace granpen
