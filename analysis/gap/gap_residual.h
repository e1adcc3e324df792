// granpen gap, stage 11 (residual): what the gap left over looks like, so that a user can
// guess its cause and design the next run. Against the model the verdict leaves (the
// confirming runs after an `explained`, the baseline on the reference beds otherwise): the
// regimes and depth range where the bin means differ beyond 2 standard errors; whether it
// moves the bin means, the fluctuations (levels and spectral bands) or both (chi^2 of each
// group, p < 0.001); where the spectrum carries it, the band, and any narrow line in the
// ratio of the measured to the model's mean periodogram (its frequency per speed, and
// whether it scales with v0: a wavelength of the bed, or stays put: a resonance of the
// set-up); and the nearest candidate with why it was rejected. docs/gap.md, "Residual".
#ifndef GRANPEN_GAP_RESIDUAL_H
#define GRANPEN_GAP_RESIDUAL_H

#include "gap_confirm.h"
#include "gap_data.h"
#include "gap_fit.h"
#include "gap_runs.h"
#include "gap_verdict.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace granpen {

// A narrow line at one speed: its frequency and how far the measured power stands above
// the model's there, beyond the ratio's local level (in standard deviations of the log
// ratio of two mean periodograms).
struct SpectralLine {
  double v0 = 0, freq = 0, ratio = 1, sigma = 0;
};

// Per speed, what the figure draws: the residual of the bin means with its 2-sigma band,
// and the ratio of the mean periodograms (measured / model) against frequency.
struct ResidualCurves {
  double v0 = 0;
  std::vector<double> z, resid, band;
  std::vector<double> freq, ratio;
};

struct Residual {
  std::string against;                    // "baseline" or "corrected"
  std::vector<std::string> regimes;       // where bins differ beyond 2 sigma
  double z_from = 0, z_to = 0;            // their depth range (both 0 when none)
  int bins_beyond = 0;                    // how many (of dof_means; noise alone: 4.6%)
  double chi2_means = 0, chi2_fluct = 0;  // over the bin means, over the fluctuation features
  int dof_means = 0, dof_fluct = 0;
  double p_means = 1, p_fluct = 1;
  std::string moves;                      // "bin means", "spectrum", "both", or "neither"
  std::string band;                       // e.g. "450-1350 Hz" ("" unless the spectrum moves)
  double band_ratio = 1;                  // measured / model amplitude there, mean over speeds
  std::vector<SpectralLine> lines;        // at most one per speed
  std::string line_scaling;               // "scales with v0", "fixed", or "" (fewer than 2 speeds)
  std::string nearest, why_rejected;      // the candidate nearest to explaining it, and why not
  std::vector<ResidualCurves> curves;
};

// The features of one side, per speed: ensemble means and variances of the mean (the
// measured side's and the model's), and the runs (aligned) for the periodograms.
struct ResidualSide {
  std::vector<std::vector<double>> mean, err;    // [speed][feature]
  std::vector<std::vector<const TraceRun *>> runs;
};

// A narrow line in the ratio of two sets of runs' mean periodograms over the grid (common
// length: each run's first N samples in range, N the fewest): the bin whose log ratio
// stands highest above its neighbours' median (+-8 bins), when that is above 5 standard
// deviations of a log ratio of means of n_R and n_S periodogram bins and falls to half
// within 2 bins on both sides. Also returns the ratio curve (freq, ratio).
bool find_line(const std::vector<const TraceRun *> &real, const std::vector<const TraceRun *> &model,
               const GapGrid &grid, SpectralLine &line, std::vector<double> &freq, std::vector<double> &ratio);

// "scales with v0" when f / v0 varies less across speeds than f does (relative spread), else
// "fixed"; "" with fewer than 2 lines.
std::string line_scaling(const std::vector<SpectralLine> &lines);

// The whole description. speeds: the measured speeds; peak_end: 0.35 D; z_transient_end per
// speed; ranking best first; verdict and top/tested effects as decided.
struct ResidualContext {
  std::vector<double> speeds, z_transient_end;
  double peak_end = 0;
  std::string against;
  Verdict verdict = Verdict::none;
  std::string top_effect, tested_effect;
  std::vector<EffectFit> ranking;
  int n_null = 0;
  std::vector<CandidateRecord> records;    // the verdict's record (gap_verdict.h): why each candidate is not the answer
};
Residual describe_residual(const ResidualSide &real, const ResidualSide &model, const GapGrid &grid,
                           const ResidualContext &ctx);

// Why a candidate was not the answer: the shortfalls the verdict recorded for it (ctx.records).
std::string why_rejected(const EffectFit &fit, const ResidualContext &ctx);

// The stage: for every verdict but `none` (the verdict that stands), the residual against the
// runs it leaves as the model: the confirmation's runs when it simulated some; else an
// explained verdict's fitted prediction (the fits' model data at the named magnitude); else
// the reference beds (fresh). The regimes: where.before's z_transient_end and peak_end.
std::optional<Residual> residual_stage(const Features &f, const RunsBySpeed &real, const RunsBySpeed &fresh,
                                       const GapGrid &grid, double peak_end, const WhereResult &where,
                                       const FittedCandidates &fitted, const VerdictDecision &verdict,
                                       const Confirmation &confirmation);

}    // namespace granpen

#endif
