// granpen gap: the library of candidate unmodelled effects. Each is a real change to the
// simulation (deck variables of in.pour, inputs/model/contact.lmp and in.push), with a
// magnitude in physical units and the reference magnitudes ("knots") at which its
// signature on the observables is simulated. Pure: no processes, no files.
#ifndef GRANPEN_GAP_EFFECTS_H
#define GRANPEN_GAP_EFFECTS_H

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
};

// The library, in a fixed order.
const std::vector<Effect> &effect_library();
const Effect *find_effect(const std::string &name);

// A number as the decks and folder names get it: %.6g, no trailing noise.
std::string deck_number(double v);

// The folder (sweep) name of an effect at magnitude a, e.g. "rolling_resistance_0.1".
std::string effect_sweep_name(const Effect &e, double a);

}    // namespace granpen

#endif
