// granpen gap, stage 4 (align and bin): see gap_align.h.
#include "gap_align.h"

#include "onset_alignment.h"
#include "text_util.h"

#include <algorithm>
#include <cmath>

namespace granpen {

namespace {

std::string fmt(double v, const char *f = "%.4g") { return printf_number(f, v); }

std::vector<double> onsets_of(const std::vector<TraceRun> &runs)
{
  std::vector<double> o;
  for (const auto &r : runs) o.push_back(r.onset);
  return o;
}

// aligns an ensemble at speed v to onset; returns its deepest common depth
double align_ensemble(std::vector<TraceRun> &runs, double onset, const std::string &what, double v)
{
  if (runs.size() < 2) throw InputError(what + " has fewer than 2 runs at v0 = " + fmt(v));
  align_runs(runs, onset);
  return deepest_common(runs);
}

}    // namespace

Alignment align_and_bin(RunsBySpeed &real, SimulatedRuns &sims, double max_depth)
{
  Alignment out;
  double zdeep = max_depth;
  for (auto &[v, runs] : real) {
    auto &base = sims.base[v];
    if (base.size() < 2) throw InputError("the baseline has fewer than 2 runs at v0 = " + fmt(v));
    const double ref = out.onset[v] = align_onsets(onsets_of(base)).reference;
    const double shift_max = align_onsets(onsets_of(runs), ref).max_shift;
    if (shift_max > 0.01)
      out.notes.push_back("v0 = " + fmt(v) + ": measured depth origins moved by up to " + fmt(shift_max, "%.3f") +
                          " cm to align the force onsets with the simulation's");
    align_runs(runs, ref);
    align_runs(base, ref);
    zdeep = std::min({zdeep, deepest_common(runs), deepest_common(base)});
    zdeep = std::min(zdeep, align_ensemble(sims.fresh[v], ref, "the fresh baseline", v));
    for (auto &[name, by] : sims.knots) zdeep = std::min(zdeep, align_ensemble(by[v], ref, "sweep " + name, v));
  }
  out.grid.zmax = std::floor(zdeep / out.grid.w + 1e-9) * out.grid.w;
  if (out.grid.zmax < 1.0)
    throw InputError("the runs share less than 1 cm of depth (deepest common depth " + fmt(zdeep) + " cm)");
  return out;
}

}    // namespace granpen
