// The adaptive plan's decision (analysis/gap/gap_adaptive.h), alone: which pour-level
// candidates a diagnosis simulates after its cheap stage, on hand-made what-was-seen.
#include "gap_adaptive.h"
#include "gap_thresholds.h"

#include <gtest/gtest.h>

using namespace granpen;

namespace {

constexpr double FLOOR = GapThresholds::lr_chi2_1_p1e4, MARGIN = GapThresholds::evidence_margin;

const PurchaseDecision &decision(const std::vector<PurchaseDecision> &ds, const std::string &effect)
{
  for (const auto &d : ds)
    if (d.effect == effect) return d;
  throw std::runtime_error("no decision for " + effect);
}

}    // namespace

TEST(GapAdaptive, ACheapCandidateThatExplainsSkipsWhatCannotComeWithinTheMargin)
{
  // the mount explains with evidence 70 of a squared gap of 80: a pour-level candidate changes
  // that only by coming within the margin (64); along their signatures the gap holds 10 and 40
  CheapStageSeen seen{80.0, "measurement_chain", 70.0, true, false};
  const auto ds = decide_purchases(seen, {{"rolling_resistance", 6.0, 10.0}, {"packing", 4.0, 40.0}}, FLOOR, MARGIN);
  ASSERT_EQ(ds.size(), 2u);
  for (const auto &d : ds) {
    EXPECT_FALSE(d.simulate) << d.effect << ": " << d.why;
    EXPECT_DOUBLE_EQ(d.needed, 70.0 - MARGIN);
  }
  EXPECT_DOUBLE_EQ(decision(ds, "packing").bound, 40.0);
  EXPECT_NE(decision(ds, "packing").why.find("cannot reach 64.0"), std::string::npos) << decision(ds, "packing").why;
  // nothing pour-level simulated: the record says so with the bound
  PlanRecord r;
  r.decisions = ds;
  EXPECT_NE(plan_record_text(r).find("0 simulated, 2 skipped"), std::string::npos) << plan_record_text(r);
}

TEST(GapAdaptive, ACandidateWhoseDirectionIsUnknownIsBoundedByTheWholeGap)
{
  // no direction: it could take the whole squared gap (80), which reaches the margin of the
  // mount's 70: simulated. A bound never exceeds the whole gap, whatever a projection says
  CheapStageSeen seen{80.0, "measurement_chain", 70.0, true, false};
  const auto ds = decide_purchases(seen, {{"cohesion", 9.0, std::nullopt}, {"packing", 4.0, 500.0}}, FLOOR, MARGIN);
  EXPECT_TRUE(decision(ds, "cohesion").simulate);
  EXPECT_DOUBLE_EQ(decision(ds, "cohesion").bound, 80.0);
  EXPECT_DOUBLE_EQ(decision(ds, "packing").bound, 80.0);
  // bought cheapest first
  EXPECT_EQ(ds[0].effect, "packing");
}

TEST(GapAdaptive, NothingExplainsAndNothingCanPassStopsAfterTheCheapStage)
{
  // a squared gap of 12 at magnitude 0: no candidate's likelihood ratio can reach the least
  // threshold (15.14), whatever its direction
  CheapStageSeen seen{12.0, "rod_friction", 3.0, false, false};
  const auto ds = decide_purchases(seen, {{"cohesion", 9.0, std::nullopt}, {"friction", 5.0, std::nullopt}}, FLOOR, MARGIN);
  for (const auto &d : ds) {
    EXPECT_FALSE(d.simulate) << d.effect;
    EXPECT_DOUBLE_EQ(d.needed, FLOOR);
    EXPECT_NE(d.why.find("its threshold"), std::string::npos) << d.why;
  }
  // one more unit of squared gap above the threshold and the same candidates are bought
  seen.chi2_0 = FLOOR + 1.0;
  for (const auto &d : decide_purchases(seen, {{"cohesion", 9.0, std::nullopt}, {"friction", 5.0, std::nullopt}}, FLOOR, MARGIN))
    EXPECT_TRUE(d.simulate) << d.effect;
}

TEST(GapAdaptive, AScaleThatExplainsStillNeedsItsLookAlikes)
{
  // a uniform scale names no cause: the pour-level signatures near it are what the verdict
  // lists, so the bar is the threshold, not the scale's evidence
  CheapStageSeen seen{200.0, "force_scale", 190.0, true, true};
  const auto ds = decide_purchases(seen, {{"packing", 4.0, 30.0}, {"polydispersity", 4.0, 10.0}}, FLOOR, MARGIN);
  EXPECT_TRUE(decision(ds, "packing").simulate);
  EXPECT_DOUBLE_EQ(decision(ds, "packing").needed, FLOOR);
  EXPECT_FALSE(decision(ds, "polydispersity").simulate);
}

TEST(GapAdaptive, TheRecordSaysTheRangeAndWhatThisRunSpent)
{
  PlanRecord r;
  r.jobs = 2, r.least = 3.5, r.most = 40, r.spent = 12.3, r.wall_least = 1.9, r.wall_most = 21.1, r.wall_spent = 6.45;
  r.decides = "the bound";
  r.confirmation = {"confirm_packing_-0.1"};
  const std::string t = plan_record_text(r);
  EXPECT_NE(t.find("this run 12.3 (6.45 of wall time) within the plan's 3.5 to 40"), std::string::npos) << t;
  EXPECT_NE(t.find("--jobs 2"), std::string::npos) << t;
  EXPECT_NE(t.find("confirm_packing_-0.1"), std::string::npos) << t;
}
