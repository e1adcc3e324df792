// granpen gap, stage 6 (where): the gap against the baseline on the reference beds (what
// the fits see; four beds, as many as the confirmation has, so that G before and after
// share a noise floor): the gap curve and G per speed, the regimes from the baseline's
// crossover, the paper's observables per regime with z-scores, the omnibus chi^2 over every
// feature, and the held-out speed. docs/gap.md, "Where" 6-8. where_stage returns it all as
// a WhereResult; the functions it is made of each return their part.
#ifndef GRANPEN_GAP_WHERE_H
#define GRANPEN_GAP_WHERE_H

#include "gap_data.h"
#include "gap_features.h"
#include "gap_runs.h"
#include "gap_sims.h"
#include "scenario.h"

#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace granpen {

struct Finding {
  std::string regime, observable;
  double v0 = 0, real = 0, sim = 0, real_se = 0, sim_se = 0, zscore = 0;
  bool significant = false;
};

struct SpeedCurves {           // per speed, on the grid's bin centres
  double v0 = 0;
  int n_real = 0, n_base = 0, n_corr = 0;
  std::vector<double> z, real, real_se, base, base_se, corr, corr_se, gap, band;
  double G_before = 0, G_after = 0;      // G: the bin means (gap-metric v1)
  double Gs_before = 0, Gs_after = 0;    // G_spec: the fluctuation spectrum's bands (v2)
  double all_before() const { return gap_all(G_before, Gs_before); }
  double all_after() const { return gap_all(G_after, Gs_after); }
  double z_transient_end = 0;  // peak: z <= 0.35 D; transient: up to this; linear: beyond
};

// The overall gap's two parts (means over speeds) and the runs per speed behind them (fewest).
struct GapParts {
  double G = 0, G_spec = 0;
  int runs_real = 0, runs_sim = 0;
  double all() const { return gap_all(G, G_spec); }
};

// The curves before (the "after" unset: the confirmation's), G and G_spec per speed and their
// means, the runs behind them (measured: the fewest per speed; simulated: the reference beds).
// gap_within_bound: G_all against the baseline times 1 + scale_within_bound (the baseline
// within the calibration bound, baseline_scale_within_bound), the footing of an "after" that
// is compared times 1 + its fitted scale (docs/gap.md, "Before and after").
struct GapCurves {
  std::vector<SpeedCurves> speeds;       // z_transient_end unset (transient_ends)
  GapParts parts;
  double gap = 0;                        // G_all, mean over speeds (gap-metric.md: the data against the baseline)
  double gap_within_bound = 0, scale_within_bound = 0;
  int n_real_min = 0, n_sim = 0;
};
GapCurves gap_curves(const Features &f, const GapGrid &grid);

// The force scale within the calibration bound (GapThresholds::calibration_scale_bound) that
// brings the reference beds' baseline nearest the measurement: the weighted least-squares
// factor over every feature (the omnibus chi^2's weights), clamped; as the fits' nuisance
// scale at magnitude 0 (gap_fit.h, nuisance_scale).
double baseline_scale_within_bound(const Target &t, const Features &f);

// Per speed: the reference runs' mean crossover depth t~* v0 sqrt(D/g) (z_max when any run
// does not cross), kept within [0.35 D, z_max]: where the transient regime ends.
std::vector<double> transient_ends(const Features &f, const RunsBySpeed &fresh, const Scenario &sc, const GapGrid &grid);

// Each observable's measured and simulated means with standard errors from the run-to-run
// variance pooled over every simulated ensemble, |z| first; a note for each observable
// without scatter (no z-score). z_transient_end: per speed (transient_ends).
struct ObservableFindings {
  std::vector<Finding> findings;
  std::vector<std::string> notes;
};
ObservableFindings observable_findings(const Features &f, const RunsBySpeed &real, const SimulatedRuns &sims,
                                       const Scenario &sc, const GapGrid &grid, const std::vector<double> &z_transient_end);

// chi^2 of a measurement's means against the reference beds' over every feature, the
// reference's means times 1 + scale (0: the raw gap).
double omnibus_chi2(const Target &t, const Features &f, double scale = 0.0);

// The omnibus test: chi^2 over every feature, its p-value, significant below significance_p
// (the raw gap: whether the data differ from the baseline at all). chi2_within_bound: the
// same chi^2 against the baseline within the calibration bound (baseline_scale_within_bound),
// what a confirmation's runs, compared times 1 + their fitted scale, are judged against.
struct Significance {
  double chi2_0 = 0, p_value = 1;
  double chi2_within_bound = 0, scale_within_bound = 0;
  std::size_t nfeatures = 0;
  bool significant = false;
};
Significance gap_significance(const Features &f, const GapGrid &grid);

// The held-out speed the confirmation judges a fit by: the one with the largest G_all.
struct HeldOut {
  std::size_t index = 0;
  double v0 = 0, gap = 0;                // gap: its G_all before
};
HeldOut heldout_speed(const std::vector<SpeedCurves> &speeds);

// The stage's result.
struct WhereResult {
  GapCurves before;                      // with each speed's z_transient_end
  std::vector<Finding> findings;         // |z| first
  std::vector<std::string> notes;        // observables without scatter
  Significance omnibus;
  HeldOut heldout;
  std::vector<std::string> baseline_files;    // the reference runs (OUT/baseline), by speed
};
WhereResult where_stage(const Features &f, const RunsBySpeed &real, const SimulatedRuns &sims, const Scenario &sc,
                        const GapGrid &grid);

// G per regime before and after (peak: z <= peak_end; transient: up to each speed's
// z_transient_end; linear: beyond): the mean over speeds of G restricted to the regime's
// bins, from the curves before and after the confirmation (without the noise debiasing,
// which is in the overall G).
using RegimeGaps = std::map<std::string, std::pair<double, double>>;
RegimeGaps gap_by_regime(const GapGrid &grid, double peak_end, const std::vector<SpeedCurves> &speeds);

}    // namespace granpen

#endif
