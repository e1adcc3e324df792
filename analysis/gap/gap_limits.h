// granpen gap, stage 10 (limits): how blind the diagnosis was, and what would see more.
// From the signatures already simulated (the knots) and the measured data's noise, no new
// simulation:
// - detection limits: per candidate, the smallest magnitude whose signature the targeted
//   test (gap_fit.h: the likelihood ratio against the effect's own threshold) would call
//   detected at this data's noise; and the measured runs per speed that would bring it down
//   to the effect's first reference value (the measured standard errors scale as 1/sqrt(n),
//   the reference beds' stay);
// - look-alikes: per pair of candidates, the angle between their signatures in whitened
//   feature space and how far apart their fitted predictions lie at the data's noise;
// - the next measurement: the speed and number of further runs that would best separate
//   the top two candidates, or detect the most likely undetected one;
// - the false alarms: the null replicates put through the fits' verdict.
// how_blind returns them all as the stage's result (Blindness), after the verdict that
// stands (the next measurement follows it). docs/gap.md, "How blind" and "Look-alikes".
#ifndef GRANPEN_GAP_LIMITS_H
#define GRANPEN_GAP_LIMITS_H

#include "effects.h"
#include "gap_features.h"
#include "gap_fit.h"
#include "gap_verdict.h"

#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace granpen {

// Per speed, the factor on the measured side's variance of the mean: n_now / n_then.
using NoiseFactors = std::vector<double>;

// The expected likelihood ratio of an effect present at magnitude a: the squared norm of its
// signature (less what the knots' own noise adds to it) in the fit's weights, the measured
// variances times factors, less the part of it that the fit's nuisance scale at magnitude 0
// takes (a uniform scale of the baseline within EffectData::scale_bound). The targeted test
// detects the effect half the time when this equals its threshold.
double signature_strength(const EffectData &ed, const Target &t, double a, const NoiseFactors &factors);

struct DetectionLimit {
  std::string effect, unit;
  double reference = 0;                    // the effect's reference value (reference_magnitude: its first knot unless set)
  double threshold = 0;                    // its likelihood ratio's threshold in this diagnosis
  std::optional<double> limit;             // on the reference's side of 0; none: not within the knots
  std::optional<double> limit_other_side;  // two-sided effects: the same on the other side
  std::optional<int> runs_needed;          // measured runs per speed that bring the limit to `reference`
};

// Up to this many measured runs per speed are considered for runs_needed and the next
// measurement (beyond, the reference beds' noise dominates in the bench scenario).
constexpr int MAX_RUNS_PER_SPEED = 64;

// The limit of one effect (ed its model data, fit its fit with the threshold).
DetectionLimit detection_limit(const Effect &e, const EffectData &ed, const EffectFit &fit, const Features &f);

struct LookAlike {
  std::string a, b;
  double angle_deg = 90;       // between the signatures at the first reference values, whitened
  // sigmas by which the one at its first reference value stands off the other's best
  // multiple and the fits' nuisance scale of the baseline (off_span2; |u| sin(angle) without
  // it), the smaller of the two ways round (knot noise not subtracted): what the data can
  // tell them apart by at this noise
  double separation = 0;
  bool look_alike = false;     // separation^2 below the evidence margin: not told apart here
  double fit_separation = 0;   // sigmas between their fitted predictions, each with its scale (knot noise subtracted)
};

// The two fitted predictions' squared distance in the fit's weights (measured variances
// times factors), less the knots' noise in it: the evidence the data would give between them.
// Each prediction carries its fit's nuisance scale (EffectFit::scale): (1 + sa) M_a(ma)
// against (1 + sb) M_b(mb).
double prediction_separation2(const EffectData &a, double ma, double sa, const EffectData &b, double mb, double sb,
                              const Target &t, const NoiseFactors &factors);

// A candidate below its detection limit that can pass for the named one (issue 37, section 0:
// a below-limit effect named as another). The top's fitted prediction ((1 + s) M_top(a), the
// fit's nuisance scale s) against the nearest prediction (1 + c) M_other(m) the other candidate
// makes at a magnitude m its fit could reach (magnitude_range) where the data would not detect
// it on its own (signature_strength below its threshold: below its detection limit), c within
// the calibration bound: the squared standard deviations between them (the knots' noise not
// subtracted, as the look-alikes' separation), and that m. Under the evidence margin the data
// cannot tell the top from the other at a magnitude that the other's own test could not have
// seen. NaN (and m NaN) when no such magnitude exists.
struct BelowLimitMimic {
  double separation2 = std::numeric_limits<double>::quiet_NaN();
  double magnitude = std::numeric_limits<double>::quiet_NaN();
};
BelowLimitMimic below_limit_mimic(const EffectData &top, const EffectFit &top_fit, const EffectData &other,
                                  const EffectFit &other_fit, const Target &t);

// Inner products, in the fit's weights, of a signature x, another y and the reference R (the
// baseline at magnitude 0): the squared distance of x from the span of y and a uniform scale
// of R with |c| <= bound (the fits' nuisance), min over beta and c of |x - beta y - c R|^2.
struct SpanProducts {
  double xx = 0, xy = 0, yy = 0, xR = 0, yR = 0, RR = 0;
};
double off_span2(const SpanProducts &p, double bound);

// Every pair of the ranking's candidates (in ranking order).
std::vector<LookAlike> look_alikes(const std::vector<EffectFit> &ranking, const std::map<std::string, EffectData> &data,
                                   const std::map<std::string, const Effect *> &effects, const Features &f);

// Where a knot earns its cost: knot j's ensemble against the line through its two neighbours
// (the model the fit would use were j not simulated), in the fit's weights at this data's
// noise, the knots' own noise subtracted. At the baseline of a two-sided effect it tests
// linear response through 0, i.e. whether one side could be the mirror of the other.
// A knot whose bend^2 stays under the evidence margin changes no fit the data could tell
// apart: at this noise its pours and pushes buy nothing (docs/gap.md, "Knots that earn their cost").
struct KnotBend {
  std::string effect;
  double knot = 0, left = 0, right = 0;   // the knot and its neighbours (0: the baseline)
  double bend2 = 0;        // squared standard deviations off the line, knot noise subtracted (may be < 0)
  double noise2 = 0;       // the knot noise's part, subtracted: bend2's own expected size when flat
  // bend2's standard deviation from the knots' noise (each term's d^2 of a normal d: 2 v^2 +
  // 4 mu^2 v, features taken as independent, so a lower bound): where it is as large as the
  // margin, the knots' noise hides whether the knot is needed
  double bend2_sd = 0;
  bool earns_cost = false; // bend2 >= GapThresholds::evidence_margin: the knot is needed at this noise
  bool resolved = false;   // bend2 + 2 sd < GapThresholds::evidence_margin or bend2 - 2 sd >= it: the answer is not the knots' noise
};

// Every interior knot of the effect (knots with a neighbour on both sides, the baseline of a
// two-sided effect included); none for an effect of fewer than two knots besides 0.
std::vector<KnotBend> knot_bends(const EffectData &ed, const Target &t);

struct NextMeasurement {
  std::string goal;                // "separate" (the top two) or "detect" (one undetected)
  std::vector<std::string> effects;
  double v0 = 0;
  int runs = 0;                    // further measured runs at v0
  double now = 0, after = 0;       // the squared separation, or expected likelihood ratio, now and after
  double target = 0;               // what it must reach: the evidence margin, or the threshold
  bool reaches = false;            // within MAX_RUNS_PER_SPEED runs at that speed
  double gain() const { return after - now; }
};

// The next measurement after a verdict: nothing after `explained`; after a `tie`, or an
// `unexplained` whose top two contend (either detected), the runs that bring their fitted
// predictions GapThresholds::evidence_margin apart; else (`none`, or no contest) for the undetected
// candidate nearest its threshold (the largest lr / threshold) the runs that would detect
// it at the magnitude its likelihood ratio now says (the signature whose expected ratio is
// the measured one). None when there is no such candidate.
std::optional<NextMeasurement> next_measurement(const std::vector<EffectFit> &ranking,
                                                const std::map<std::string, EffectData> &data, const Features &f,
                                                Verdict verdict);

// What can make a gap that only a uniform force scale explains (Verdict::scale_only), and the
// measurement that tells each apart: a sensor's calibration, the grains' density (both the
// same scale of F, told apart only off the rig), and every library effect whose fitted
// prediction lies within the evidence margin of the scale's (its signature within the
// look-alike angle of a uniform scale at the magnitude that would give this gap).
struct ScaleCause {
  std::string cause;             // "calibration", "density", or an effect's name
  std::string what;              // one line: what it would mean
  double magnitude = 0;          // the magnitude that gives this gap (the scale itself for the first two)
  std::string unit;
  double separation2 = -1;       // an effect: squared sigmas between its fitted prediction and the scale's (knot noise out)
  std::string tell_apart;        // the measurement that tells it from the others
  std::optional<NextMeasurement> runs;    // an effect: the measured runs that would separate it from the scale
};

struct ScaleFinding {
  double scale = 0, scale_error = 0;   // the relative scale (the confirmed magnitude when refined) and its standard error
  double bound = 0;                    // the calibration bound it exceeds (GapThresholds::calibration_scale_bound)
  std::vector<ScaleCause> causes;
};

// The finding for the scale candidate `scale` (its fit, at magnitude `magnitude`) against the
// other candidates of the ranking: besides calibration and density, each effect whose fitted
// prediction lies within the evidence margin of the scale's (a look-alike), and each detected
// on its own whose chi^2 within the calibration bound is at most the margin above the scale's.
ScaleFinding scale_finding(const EffectFit &scale, double magnitude, const std::vector<EffectFit> &ranking,
                           const std::map<std::string, EffectData> &data, const std::map<std::string, const Effect *> &effects,
                           const Features &f);

// Verdicts of the null replicates (the reference beds split into a no-effect measurement and
// its reference), each put through the verdict with thresholds calibrated on the others.
struct FalseAlarms {
  int replicates = 0, not_none = 0;
  std::map<std::string, int> verdicts;
  double rate() const { return replicates ? (double) not_none / replicates : 0.0; }
};

// The stage's result: how blind the diagnosis was.
struct Blindness {
  std::vector<DetectionLimit> limits;        // every effect of the ranking, in library order
  std::vector<LookAlike> look_alikes;        // every pair of the ranking
  std::vector<KnotBend> knot_bends;          // per interior knot: what it adds at this noise (cost design)
  std::optional<NextMeasurement> next;       // after the verdict that stands
  FalseAlarms false_alarms;                  // the null replicates through the fits' verdict
  std::optional<ScaleFinding> scale_only;    // scale_only: the scale as confirmed, and what can do it
};

// The stage, from the effects' model data, the fits' ranking (best first), the verdict that
// stands and the magnitude it names (the confirmed one: refined when it was).
Blindness how_blind(const std::vector<const Effect *> &effects, const std::map<std::string, EffectData> &data,
                    const Features &f, const std::vector<EffectFit> &ranking, const VerdictDecision &verdict,
                    double magnitude);

}    // namespace granpen

#endif
