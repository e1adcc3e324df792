// granpen gap, stage 6 (where): the gap against the baseline on the reference beds (what
// the fits see; four beds, as many as the confirmation has, so that G before and after
// share a noise floor): the gap curve and G per speed, the regimes from the baseline's
// crossover, the paper's observables per regime with z-scores, and the omnibus chi^2 over
// every feature. docs/gap.md, "Where" 6-8. Each function fills its part of the Diagnosis.
#ifndef GRANPEN_GAP_WHERE_H
#define GRANPEN_GAP_WHERE_H

#include "gap_features.h"
#include "gap_result.h"
#include "gap_runs.h"
#include "gap_sims.h"
#include "scenario.h"

namespace granpen {

// d.speeds (the curves before, G and G_spec per speed; z_transient_end unset), d.parts_before,
// d.gap_before (G_all), d.n_real_min, d.n_sim.
void gap_curves(const Features &f, const GapGrid &grid, Diagnosis &d);

// d.speeds[s].z_transient_end: the reference runs' mean crossover depth t~* v0 sqrt(D/g)
// (z_max when any run does not cross), kept within [0.35 D, z_max].
void regimes(const Features &f, const RunsBySpeed &fresh, const Scenario &sc, const GapGrid &grid, Diagnosis &d);

// d.where: each observable's measured and simulated means with standard errors from the
// run-to-run variance pooled over every simulated ensemble, |z| first.
void observable_findings(const Features &f, const RunsBySpeed &real, const SimulatedRuns &sims, const Scenario &sc,
                         const GapGrid &grid, Diagnosis &d);

// chi^2 of a measurement's means against the reference beds' over every feature.
double omnibus_chi2(const Target &t, const Features &f);

// d.chi2_0, d.nfeatures, d.p_value, d.significant (p < 0.001).
void gap_significance(const Features &f, const GapGrid &grid, Diagnosis &d);

// G per regime before and after (peak: z <= peak_end; transient: up to each speed's
// z_transient_end; linear: beyond): the mean over speeds of G restricted to the regime's
// bins, from the curves before and after the confirmation (without the noise debiasing,
// which is in the overall G).
using RegimeGaps = std::map<std::string, std::pair<double, double>>;
RegimeGaps gap_by_regime(const GapGrid &grid, double peak_end, const std::vector<SpeedCurves> &speeds);

}    // namespace granpen

#endif
