// granpen analysis: the rod's disturbance reaching stations about its axis (see wave_arrival.h).
#include "wave_arrival.h"

#include <stdexcept>

namespace granpen {

namespace {

StationArrival arrival_at(const std::vector<double> &t, const std::vector<double> &s, double r, double t_contact,
                          double factor)
{
  StationArrival a;
  a.r = r;
  double sum = 0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < t.size() && t[i] < t_contact; ++i)
    if (t[i] > 0 && std::isfinite(s[i])) sum += s[i], ++n;
  if (n < 3) return a;
  a.background = sum / double(n);
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] >= t_contact && s[i] > factor * a.background) {
      a.arrived = true;
      a.t = t[i];
      break;
    }
  return a;
}

}    // namespace

WaveArrival wave_arrival(const std::vector<double> &t, const std::vector<std::vector<double>> &signal,
                         const std::vector<double> &r, double t_contact, const ArrivalSettings &settings)
{
  if (!(settings.factor > 1) || !std::isfinite(settings.factor))
    throw std::invalid_argument("wave arrival: the factor over the background must be above 1");
  if (signal.size() != r.size()) throw std::invalid_argument("wave arrival: as many distances as signals needed");
  if (!std::isfinite(t_contact)) throw std::invalid_argument("wave arrival: the contact time must be finite");
  WaveArrival w;
  for (std::size_t k = 0; k < r.size(); ++k) {
    if (signal[k].size() != t.size()) throw std::invalid_argument("wave arrival: a signal not the length of the times");
    w.stations.push_back(arrival_at(t, signal[k], r[k], t_contact, settings.factor));
    if (w.stations.back().arrived) ++w.arrived;
  }
  // least squares of t against r over the stations reached
  double sr = 0, st = 0, srr = 0, srt = 0;
  for (const auto &s : w.stations)
    if (s.arrived) sr += s.r, st += s.t, srr += s.r * s.r, srt += s.r * s.t;
  const double n = double(w.arrived), sxx = srr - sr * sr / n;
  if (w.arrived < 2 || !(sxx > 0)) return w;
  w.fitted = true;
  w.slowness = (srt - sr * st / n) / sxx;
  w.t_axis = (st - w.slowness * sr) / n;
  if (w.slowness > 0) w.speed = 1 / w.slowness;
  if (w.arrived > 2) {
    double res = 0;
    for (const auto &s : w.stations)
      if (s.arrived) res += std::pow(s.t - w.t_axis - w.slowness * s.r, 2);
    w.slowness_se = std::sqrt(res / (n - 2) / sxx);
    w.speed_se = w.speed * w.slowness_se / w.slowness;
  }
  return w;
}

}    // namespace granpen
