// granpen analysis: when two pushes part (plain arrays in, no files). Two pushes over the
// same grains (the same tile under the rod in boxes of different width, a run and its
// repeat) give the same drag until something reaches the rod that one has and the other
// has not: an echo from the narrower box's cell boundary, the flow meeting a wall. The
// kernel reads both in windows of time after each one's own contact, the ratio A / B of
// their mean drag per window, and the parting: the first window from which `sustain`
// windows in a row leave 1 by at least `threshold`, on the same side. Time, not depth:
// a wave arrives at a time, a flow front at a depth, and the two read apart when the
// speed changes (docs/results.md, "When the boxes part"; granpen parting).
#ifndef GRANPEN_TRACE_PARTING_H
#define GRANPEN_TRACE_PARTING_H

#include <cmath>
#include <cstddef>
#include <vector>

namespace granpen {

struct PartingSettings {
  double window = 5e-4;       // s; a window of 0.5 ms is 5 samples of the presets' traces
  double threshold = 0.03;    // |A / B - 1| at or above it counts as apart
  int sustain = 2;            // windows in a row, on the same side of 1
};

struct PartingWindow {
  double t_lo = 0, t_hi = 0;          // s after contact
  std::size_t n_a = 0, n_b = 0;       // samples of each trace in it (the last may be cut)
  double mean_a = 0, mean_b = 0;      // mean F
  double ratio = NAN;                 // mean_a / mean_b; NaN when mean_b is not positive
};

struct Parting {
  double contact_a = NAN, contact_b = NAN;    // s: each trace's first sample with F > 0
  std::vector<PartingWindow> windows;         // while both traces have samples in it
  bool parted = false;
  std::size_t first = 0;           // index of the first window of the parting
  double t_part = NAN;             // s after contact: that window's start
  double z_part = NAN;             // B's depth (its z) at its contact + t_part
  double largest_before = 0;       // largest |ratio - 1| before the parting (over all when none)
};

// A trace's contact: the time of its first sample with F > 0; NaN when F is never above 0
// (granpen parting and granpen arrival both read time after it).
double contact_time(const std::vector<double> &t, const std::vector<double> &F);

// The parting of traces A (t_a, F_a) and B (t_b, z_b, F_b). t and F of a trace the same
// length, t increasing. A trace without a contact (F never positive) has a NaN contact, and
// then there are no windows. Throws std::invalid_argument for window <= 0 or not
// finite, threshold <= 0 or not finite, sustain < 1, or arrays of different lengths.
Parting parting_time(const std::vector<double> &t_a, const std::vector<double> &F_a, const std::vector<double> &t_b,
                     const std::vector<double> &z_b, const std::vector<double> &F_b,
                     const PartingSettings &settings = PartingSettings());

}    // namespace granpen

#endif
