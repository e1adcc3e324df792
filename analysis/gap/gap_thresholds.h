// granpen gap: every threshold a decision of the diagnosis rests on, in one table, each with
// the reason for its size. The stages read them from here (no bare literal in the logic), and
// diagnosis.json writes the table as its own object ("thresholds"), so a reader of a
// diagnosis sees the rules it was judged by. docs/gap.md, "Where each rule lives".
#ifndef GRANPEN_GAP_THRESHOLDS_H
#define GRANPEN_GAP_THRESHOLDS_H

#include <utility>
#include <vector>

namespace granpen {

struct GapThresholds {
  // a p-value below 1e-3 is significant: the omnibus chi^2 test, the null replicates' own
  // omnibus test and the residual's two tests; over the about 7 targeted tests (p = 1e-4
  // each, GapThresholds::lr_chi2_1_p1e4) the same family-wise rate
  static constexpr double significance_p = 1e-3;
  // the targeted test's threshold: the chi^2(1) quantile of p = 1e-4 (15.14), times the
  // null replicates' mean likelihood ratio when that exceeds 1 (gap_fit.h, lr_threshold)
  static constexpr double lr_chi2_1_p1e4 = 15.137;
  // a pair of effects (two magnitudes fitted jointly, gap_pairs.h) is detected by the chi^2(2)
  // quantile of the same p = 1e-4, -2 ln(1e-4) = 18.42, times its null mean over 2 when that
  // exceeds 1; beyond its best single member it must gain lr_chi2_1_p1e4 more (its second
  // magnitude passes the test a single effect passes)
  static constexpr double lr_chi2_2_p1e4 = 18.421;
  // two candidates are told apart by an evidence margin of 6: a likelihood ratio of e^3 = 20
  static constexpr double evidence_margin = 6.0;
  // a candidate explains the gap when its fit removes at least half of it: less, and more of
  // the gap is left than explained
  static constexpr double explained_min = 0.5;
  // ... and predicts the speeds left out to 0.3: a fit of every speed that explains half
  // but predicts none of a speed it has not seen is fitting that speed's noise (the
  // leave-one-speed-out fractions scatter by about 0.2 at the selftest's noise)
  static constexpr double heldout_explained_min = 0.3;
  // a quarter: the ramp case of the selftest explains 0.32 from knots 1.6 and 3.2 at its true
  // 2.4 cm; below a quarter the candidate is too weak to be worth fresh beds between knots
  static constexpr double between_knots_min_explained = 0.25;
  // 0.05 of an effect's range in the library (every knot, bought or not: EffectData::
  // library_span, same_magnitude_tolerance): two magnitudes closer than that are the same
  // simulation at the knots' noise (a fitted magnitude at a knot, a refined magnitude that
  // barely moves, a held-out magnitude equal to the fitted one are not simulated again)
  static constexpr double same_magnitude_of_range = 0.05;
  // chi^2 moves beyond its noise when by more than 3 of its standard deviations
  // sqrt(2 P) over P features (a 3-sigma change; used for the confirmation's chi^2 test and
  // for a speed whose own gap stands out of the noise)
  static constexpr double chi2_noise_sigmas = 3.0;
  // on the omnibus route fresh runs confirm when they also remove a quarter of the chi^2
  // excess: a drop beyond the noise that leaves three quarters of the gap is not the effect
  static constexpr double confirm_excess_removed = 0.25;
  // on the targeted route fresh runs confirm when the squared gap along the signature drops
  // by at least 9 (3 sigma squared: the projection's own 3-sigma change)
  static constexpr double confirm_projection_drop2 = 9.0;
  // confirming runs that leave 3 sigma along the signature leave a significant part of the
  // effect: the magnitude is refined (gap_confirm.h)
  static constexpr double refine_projection_sigmas = 3.0;
  // an explained verdict needs G_all to shrink to at most half on fresh runs (issue 21's
  // "how far it shrinks"): a confirmation that halves less is the mark of the effect's own
  // signature noise fitted, or of a look-alike's part of the gap (the synthetic friction case
  // named polydispersity, G_all 0.088 -> 0.074)
  static constexpr double gap_shrink_explained = 0.5;
  // the force scale a lab's calibration allows, a nuisance of every fit: a load cell
  // calibrated with weights is good to 1 to 2%, and the grains' density (which scales the
  // lithostatic term and the impact peak alike) is known to about as much, so together a
  // few percent. Every candidate is fitted with a uniform scale of the force free within
  // +-3%, and the gap at magnitude 0 is the baseline's within the same bound: a scale that
  // small is nobody's evidence. A scale beyond it is a finding of its own kind (scale_only),
  // never a physical effect's
  static constexpr double calibration_scale_bound = 0.03;
};

// The table as name, value pairs, in the order above (for diagnosis.json).
inline std::vector<std::pair<const char *, double>> gap_threshold_table()
{
  using T = GapThresholds;
  return {{"significance_p", T::significance_p},
          {"lr_chi2_1_p1e4", T::lr_chi2_1_p1e4},
          {"lr_chi2_2_p1e4", T::lr_chi2_2_p1e4},
          {"evidence_margin", T::evidence_margin},
          {"explained_min", T::explained_min},
          {"heldout_explained_min", T::heldout_explained_min},
          {"between_knots_min_explained", T::between_knots_min_explained},
          {"same_magnitude_of_range", T::same_magnitude_of_range},
          {"chi2_noise_sigmas", T::chi2_noise_sigmas},
          {"confirm_excess_removed", T::confirm_excess_removed},
          {"confirm_projection_drop2", T::confirm_projection_drop2},
          {"refine_projection_sigmas", T::refine_projection_sigmas},
          {"gap_shrink_explained", T::gap_shrink_explained},
          {"calibration_scale_bound", T::calibration_scale_bound}};
}

}    // namespace granpen

#endif
