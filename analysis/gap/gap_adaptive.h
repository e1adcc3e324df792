// granpen gap, stage 2b (adaptive plan): which pour-level candidates are worth simulating,
// given what the cheap stage saw (the baseline, the reference beds, the transforms and the
// push-only knots, fitted), and what the diagnosis cost against its plan's range. Pure: typed
// inputs, a typed decision; no files, no simulation (docs/gap.md, "The plan's cost").
//
// A candidate not yet simulated can change the verdict only if its likelihood ratio could
// reach its threshold (lambda x 15.14, lambda >= 1: 15.14 at least) and, when a cheap
// candidate already explains the gap, come within the evidence margin of that candidate's
// evidence. Its likelihood ratio is the squared gap it removes, so it is bounded by the
// squared gap along its signature's direction when that is known (`projection2`), and by
// the whole squared gap at magnitude 0 (chi2_0) when it is not: no direction can take more.
// A candidate whose bound falls short is skipped, and said so with its bound.
#ifndef GRANPEN_GAP_ADAPTIVE_H
#define GRANPEN_GAP_ADAPTIVE_H

#include <optional>
#include <string>
#include <vector>

namespace granpen {

// What the cheap stage saw: the squared gap at magnitude 0 (noise-weighted, against the
// reference beds, within the nuisance scale), and its best candidate.
struct CheapStageSeen {
  double chi2_0 = 0;
  std::string best;                 // the best cheap candidate ("" = none fitted)
  double best_evidence = 0;         // its evidence (likelihood ratio beyond the noise's)
  bool best_explains = false;       // it passes every rule of an explanation (gap_verdict.h, explains)
  bool best_is_scale = false;       // it is a uniform scale: a nuisance, never the cause (its look-alikes are needed)
};

// A pour-level candidate before its knots are simulated.
struct PourCandidate {
  std::string effect;
  double cost = 0;                          // probe pours of core time its knots cost (what the cache lacks)
  std::optional<double> projection2;        // the squared gap along its signature, when a direction is known
};

// The decision on one candidate: simulated or skipped, the bound and what it was held against.
struct PurchaseDecision {
  std::string effect;
  bool simulate = true;
  double bound = 0;        // the most its likelihood ratio can reach on this data
  double needed = 0;       // what it would have to reach to change the verdict
  double cost = 0;         // probe pours of core time
  std::string why;         // the rule, with its numbers
};

// Per pour-level candidate, in the order they are bought (least cost first: the evidence per
// CPU-second a knot buys is its inverse noise over its cost, and the pour-level knots' noise
// is alike, docs/gap.md), whether to simulate it. lr_floor: the least threshold a candidate
// can have (GapThresholds::lr_chi2_1_p1e4); margin: the evidence margin of a tie.
std::vector<PurchaseDecision> decide_purchases(const CheapStageSeen &seen, const std::vector<PourCandidate> &candidates,
                                               double lr_floor, double margin);

// The plan's record of a diagnosis (diagnosis.json "plan", report.md): its cost range in the
// plan's one unit (probe pours of core time; wall time at --jobs N from it), both as a cold
// cache runs it (the plan printed counts what the cache lacks), what decides
// where in the range a run lands, what this run spent (counted as a cold cache would have
// run it), and every purchase decision.
struct PlanRecord {
  int jobs = 1;
  double least = 0, most = 0, spent = 0;                 // probe pours of core time
  double wall_least = 0, wall_most = 0, wall_spent = 0;  // probe pours of wall time at --jobs
  double core_hours_spent = 0;                           // spent at the probe's 2026-11-22 speed
  std::string decides;                                   // what sets where a run lands
  std::vector<PurchaseDecision> decisions;
  std::vector<std::string> confirmation;                 // the confirmation's sweeps, as run
};

// report.md's sentence on the plan: the range, what this run spent, what it skipped and why.
std::string plan_record_text(const PlanRecord &r);

}    // namespace granpen

#endif
