// granpen analysis: when the rod's disturbance reaches stations at known distances from its
// axis, and how fast it travels (plain arrays in, no files). The signal of a station is a
// sum over its grains that is quiet in a settled bed and jumps when the front arrives (the
// kinetic energy of a ring of grains about the axis: observe/arrival.lmp). Its arrival is
// the first sample at or after the rod's contact above `factor` times the station's own
// background, the mean over the samples before contact (t > 0: the first row, written at
// the push's setup, is no sample of the bed's motion). The front's speed is the inverse
// slope of the arrival times against the distances, fitted by least squares. An echo from
// a box's cell boundary comes back at the speed this measures, by another route
// (core/trace_parting.h): docs/results.md, "When the boxes part".
#ifndef GRANPEN_WAVE_ARRIVAL_H
#define GRANPEN_WAVE_ARRIVAL_H

#include <cmath>
#include <cstddef>
#include <vector>

namespace granpen {

struct ArrivalSettings {
  double factor = 100;    // the front: the signal above factor x its background
};

struct StationArrival {
  double r = 0;               // distance from the axis (cm)
  double background = NAN;    // mean signal before contact; NaN with fewer than 3 samples
  bool arrived = false;
  double t = NAN;             // arrival time (the samples' clock)
};

struct WaveArrival {
  std::vector<StationArrival> stations;
  std::size_t arrived = 0;       // stations the front reached
  bool fitted = false;           // two or more arrived, at two distances or more
  double slowness = NAN;         // s/cm, the fit's slope
  double slowness_se = NAN;      // its standard error (NaN with only 2 stations)
  double speed = NAN;            // cm/s: 1 / slowness (NaN when not positive)
  double speed_se = NAN;         // its standard error, speed x slowness_se / slowness
  double t_axis = NAN;           // the fit's arrival at r = 0
};

// signal[k] is station k's signal at the times t (increasing), r[k] its distance. Throws
// std::invalid_argument for factor <= 1 or not finite, r and signal of different counts,
// a signal not the length of t, or t_contact not finite.
WaveArrival wave_arrival(const std::vector<double> &t, const std::vector<std::vector<double>> &signal,
                         const std::vector<double> &r, double t_contact, const ArrivalSettings &settings = ArrivalSettings());

}    // namespace granpen

#endif
