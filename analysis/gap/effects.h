// granpen gap: the library of candidate unmodelled effects. Each is a real change to the
// simulation (deck variables of in.pour, inputs/model/contact.lmp and in.push), with a
// magnitude in physical units and the reference magnitudes ("knots") at which its
// signature on the observables is simulated, or, for an effect that is a linear filter on
// the force (the measurement chain), computed from the baseline's own traces. Pure: no
// processes, no files.
#ifndef GRANPEN_GAP_EFFECTS_H
#define GRANPEN_GAP_EFFECTS_H

#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace granpen {

using DeckVars = std::vector<std::pair<std::string, std::string>>;

struct Effect {
  std::string name;         // as in diagnosis.json
  std::string what;         // one line: what it changes
  std::string unit;         // of the magnitude
  bool pour_level = true;   // changes the bed (new pours) or only the push
  std::vector<double> knots;    // simulated magnitudes; 0 (the baseline) is implicit
  bool one_sided = true;        // magnitudes below 0 mean nothing (a negative ramp, mount period)
  // deck variables of the model at magnitude a: pour (and push) vars, push-only vars
  DeckVars (*set)(double a) = nullptr;
  DeckVars (*push_set)(double a) = nullptr;
  std::string pour_mu;      // friction of the pours ("" = the scenario's)
  std::string (*pour_mu_at)(double a) = nullptr;    // packing: the pour friction sets phi_0
  bool push_mu_follows = false;  // the push keeps the pour's friction (else the scenario's 0.3)
  // A push-only effect realised by a transform of the baseline's traces instead of a
  // simulation, at magnitudes up to transform_max: F at magnitude a from the baseline's F,
  // sampled every dt s (the measurement chain: a filter on the force the grains exert,
  // core/sensor_response.h, while the rod's motion does not feed back into the grains). Its
  // knots there cost nothing, and its confirming runs are the baseline pushed on fresh beds,
  // transformed. Beyond transform_max (and without a transform) it is simulated (push_set).
  std::vector<double> (*transform)(const std::vector<double> &F, double dt, double a) = nullptr;
  double transform_max = INFINITY;
  // The reference value (detection limit, look-alikes); NaN: the first knot.
  double reference = NAN;
  // The effect is a uniform scale of the measured force (a sensor's gain, the grains'
  // density): a nuisance within a lab's calibration bound, never a physical cause (gap_fit.h,
  // EffectData::is_scale; gap_verdict.h, Verdict::scale_only).
  bool uniform_scale = false;
  // Not in the default library: simulated and fitted only when --effects names it (its
  // pour-level knots would move the noise model every other case is judged by: docs/gap.md,
  // "Cohesion of a second law").
  bool opt_in = false;
};

// The effect's reference value: Effect::reference, or its first knot.
double reference_magnitude(const Effect &e);

// Whether effect e at magnitude a is realised by its transform (nothing simulated).
bool by_transform(const Effect &e, double a);

// Whether some of e's knots are simulated (not realised by its transform).
bool has_simulated_knots(const Effect &e);
// The part of e that costs nothing: e with only the knots its transform realises (the
// measurement chain up to 2 ms), its name and all else kept; e itself when every knot is
// realised so. The adaptive plan fits it first and buys the rest only when its bound says
// the knots beyond could matter (gap_adaptive.h). Null for an effect without a transform
// (and for one with simulated knots that is not the library's).
const Effect *transform_part(const Effect &e);

// The effects commonest in labs, whose detection limits a `none` reports first (report.md's
// first screen): the force's calibration and the grains' density, the grains' friction and
// packing (the calibration's numbers), the sensor's mount and the rod's surface (the rig's).
bool common_in_labs(const Effect &e);

// The library, in a fixed order.
const std::vector<Effect> &effect_library();
const Effect *find_effect(const std::string &name);

// A number as the decks and folder names get it: %.6g, no trailing noise.
std::string deck_number(double v);

// The folder (sweep) name of an effect at magnitude a, e.g. "rolling_resistance_0.1".
std::string effect_sweep_name(const Effect &e, double a);

}    // namespace granpen

#endif
