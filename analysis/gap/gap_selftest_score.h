// granpen gap: the selftest's scoring (bench/gap_selftest.sh, docs/gap-validation.md). A
// diagnosis made blind on data with one effect withheld is scored against the case's truth
// by issue 21's rules:
//   - the no-effect case: right when the verdict finds no gap (none);
//   - a library case: right when the verdict names the truth and its fresh runs shrink G_all
//     as an explained verdict must (gap_verdict.h, gap_shrinks), or names the truth among the
//     candidates it cannot tell apart (a tie); a true magnitude below the case's detection
//     limit in this data (diagnosis.json detection_limits, on the truth's side of 0; null:
//     none within the knots) may be missed (a verdict that names nothing);
//   - a below-limit case (a library effect at about half its detection limit, issue 37):
//     right when the verdict names no physical effect (none, unexplained, scale_only) or
//     names the truth (alone or in a tie), wrong when it names another effect alone or a
//     tie without the truth;
//   - an outside case (an effect the library lacks): right unless a top effect is named,
//     except the library effect that does to the force what the outside one does (as_effect)
//     at its magnitude within two of its fit's standard errors;
//   - a pair case (two library effects at once, issue 37): right when the verdict is `pair`
//     and names both; one of the two named alone (explained and G_all shrunk, or in a tie, or
//     among a scale's causes) is not a confident wrong answer, since the truth holds it: right,
//     marked as a part of the pair; a miss (a verdict that names nothing) is right only when
//     one of the two lies below its detection limit (a pair with a member the data cannot see
//     is no pair to name); any effect named that the truth lacks is wrong, a pair with one
//     included.
// How each verdict kind counts is one table (gap_selftest_score.cpp, VERDICT_READINGS), so a
// new kind of the enum is one line there; a verdict the table lacks is a named error.
#ifndef GRANPEN_GAP_SELFTEST_SCORE_H
#define GRANPEN_GAP_SELFTEST_SCORE_H

#include "gap_verdict.h"
#include "json_writer.h"    // Json

#include <string>
#include <vector>

namespace granpen {

// What a verdict kind says about the effect, as the selftest reads it.
enum class VerdictReading {
  no_gap,              // no gap beyond the noise (none)
  gap_unnamed,         // a gap, no effect named (unexplained)
  names_top,           // one effect named (explained)
  names_candidates,    // candidates that cannot be told apart (tie)
  names_scale,         // a uniform force scale, no effect named; its possible causes listed (scale_only)
  names_pair           // two effects present at once (pair)
};

// The reading of verdict v (the table's entry).
VerdictReading verdict_reading(Verdict v);
// The verdict kind written as name in diagnosis.json; false when the table has none.
bool verdict_from_name(const std::string &name, Verdict &v);

// A selftest case: its truth and, for an outside case, the library effect that stands for it.
struct SelftestCase {
  enum class Truth { none, library, outside, pair };
  Truth truth = Truth::none;
  std::string effect;            // library: the effect withheld (pair: the first)
  double magnitude = 0;          // library: its true magnitude
  bool below_limit = false;      // library: set at about half its detection limit (a miss is right)
  std::string effect2;           // pair: the second effect
  double magnitude2 = 0;         // ... and its true magnitude
  std::string as_effect;         // outside: the library effect that is a right answer ("": none)
  double as_magnitude = 0;       // ... at this magnitude
};

// The case's detection limit in the diagnosis (library cases).
struct SelftestLimit {
  enum class Kind {
    not_applicable,      // not a library case
    missing,             // the diagnosis lists no limit for the effect
    none_within_knots,   // null: not detectable within the simulated range
    value                // the limit on the truth's side of 0
  };
  Kind kind = Kind::not_applicable;
  double value = 0;
  bool truth_below = false;    // the true magnitude closer to 0 than the limit (or no limit within the knots)
};

// An optional number of diagnosis.json (null: absent).
struct MaybeNumber {
  bool known = false;
  double value = 0;
};

struct SelftestScore {
  Verdict verdict = Verdict::none;
  std::string top_effect;              // "" when null
  std::vector<std::string> tie;        // the tie's candidates, best first
  std::vector<std::string> pair;       // the pair's two effects (empty unless the verdict is pair)
  MaybeNumber magnitude;               // the top effect's fitted magnitude
  double gap_before = 0, gap_after = 0;
  MaybeNumber heldout_v0, heldout_before, heldout_after;
  MaybeNumber explained_fraction;      // the confirmation's chi^2 excess removed
  SelftestLimit limit;                 // pair: the first effect's
  SelftestLimit limit2;                // pair: the second effect's
  bool pass = false;
  // how a right answer was right (for the table): by the tie naming the truth, by a miss
  // below the detection limit; an outside case's named effect: its distance from as_magnitude
  bool tie_names_truth = false;
  bool scale_causes_hold_truth = false;    // scale_only whose causes list the truth
  bool missed_below_limit = false;
  bool pair_names_truth = false;       // pair case: the pair verdict names both
  bool names_part_of_pair = false;     // pair case: one of the two named alone (right: the truth holds it)
  bool named_as_effect = false;        // outside: the top effect is as_effect
  MaybeNumber as_effect_error;         // its fit's standard error (null: none)
};

// The score of diagnosis (diagnosis.json, parsed) against c. Throws InputError naming
// `source` and the key when a key the score needs is missing or of the wrong type, or the
// verdict is one the table lacks.
SelftestScore score_selftest(const Json &diagnosis, const SelftestCase &c, const std::string &source);

}    // namespace granpen

#endif
