/* -*- c++ -*- ----------------------------------------------------------
   granpen analysis: ordinary least squares on plain arrays.
   y = a + b x (linear_fit), y = b x (linear_fit_origin) and y = a x + b x^2
   (quadratic_fit_origin), with the standard errors of the parameters from the
   residual variance.
------------------------------------------------------------------------- */

#ifndef GRANPEN_LINEAR_FIT_H
#define GRANPEN_LINEAR_FIT_H

#include <cstddef>
#include <vector>

namespace granpen {

struct LinearFit {
  double a = 0.0;       // intercept (0 for the through-origin fit)
  double b = 0.0;       // slope
  double se_a = 0.0;    // standard error of a (0 for the through-origin fit)
  double se_b = 0.0;    // standard error of b
  double rms = 0.0;     // root mean square of the residuals, sqrt(sum r^2 / n)
  std::size_t n = 0;    // number of points
};

// y = a + b x. se_b = s / sqrt(Sxx), se_a = s sqrt(1/n + xbar^2 / Sxx), with
// s^2 = sum r^2 / (n - 2). Throws std::invalid_argument for arrays of different
// lengths, fewer than 3 points, non-finite values or zero spread in x.
LinearFit linear_fit(const std::vector<double> &x, const std::vector<double> &y);

// y = b x. se_b = s / sqrt(sum x^2), s^2 = sum r^2 / (n - 1). Throws
// std::invalid_argument for arrays of different lengths, fewer than 3 points,
// non-finite values or zero spread of x about the origin (every x = 0).
LinearFit linear_fit_origin(const std::vector<double> &x, const std::vector<double> &y);

// y = a x + b x^2 (through the origin: a depth-linear and a depth-squared force, e.g. a
// tip's and a shaft's side friction). The 2 x 2 normal equations in sum x^2, x^3, x^4;
// se from s^2 = sum r^2 / (n - 2) times the inverse's diagonal. Throws
// std::invalid_argument for arrays of different lengths, fewer than 3 points, non-finite
// values or fewer than 2 distinct nonzero x (the two terms cannot be told apart).
struct QuadraticFit {
  double a = 0.0, b = 0.0;          // y = a x + b x^2
  double se_a = 0.0, se_b = 0.0;
  double rms = 0.0;                 // sqrt(sum r^2 / n)
  std::size_t n = 0;
};
QuadraticFit quadratic_fit_origin(const std::vector<double> &x, const std::vector<double> &y);

}    // namespace granpen

#endif
