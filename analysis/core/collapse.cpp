/* ----------------------------------------------------------------------
   granpen analysis: the t~ collapse (see collapse.h).
------------------------------------------------------------------------- */

#include "collapse.h"

#include "linear_fit.h"
#include "scaling_laws.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace granpen {

double t95(int dof)
{
  static const double table[] = {12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228,
                                 2.201,  2.179, 2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086,
                                 2.080,  2.074, 2.069, 2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042};
  if (dof < 1) return 0.0;
  return dof <= 30 ? table[dof - 1] : 1.96;
}

namespace {

// mean of y in bins of x of width w: bin index -> (sum, count)
std::map<long, std::pair<double, int>> binned(const std::vector<double> &x, const std::vector<double> &y,
                                              double w)
{
  std::map<long, std::pair<double, int>> b;
  for (std::size_t i = 0; i < x.size(); ++i) {
    auto &s = b[static_cast<long>(std::floor(x[i] / w))];
    s.first += y[i];
    s.second += 1;
  }
  return b;
}

// mean over bins (holding at least two curves) of the across-curve coefficient of variation
double spread(const std::vector<std::map<long, std::pair<double, int>>> &curves)
{
  std::map<long, std::vector<double>> per_bin;
  for (const auto &c : curves)
    for (const auto &kv : c) per_bin[kv.first].push_back(kv.second.first / kv.second.second);
  double sum = 0.0;
  int n = 0;
  for (const auto &kv : per_bin) {
    const auto &v = kv.second;
    if (v.size() < 2) continue;
    double m = 0.0, s2 = 0.0;
    for (double x : v) m += x;
    m /= v.size();
    for (double x : v) s2 += (x - m) * (x - m);
    const double sd = std::sqrt(s2 / (v.size() - 1));
    if (std::fabs(m) > 0.0) {
      sum += sd / std::fabs(m);
      ++n;
    }
  }
  return n ? sum / n : 0.0;
}

// first bin from which every later bin stays in the band (at least two bins): its start
bool crossover(const std::vector<double> &t, const std::vector<double> &ratio, const CollapseParams &p,
               double &t_star)
{
  for (std::size_t k = 0; k + 1 < ratio.size(); ++k) {
    bool stays = true;
    for (std::size_t j = k; j < ratio.size() && stays; ++j) stays = std::fabs(ratio[j] - 1.0) <= p.band;
    if (stays) {
      t_star = t[k] - 0.5 * p.tbin;
      return true;
    }
  }
  return false;
}

}    // namespace

CollapseResult collapse(const std::vector<CollapseInput> &inputs, const CollapseParams &p)
{
  CollapseResult res;
  std::vector<std::map<long, std::pair<double, int>>> by_z, by_t;
  std::vector<double> logv, logpeak, v_of_peak, peak_per_v;
  std::vector<double> stars;
  for (const auto &in : inputs) {
    if (!(in.v0 > 0 && in.D > 0 && in.g > 0 && in.k_z > 0))
      throw std::invalid_argument(in.name + ": collapse needs v0, D, g and k_z > 0");
    CollapseCurve c;
    c.name = in.name;
    c.v0 = in.v0, c.D = in.D, c.g = in.g, c.k_z = in.k_z;
    std::vector<double> zs, ts, rs;
    for (std::size_t i = 0; i < in.z.size(); ++i) {
      const double z = in.z[i];
      if (in_peak_regime(z, in.D) && in.F[i] > c.peak) c.peak = in.F[i], c.peak_z = z;
      if (z < p.zmin) continue;
      zs.push_back(z);
      ts.push_back(t_tilde(z, in.v0, in.g, in.D));
      rs.push_back(in.F[i] / (in.k_z * z));
    }
    auto bz = binned(zs, rs, p.zbin), bt = binned(ts, rs, p.tbin);
    for (const auto &kv : bt) {
      c.t.push_back((kv.first + 0.5) * p.tbin);
      c.ratio.push_back(kv.second.first / kv.second.second);
    }
    c.crossed = crossover(c.t, c.ratio, p, c.t_star);
    if (c.crossed) stars.push_back(c.t_star);
    if (c.peak > 0.0) {
      logv.push_back(std::log(in.v0));
      logpeak.push_back(std::log(c.peak));
      v_of_peak.push_back(in.v0);
      peak_per_v.push_back(c.peak / in.v0);
    }
    by_z.push_back(bz);
    by_t.push_back(bt);
    res.curves.push_back(c);
  }
  res.n_crossed = static_cast<int>(stars.size());
  if (!stars.empty()) {
    double m = 0.0, s2 = 0.0;
    for (double s : stars) m += s;
    m /= stars.size();
    for (double s : stars) s2 += (s - m) * (s - m);
    res.t_star_mean = m;
    res.t_star_sd = stars.size() > 1 ? std::sqrt(s2 / (stars.size() - 1)) : 0.0;
  }
  // the ensemble curve: per t~ bin, the mean over curves of each curve's bin mean
  std::map<long, std::vector<double>> per_bin;
  for (const auto &c : by_t)
    for (const auto &kv : c) per_bin[kv.first].push_back(kv.second.first / kv.second.second);
  const std::size_t need = std::max<std::size_t>(1, std::min<std::size_t>(p.min_curves, by_t.size()));
  for (const auto &kv : per_bin) {
    const auto &v = kv.second;
    if (v.size() < need) continue;
    double m = 0.0, s2 = 0.0;
    for (double x : v) m += x;
    m /= v.size();
    for (double x : v) s2 += (x - m) * (x - m);
    res.ens_t.push_back((kv.first + 0.5) * p.tbin);
    res.ens_ratio.push_back(m);
    res.ens_se.push_back(v.size() > 1 ? std::sqrt(s2 / (v.size() - 1) / v.size()) : 0.0);
    res.ens_n.push_back(static_cast<int>(v.size()));
  }
  res.ens_crossed = crossover(res.ens_t, res.ens_ratio, p, res.t_star_ensemble);
  res.spread_z = spread(by_z);
  res.spread_t = spread(by_t);

  std::vector<double> distinct = logv;
  std::sort(distinct.begin(), distinct.end());
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  if (logv.size() >= 3 && distinct.size() >= 2) {
    auto f = linear_fit(logv, logpeak);
    res.peak_law.ok = true;
    res.peak_law.exponent = f.b;
    res.peak_law.exponent_se = f.se_b;
    res.peak_law.exponent_ci95 = t95(static_cast<int>(f.n) - 2) * f.se_b;
    res.peak_law.prefactor = std::exp(f.a);
    double mv = 0, mp = 0;
    for (std::size_t k = 0; k < logv.size(); ++k) mv += logv[k], mp += logpeak[k];
    mv /= (double) logv.size(), mp /= (double) logv.size();
    res.peak_law.v2_prefactor = std::exp(mp - 2 * mv);
    const auto t = linear_fit(v_of_peak, peak_per_v);
    res.peak_law.two_term_ok = true;
    res.peak_law.linear = t.a, res.peak_law.linear_se = t.se_a;
    res.peak_law.quadratic = t.b, res.peak_law.quadratic_se = t.se_b;
    if (t.b > 0.0) {
      double vbar = 0.0;
      for (double v : v_of_peak) vbar += v;
      vbar /= (double) v_of_peak.size();
      // v_x = a / b: var = (var_a - 2 v_x cov_ab + v_x^2 var_b) / b^2, with cov(a, b) =
      // -vbar se_b^2 for a straight line through the points
      const double vx = t.a / t.b, cov = -vbar * t.se_b * t.se_b;
      const double var = (t.se_a * t.se_a - 2.0 * vx * cov + vx * vx * t.se_b * t.se_b) / (t.b * t.b);
      res.peak_law.crossover_ok = true;
      res.peak_law.crossover_speed = vx;
      res.peak_law.crossover_speed_se = std::sqrt(std::max(0.0, var));
    }
  }
  res.peak_law.points = logv.size();
  return res;
}

}    // namespace granpen
