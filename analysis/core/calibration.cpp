/* ----------------------------------------------------------------------
   granpen analysis: the friction-calibration table (see calibration.h).
------------------------------------------------------------------------- */

#include "calibration.h"

#include <algorithm>
#include <cmath>

namespace granpen {

namespace {

bool same(double a, double b)
{
  return std::fabs(a - b) <= 1e-9 * std::max({std::fabs(a), std::fabs(b), 1e-300});
}

// distinct values, sorted, nearly equal ones merged (the first of a run stands for it)
std::vector<double> distinct(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  std::vector<double> out;
  for (double x : v)
    if (out.empty() || !same(out.back(), x)) out.push_back(x);
  return out;
}

}    // namespace

Stat mean_sd(const std::vector<double> &values)
{
  Stat s;
  s.n = values.size();
  if (!s.n) return s;
  for (double v : values) s.mean += v;
  s.mean /= (double) s.n;
  if (s.n < 2) return s;
  double ss = 0.0;
  for (double v : values) ss += (v - s.mean) * (v - s.mean);
  s.sd = std::sqrt(ss / (double) (s.n - 1));
  return s;
}

std::vector<CalibrationRow> calibration_table(const std::vector<CalibrationBed> &beds,
                                              const std::vector<CalibrationPush> &pushes)
{
  std::vector<double> mus;
  for (const auto &b : beds) mus.push_back(b.mu);
  for (const auto &p : pushes) mus.push_back(p.mu);

  std::vector<CalibrationRow> rows;
  for (double mu : distinct(mus)) {
    CalibrationRow base;
    base.mu = mu;
    std::vector<double> phis;
    for (const auto &b : beds)
      if (same(b.mu, mu)) {
        base.beds.push_back(b);
        phis.push_back(b.phi_0);
      }
    base.phi_0 = mean_sd(phis);

    std::vector<double> v0s;
    for (const auto &p : pushes)
      if (same(p.mu, mu)) v0s.push_back(p.v0);
    if (v0s.empty()) {
      rows.push_back(base);
      continue;
    }
    for (double v0 : distinct(v0s)) {
      CalibrationRow row = base;
      row.v0 = v0;
      std::vector<double> ks, as;
      for (const auto &p : pushes)
        if (same(p.mu, mu) && same(p.v0, v0)) {
          row.pushes.push_back(p);
          ks.push_back(p.k_z);
          as.push_back(p.alpha);
        }
      row.k_z = mean_sd(ks);
      row.alpha = mean_sd(as);
      if (row.beds.empty()) {
        // mu raised in beds poured at another mu: phi_0 is that of the beds pushed into
        std::vector<double> used;
        for (const auto &b : beds)
          for (const auto &p : row.pushes)
            if (p.bed == b.name) {
              row.beds.push_back(b);
              used.push_back(b.phi_0);
              break;
            }
        row.phi_0 = mean_sd(used);
      }
      rows.push_back(row);
    }
  }
  return rows;
}

}    // namespace granpen
