// The rod's shape from its atoms (rod_shape.h): a ring of known centre and radius, whole
// and across a periodic boundary, and in two parts combined as two MPI ranks combine them.
#include "rod_shape.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace granpen;

namespace {

const double PI = 3.14159265358979323846;

struct Atoms {
  std::vector<double> x, y, z, r;
};

// 8 spheres of radius 0.2 on a ring of radius 0.8 about (cx, cy), z from 5 up; x wrapped
// into [0, period_x) when period_x > 0: an outer diameter of 2, a tip at 4.8
Atoms ring(double cx, double cy, double period_x)
{
  Atoms a;
  for (int k = 0; k < 8; ++k) {
    double px = cx + 0.8 * std::cos(k * PI / 4);
    if (period_x > 0.0) px -= period_x * std::floor(px / period_x);
    a.x.push_back(px), a.y.push_back(cy + 0.8 * std::sin(k * PI / 4));
    a.z.push_back(5.0 + 0.1 * k), a.r.push_back(0.2);
  }
  return a;
}

// the two passes over atoms [lo, hi) of each part, summed and maxed as MPI would
RodShapeXY measure(const Atoms &a, const RodImageFrame &f, const std::vector<std::size_t> &cuts)
{
  RodAxisSums total = rod_axis_start();
  for (std::size_t p = 0; p + 1 < cuts.size(); ++p) {
    RodAxisSums part = rod_axis_start();
    for (std::size_t i = cuts[p]; i < cuts[p + 1]; ++i) rod_axis_add(part, f, a.x[i], a.y[i]);
    for (int k = 0; k < 3; ++k) total.v[k] += part.v[k];
  }
  double ax, ay;
  rod_axis(total, f, ax, ay);
  RodExtent ext = rod_extent_start();
  for (std::size_t p = 0; p + 1 < cuts.size(); ++p) {
    RodExtent part = rod_extent_start();
    for (std::size_t i = cuts[p]; i < cuts[p + 1]; ++i) rod_extent_add(part, f, ax, ay, a.x[i], a.y[i], a.z[i], a.r[i]);
    for (int k = 0; k < 2; ++k) ext.v[k] = std::max(ext.v[k], part.v[k]);
  }
  return rod_shape(total, ext, f);
}

}    // namespace

// tolerances: a few ulps of the cosines and of sums of 8 numbers near 1
TEST(RodShape, RingInTheBox)
{
  const Atoms a = ring(3.0, 3.0, 0.0);
  const RodShapeXY s = measure(a, RodImageFrame{a.x[0], a.y[0], 6.0, 6.0}, {0, 8});
  EXPECT_EQ(s.count, 8.0);
  EXPECT_NEAR(s.axis_x, 3.0, 1e-12);
  EXPECT_NEAR(s.axis_y, 3.0, 1e-12);
  EXPECT_NEAR(s.diameter, 2.0, 1e-12);
  EXPECT_NEAR(s.tip, 4.8, 1e-12);
}

TEST(RodShape, RingAcrossThePeriodicBoundaryStaysWhole)
{
  // centred on x = 0.1 of a box 6 wide: half its atoms sit near x = 6
  const Atoms a = ring(0.1, 3.0, 6.0);
  for (std::size_t first : {0u, 3u, 4u}) {    // any atom as the reference
    const RodShapeXY s = measure(a, RodImageFrame{a.x[first], a.y[first], 6.0, 0.0}, {0, 8});
    EXPECT_NEAR(std::remainder(s.axis_x - 0.1, 6.0), 0.0, 1e-12) << first;
    EXPECT_NEAR(s.axis_y, 3.0, 1e-12);
    EXPECT_NEAR(s.diameter, 2.0, 1e-12);
  }
  // without the period the same atoms span the box: the raw centroid, a wide "rod"
  const RodShapeXY raw = measure(a, RodImageFrame{a.x[0], a.y[0], 0.0, 0.0}, {0, 8});
  EXPECT_GT(raw.diameter, 5.0);
}

TEST(RodShape, PartsCombineToTheWhole)
{
  const Atoms a = ring(0.1, 3.0, 6.0);
  const RodImageFrame f{a.x[5], a.y[5], 6.0, 0.0};
  const RodShapeXY whole = measure(a, f, {0, 8}), split = measure(a, f, {0, 3, 8});
  EXPECT_NEAR(split.axis_x, whole.axis_x, 1e-12);
  EXPECT_NEAR(split.diameter, whole.diameter, 1e-12);
  EXPECT_EQ(split.tip, whole.tip);
}

TEST(RodShape, NoAtomsNoShape)
{
  const RodShapeXY s = rod_shape(rod_axis_start(), rod_extent_start(), RodImageFrame{1.0, 2.0, 0.0, 0.0});
  EXPECT_EQ(s.count, 0.0);
  EXPECT_EQ(s.diameter, 0.0);
}
