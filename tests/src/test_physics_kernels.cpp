// The physics kernels of src/ that compute flow/azimuthal, compute momentum/vbin and
// analysis/core share (flow_bins, voronoi_cells, momentum_class_limits), each against a
// known answer worked out by hand in the test.
#include "flow_bins.h"
#include "momentum_class_limits.h"
#include "voronoi_cells.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

using namespace granpen;

namespace {
const double PI = 3.14159265358979323846;

std::string message_of(double rmax, double dr, double dz)
{
  try {
    make_flow_grid(0.0, rmax, dr, 0.0, 1.0, dz, FlowGridNames("", "rbin", "zbin"));
  } catch (std::invalid_argument &e) {
    return e.what();
  }
  return "";
}
}    // namespace

// ---------------------------------------------------------------- grid

TEST(FlowBinsGrid, WholeBinsRoundedAsLround)
{
  // 3 / 0.4 = 7.5 rounds away from zero to 8 bins of 0.375; 10 / 0.4 = 25 bins of 0.4
  const FlowGrid g = make_flow_grid(0.0, 3.0, 0.4, -4.0, 6.0, 0.4);
  EXPECT_EQ(g.nr, 8);
  EXPECT_EQ(g.nz, 25);
  EXPECT_DOUBLE_EQ(g.dr, 0.375);
  EXPECT_DOUBLE_EQ(g.dz, 0.4);
  EXPECT_EQ(whole_bin_count(0.1, 1.0, "slice dz", true), 1);    // at least one when asked
  EXPECT_EQ(whole_bin_count(0.1, 1.0, "slice dz", false), 0);
}

TEST(FlowBinsGrid, CountsCheckedAgainstTheLimitBeforeTheCast)
{
  // 4 / 1e-9 = 4e9 and 4 / 6e-10 = 6.7e9 bins: beyond int, refused as doubles with the
  // name the caller gave
  EXPECT_NE(message_of(4.0, 1e-9, 0.5).find("rbin 1e-09 gives 4e+09 bins over the range 4: more than the limit "
                                            "of 1000000 bins"),
            std::string::npos)
      << message_of(4.0, 1e-9, 0.5);
  EXPECT_NE(message_of(4.0, 6e-10, 0.5).find("rbin 6e-10 gives 6.66667e+09 bins"), std::string::npos);
  EXPECT_NE(message_of(4.0, 0.5, 1e-12).find("zbin 1e-12 gives 1e+12 bins"), std::string::npos);
  // 4000 x 1000 bins: each axis within the limit, their product not
  EXPECT_NE(message_of(4.0, 0.001, 0.001).find("give 4e+06 bins: more than the limit of 1000000"),
            std::string::npos);
  // exactly at the limit: 1000 x 1000
  EXPECT_EQ(make_flow_grid(0.0, 4.0, 0.004, 0.0, 1.0, 0.001).bins(), 1000000);
  EXPECT_THROW(make_flow_grid(0.0, 4.0, std::nan(""), 0.0, 1.0, 0.5), std::invalid_argument);
  EXPECT_THROW(make_flow_grid(0.0, INFINITY, 0.5, 0.0, 1.0, 0.5), std::invalid_argument);
  EXPECT_NE(message_of(1.0, 5.0, 0.5).find("bins larger than their range: rbin 5 over 1, zbin 0.5 over 1"),
            std::string::npos);
}

TEST(FlowBinsGrid, BinOfAPointAndTheNearestImage)
{
  const FlowGrid g = make_flow_grid(0.0, 2.0, 0.5, -1.0, 1.0, 0.5);    // 4 x 4
  EXPECT_EQ(flow_bin_of(g, 0.0, -1.0), 0);
  EXPECT_EQ(flow_bin_of(g, 1.74, 0.26), 2 * 4 + 3);
  EXPECT_EQ(flow_bin_of(g, 2.0, 0.0), -1);     // rmax is open
  EXPECT_EQ(flow_bin_of(g, 1.0, 1.0), -1);     // zhi is open
  EXPECT_EQ(flow_bin_of(g, 1.0, -1.01), -1);
  EXPECT_DOUBLE_EQ(nearest_image(7.0, 10.0), -3.0);
  EXPECT_DOUBLE_EQ(nearest_image(-6.0, 10.0), 4.0);
  EXPECT_DOUBLE_EQ(nearest_image(7.0, 0.0), 7.0);    // not periodic
}

// ---------------------------------------------------------------- bin moments

// One bin (r < 1, 0 <= z < 1: V = pi). Two grains of mass 2 and radius 0.1 at (0.5, 0),
// moving (3, 0, 5) and (-3, 0, 5): mean v = (0, 5, 0) in (r, z, theta), T = 3^2 / 3 = 3;
// stress x volume (-1, -2, -3) and (-4, -5, -6): p = 21 / (3 pi), sigma_zz = 9 / pi; cells
// of 0.01 each: phi_voronoi = 2 (4/3 pi 0.001) / 0.02.
TEST(FlowBinsMoments, TwoGrainsInOneBin)
{
  const FlowGrid g = make_flow_grid(0.0, 1.0, 1.0, 0.0, 1.0, 1.0);
  std::vector<double> sums(FLOW_NSUM, 0.0);
  const double cell = 0.01, s1[3] = {-1, -2, -3}, s2[3] = {-4, -5, -6};
  add_grain_to_bin(sums.data(), 0.5, 0.0, 0.25, 3.0, 0.0, 5.0, 0.1, 2.0, &cell, s1);
  add_grain_to_bin(sums.data(), 0.5, 0.0, 0.75, -3.0, 0.0, 5.0, 0.1, 2.0, &cell, s2);
  const std::vector<FlowBin> one = flow_bins_from_sums(g, sums.data(), 1.0, 1.0, true, 0.4, 3.0);
  ASSERT_EQ(one.size(), 1u);
  const FlowBin &b = one[0];
  const double tol = 1e-14;    // a few operations on O(1) numbers: round-off only
  EXPECT_DOUBLE_EQ(b.r, 0.5);
  EXPECT_DOUBLE_EQ(b.z, 0.5);
  EXPECT_EQ(b.count, 2.0);
  EXPECT_EQ(b.mass, 4.0);
  EXPECT_NEAR(b.vr, 0.0, tol);
  EXPECT_NEAR(b.vz, 5.0, tol);
  EXPECT_NEAR(b.vtheta, 0.0, tol);
  EXPECT_NEAR(b.T, 3.0, tol);
  EXPECT_NEAR(b.p, 21.0 / (3.0 * PI), tol);
  EXPECT_NEAR(b.sigma_zz, 9.0 / PI, tol);
  EXPECT_NEAR(b.phi_centre, 2.0 * sphere_volume(0.1) / PI, tol);
  EXPECT_NEAR(b.phi_voronoi, 2.0 * sphere_volume(0.1) / 0.02, tol);
  EXPECT_NEAR(b.rbar, 0.5, tol);
  EXPECT_NEAR(b.zbar, 0.5, tol);
  EXPECT_EQ(b.gammadot, 0.0);    // one bin: no neighbour to differentiate against

  // the same sums pooled over 2 frames (one with stress): per-frame count and phi, p over
  // the frame with stress, velocities and T unchanged; no phi_voronoi unless every frame
  const FlowBin two = flow_bins_from_sums(g, sums.data(), 2.0, 1.0, false, 0.4, 3.0)[0];
  EXPECT_EQ(two.count, 1.0);
  EXPECT_NEAR(two.phi_centre, sphere_volume(0.1) / PI, tol);
  EXPECT_NEAR(two.p, 21.0 / (3.0 * PI), tol);
  EXPECT_NEAR(two.T, 3.0, tol);
  EXPECT_EQ(two.phi_voronoi, 0.0);
}

// One ring's moments (bin_moments), as the slices of granpen flow take them: a ring
// 1 <= r < 2 of height 0.5 (volume 1.5 pi) with one grain of mass 2 and radius 0.1 at
// v_z = 4, over 2 frames without stress; an empty ring keeps its centre as rbar, zbar.
TEST(FlowBinsMoments, OneRingOverTwoFrames)
{
  EXPECT_NEAR(ring_volume(1.0, 2.0, 0.5), 1.5 * PI, 1e-15);
  std::vector<double> sums(FLOW_NSUM, 0.0);
  add_grain_to_bin(sums.data(), 0.0, 1.5, 0.1, 0.0, 0.0, 4.0, 0.1, 2.0, nullptr, nullptr);
  FlowBin m;
  m.r = 1.5, m.z = 0.25;
  bin_moments(sums.data(), ring_volume(1.0, 2.0, 0.5), 2.0, 0.0, false, m);
  const double tol = 1e-15;    // a division or two of O(1) numbers
  EXPECT_EQ(m.count, 0.5);
  EXPECT_EQ(m.mass, 1.0);
  EXPECT_NEAR(m.phi_centre, sphere_volume(0.1) / (1.5 * PI * 2.0), tol);
  EXPECT_EQ(m.vz, 4.0);
  EXPECT_EQ(m.vr, 0.0);
  EXPECT_EQ(m.T, 0.0);    // one grain: no spread about the mean
  EXPECT_EQ(m.p, 0.0);    // no stress frames
  EXPECT_EQ(m.rbar, 1.5);
  EXPECT_NEAR(m.zbar, 0.1, tol);
  FlowBin empty;
  empty.r = 1.5, empty.z = 0.25;
  const std::vector<double> none(FLOW_NSUM, 0.0);
  bin_moments(none.data(), 1.0, 2.0, 0.0, true, empty);
  EXPECT_EQ(empty.count, 0.0);
  EXPECT_EQ(empty.vz, 0.0);
  EXPECT_EQ(empty.rbar, 1.5);
  EXPECT_EQ(empty.zbar, 0.25);
}

TEST(FlowBinsMoments, RigidMotionHasNoTemperature)
{
  // every grain at the same velocity: T = 0 exactly (round-off clipped), never negative
  EXPECT_EQ(granular_temperature(3.0 * 0.1 * 0.1, 3.0, 0.1, 0.0, 0.0), 0.0);
  EXPECT_EQ(granular_temperature(0.0, 0.0, 0.0, 0.0, 0.0), 0.0);    // empty bin
}

TEST(FlowBinsMoments, InertialNumber)
{
  // I = gammadot d / sqrt(p / rho) = 10 x 0.4 / sqrt(30 / 3) = 4 / sqrt(10)
  EXPECT_NEAR(inertial_number(10.0, 30.0, 0.4, 3.0), 4.0 / std::sqrt(10.0), 1e-15);
  EXPECT_EQ(inertial_number(10.0, 0.0, 0.4, 3.0), 0.0);     // no pressure: 0, not infinity
  EXPECT_EQ(inertial_number(10.0, -1.0, 0.4, 3.0), 0.0);    // tension
}

// ---------------------------------------------------------------- shear rate

// A linear field v_r = a r + b z, v_z = c r + d z: centred and one-sided differences are
// exact when the bins along r share their mean z and those along z their mean r (the mean
// positions may sit anywhere in the bins), so every occupied bin has
// gammadot = sqrt((a - d)^2 / 2 + (b + c)^2 / 2), also next to an empty bin and at the edges;
// but a bin with no occupied neighbour along r (at the edge, next to the empty one) has no
// r-derivatives: there gammadot = sqrt(d^2 / 2 + b^2 / 2).
TEST(FlowBinsShear, LinearFieldExactEverywhere)
{
  const double a = 0.3, b = -1.2, c = 0.7, d = 2.0, p = 30.0;
  const FlowGrid g = make_flow_grid(0.0, 4.0, 1.0, -2.0, 3.0, 1.0);    // 4 x 5 bins of 1
  std::vector<FlowBin> bins((std::size_t) g.bins());
  for (int iz = 0; iz < g.nz; ++iz)
    for (int ir = 0; ir < g.nr; ++ir) {
      FlowBin &x = bins[(std::size_t) iz * g.nr + ir];
      x.rbar = g.rmin + (ir + 0.3) * g.dr + 0.02 * ir * ir;    // off the centres, unevenly
      x.zbar = g.zlo + (iz + 0.6) * g.dz - 0.03 * iz * iz;
      x.vr = a * x.rbar + b * x.zbar;
      x.vz = c * x.rbar + d * x.zbar;
      x.count = 1.0;
      x.p = p;
    }
  const int empty = 2 * g.nr + 1, alone_in_r = 2 * g.nr;
  bins[empty].count = 0.0;
  shear_rate_and_inertial_number(g, bins, 0.4, 3.0);
  const double full = std::sqrt(0.5 * (a - d) * (a - d) + 0.5 * (b + c) * (b + c));
  const double z_only = std::sqrt(0.5 * d * d + 0.5 * b * b);
  for (int k = 0; k < g.bins(); ++k) {
    const double expect = k == alone_in_r ? z_only : full;
    if (k == empty) {
      EXPECT_EQ(bins[k].gammadot, 0.0) << "the empty bin";
      EXPECT_EQ(bins[k].I, 0.0);
      continue;
    }
    // differences of O(1) values over spacings of about 1: a few ulps of round-off
    EXPECT_NEAR(bins[k].gammadot, expect, 1e-13) << "bin " << k;
    EXPECT_NEAR(bins[k].I, expect * 0.4 / std::sqrt(p / 3.0), 1e-13) << "bin " << k;
  }
}

TEST(FlowBinsShear, SimpleShearIsGammaOverRootTwo)
{
  // v_z = gamma r in two bins side by side: dvz/dr = gamma, gammadot = gamma / sqrt(2)
  const FlowGrid g = make_flow_grid(0.0, 2.0, 1.0, 0.0, 1.0, 1.0);
  std::vector<FlowBin> bins(2);
  for (int ir = 0; ir < 2; ++ir) {
    bins[ir].count = 1.0;
    bins[ir].rbar = ir + 0.5;
    bins[ir].zbar = 0.5;
    bins[ir].vz = 4.0 * bins[ir].rbar;
  }
  shear_rate_and_inertial_number(g, bins, 0.4, 3.0);
  EXPECT_NEAR(bins[0].gammadot, 4.0 / std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(bins[1].gammadot, 4.0 / std::sqrt(2.0), 1e-15);
  EXPECT_EQ(bins[0].I, 0.0);    // p = 0
}

// ---------------------------------------------------------------- Voronoi cells

// A simple cubic lattice of spacing 1 in a periodic 4 x 4 x 4 box, equal radii: every
// cell is the unit cube. The points are given as LAMMPS holds them, x[i][3] (stride 3).
TEST(VoronoiCells, CubicLatticeCellsAreUnitCubes)
{
  std::vector<double> xyz, rad;
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i) {
        xyz.push_back(i + 0.5);
        xyz.push_back(j + 0.5);
        xyz.push_back(k + 0.5);
        rad.push_back(0.3);
      }
  const std::size_t n = rad.size();
  VoronoiContainer c = {{0, 0, 0}, {4, 4, 4}, {true, true, true}};
  std::vector<double> vol(n, -1.0);
  EXPECT_EQ(voronoi_cell_volumes(c, n, &xyz[0], &xyz[1], &xyz[2], 3, rad.data(), nullptr, nullptr, vol.data()), n);
  for (std::size_t i = 0; i < n; ++i) EXPECT_NEAR(vol[i], 1.0, 1e-12) << i;    // Voro++'s round-off

  // one point left out of the tessellation: its neighbours share its cube (total 64, a
  // conservation law), and only the wanted cells are computed, the others left as given
  std::vector<char> put(n, 1), wanted(n, 1);
  put[21] = 0;
  wanted[63] = 0;    // (3.5, 3.5, 3.5): two cells from 21 in every direction, even periodic
  std::vector<double> v2(n, -1.0);
  EXPECT_EQ(voronoi_cell_volumes(c, n, &xyz[0], &xyz[1], &xyz[2], 3, rad.data(), put.data(), wanted.data(), v2.data()),
            n - 2);
  EXPECT_EQ(v2[63], -1.0);
  EXPECT_EQ(v2[21], -1.0);
  double total = 1.0;    // the cell of point 63, not computed: still a unit cube
  for (std::size_t i = 0; i < n; ++i)
    if (i != 21 && i != 63) total += v2[i];
  EXPECT_NEAR(total, 64.0, 1e-10);
}

TEST(VoronoiCells, LidThreeRadiiBeyondTheOutermostGrain)
{
  // grains z in [0.5, 3.5], largest radius 0.3: the lid at 3.5 + 0.9 = 4.4, the floor at the
  // box bottom (0.5 - 0.9 < 0); periodic x, y untouched
  VoronoiContainer c = {{0, 0, 0}, {4, 4, 10}, {true, true, false}};
  const bool lid[3] = {false, false, true};
  const double amin[3] = {0.5, 0.5, 0.5}, amax[3] = {3.5, 3.5, 3.5};
  close_container(c, lid, amin, amax, 0.3);
  EXPECT_EQ(c.lo[2], 0.0);
  EXPECT_DOUBLE_EQ(c.hi[2], 4.4);
  EXPECT_EQ(c.hi[0], 4.0);
  // grains all above the box: the side would leave no room, the container stays
  VoronoiContainer d = {{0, 0, 0}, {4, 4, 10}, {true, true, false}};
  const double above_min[3] = {0, 0, 20}, above_max[3] = {4, 4, 30};
  close_container(d, lid, above_min, above_max, 0.3);
  EXPECT_EQ(d.lo[2], 0.0);
  EXPECT_EQ(d.hi[2], 10.0);
}

// ---------------------------------------------------------------- momentum classes

TEST(MomentumClassLimits, PaperClassesOpenAndClosedEnds)
{
  // v0 = 320: bounds 32, 4, 1, 0.5 and v_move = 1, all exact (v0 divided)
  const MomentumClasses c = momentum_classes(320.0);
  EXPECT_EQ(c.bound[0], 32.0);
  EXPECT_EQ(c.bound[1], 4.0);
  EXPECT_EQ(c.bound[2], 1.0);
  EXPECT_EQ(c.bound[3], 0.5);
  EXPECT_EQ(c.vmove, 1.0);
  EXPECT_EQ(momentum_class(c, 32.0), 0);     // fast: v_z >= v0/10
  EXPECT_EQ(momentum_class(c, 31.9), 1);
  EXPECT_EQ(momentum_class(c, 4.0), 1);      // intermediate: v0/80 <= v_z
  EXPECT_EQ(momentum_class(c, 3.9), 2);
  EXPECT_EQ(momentum_class(c, 1.0), 3);      // slow: v_z > v0/320 (open)
  EXPECT_EQ(momentum_class(c, 0.51), 3);     // noise: v0/640 < v_z <= v0/320
  EXPECT_EQ(momentum_class(c, 0.5), -1);
  EXPECT_EQ(momentum_class(c, -5.0), -1);
  EXPECT_STREQ(MOMENTUM_CLASS_NAMES[2], "slow");
}

TEST(MomentumClassLimits, UserThresholdsAndMoveThreshold)
{
  const double f[MOMENTUM_NCLASS] = {0.5, 0.25, 0.125, 0.0625};
  const MomentumClasses c = momentum_classes(16.0, f);
  EXPECT_EQ(c.bound[0], 8.0);
  EXPECT_EQ(c.bound[3], 1.0);
  EXPECT_EQ(c.vmove, 2.0);                                      // f3 v0
  EXPECT_EQ(momentum_classes(16.0, f, 0.25).vmove, 4.0);        // mfrac v0
  EXPECT_EQ(momentum_classes(320.0, nullptr, 0.25).vmove, 80.0);    // the paper's classes, user v_move
  EXPECT_EQ(momentum_classes(320.0, nullptr, 0.25).bound[0], 32.0);
  const double bad[MOMENTUM_NCLASS] = {0.5, 0.5, 0.1, 0.05};
  EXPECT_THROW(momentum_classes(16.0, bad), std::invalid_argument);
  EXPECT_THROW(momentum_classes(0.0), std::invalid_argument);
  EXPECT_THROW(momentum_classes(16.0, f, -1.0), std::invalid_argument);
}

TEST(MomentumClassLimits, LogBins)
{
  // v0 = 100, 2 classes from 0.01 v0 to v0: edges 1, 10, 100; the fastest class first
  const std::vector<double> e = momentum_log_edges(100.0, 2, 0.01, 1.0);
  ASSERT_EQ(e.size(), 3u);
  EXPECT_NEAR(e[0], 1.0, 1e-14);    // 100 x 0.01: one rounding
  EXPECT_NEAR(e[1], 10.0, 1e-13);   // through pow: a few roundings
  EXPECT_EQ(e[2], 100.0);           // the top edge is v0 fmax exactly
  EXPECT_EQ(momentum_log_class(e, 50.0), 0);
  EXPECT_EQ(momentum_log_class(e, e[1]), 0);    // [edges[k], edges[k+1])
  EXPECT_EQ(momentum_log_class(e, 5.0), 1);
  EXPECT_EQ(momentum_log_class(e, e[0]), 1);
  EXPECT_EQ(momentum_log_class(e, 100.0), -1);
  EXPECT_EQ(momentum_log_class(e, 0.99), -1);
  EXPECT_THROW(momentum_log_edges(100.0, 0, 0.01, 1.0), std::invalid_argument);
  EXPECT_EQ(momentum_log_edges(100.0, MOMENTUM_MAX_LOG_CLASSES, 0.01, 1.0).size(), 10001u);
  EXPECT_THROW(momentum_log_edges(100.0, MOMENTUM_MAX_LOG_CLASSES + 1, 0.01, 1.0), std::invalid_argument);
  EXPECT_THROW(momentum_log_edges(100.0, 2, 1.0, 0.01), std::invalid_argument);
}
