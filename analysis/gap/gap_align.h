// granpen gap, stage 4 (align and bin): every run's depth origin moved so that its force
// onset sits at the baseline's mean onset for its speed (measured origins may be off by a
// grain diameter), and the common grid: 0.25 cm bins down to the deepest depth every run
// of both sides reaches. docs/gap.md, "Where" 1-2.
#ifndef GRANPEN_GAP_ALIGN_H
#define GRANPEN_GAP_ALIGN_H

#include "gap_data.h"
#include "gap_runs.h"
#include "gap_sims.h"

#include <map>
#include <string>
#include <vector>

namespace granpen {

struct Alignment {
  GapGrid grid;                       // zmax set
  std::map<double, double> onset;     // per measured speed: the baseline's mean onset, cm
  std::vector<std::string> notes;     // how far measured origins moved
};

// Aligns the measured runs and every simulated ensemble at the measured speeds (in place)
// and sets the grid, no deeper than max_depth (the scenario's push depth). Throws
// InputError when a simulated ensemble has fewer than 2 runs at a measured speed, or when
// the runs share less than 1 cm of depth.
Alignment align_and_bin(RunsBySpeed &real, SimulatedRuns &sims, double max_depth);

}    // namespace granpen

#endif
