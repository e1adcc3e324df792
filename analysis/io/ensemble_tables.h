// granpen analysis: ensembles of trace files for granpen fit, collapse and plot --ensemble:
// traces grouped by case (same v0, g and D), each group's ensemble mean as
// core/ensemble_averaging.h gives it, and the files they write: the mean curves as CSV, the
// alignment and the estimates (core/ensemble_fit.h) as JSON.
#ifndef GRANPEN_ENSEMBLE_TABLES_H
#define GRANPEN_ENSEMBLE_TABLES_H

#include "ensemble_average.h"
#include "ensemble_averaging.h"
#include "ensemble_fit.h"
#include "json_writer.h"
#include "trace_reader.h"

#include <string>
#include <vector>

namespace granpen {

struct TraceGroup {
  double v0 = 0.0, g = 0.0, D = 0.0;    // cgs; v0 the mean of the runs' v0 when grouped within a tolerance
  double v0_min = 0.0, v0_max = 0.0;    // the runs' v0 range
  double v0_tolerance = 0.0;            // the grouping's (0: equal v0)
  std::vector<Trace> traces;            // cgs, in the order given
  EnsembleMean mean;                    // set by keep_averaged
  std::string label() const;            // "v0 = 100 cm/s, g = 981 cm/s^2, D = 2 cm"
};

// Traces grouped by (v0, g, D), each rounded to 6 significant digits so that "100" and
// "1.0 m/s" meet; groups sorted by g, D, then v0. Traces arrive in cgs. With
// v0_tolerance > 0, the runs of one (g, D) sorted by v0 form a new group at each v0 more
// than v0_tolerance above the slowest of the current group; the group's v0 is its runs'
// mean. Runs of one group whose grains differ (d_g, rho_g or mu, a key given in one and
// not in another included) are an InputError naming two of them: an ensemble is of one
// material.
std::vector<TraceGroup> group_traces(const std::vector<Trace> &traces, double v0_tolerance = 0.0);

// Reads the files (cgs); an unreadable file is a line in problems naming it.
std::vector<Trace> read_traces(const std::vector<std::string> &files, std::vector<std::string> &problems);

// The groups' runs (cgs), each named by its label: the input of average_ensembles.
std::vector<EnsembleRuns> ensemble_runs(const std::vector<TraceGroup> &groups);
// Each group's mean from a (the averaging of ensemble_runs(groups) with p); a group that
// could not be averaged (runs that share no depth) is a line in problems and removed.
// Throws InputError naming --ensemble-bin when a refused p.bin (more than kMaxEnsembleBins
// bins over a group's depths).
void keep_averaged(std::vector<TraceGroup> &groups, const EnsembleAveraging &a, const EnsembleParams &p,
                   std::vector<std::string> &problems);

// One line per group saying what the averaging did: runs, bins, range, the largest onset
// shift, and its notes.
std::string ensemble_summary(const TraceGroup &g);

// The mean curves: v0,g,D,runs,z,F_mean,F_se,F_sd (cgs), one row per bin.
std::string ensemble_curves_csv(const std::vector<TraceGroup> &groups);

// An estimate as {"ok", "value", "se_ok", "se", "ci95", "defined"}.
Json estimate_json(const Estimate &e);
// A group's case, files, alignment (reference onset, shift per file) and grid.
Json ensemble_json(const TraceGroup &g);
// ensemble_json with the fit of its mean: window, notes, and each estimate.
Json ensemble_fit_json(const TraceGroup &g, const EnsembleFit &f);
// The collapse of ensembles (groups[i] is case i): per ensemble its k_z, peak and t~*, and
// the crossover, collapse quality and peak law, each an estimate.
Json ensemble_collapse_json(const std::vector<TraceGroup> &groups, const EnsembleCollapse &c);
// The binned F/F_z curves of the ensembles as rows of collapse_curves_csv (trace
// "ensemble v0=V g=G D=D runs=N").
std::string ensemble_collapse_csv_rows(const std::vector<TraceGroup> &groups, const EnsembleCollapse &c);

}    // namespace granpen

#endif
