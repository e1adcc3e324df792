/* -*- c++ -*- ----------------------------------------------------------
   granpen analysis: the collapse of F / F_z against t~ = (z / v0) sqrt(g / D)
   over a set of traces (paper: Velocity Dependence). Plain arrays in:
   - each curve F/F_z (F_z = k_z z) binned in t~; the crossover t~* of a curve
     is the start of the first bin after which every later bin stays within
     1 +- band;
   - the ensemble crossover: the same rule on the mean of F/F_z across curves
     per t~ bin (bins holding at least min_curves curves), where the grain-scale
     fluctuations of single runs (tens of percent in small beds) average out;
   - collapse quality: the spread of the curves (coefficient of variation across
     curves, averaged over bins) binned against z, and against t~;
   - the peak law: peak height (max F over 0 < z < 0.7 R) against v0 on log
     axes, the exponent with its 95% confidence interval; and the same peaks as
     a linear plus an inertial term, peak = c1 v0 + c2 v0^2, whose crossover
     speed c1 / c2 says where a power law fitted over a range of v0 lies between
     1 and 2.
   Knows nothing of files.
------------------------------------------------------------------------- */

#ifndef GRANPEN_COLLAPSE_H
#define GRANPEN_COLLAPSE_H

#include <string>
#include <vector>

namespace granpen {

struct CollapseInput {
  std::string name;
  std::vector<double> z, F;    // cm, dyne
  double v0 = 0.0, D = 0.0, g = 0.0;
  double k_z = 0.0;            // dyne/cm: F_z = k_z z
};

struct CollapseParams {
  double zmin = 0.2;       // ignore z below this (F_z -> 0)
  double band = 0.2;       // |F/F_z - 1| <= band counts as joined
  double tbin = 0.1;       // t~ bin width
  double zbin = 0.25;      // z bin width for the spread before collapse
  int min_curves = 3;      // ensemble bins need this many curves (fewer if fewer curves)
};

struct CollapseCurve {
  std::string name;
  double v0 = 0.0, D = 0.0, g = 0.0, k_z = 0.0;
  std::vector<double> t, ratio;    // bin centres and mean F/F_z of non-empty t~ bins
  bool crossed = false;
  double t_star = 0.0;
  double peak = 0.0, peak_z = 0.0;
};

// The peak law over a set of curves: one value, so that a front end adopts another set's
// law (the ensemble means', the whole sweep's) by one assignment.
struct PeakLaw {
  bool ok = false;                     // at least 3 curves with distinct v0
  double exponent = 0.0, exponent_se = 0.0, exponent_ci95 = 0.0;
  double prefactor = 0.0;              // peak = prefactor v0^exponent (the fit's exp(intercept))
  double v2_prefactor = 0.0;           // the paper's peak ~ v0^2 through the points' mean (log-log)
  std::size_t points = 0;              // curves with a positive peak, in the fit
  // peak = c1 v0 + c2 v0^2, least squares of peak / v0 = c1 + c2 v0 over the curves (same
  // points as the exponent); standard errors from the residuals; the crossover speed
  // v_x = c1 / c2 (where the two terms are equal) with its error by the delta method,
  // the covariance of c1 and c2 included; v_x only when c2 > 0
  bool two_term_ok = false;
  double linear = 0.0, linear_se = 0.0;          // c1 (force / speed)
  double quadratic = 0.0, quadratic_se = 0.0;    // c2 (force / speed^2)
  bool crossover_ok = false;
  double crossover_speed = 0.0, crossover_speed_se = 0.0;
};

struct CollapseResult {
  std::vector<CollapseCurve> curves;
  int n_crossed = 0;
  double t_star_mean = 0.0, t_star_sd = 0.0;
  double spread_z = 0.0, spread_t = 0.0;    // before (against z) and after (against t~)
  std::vector<double> ens_t, ens_ratio, ens_se;    // the ensemble curve: bin centre, mean, its standard error
  std::vector<int> ens_n;                          // curves in each bin
  bool ens_crossed = false;
  double t_star_ensemble = 0.0;
  PeakLaw peak_law;    // over the curves' peaks
};

// Throws std::invalid_argument for an input with non-positive v0, D, g or k_z.
CollapseResult collapse(const std::vector<CollapseInput> &inputs, const CollapseParams &p);

// Two-sided 95% quantile of Student's t with dof degrees of freedom (1.96 beyond 30).
double t95(int dof);

}    // namespace granpen

#endif
