// granpen analysis: the depth alignment of force traces at their force onsets (plain
// arrays in, no files). Measured depth origins may be off by a grain diameter or more (a
// surface found by a force threshold, a crosshead zeroed elsewhere); runs of one case are
// compared or averaged only after each run's depths are shifted so that its onset sits at a
// common reference, by default the runs' mean onset. The gap diagnosis (gap/gap_align.h)
// and the ensembles of granpen fit/collapse/plot --ensemble (core/ensemble_average.h) both
// align through this file.
#ifndef GRANPEN_ONSET_ALIGNMENT_H
#define GRANPEN_ONSET_ALIGNMENT_H

#include <cmath>
#include <cstddef>
#include <vector>

namespace granpen {

// Depth (cm) where F first reaches frac of its largest value over the first `search` cm
// after F first rises above 2% of the run's largest force, interpolated between samples;
// NaN without contact (F never positive).
double force_onset(const std::vector<double> &z, const std::vector<double> &F, double frac = 0.2,
                   double search = 1.0);

// Where each run goes: shift[i] is added to run i's depths so that its onset sits at the
// reference. A run without an onset (NaN) is not moved and is listed.
struct OnsetAlignment {
  double reference = NAN;                      // cm
  std::vector<double> onset;                   // each run's own onset, as given
  std::vector<double> shift;                   // cm, added to z
  std::vector<std::size_t> without_onset;      // indices of runs left where they were
  double max_shift = 0.0;                      // largest |shift|, cm
};

// The alignment of runs with the given onsets at `reference`; a NaN reference means the
// mean of the finite onsets (NaN when there is none: then nothing moves).
OnsetAlignment align_onsets(const std::vector<double> &onsets, double reference = NAN);

// The shift applied: z[k] += shift.
void shift_depths(std::vector<double> &z, double shift);

// The deepest depth every run reaches: the smallest of the runs' largest depths (-inf when
// a run is empty, +inf without runs).
double deepest_common(const std::vector<const std::vector<double> *> &z_of_runs);

}    // namespace granpen

#endif
