// granpen gap, stage 12 (record): everything a diagnosis found, as the report writer needs
// it (gap_report.h, stage 13, a pure function of it). assemble_diagnosis makes the record once,
// from the stages' typed results, after the last of them: the one function here (with
// record_verdict, gap_verdict.cpp, the verdict's one writer) that fills a Diagnosis. It
// copies, but for G per regime before and after (gap_by_regime, from the curves before and
// the confirmation's after) and the sentences the verdict's record and a second simulation's
// record make (gap_verdict.h, gap_confirm.h).
#ifndef GRANPEN_GAP_RESULT_H
#define GRANPEN_GAP_RESULT_H

#include "gap_adaptive.h"
#include "gap_bench_rate.h"
#include "gap_confirm.h"
#include "gap_data.h"
#include "gap_fit.h"
#include "gap_limits.h"
#include "gap_pairs.h"
#include "gap_residual.h"
#include "gap_verdict.h"
#include "gap_where.h"
#include "gap_which.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace granpen {

struct Diagnosis {
  std::string scenario, real_dir;
  GapGrid grid;
  double peak_end = 0;                      // 0.35 D: the peak regime ends here
  std::vector<std::string> notes;           // warnings and choices, said in the report
  std::vector<std::string> real_files, baseline_files, corrected_files;
  // the corrected runs are corrected_files transformed by this effect at this magnitude (a
  // transform effect, effects.h: the baseline's traces filtered); "": the files as they are
  std::string corrected_effect;
  double corrected_magnitude = 0;
  // ... and the corrected runs as the verdict compared them (transformed, times 1 + the fitted
  // force scale) as the files of OUT/corrected/ (name, text; made by the confirmation, so that
  // the report only writes them); empty: corrected_files copied as they are
  std::vector<std::pair<std::string, std::string>> corrected_traces;
  double chi2_0 = 0, p_value = 1;
  // the gap against the baseline within the calibration bound (times 1 + scale_within_bound):
  // chi^2, what the confirmation's chi^2 after is judged against; G_all, beside gap_before
  double chi2_within_bound = 0, gap_within_bound = 0, scale_within_bound = 0;
  double chi2_after = 0, confirmed_fraction = 0;    // the fresh runs of the tested effect
  std::size_t nfeatures = 0;
  bool significant = false;
  bool targeted = false;                    // found by one effect's likelihood ratio, not the omnibus chi^2
  bool provisional = false;                 // --fit-only: an explained verdict not confirmed
  int n_null = 0;                           // null replicates (reference-bed subsets) of the targeted test
  int n_reference = 0;                      // reference beds (runs per speed, fewest) the fits measure against
  double proj_before = 0, proj_after = 0;   // targeted confirmation: the gap along the signature, in sigmas
  // refinement: the confirming runs left >= 3 sigma along the signature, so the magnitude was
  // corrected from them (refined_from -> magnitude) and simulated on further fresh beds
  bool refined = false;
  // an "unexplained" from the fits whose top candidate would be the answer but for its
  // interpolated signature (detected, inside its range, alone by the evidence margin, no
  // look-alike, explaining at least a quarter of the gap): the signature between two knots
  // is a blend of theirs, and a response that bends between them (a ramp moving the peak, a
  // cohesion that sets in) is not one. The confirmation then simulates the candidate at its
  // fitted magnitude on fresh beds, and the verdict is what those runs say (gap_confirm.h).
  bool between_knots = false;
  double refined_from = 0, gap_after_first = 0, proj_refined = 0;    // gap_after_first: G_all
  std::vector<Finding> where;
  std::vector<EffectFit> ranking;           // best first
  std::map<std::string, std::string> magnitude_note;    // effect -> e.g. "phi_0 shift -0.012"
  Verdict verdict = Verdict::none;           // written by gap_verdict.cpp alone (record_verdict)
  std::string top_effect;                    // "" = null; verdict tie: see tie
  std::string scale_effect;                  // scale_only: the scale candidate that explains the gap (no physical effect)
  std::optional<ScaleFinding> scale_only;    // scale_only: the scale and what can do it (gap_limits.h)
  std::vector<std::string> tie;              // "tie": the candidates (two or more) that cannot be told apart
  std::vector<std::string> pair;             // "pair": the two effects present at once (the filter first)
  std::optional<PairStage> pairs;            // the pair stage's record (gap_pairs.h): null when not entered
  std::vector<CandidateRecord> candidates;   // the verdict's record: per candidate, the rules it fell short of
  std::string tested_effect;                 // simulated for confirmation (even when downgraded)
  double magnitude = 0;
  std::string magnitude_unit;
  std::vector<SpeedCurves> speeds;
  double gap_before = 0, gap_after = 0;      // G_all (gap-metric v2), mean over speeds
  GapParts parts_before, parts_after;
  std::map<std::string, std::pair<double, double>> gap_by_regime;    // before, after
  double heldout_v0 = 0, heldout_before = 0, heldout_after = 0, heldout_magnitude = 0;    // G_all there
  int n_real_min = 0, n_sim = 0;
  // how blind: per candidate the detection limit, per pair how alike, the next measurement,
  // and the verdicts of the null replicates
  std::vector<DetectionLimit> limits;
  std::vector<LookAlike> look_alikes;
  std::vector<KnotBend> knot_bends;         // per interior knot: what it adds at this noise (cost design)
  std::optional<NextMeasurement> next;
  FalseAlarms false_alarms;
  std::optional<MeasuredFalseAlarms> measured_false_alarms;    // at the scenario's scale on real LAMMPS (gap_bench_rate.h)
  std::optional<Residual> residual;          // what the gap left over (none for a `none`)
  PlanRecord plan;                           // the plan's range, what this run spent, what it simulated and skipped and why
};

// What the record says of the inputs, and the notes of the stages before "where" (validate,
// align, features: in that order).
struct DiagnosisInputs {
  std::string scenario, real_dir;
  std::vector<std::string> real_files, notes;
  GapGrid grid;
  double peak_end = 0;                      // 0.35 D
  int n_reference = 0;                      // reference beds per speed (fewest)
  PlanRecord plan;                          // stages 2-3: the plan's range, what was simulated, skipped, spent
  std::optional<MeasuredFalseAlarms> measured_false_alarms;    // stage 1: the scenario's committed figure
};

// The record, from the stages' results: where (6), the fits (7) and their verdict (8), the
// confirmation (9), the verdict that stands (8 again, with the pair stage's outcome), how
// blind (10), the residual (11), the pair stage (11b; null when not entered: after a pair
// verdict its confirming runs are the "after").
Diagnosis assemble_diagnosis(const DiagnosisInputs &in, const WhereResult &where, const FittedCandidates &fitted,
                             const VerdictDecision &fits_verdict, const Confirmation &confirmation,
                             const VerdictDecision &verdict, const Blindness &blind, std::optional<Residual> residual,
                             std::optional<PairStage> pairs = std::nullopt);

// The decision into the record (the verdict, its effect or tie, the routes, the flags), with
// the sentences that say why appended to its notes: the one writer of d.verdict, defined
// beside decide_verdict (gap_verdict.cpp).
void record_verdict(const VerdictDecision &v, const std::vector<std::string> &notes, Diagnosis &d);

// The tie's candidates as a sentence names them: "a or b", "a, b or c".
inline std::string tie_names(const std::vector<std::string> &tie)
{
  std::string s;
  for (std::size_t i = 0; i < tie.size(); ++i) s += (i == 0 ? "" : i + 1 == tie.size() ? " or " : ", ") + tie[i];
  return s;
}

}    // namespace granpen

#endif
