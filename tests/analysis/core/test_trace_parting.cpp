// core/trace_parting.h: when two pushes part, on traces of known answer (a step in the
// ratio at a known time, a one-window blip, a sign that flips, a shifted contact).
#include "trace_parting.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

using granpen::Parting;
using granpen::parting_time;
using granpen::PartingSettings;

namespace {

// a push as the presets write it: samples every 0.1 ms (50 steps of 2e-6 s), the rod 0.5 cm
// above the surface at t = 0, v0 = 100 cm/s, F = 0 before contact and a smooth rise after
struct Push {
  std::vector<double> t, z, F;
};
Push push(double contact = 5e-3, double duration = 20e-3, double v0 = 100)
{
  Push p;
  double t = 0;
  for (int i = 0; t <= duration; ++i) {
    p.t.push_back(t);
    p.z.push_back(-0.5 + v0 * t);
    p.F.push_back(t < contact - 1e-12 ? 0.0 : 1000.0 * (1 + 3e2 * (t - contact)));
    t += 1e-4;    // summed, not i * 1e-4: samples land on either side of window edges
  }
  return p;
}

// multiplies F from `from` s after the contact on by `factor`
void scale_after(Push &p, double contact, double from, double factor)
{
  for (std::size_t i = 0; i < p.t.size(); ++i)
    if (p.t[i] >= contact + from - 1e-9) p.F[i] *= factor;
}

Parting part(const Push &a, const Push &b, PartingSettings s = PartingSettings())
{
  return parting_time(a.t, a.F, b.t, b.z, b.F, s);
}

// ratios of equal sums are 1 to rounding
constexpr double ROUNDING = 1e-12;

}    // namespace

TEST(TraceParting, IdenticalPushesNeverPart)
{
  const Push a = push();
  const Parting p = part(a, a);
  EXPECT_FALSE(p.parted);
  EXPECT_DOUBLE_EQ(p.contact_a, p.contact_b);
  // 15 ms after a contact at 5 ms, in windows of 0.5 ms: 30 whole ones and the last sample's
  ASSERT_GE(p.windows.size(), 30u);
  EXPECT_LE(p.windows.size(), 31u);
  for (std::size_t k = 0; k + 1 < p.windows.size(); ++k) {
    EXPECT_EQ(p.windows[k].n_a, 5u) << "window " << k << ": every window holds 5 samples of 0.1 ms";
    EXPECT_NEAR(p.windows[k].ratio, 1.0, ROUNDING);
  }
  EXPECT_NEAR(p.largest_before, 0.0, ROUNDING);
}

TEST(TraceParting, AStepPartsAtItsTimeAndDepth)
{
  const Push b = push();
  Push a = push();
  scale_after(a, 5e-3, 2.5e-3, 1.10);
  const Parting p = part(a, b);
  ASSERT_TRUE(p.parted);
  EXPECT_NEAR(p.t_part, 2.5e-3, 1e-12);
  EXPECT_EQ(p.first, 5u);
  EXPECT_NEAR(p.windows[p.first].ratio, 1.10, 1e-9);
  // B's depth 7.5 ms after the start: -0.5 + 100 * 0.0075 (z linear in t, interpolation exact)
  EXPECT_NEAR(p.z_part, 0.25, 1e-9);
  EXPECT_NEAR(p.largest_before, 0.0, ROUNDING);
  // below the threshold the same step does not part
  Push small = push();
  scale_after(small, 5e-3, 2.5e-3, 1.02);
  const Parting q = part(small, b);
  EXPECT_FALSE(q.parted);
  EXPECT_NEAR(q.largest_before, 0.02, 1e-9);
}

TEST(TraceParting, AWideBoxLowerPartsBelowOne)
{
  const Push b = push();
  Push a = push();
  scale_after(a, 5e-3, 4e-3, 0.8);
  const Parting p = part(a, b);
  ASSERT_TRUE(p.parted);
  EXPECT_NEAR(p.t_part, 4e-3, 1e-12);
  EXPECT_LT(p.windows[p.first].ratio, 1.0);
}

TEST(TraceParting, OneWindowBlipIsNotAPartingUnlessSustainIsOne)
{
  const Push b = push();
  Push a = push();
  scale_after(a, 5e-3, 1.0e-3, 1.2);
  scale_after(a, 5e-3, 1.5e-3, 1 / 1.2);    // back to B after one window
  EXPECT_FALSE(part(a, b).parted);
  PartingSettings one;
  one.sustain = 1;
  const Parting p = part(a, b, one);
  ASSERT_TRUE(p.parted);
  EXPECT_NEAR(p.t_part, 1.0e-3, 1e-12);
}

TEST(TraceParting, AlternatingSidesDoNotPart)
{
  const Push b = push();
  Push a = push();
  for (int k = 0; k < 30; ++k) scale_after(a, 5e-3, k * 5e-4, k % 2 ? 1 / 1.05 / 1.05 : 1.05 * 1.05);
  // every window is 5% off, but never two in a row on the same side
  const Parting p = part(a, b);
  EXPECT_FALSE(p.parted);
  EXPECT_GT(p.largest_before, 0.04);
}

TEST(TraceParting, EachTraceIsReadFromItsOwnContact)
{
  // the same push with its surface 0.03 cm lower: contact 0.3 ms later (and its record
  // 0.3 ms longer, so that its last window is not cut shorter than B's), every window equal
  const Push b = push(5e-3), a = push(5.3e-3, 20.3e-3);
  const Parting p = part(a, b);
  EXPECT_NEAR(p.contact_a - p.contact_b, 3e-4, 1e-9);
  EXPECT_FALSE(p.parted);
  // equal to the rounding of the summed sample times (1e-4 added 200 times)
  EXPECT_LT(p.largest_before, 1e-6);
}

TEST(TraceParting, AWindowFinerThanTheSamplesEndsAtTheFirstGap)
{
  // windows of 1e-9 s on samples 1e-4 s apart: window 0 holds the contact sample, window 1
  // nothing, and there the comparison ends (a table as long as the samples, at most)
  const Push a = push();
  PartingSettings fine;
  fine.window = 1e-9;
  const Parting p = part(a, a, fine);
  EXPECT_EQ(p.windows.size(), 1u);
  EXPECT_FALSE(p.parted);
}

TEST(TraceParting, NoContactGivesNoWindows)
{
  Push a = push();
  const Push b = push();
  for (double &f : a.F) f = 0;
  const Parting p = part(a, b);
  EXPECT_TRUE(std::isnan(p.contact_a));
  // B's contact is still read: the caller names the trace that never touches
  EXPECT_DOUBLE_EQ(p.contact_b, granpen::contact_time(b.t, b.F));
  EXPECT_NEAR(p.contact_b, 5e-3, 1e-9);
  EXPECT_TRUE(std::isnan(granpen::contact_time(a.t, a.F)));
  EXPECT_TRUE(p.windows.empty());
  EXPECT_FALSE(p.parted);
}

TEST(TraceParting, RefusesSettingsWithoutMeaning)
{
  const Push a = push();
  PartingSettings s;
  s.window = 0;
  EXPECT_THROW(part(a, a, s), std::invalid_argument);
  s = PartingSettings();
  s.threshold = -0.1;
  EXPECT_THROW(part(a, a, s), std::invalid_argument);
  s = PartingSettings();
  s.sustain = 0;
  EXPECT_THROW(part(a, a, s), std::invalid_argument);
  std::vector<double> short_F(a.F.begin(), a.F.end() - 1);
  EXPECT_THROW(parting_time(a.t, short_F, a.t, a.z, a.F), std::invalid_argument);
}
