// Rod geometry: the bench scenario's rod as built for the reference data.
#include "rod_geometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

using granpen::build_rod;
using granpen::RodSpec;

TEST(RodGeometry, RingCountsFollowSpacing)
{
  EXPECT_EQ(granpen::ring_count(0.0, 0.2), 1);
  EXPECT_EQ(granpen::ring_count(0.2, 0.2), 6);
  EXPECT_EQ(granpen::ring_count(0.4, 0.2), 13);
  EXPECT_EQ(granpen::ring_count(0.6, 0.2), 19);
  EXPECT_EQ(granpen::ring_count(0.8, 0.2), 25);
}

TEST(RodGeometry, BenchRodIs764Spheres)
{
  RodSpec s;    // defaults: D 2, length 6, sphere 0.4, spacing 0.2, shell
  auto rod = build_rod(s);
  ASSERT_EQ(rod.size(), 764u);

  // 29 shell rings of 25 at r = 0.8, 0.2 apart, from z = 0.2; the disc in the lowest layer
  std::map<long, int> per_layer;
  double rmax = 0.0, zmin = 1e9, zmax = -1e9;
  for (auto &p : rod) {
    per_layer[std::lround(p.z / 0.2)]++;
    rmax = std::max(rmax, std::hypot(p.x, p.y));
    zmin = std::min(zmin, p.z);
    zmax = std::max(zmax, p.z);
  }
  EXPECT_EQ(per_layer.size(), 29u);
  EXPECT_EQ(per_layer[1], 25 + 1 + 6 + 13 + 19);
  EXPECT_EQ(per_layer[2], 25);
  EXPECT_NEAR(rmax + 0.2, 1.0, 1e-12);    // outer surface at D/2
  EXPECT_NEAR(zmin - 0.2, 0.0, 1e-12);    // tip at z = 0
  EXPECT_NEAR(zmax + 0.2, 6.0, 1e-12);    // top at the length
}

// layer is the sphere's layer counted from the tip (its height: d/2 + layer spacing), for a
// shell and a filled rod: two routes to the same index; and only layer 0 holds the disc
TEST(RodGeometry, LayerIndexIsTheHeightInSpacingsAboveTheTipLayer)
{
  for (bool filled : {false, true}) {
    RodSpec s;
    s.filled = filled;
    int nlayer0 = 0;
    for (auto &p : build_rod(s)) {
      // heights are exact multiples of 0.2 up to the rounding of d/2 + k spacing
      EXPECT_EQ(p.layer, std::lround((p.z - 0.2) / 0.2)) << "z = " << p.z;
      if (p.layer == 0) ++nlayer0;
      if (!filled && p.layer > 0) EXPECT_NEAR(std::hypot(p.x, p.y), 0.8, 1e-12) << "a disc sphere above the tip";
    }
    EXPECT_EQ(nlayer0, 25 + 1 + 6 + 13 + 19);
  }
}

TEST(RodGeometry, AlternateRingsRotatedByHalfSpacing)
{
  auto rod = build_rod(RodSpec{});
  const double half = M_PI / 25.0;
  bool found0 = false, found1 = false;
  for (auto &p : rod) {
    if (std::hypot(p.x, p.y) < 0.79) continue;
    double a = std::atan2(p.y, p.x);
    if (std::fabs(p.z - 0.2) < 1e-9 && std::fabs(a) < 1e-9) found0 = true;
    if (std::fabs(p.z - 0.4) < 1e-9 && std::fabs(a - half) < 1e-9) found1 = true;
  }
  EXPECT_TRUE(found0);
  EXPECT_TRUE(found1);
}

TEST(RodGeometry, FilledRodRepeatsTheDiscInEveryLayer)
{
  RodSpec s;
  s.filled = true;
  auto rod = build_rod(s);
  EXPECT_EQ(rod.size(), 29u * (25 + 1 + 6 + 13 + 19));
}

// the count without building is build_rod's size, for shells and filled rods of several
// sizes (two routes: a closed count against the spheres made)
TEST(RodGeometry, SphereCountIsTheBuiltRodsSize)
{
  for (bool filled : {false, true})
    for (double D : {0.6, 1.0, 2.0, 3.3})
      for (double spacing : {0.1, 0.2, 0.3}) {
        RodSpec s;
        s.diameter = D, s.spacing = spacing, s.filled = filled, s.sphere = 0.4, s.length = 3.0;
        EXPECT_EQ(granpen::rod_sphere_count(s), static_cast<double>(build_rod(s).size()))
            << "D " << D << " spacing " << spacing << " filled " << filled;
      }
}

// a spec of unbounded sphere count is refused before anything is allocated (it ended in
// std::bad_alloc in create_rod): a spacing of 1e-5 cm, a diameter of 1e7 cm, a length of 1e12
TEST(RodGeometry, RefusesARodOfTooManySpheres)
{
  RodSpec s;
  s.sphere = 1e-5, s.spacing = 1e-5, s.filled = true;
  EXPECT_GT(granpen::rod_sphere_count(s), granpen::MAX_ROD_SPHERES);
  EXPECT_THROW(build_rod(s), std::invalid_argument);
  s = RodSpec{};
  s.diameter = 1e7;
  EXPECT_THROW(build_rod(s), std::invalid_argument);
  s = RodSpec{};
  s.length = 1e12;
  EXPECT_THROW(build_rod(s), std::invalid_argument);
  s = RodSpec{};
  s.diameter = INFINITY;
  EXPECT_THROW(build_rod(s), std::invalid_argument);
  try {
    s = RodSpec{};
    s.diameter = 1e7;
    build_rod(s);
  } catch (std::invalid_argument &e) {
    EXPECT_NE(std::string(e.what()).find("more than the 10000000 a rod may have"), std::string::npos) << e.what();
  }
}

TEST(RodGeometry, RejectsImpossibleSpecs)
{
  RodSpec s;
  s.sphere = 0.0;
  EXPECT_THROW(build_rod(s), std::invalid_argument);
  s = RodSpec{};
  s.diameter = 0.3;
  EXPECT_THROW(build_rod(s), std::invalid_argument);
  s = RodSpec{};
  s.spacing = 0.5;    // gaps between spheres
  EXPECT_THROW(build_rod(s), std::invalid_argument);
  s = RodSpec{};
  s.length = 0.1;
  EXPECT_THROW(build_rod(s), std::invalid_argument);
}
