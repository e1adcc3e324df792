// granpen analysis: when two pushes part (see trace_parting.h).
#include "trace_parting.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace granpen {

namespace {

// index of the first sample with F > 0; n when there is none
std::size_t first_contact(const std::vector<double> &F)
{
  std::size_t i = 0;
  while (i < F.size() && !(F[i] > 0)) ++i;
  return i;
}

// sums of F per window of width w after t[c], samples from c on; a sample's window is
// floor((t - t_c) / w), nudged by a millionth of a window so that a sample written on a
// window's edge (t = 0.0005 as 0.00049999...) falls in the window it starts
struct WindowSums {
  std::vector<double> sum;
  std::vector<std::size_t> count;
};
WindowSums window_sums(const std::vector<double> &t, const std::vector<double> &F, std::size_t c, double w)
{
  WindowSums s;
  for (std::size_t i = c; i < t.size(); ++i) {
    const double k = std::floor((t[i] - t[c]) / w + 1e-6);
    // a window past an empty one ends the comparison (parting_time): stop there, so the table
    // never holds more windows than the trace has samples, whatever the window's width
    if (!(k >= 0) || k > double(s.sum.size())) break;
    const std::size_t j = std::size_t(k);
    if (j >= s.sum.size()) {
      s.sum.resize(j + 1, 0.0);
      s.count.resize(j + 1, 0);
    }
    s.sum[j] += F[i];
    ++s.count[j];
  }
  return s;
}

// z of a trace at time t, linear between samples (the end values beyond them)
double depth_at(const std::vector<double> &t, const std::vector<double> &z, double at)
{
  if (t.empty()) return std::numeric_limits<double>::quiet_NaN();
  if (at <= t.front()) return z.front();
  if (at >= t.back()) return z.back();
  const std::size_t i = std::size_t(std::upper_bound(t.begin(), t.end(), at) - t.begin());
  const double f = (at - t[i - 1]) / (t[i] - t[i - 1]);
  return z[i - 1] + f * (z[i] - z[i - 1]);
}

bool apart(const PartingWindow &w, double threshold, double side)
{
  const double d = w.ratio - 1;
  return std::isfinite(w.ratio) && std::fabs(d) >= threshold && d * side > 0;
}

}    // namespace

double contact_time(const std::vector<double> &t, const std::vector<double> &F)
{
  const std::size_t i = first_contact(F);
  return i < F.size() ? t.at(i) : std::numeric_limits<double>::quiet_NaN();
}

Parting parting_time(const std::vector<double> &t_a, const std::vector<double> &F_a, const std::vector<double> &t_b,
                     const std::vector<double> &z_b, const std::vector<double> &F_b, const PartingSettings &settings)
{
  if (!(settings.window > 0) || !std::isfinite(settings.window))
    throw std::invalid_argument("parting: the window must be a positive time");
  if (!(settings.threshold > 0) || !std::isfinite(settings.threshold))
    throw std::invalid_argument("parting: the threshold must be positive");
  if (settings.sustain < 1) throw std::invalid_argument("parting: sustain must be 1 or more windows");
  if (t_a.size() != F_a.size() || t_b.size() != F_b.size() || t_b.size() != z_b.size())
    throw std::invalid_argument("parting: t, z and F of a trace differ in length");

  Parting p;
  const std::size_t ca = first_contact(F_a), cb = first_contact(F_b);
  if (ca < F_a.size()) p.contact_a = t_a[ca];
  if (cb < F_b.size()) p.contact_b = t_b[cb];
  if (ca == F_a.size() || cb == F_b.size()) return p;
  const WindowSums a = window_sums(t_a, F_a, ca, settings.window), b = window_sums(t_b, F_b, cb, settings.window);
  for (std::size_t k = 0; k < std::min(a.sum.size(), b.sum.size()); ++k) {
    if (a.count[k] == 0 || b.count[k] == 0) break;    // a gap in either trace ends the comparison
    PartingWindow w;
    w.t_lo = double(k) * settings.window;
    w.t_hi = double(k + 1) * settings.window;
    w.n_a = a.count[k];
    w.n_b = b.count[k];
    w.mean_a = a.sum[k] / double(w.n_a);
    w.mean_b = b.sum[k] / double(w.n_b);
    if (w.mean_b > 0) w.ratio = w.mean_a / w.mean_b;
    p.windows.push_back(w);
  }

  const std::size_t n = p.windows.size(), need = std::size_t(settings.sustain);
  for (std::size_t k = 0; k + need <= n && !p.parted; ++k) {
    const double side = p.windows[k].ratio - 1;
    bool all = true;
    for (std::size_t j = k; j < k + need && all; ++j) all = apart(p.windows[j], settings.threshold, side);
    if (all) {
      p.parted = true;
      p.first = k;
    }
  }
  const std::size_t before = p.parted ? p.first : n;
  for (std::size_t k = 0; k < before; ++k)
    if (std::isfinite(p.windows[k].ratio))
      p.largest_before = std::max(p.largest_before, std::fabs(p.windows[k].ratio - 1));
  if (p.parted) {
    p.t_part = p.windows[p.first].t_lo;
    p.z_part = depth_at(t_b, z_b, p.contact_b + p.t_part);
  }
  return p;
}

}    // namespace granpen
