// granpen gap: fitting a candidate effect's magnitude to a gap, and scoring it.
// Plain arrays: per speed s and feature p, the measured ensemble mean and its variance,
// and for the effect the simulated ensemble means at its knots (magnitude 0 = the
// baseline, then the reference magnitudes) with their variances. The model at magnitude
// a is the piecewise-linear interpolation between knots (extrapolated at most `reach`
// of the outer segments beyond the end knots; a two-sided effect whose knots lie on one
// side of 0 extrapolates linearly to the mirror of its farthest knot); the variance of the model's prediction
// follows the interpolation weights, and for a push-only effect (paired: the knots share
// the baseline's beds) the knots' paired differences to the baseline.
#ifndef GRANPEN_GAP_FIT_H
#define GRANPEN_GAP_FIT_H

#include "gap_thresholds.h"

#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace granpen {

using Table = std::vector<std::vector<double>>;    // [speed][feature]

struct EffectData {
  std::string name;
  std::vector<double> knots;          // sorted ascending, one of them 0 (the baseline)
  std::vector<Table> mean, err;       // per knot: ensemble means and variances of the mean
  bool paired = false;
  std::vector<Table> diff_err;        // paired: variance of the mean paired difference to knot 0
  double reach = 0.25;
  bool one_sided = false;             // no magnitude below 0
  // Knot 0 may be a reference ensemble other than the one the knots' signatures were
  // simulated against (fresh beds: see gap_analysis.cpp): then mean[j] = reference +
  // (knot j - signature baseline), err[0] is the reference's, and ref_err the signature
  // baseline's variance, which a pour-level (unpaired) prediction carries with weight
  // (1 - w0)^2. Empty: knot 0 is the signature baseline itself.
  std::vector<Table> ref_err;         // [0]: per speed and feature
  // Per speed: the weighted squared residual at magnitude 0 that run-to-run noise alone
  // leaves (its mean over null replicates, noise_residual()). Given, the explained fractions
  // are fractions of the residual's excess over it (a certain signature cannot explain the
  // noise part of a residual); empty: fractions of the whole residual.
  std::vector<double> noise_r2;
  // The nuisance force scale (GapThresholds::calibration_scale_bound): every prediction is
  // taken as (1 + c) M(a) with the c in [-scale_bound, scale_bound] that fits the target best
  // (fixed weights, closed form), the baseline at a = 0 included, so a gap no larger than a
  // calibration allows is evidence for nothing. 0: no nuisance. is_scale: the effect is itself
  // a uniform scale of the force (force_scale): the nuisance applies at a = 0 only (its
  // magnitude is the scale beyond it: the two would be one parameter).
  double scale_bound = 0.0;
  bool is_scale = false;
  // The width of the effect's magnitude range over every knot the library gives it, bought
  // or not (gap_adaptive.h): the scale of "the same magnitude" (same_magnitude_tolerance), so
  // that which knots a plan bought never changes whether a refinement or a held-out run is
  // simulated. 0: this data's own magnitude_range.
  double library_span = 0.0;
};

struct Target {
  Table mean, err;                    // measured ensemble means and variances of the mean
};

// chi^2 of the target against the model at magnitude a over the given speeds, the model's
// means times 1 + scale (0: as simulated; a nuisance scale: as the verdict compares them).
double effect_chi2(const Target &t, const EffectData &e, double a, const std::vector<std::size_t> &speeds,
                   double scale = 0.0);
// Variance, per feature at speed s, of sum_j c[j] mean[j] over the effect's knots: each
// knot's own noise (a paired knot's paired difference's), the signature baseline's that
// every referenced knot carries, and with_reference the reference's (knot 0's ensemble), which
// enters every paired or referenced knot's mean and only knot 0's otherwise. One bookkeeping
// for a prediction (c: the interpolation weights), a signature (the weights less knot 0)
// and a knot's bend (knot_bends: a three-point stencil).
void knot_combination_var(const EffectData &e, const std::vector<double> &c, std::size_t s, bool with_reference,
                          std::vector<double> &var);
// Model prediction and its variance at magnitude a, speed s.
void effect_predict(const EffectData &e, double a, std::size_t s, std::vector<double> &mean, std::vector<double> &var);

// The effect's signature at magnitude a, speed s: u = M(a) - M(0) per feature, and the
// variance u carries from the knots' ensembles (the reference's, common to M(a) and M(0),
// cancels): for a paired effect the paired differences', else the knots' and the signature
// baseline's with their interpolation weights.
void effect_signature(const EffectData &e, double a, std::size_t s, std::vector<double> &u, std::vector<double> &var);
// The signature baseline's coefficient in u at magnitude a (u = ... - c B_sig): 1 - w0 for an
// unpaired effect referenced to other beds (ref_err given), else 0 (a paired effect's knots
// are differences on the same beds). Two such effects share B_sig (the baseline's signature
// beds), so it enters u_a - u_b with c_a - c_b, not with both.
double signature_baseline_share(const EffectData &e, double a);

struct EffectFit {
  std::string name;
  double magnitude = 0.0;           // best fit over all speeds
  // its standard error: where -2 log L (signature_residual: the knots' noise included)
  // rises by 1, from its curvature at the fit; NaN where the curvature is not positive
  double magnitude_error = std::numeric_limits<double>::quiet_NaN();
  double chi2_0 = 0.0, chi2 = 0.0;  // at magnitude 0 (the baseline) and at the fit, as simulated
  // the same within the calibration bound: the model times 1 + its nuisance scale (at 0: the
  // baseline's, c0, so chi2_0_within_bound is the omnibus test's chi2_within_bound; at the
  // fit: `scale`), the footing the verdict's chi^2 before and after stand on
  double chi2_0_within_bound = 0.0, chi2_within_bound = 0.0;
  std::size_t nfeatures = 0;
  double explained = 0.0;           // fraction of the noise-weighted squared gap the fit removes
                                    // (of its excess over the noise when EffectData::noise_r2 is given)
  bool at_edge = false;             // the fit sits at the end of the allowed range
  std::vector<double> loso_magnitude, loso_explained;    // per speed left out (NaN: no gap there)
  double heldout_explained = 0.0;   // mean over speeds left out that had a gap
  double score = 0.0;               // min(explained, heldout_explained), the ranking's number
  // the targeted test: -2 log likelihood ratio of the fit against magnitude 0, the
  // residual at the fit weighted with the signature's own variance too (>= 0; a
  // chi^2 with one degree of freedom for data without the effect, if the noise model
  // were exact), the same statistic's mean over null replicates (fresh baseline beds
  // taken as the measurement: how much the noise model under-states this effect's
  // direction), and the threshold lr must pass
  double lr = 0.0, lr_null_mean = 0.0, lr_threshold = 0.0;
  bool detected = false;
  std::vector<double> lr_nulls;     // the statistic on each null replicate (their mean is lr_null_mean)
  double scale = 0.0;               // the nuisance force scale fitted with the magnitude (EffectData::scale_bound)
  bool is_scale = false;            // the candidate is itself a uniform force scale (EffectData::is_scale)
};

// The nuisance scale c at magnitude a over the given speeds: the weighted least-squares
// factor of the target on (1 + c) M(a), clamped to +-scale_bound (0 when there is none).
double nuisance_scale(const Target &t, const EffectData &e, double a, const std::vector<std::size_t> &speeds);

EffectFit fit_effect(const Target &t, const EffectData &e);

// The magnitudes a fit may reach: the knots' span, extended by `reach` of the outer
// segments (a two-sided effect simulated on one side: to the mirror of its farthest knot).
std::pair<double, double> magnitude_range(const EffectData &e);

// Two magnitudes of e closer than this are the same simulation at the knots' noise:
// GapThresholds::same_magnitude_of_range of library_span (else of magnitude_range's width).
double same_magnitude_tolerance(const EffectData &e);

// Confirming runs at magnitude a that leave a gap c u along the effect's signature
// u = M(a) - M(0) (c: the leftover's weighted least-squares coefficient on u) call for
// a (1 + c) by linear response through the baseline; kept inside magnitude_range.
double refined_magnitude(const EffectData &e, double a, double c);

// The likelihood-ratio statistic of fit_effect alone (no leave-one-speed-out): for the null
// replicates.
double effect_lr(const Target &t, const EffectData &e);

// The targeted test's threshold: an effect is detected when its lr exceeds
// max(1, lr_null_mean) times the chi^2(1) quantile of p = 1e-4 (GapThresholds::lr_chi2_1_p1e4,
// 15.14; over about 7 effects a family-wise 1e-3, as the omnibus test).
double lr_threshold(double lr_null_mean);

// The likelihood ratio beyond what noise gives along the effect's signature (the null mean's
// excess over the nominal 1 subtracted): a signature that rests on few, noisy beds fits
// part of any noise, and this is the evidence two candidates are compared by.
inline double lr_evidence(const EffectFit &f) { return f.lr - (f.lr_null_mean > 1.0 ? f.lr_null_mean - 1.0 : 0.0); }

// Two candidates are told apart by an evidence margin (GapThresholds::evidence_margin).

// Per speed, the mean over null replicates (measurements without any effect) of the
// weighted squared residual at magnitude 0: for EffectData::noise_r2.
std::vector<double> noise_residual(const std::vector<Target> &nulls, const EffectData &e);

// The fraction of the weighted squared gap w0 at magnitude 0 that a fit leaving w removes: of
// its excess over the noise's share n when that is known (n > 0), the excess taken at least
// at chi2_noise_sigmas standard deviations of a chi^2 with n degrees of freedom, capped at 1
// (fit_effect's explained; the pair stage's, gap_pairs.h).
double explained_fraction(double w0, double w, double n);

// The noise's share of e's weighted squared gap over the speeds (its noise_r2 summed; a speed
// it has none for counts 0): explained_fraction's n, for a single fit and the pair stage's.
double noise_of(const EffectData &e, const std::vector<std::size_t> &speeds);

// Upper tail probability of chi^2 with k degrees of freedom.
double chi2_sf(double chi2, double k);

}    // namespace granpen

#endif
