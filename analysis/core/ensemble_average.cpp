// granpen analysis: the ensemble mean of aligned runs (see ensemble_average.h).
#include "ensemble_average.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace granpen {

namespace {

std::string num(double v)
{
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", v);
  return b;
}

// finite samples of a run, sorted by depth
void finite_sorted(const std::vector<double> &z, const std::vector<double> &F, std::vector<double> &zs,
                   std::vector<double> &Fs)
{
  std::vector<std::pair<double, double>> p;
  for (std::size_t i = 0; i < z.size(); ++i)
    if (std::isfinite(z[i]) && std::isfinite(F[i])) p.emplace_back(z[i], F[i]);
  std::stable_sort(p.begin(), p.end(), [](const auto &a, const auto &b) { return a.first < b.first; });
  zs.clear(), Fs.clear();
  for (const auto &q : p) zs.push_back(q.first), Fs.push_back(q.second);
}

double median_step(const std::vector<double> &zs)
{
  std::vector<double> d;
  for (std::size_t i = 1; i < zs.size(); ++i)
    if (zs[i] > zs[i - 1]) d.push_back(zs[i] - zs[i - 1]);
  if (d.empty()) return 0.0;
  std::nth_element(d.begin(), d.begin() + d.size() / 2, d.end());
  return d[d.size() / 2];
}

// a run's values in bins k0 .. k0 + nb - 1 of width w
std::vector<double> bin_run(const std::vector<double> &zs, const std::vector<double> &Fs, long k0, std::size_t nb,
                            double w)
{
  std::vector<double> sum(nb, 0.0);
  std::vector<int> cnt(nb, 0);
  for (std::size_t i = 0; i < zs.size(); ++i) {
    const long k = (long) std::floor(zs[i] / w) - k0;
    if (k < 0 || k >= (long) nb) continue;
    sum[k] += Fs[i], ++cnt[k];
  }
  std::size_t j = 0;
  for (std::size_t k = 0; k < nb; ++k) {
    if (cnt[k]) {
      sum[k] /= cnt[k];
      continue;
    }
    // no sample in the bin (a coarser run): interpolate at its centre
    const double zc = ((double) (k0 + (long) k) + 0.5) * w;
    while (j + 2 < zs.size() && zs[j + 1] < zc) ++j;
    const double u = zs[j + 1] > zs[j] ? (zc - zs[j]) / (zs[j + 1] - zs[j]) : 0.0;
    sum[k] = Fs[j] + std::clamp(u, 0.0, 1.0) * (Fs[j + 1] - Fs[j]);
  }
  return sum;
}

}    // namespace

EnsembleMean ensemble_mean(const std::vector<std::vector<double>> &z, const std::vector<std::vector<double>> &F,
                           const EnsembleParams &p)
{
  if (z.empty()) throw std::invalid_argument("ensemble_mean: no run");
  if (z.size() != F.size()) throw std::invalid_argument("ensemble_mean: z and F differ in the number of runs");
  EnsembleMean e;
  e.runs = z.size();
  std::vector<std::vector<double>> zs(z.size()), Fs(z.size());
  std::vector<double> onsets;
  for (std::size_t i = 0; i < z.size(); ++i) {
    if (z[i].size() != F[i].size())
      throw std::invalid_argument("ensemble_mean: run " + std::to_string(i + 1) + ": z and F differ in length");
    finite_sorted(z[i], F[i], zs[i], Fs[i]);
    if (zs[i].size() < 2 || !(zs[i].back() > zs[i].front()))
      throw std::invalid_argument("ensemble_mean: run " + std::to_string(i + 1) + " has fewer than 2 distinct depths");
    onsets.push_back(p.align ? force_onset(zs[i], Fs[i]) : 0.0);
  }
  e.alignment = align_onsets(onsets, p.align ? NAN : 0.0);
  for (std::size_t i : e.alignment.without_onset)
    e.notes.push_back("run " + std::to_string(i + 1) + " has no force onset (F never positive): not moved");
  double w = p.bin;
  double lo = -INFINITY, hi = INFINITY;
  for (std::size_t i = 0; i < zs.size(); ++i) {
    shift_depths(zs[i], e.alignment.shift[i]);
    // the default bin: the median depth step (about a sample a bin), but at least the mean
    // step, so that depths repeated with a tiny jitter (a median step of 1e-7 cm) do not
    // make it tiny; for evenly sampled runs the two agree
    const double mean_step = (zs[i].back() - zs[i].front()) / (double) (zs[i].size() - 1);
    if (!(p.bin > 0)) w = std::max({w, median_step(zs[i]), mean_step});
    lo = std::max(lo, zs[i].front()), hi = std::min(hi, zs[i].back());
  }
  if (!(w > 0) || !(hi > lo)) throw std::invalid_argument("ensemble_mean: the aligned runs share no depth range");
  if (!(p.bin > 0)) w = std::max(w, (hi - lo) / (double) kMaxEnsembleBins);
  if ((hi - lo) / w > (double) kMaxEnsembleBins)
    throw std::invalid_argument("ensemble_mean: a bin of " + num(w) + " cm makes " + num((hi - lo) / w) +
                                " bins over the runs' common depths, more than " + std::to_string(kMaxEnsembleBins) +
                                ": a wider bin");
  // whole bins inside [lo, hi]
  const long k0 = (long) std::ceil(lo / w - 1e-9), k1 = (long) std::floor(hi / w + 1e-9);
  if (k1 <= k0)
    throw std::invalid_argument("ensemble_mean: the aligned runs share less than one bin of " + num(w) + " cm");
  const std::size_t nb = (std::size_t) (k1 - k0);
  e.bin = w;
  e.z_first = lo, e.z_last = hi;
  double deepest = hi;
  for (const auto &r : zs) deepest = std::max(deepest, r.back());
  if (deepest - hi > w)
    e.notes.push_back("the aligned runs end between z = " + num(hi) + " and " + num(deepest) +
                      " cm; the mean stops where the shallowest ends");
  for (std::size_t i = 0; i < zs.size(); ++i) e.per_run.push_back(bin_run(zs[i], Fs[i], k0, nb, w));
  const double n = (double) e.runs;
  for (std::size_t k = 0; k < nb; ++k) {
    double m = 0.0, s2 = 0.0;
    for (const auto &r : e.per_run) m += r[k];
    m /= n;
    for (const auto &r : e.per_run) s2 += (r[k] - m) * (r[k] - m);
    const double sd = e.runs > 1 ? std::sqrt(s2 / (n - 1.0)) : 0.0;
    e.z.push_back(((double) (k0 + (long) k) + 0.5) * w);
    e.mean.push_back(m), e.sd.push_back(sd), e.se.push_back(sd / std::sqrt(n));
    e.n.push_back((int) e.runs);
  }
  return e;
}

void resample_mean(const EnsembleMean &e, const std::vector<std::size_t> &pick, std::vector<double> &out)
{
  const std::size_t nb = e.z.size();
  out.assign(nb, 0.0);
  if (pick.empty()) return;
  for (std::size_t i : pick) {
    const auto &r = e.per_run.at(i);
    for (std::size_t k = 0; k < nb; ++k) out[k] += r[k];
  }
  for (auto &v : out) v /= (double) pick.size();
}

}    // namespace granpen
