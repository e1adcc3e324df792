// granpen flow / momentum kernels on synthetic frames with known answers: rigid
// translation, a simple-cubic lattice (phi from both estimators, Voronoi volume = cell
// volume), the shear v_z = s r, an exponential v_z profile, the edge average, pooling of
// frames; the momentum classes on hand-made velocities; the rod and the trace lookups;
// the parameters of the two studies from option, trace header or fallback.
#include "flow_fields.h"
#include "momentum_classes.h"
#include "momentum_study.h"
#include "param_choice.h"
#include "rod_frame.h"
#include "voronoi_volumes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

using namespace granpen;

namespace {

constexpr double PI = 3.14159265358979323846;

// grains owning their arrays
struct Grains {
  std::vector<double> x, y, z, vx, vy, vz, radius, mass, vor, sxx, syy, szz;
  void add(double px, double py, double pz, double r, double rho = 3.0)
  {
    x.push_back(px), y.push_back(py), z.push_back(pz);
    vx.push_back(0), vy.push_back(0), vz.push_back(0);
    radius.push_back(r);
    mass.push_back(rho * 4.0 / 3.0 * PI * r * r * r);
  }
  std::size_t size() const { return x.size(); }
  GrainArrays arrays(bool with_vor = false, bool with_stress = false) const
  {
    GrainArrays g;
    g.n = x.size();
    g.x = x.data(), g.y = y.data(), g.z = z.data();
    g.vx = vx.data(), g.vy = vy.data(), g.vz = vz.data();
    g.radius = radius.data(), g.mass = mass.data();
    if (with_vor) g.voronoi = vor.data();
    if (with_stress) g.sxx = sxx.data(), g.syy = syy.data(), g.szz = szz.data();
    return g;
  }
};

// simple-cubic lattice of spacing a in [0, L) x [0, L) x [0, H), first site at a/2
Grains cubic(double a, double L, double H, double r)
{
  Grains g;
  const int n = (int) std::lround(L / a), m = (int) std::lround(H / a);
  for (int k = 0; k < m; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) g.add((i + 0.5) * a, (j + 0.5) * a, (k + 0.5) * a, r);
  return g;
}

// random grains (a gas: positions only matter for the binning)
Grains random_grains(std::size_t n, double L, double H, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> ux(0.0, L), uz(0.0, H), ur(0.15, 0.25);
  Grains g;
  for (std::size_t i = 0; i < n; ++i) g.add(ux(rng), ux(rng), uz(rng), ur(rng));
  return g;
}

AxisFrame axis(double x, double y, double zref, double L)
{
  AxisFrame a;
  a.x = x, a.y = y, a.zref = zref, a.period_x = L, a.period_y = L;
  return a;
}

}    // namespace

// ---------------------------------------------------------------- grid

TEST(FlowGrid, RoundsToWholeBinsAsTheCompute)
{
  const FlowGrid g = make_flow_grid(0.0, 3.0, 0.4, -4.0, 6.0, 0.4);
  EXPECT_EQ(g.nr, 8);     // round(7.5) = 8
  EXPECT_EQ(g.nz, 25);
  EXPECT_DOUBLE_EQ(g.dr, 3.0 / 8);
  EXPECT_DOUBLE_EQ(g.dz, 0.4);
  EXPECT_THROW(make_flow_grid(0.0, 3.0, 0.0, 0, 1, 0.1), std::invalid_argument);
  EXPECT_THROW(make_flow_grid(2.0, 1.0, 0.1, 0, 1, 0.1), std::invalid_argument);
  EXPECT_THROW(make_flow_grid(0.0, 1.0, 0.1, 1, 0, 0.1), std::invalid_argument);
  EXPECT_THROW(make_flow_grid(0.0, 1.0, 5.0, 0, 1, 0.1), std::invalid_argument);
}

// ---------------------------------------------------------------- fields

TEST(FlowFields, RigidTranslationGivesUniformVzNoShearNoTemperature)
{
  const double L = 8.0, w = -37.5;
  Grains g = random_grains(6000, L, 8.0, 1);
  for (auto &v : g.vz) v = w;
  FlowAccumulator acc(make_flow_grid(0.0, 3.5, 0.5, -3.0, 3.0, 0.5));
  acc.add(g.arrays(), axis(4.0, 4.0, 4.0, L));
  const FlowFields f = acc.fields(0.4, 3.0);
  int occupied = 0;
  for (const auto &b : f.bins) {
    if (b.count == 0) continue;
    ++occupied;
    EXPECT_NEAR(b.vz, w, 1e-12 * std::fabs(w));
    EXPECT_NEAR(b.vr, 0.0, 1e-12);
    EXPECT_NEAR(b.vtheta, 0.0, 1e-12);
    EXPECT_NEAR(b.T, 0.0, 1e-9);
    EXPECT_NEAR(b.gammadot, 0.0, 1e-9);
    EXPECT_EQ(b.I, 0.0);    // no stress: p = 0, I set to 0
  }
  EXPECT_EQ(occupied, f.grid.bins());
  EXPECT_FALSE(f.have_stress);
  EXPECT_FALSE(f.have_voronoi);
}

TEST(FlowFields, LinearShearGivesTheKnownShearRate)
{
  // v_z = s r: d v_z / d r = s, every other derivative 0, so
  // gammadot = sqrt(1/2 s^2) = s / sqrt(2) (the paper's and the compute's definition).
  // On a lattice every z row of bins has the same mean radii, so d v_z / d z is 0 too
  // (random grains would give each bin its own mean radius, and v_z would vary along z).
  const double L = 8.0, s = 12.0;
  Grains g = cubic(0.25, L, 8.0, 0.1);
  for (std::size_t i = 0; i < g.size(); ++i) g.vz[i] = s * std::hypot(g.x[i] - 4.0, g.y[i] - 4.0);
  FlowAccumulator acc(make_flow_grid(0.0, 3.5, 0.5, -3.0, 3.0, 0.5));
  acc.add(g.arrays(), axis(4.0, 4.0, 4.0, L));
  const FlowFields f = acc.fields(0.4, 3.0);
  for (const auto &b : f.bins) {
    ASSERT_GT(b.count, 0);
    EXPECT_NEAR(b.gammadot, s / std::sqrt(2.0), 1e-9 * s) << "bin r " << b.r << " z " << b.z;
    EXPECT_NEAR(b.vz, s * b.rbar, 1e-9 * s);
  }
}

TEST(FlowFields, StressGivesPressureAndInertialNumber)
{
  // S_i = -p0 v_i (isotropic): p = p0 sum v_i / V_bin = p0 phi_centre; with v_z = s r,
  // I = (s / sqrt 2) d_g / sqrt(p / rho_g)
  const double L = 8.0, s = 10.0, p0 = 2.0e4, d_g = 0.4, rho = 3.0;
  Grains g = cubic(0.25, L, 8.0, 0.1);
  for (std::size_t i = 0; i < g.size(); ++i) {
    g.vz[i] = s * std::hypot(g.x[i] - 4.0, g.y[i] - 4.0);
    const double v = 4.0 / 3.0 * PI * std::pow(g.radius[i], 3);
    g.sxx.push_back(-p0 * v), g.syy.push_back(-p0 * v), g.szz.push_back(-p0 * v);
  }
  FlowAccumulator acc(make_flow_grid(0.0, 3.5, 0.5, -3.0, 3.0, 0.5));
  acc.add(g.arrays(false, true), axis(4.0, 4.0, 4.0, L));
  const FlowFields f = acc.fields(d_g, rho);
  EXPECT_TRUE(f.have_stress);
  for (const auto &b : f.bins) {
    EXPECT_NEAR(b.p, p0 * b.phi_centre, 1e-9 * p0);
    EXPECT_NEAR(b.sigma_zz, p0 * b.phi_centre, 1e-9 * p0);
    EXPECT_NEAR(b.I, s / std::sqrt(2.0) * d_g / std::sqrt(b.p / rho), 1e-9);
  }
}

TEST(FlowFields, CubicLatticePackingFromBothEstimators)
{
  // sites 0.5 cm apart, grains of radius 0.2: phi = (4/3 pi 0.2^3) / 0.5^3 = 0.26808
  const double a = 0.5, L = 8.0, r = 0.2;
  const double phi = 4.0 / 3.0 * PI * r * r * r / (a * a * a);
  Grains g = cubic(a, L, 6.0, r);
  VoronoiBox box;
  box.hi[0] = box.hi[1] = L, box.hi[2] = 10.0;
  VoronoiInfo info;
  g.vor = voronoi_volumes(g.x.data(), g.y.data(), g.z.data(), g.radius.data(), g.size(), box, nullptr, &info);
  EXPECT_EQ(info.cells, g.size());
  EXPECT_EQ(info.missing, 0u);
  EXPECT_DOUBLE_EQ(info.lo[2], 0.0);               // the box floor
  EXPECT_NEAR(info.hi[2], 5.75 + 3 * r, 1e-12);    // lid 3 radii above the top grain
  for (std::size_t i = 0; i < g.size(); ++i) {
    // every cell is the lattice cell, but the top layer's, which reach up to the lid
    const double expect = g.z[i] > 5.7 ? a * a * (a / 2 + 3 * r) : a * a * a;
    ASSERT_NEAR(g.vor[i], expect, 1e-12) << "grain " << i;
  }

  // bins well inside the lattice (z 1 to 5, tip frame zref = 3)
  FlowAccumulator acc(make_flow_grid(0.0, 3.5, 0.5, -2.0, 2.0, 1.0));
  acc.add(g.arrays(true), axis(4.0, 4.0, 3.0, L));
  const FlowFields f = acc.fields(0.4, 3.0);
  ASSERT_TRUE(f.have_voronoi);
  double vol = 0.0, wphi = 0.0;
  for (const auto &b : f.bins) {
    EXPECT_NEAR(b.phi_voronoi, phi, 1e-12);    // exactly, in every bin
    const double r1 = b.r - 0.25, r2 = b.r + 0.25, V = PI * (r2 * r2 - r1 * r1) * 1.0;
    vol += V;
    wphi += V * b.phi_centre;
  }
  // centre-assigned: bins of about a grain fluctuate with the lattice, their
  // volume-weighted mean does not (the compute's FCC test: within 2%)
  EXPECT_NEAR(wphi / vol, phi, 0.02 * phi);
  // a wide slice: a cylinder of radius 3.5 and 4 cm high
  SliceAccumulator column(SliceSpec{0.0, 3.5, -2.0, 2.0, 4.0});
  column.add(g.arrays(true), axis(4.0, 4.0, 3.0, L));
  const auto sb = column.bins();
  ASSERT_EQ(sb.size(), 1u);
  EXPECT_NEAR(sb[0].phi_voronoi, phi, 1e-12);
  EXPECT_NEAR(sb[0].phi_centre, phi, 0.02 * phi);
}

TEST(FlowFields, PoolingFramesKeepsPerFrameMeansAndMergeEqualsAdd)
{
  const double L = 8.0;
  Grains g = random_grains(5000, L, 8.0, 4);
  for (std::size_t i = 0; i < g.size(); ++i) g.vz[i] = 3.0 + 0.1 * g.z[i];
  const FlowGrid grid = make_flow_grid(0.0, 3.5, 0.5, -3.0, 3.0, 0.5);
  FlowAccumulator one(grid), two(grid), a(grid), b(grid);
  one.add(g.arrays(), axis(4, 4, 4, L));
  two.add(g.arrays(), axis(4, 4, 4, L));
  two.add(g.arrays(), axis(4, 4, 4, L));
  a.add(g.arrays(), axis(4, 4, 4, L));
  b.add(g.arrays(), axis(4, 4, 4, L));
  a.merge(b);
  const FlowFields f1 = one.fields(0.4, 3), f2 = two.fields(0.4, 3), fm = a.fields(0.4, 3);
  EXPECT_EQ(f2.frames, 2);
  for (std::size_t k = 0; k < f1.bins.size(); ++k) {
    EXPECT_DOUBLE_EQ(f2.bins[k].count, f1.bins[k].count);
    EXPECT_NEAR(f2.bins[k].phi_centre, f1.bins[k].phi_centre, 1e-14);
    EXPECT_NEAR(f2.bins[k].vz, f1.bins[k].vz, 1e-12);
    EXPECT_NEAR(f2.bins[k].gammadot, f1.bins[k].gammadot, 1e-9);
    EXPECT_EQ(fm.bins[k].count, f2.bins[k].count);
    EXPECT_NEAR(fm.bins[k].vz, f2.bins[k].vz, 1e-12);
  }
}

TEST(FlowFields, TipFrameAndPeriodicAxisImage)
{
  // a grain 0.3 cm right of an axis at x = 0.1 across the periodic boundary (x = 7.8
  // with L = 8), 0.25 below the tip at z = 5
  Grains g;
  g.add(7.8, 4.0, 4.75, 0.2);
  g.vz[0] = 1.0;
  FlowAccumulator acc(make_flow_grid(0.0, 1.0, 0.5, -1.0, 1.0, 0.5));
  acc.add(g.arrays(), axis(0.1, 4.0, 5.0, 8.0));
  const FlowFields f = acc.fields(0.4, 3.0);
  EXPECT_EQ(f.at(0, 1).count, 1.0);    // r = 0.3 in bin 0, z = -0.25 in bin 1 of -1..1
  EXPECT_NEAR(f.at(0, 1).rbar, 0.3, 1e-12);
  EXPECT_NEAR(f.at(0, 1).zbar, -0.25, 1e-12);
}

// ---------------------------------------------------------------- profiles and fits

TEST(FlowProfile, ExponentialProfileBelowTheRodRecoversLambda)
{
  // v_z = -A exp(z / lambda) below the tip (z < 0), grains on a lattice so each z bin
  // holds the same pattern: the bin means are exp(z_c / lambda) times one constant
  const double L = 8.0, lambda = 1.96, A = 80.0, tip = 7.0;
  Grains g = cubic(0.25, L, 7.0, 0.1);
  for (std::size_t i = 0; i < g.size(); ++i) g.vz[i] = -A * std::exp((g.z[i] - tip) / lambda);
  SliceAccumulator below(SliceSpec{0.0, 2.0 / 3.0, -6.0, 0.0, 0.5});
  below.add(g.arrays(), axis(4.0, 4.0, tip, L));
  std::vector<double> z, v, se;
  for (const auto &b : below.bins()) {
    ASSERT_GT(b.samples, 1);
    z.push_back(b.z), v.push_back(b.vz), se.push_back(b.vz_se);
  }
  const ExpFit fit = fit_exponential(z, v, se);
  ASSERT_TRUE(fit.ok) << fit.note;
  EXPECT_NEAR(fit.lambda, lambda, 1e-9 * lambda);
  EXPECT_LT(fit.lambda_se, 1e-9);
  EXPECT_LT(fit.A, 0.0);
  const double h = 0.25 / lambda;    // a bin of 0.5 holds 2 layers at z_c -+ 0.125
  EXPECT_NEAR(fit.A, -A * std::cosh(h / 2), 1e-6 * A);

  // noisy exact points: lambda within its error
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.02);
  std::vector<double> zz, vv, ee;
  for (double zi = -5.0; zi < 0.0; zi += 0.25) {
    zz.push_back(zi);
    vv.push_back(A * std::exp(zi / lambda) * (1.0 + noise(rng)));
    ee.push_back(0.02 * A * std::exp(zi / lambda));
  }
  const ExpFit nf = fit_exponential(zz, vv, ee);
  ASSERT_TRUE(nf.ok);
  EXPECT_NEAR(nf.lambda, lambda, 4 * nf.lambda_se);
  EXPECT_GT(nf.lambda_se, 0.0);
  EXPECT_NEAR(nf.A, A, 4 * nf.A_se);
  // too few points, no decay
  EXPECT_FALSE(fit_exponential({-1, 0}, {1, 2}).ok);
  EXPECT_FALSE(fit_exponential({-2, -1, 0}, {3, 2, 1}).ok);
}

// The local decay length: a profile of two exponentials, e-folding every 1.2 cm within 1 cm
// of the face and every 0.6 cm beyond (continuous at z = -1), sampled every 0.2 cm. Exact
// points: each window wholly on one side gives that side's lambda to rounding, a window across
// the kink lies between the two, windows are those of the points that fit whole, and a window
// with a rising part keeps its note instead of being dropped.
TEST(FlowProfile, LocalFitsFollowTheProfilesOwnDecay)
{
  const double near = 1.2, far = 0.6, A = 40.0;
  std::vector<double> z, v, se;
  for (int k = 0; k < 25; ++k) {    // z = -4.9 ... -0.1, given deepest last (the fits sort)
    const double zz = -0.1 - 0.2 * k;
    z.push_back(zz);
    v.push_back(-A * (zz > -1.0 ? std::exp(zz / near) : std::exp(-1.0 / near) * std::exp((zz + 1.0) / far)));
    se.push_back(0.0);
  }
  const double width = 0.8;    // 5 points a window
  const auto w = local_exponential_fits(z, v, se, width);
  ASSERT_EQ(w.size(), 21u);    // starts z = -4.9 ... -0.9: z_lo + 0.8 <= -0.1
  for (std::size_t i = 0; i < w.size(); ++i) {
    ASSERT_TRUE(w[i].fit.ok) << w[i].fit.note;
    EXPECT_NEAR(w[i].z_hi - w[i].z_lo, width, 1e-12);
    EXPECT_EQ(w[i].fit.n, 5u);
    if (i > 0) EXPECT_GT(w[i].z_lo, w[i - 1].z_lo);
    if (w[i].z_hi <= -1.0 + 1e-9) EXPECT_NEAR(w[i].fit.lambda, far, 1e-9 * far) << w[i].z_lo;
    else if (w[i].z_lo >= -1.0 - 1e-9) EXPECT_NEAR(w[i].fit.lambda, near, 1e-9 * near) << w[i].z_lo;
    else {
      EXPECT_GT(w[i].fit.lambda, far) << w[i].z_lo;
      EXPECT_LT(w[i].fit.lambda, near) << w[i].z_lo;
    }
  }
  EXPECT_NEAR(w.front().z_lo, -4.9, 1e-12);
  EXPECT_NEAR(w.back().z_lo, -0.9, 1e-12);
  // the single fit over all of it is one number between the two
  const ExpFit all = fit_exponential(z, v, se);
  ASSERT_TRUE(all.ok);
  EXPECT_GT(all.lambda, far);
  EXPECT_LT(all.lambda, near);
  // a rise near the face: its windows stay, not fitted, with the fit's note
  std::vector<double> up = v;
  up[2] = -20.0, up[1] = -10.0, up[0] = -5.0;    // z = -0.5, -0.3, -0.1: |v| falls towards the face
  const auto u = local_exponential_fits(z, up, se, 0.4);
  ASSERT_FALSE(u.empty());
  EXPECT_FALSE(u.back().fit.ok);    // z -0.5 to -0.1: rising towards the face
  EXPECT_NE(u.back().fit.note.find("do not decay"), std::string::npos) << u.back().fit.note;
  // no window: a width wider than the profile, or none at all
  EXPECT_TRUE(local_exponential_fits(z, v, se, 5.0).empty());
  EXPECT_TRUE(local_exponential_fits(z, v, se, 0.0).empty());
  EXPECT_TRUE(local_exponential_fits(z, v, {1.0}, 0.8).empty());    // se of another length
}

TEST(FlowProfile, SliceMeansAndStandardError)
{
  // two grains of equal mass in one bin with v_z 1 and 3: mean 2, var 1, se = 1
  Grains g;
  g.add(4.5, 4.0, 1.0, 0.2);
  g.add(3.5, 4.0, 1.2, 0.2);
  g.vz = {1.0, 3.0};
  SliceAccumulator s(SliceSpec{0.0, 1.0, 0.0, 2.0, 2.0});
  s.add(g.arrays(), axis(4.0, 4.0, 0.0, 8.0));
  const auto b = s.bins();
  ASSERT_EQ(b.size(), 1u);
  EXPECT_DOUBLE_EQ(b[0].vz, 2.0);
  EXPECT_DOUBLE_EQ(b[0].vz_se, 1.0);
  EXPECT_NEAR(b[0].T, 1.0 / 3.0, 1e-12);    // (<v^2> - <v>^2) / 3 = (5 - 4) / 3
  EXPECT_NEAR(b[0].phi_centre, 2 * 4.0 / 3.0 * PI * 0.008 / (PI * 2.0), 1e-12);
  EXPECT_THROW(SliceAccumulator(SliceSpec{1.0, 1.0, 0, 1, 1}), std::invalid_argument);
}

TEST(FlowEdge, AveragesTheBinsAtTheRodEdge)
{
  FlowFields f;
  f.grid = make_flow_grid(0.0, 2.0, 0.5, -1.0, 1.0, 0.5);
  f.bins.resize(f.grid.bins());
  for (int iz = 0; iz < 4; ++iz)
    for (int ir = 0; ir < 4; ++ir) {
      FlowBin &b = f.bins[iz * 4 + ir];
      b.r = 0.25 + 0.5 * ir, b.z = -0.75 + 0.5 * iz;
      b.mass = 1.0;
      b.I = (ir == 1 || ir == 2) && (iz == 1 || iz == 2) ? 0.1 : 9.0;
      b.phi_voronoi = 0.55;
    }
  const EdgeAverage e = edge_average(f, 1.0, 0.5, 0.5);    // r 0.75, 1.25 and z -0.25, 0.25
  EXPECT_EQ(e.bins, 4);
  EXPECT_DOUBLE_EQ(e.I, 0.1);
  EXPECT_DOUBLE_EQ(e.phi_voronoi, 0.55);
}

TEST(FlowSurface, LastDownCrossing)
{
  // v = 1 - t sampled every 0.3: crosses at 1 exactly (linear); an earlier dip below zero
  // and back up does not count; never positive, or never down: NaN
  std::vector<double> t, v;
  for (int i = 0; i <= 10; ++i) t.push_back(0.3 * i), v.push_back(1.0 - 0.3 * i);
  EXPECT_NEAR(last_down_crossing(t, v), 1.0, 1e-12);
  v[1] = -0.5;    // t = 0.3: a dip
  EXPECT_NEAR(last_down_crossing(t, v), 1.0, 1e-12);
  EXPECT_TRUE(std::isnan(last_down_crossing(t, std::vector<double>(t.size(), -1.0))));
  EXPECT_TRUE(std::isnan(last_down_crossing(t, std::vector<double>(t.size(), 2.0))));
}

// ---------------------------------------------------------------- Voronoi

TEST(Voronoi, RadicalCellsOfTwoSizesTileThePeriodicBox)
{
  // random polydisperse grains in a fully periodic box: the cells tile the box
  Grains g = random_grains(2000, 6.0, 6.0, 9);
  VoronoiBox box;
  box.hi[0] = box.hi[1] = box.hi[2] = 6.0;
  box.periodic[2] = true;
  const auto v = voronoi_volumes(g.x.data(), g.y.data(), g.z.data(), g.radius.data(), g.size(), box);
  double sum = 0.0;
  for (double c : v) sum += c;
  EXPECT_NEAR(sum, 216.0, 1e-9 * 216.0);
  // only the wanted cells
  std::vector<char> wanted(g.size(), 0);
  wanted[5] = 1;
  VoronoiInfo info;
  const auto w = voronoi_volumes(g.x.data(), g.y.data(), g.z.data(), g.radius.data(), g.size(), box, &wanted, &info);
  EXPECT_EQ(info.cells, 1u);
  EXPECT_DOUBLE_EQ(w[5], v[5]);
  EXPECT_EQ(w[6], 0.0);
  VoronoiBox bad;
  EXPECT_THROW(voronoi_volumes(g.x.data(), g.y.data(), g.z.data(), g.radius.data(), g.size(), bad), std::invalid_argument);
}

TEST(Voronoi, ObstaclesBoundTheGrainsCells)
{
  // the grains' cells among obstacles are the grains' cells of the whole tessellation (the
  // obstacles as particles), and with the obstacles' cells they tile the periodic box; the
  // grains next to an obstacle lose volume to it
  Grains g = random_grains(1500, 6.0, 6.0, 11);
  const std::size_t m = 20, n = g.size() - m;    // the last 20 act as obstacles
  VoronoiBox box;
  box.hi[0] = box.hi[1] = box.hi[2] = 6.0;
  box.periodic[2] = true;
  const auto all = voronoi_volumes(g.x.data(), g.y.data(), g.z.data(), g.radius.data(), g.size(), box);
  VoronoiInfo info;
  const auto v = voronoi_volumes_among(g.x.data(), g.y.data(), g.z.data(), g.radius.data(), n, g.x.data() + n,
                                       g.y.data() + n, g.z.data() + n, g.radius.data() + n, m, box, &info);
  ASSERT_EQ(v.size(), n);
  EXPECT_EQ(info.cells, n);
  double sum = 0.0, obstacles = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_NEAR(v[i], all[i], 1e-12 * all[i]);
    sum += v[i];
  }
  for (std::size_t i = n; i < g.size(); ++i) obstacles += all[i];
  EXPECT_NEAR(sum + obstacles, 216.0, 1e-9 * 216.0);
  const auto alone = voronoi_volumes(g.x.data(), g.y.data(), g.z.data(), g.radius.data(), n, box);
  double sum_alone = 0.0;
  for (double c : alone) sum_alone += c;
  EXPECT_NEAR(sum_alone, 216.0, 1e-9 * 216.0);    // without them the grains fill the box
}

// ---------------------------------------------------------------- rod frame

TEST(RodFrame, FindsAxisTipAndDiameterAcrossThePeriodicBoundary)
{
  // 8 rod atoms (type 2) of radius 0.2 on a ring of radius 0.8 about (0.1, 3), which
  // wraps across x = 0 of a periodic box of length 6; one grain (type 1) lower down
  std::vector<double> x, y, z, r, type;
  for (int k = 0; k < 8; ++k) {
    double px = 0.1 + 0.8 * std::cos(k * PI / 4);
    if (px < 0) px += 6.0;
    x.push_back(px), y.push_back(3.0 + 0.8 * std::sin(k * PI / 4)), z.push_back(5.0 + 0.1 * k);
    r.push_back(0.2), type.push_back(2);
  }
  x.push_back(3), y.push_back(3), z.push_back(1), r.push_back(0.2), type.push_back(1);
  const RodPosition rod = find_rod(x.data(), y.data(), z.data(), r.data(), type.data(), x.size(), 2, 6.0, 0.0);
  ASSERT_TRUE(rod.found);
  EXPECT_EQ(rod.atoms, 8u);
  EXPECT_NEAR(rod.axis_x, 0.1, 1e-12);
  EXPECT_NEAR(rod.axis_y, 3.0, 1e-12);
  EXPECT_NEAR(rod.tip, 4.8, 1e-12);
  EXPECT_NEAR(rod.diameter, 2.0, 1e-12);
  EXPECT_FALSE(find_rod(x.data(), y.data(), z.data(), r.data(), type.data(), x.size(), 3, 6, 6).found);

  std::vector<char> skip(type.size());
  for (std::size_t i = 0; i < type.size(); ++i) skip[i] = type[i] == 2;
  int nempty = 0;
  const double zs = bed_surface(x.data(), y.data(), z.data(), r.data(), skip.data(), x.size(), 0, 6, 0, 6, 1, nempty);
  EXPECT_DOUBLE_EQ(zs, 1.2);
  EXPECT_EQ(nempty, 0);
}

// ---------------------------------------------------------------- momentum

TEST(Momentum, ClassesOnHandMadeVelocities)
{
  // v0 = 320: bounds 32, 4, 1, 0.5 (exact); R = 1 about (4, 4)
  const MomentumClasses c = momentum_classes(320.0);
  EXPECT_EQ(c.bound[0], 32.0);
  EXPECT_EQ(c.bound[3], 0.5);
  EXPECT_EQ(c.vmove, 1.0);
  const std::vector<double> vz = {32.0, 31.99, 4.0, 3.99, 1.0001, 1.0, 0.50001, 0.5, -5.0, 100.0, 100.0, 7.0};
  const std::vector<int> cls = {0, 1, 1, 2, 2, 3, 3, -1, -1, 0, 0, 1};
  std::vector<double> x(vz.size(), 6.0), y(vz.size(), 4.0), m(vz.size());
  for (std::size_t i = 0; i < vz.size(); ++i) m[i] = 1.0 + i;
  x[9] = 4.5;     // inside the rod radius: not selected
  x[10] = 5.0;    // exactly at r = R: not selected (strictly r > R)
  x[11] = 0.0;    // across the periodic boundary: r = 4 - 0 -> minimum image 4 (L = 8): selected
  for (std::size_t i = 0; i < vz.size(); ++i)
    if (i < 9 || i == 11) {
      EXPECT_EQ(momentum_class(c, vz[i]), cls[i]) << "v_z " << vz[i];
    }
  const MomentumTally t = tally_momentum(c, x.data(), y.data(), vz.data(), m.data(), vz.size(), 4.0, 4.0, 1.0, 8.0, 8.0);
  EXPECT_EQ(t.selected, 10u);
  double count[4] = {0, 0, 0, 0}, mass[4] = {0, 0, 0, 0}, p[4] = {0, 0, 0, 0}, move = 0;
  for (std::size_t i = 0; i < vz.size(); ++i) {
    if (i == 9 || i == 10) continue;
    if (vz[i] > 1.0) move += m[i];
    if (cls[i] < 0) continue;
    count[cls[i]] += 1, mass[cls[i]] += m[i], p[cls[i]] += m[i] * vz[i];
  }
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(t.count[k], count[k]) << MOMENTUM_CLASS_NAMES[k];
    EXPECT_DOUBLE_EQ(t.mass[k], mass[k]);
    EXPECT_DOUBLE_EQ(t.p_up[k], p[k]);
  }
  EXPECT_EQ(t.count[0], 1.0);
  EXPECT_EQ(t.count[2], 2.0);
  EXPECT_DOUBLE_EQ(t.M_slow, m[3] + m[4]);
  EXPECT_DOUBLE_EQ(t.M_move, move);

  // user thresholds: v_move is the third one unless mthreshold is given
  const double f[4] = {0.5, 0.1, 0.01, 0.001};
  EXPECT_DOUBLE_EQ(momentum_classes(100.0, f).vmove, 1.0);
  EXPECT_DOUBLE_EQ(momentum_classes(100.0, f, 0.05).vmove, 5.0);
  const double bad[4] = {0.1, 0.2, 0.01, 0.001};
  EXPECT_THROW(momentum_classes(100.0, bad), std::invalid_argument);
  EXPECT_THROW(momentum_classes(0.0), std::invalid_argument);
}

TEST(Momentum, TraceLookupAndDragComparison)
{
  const std::vector<double> t = {0.0, 0.1, 0.2, 0.3}, z = {-0.5, 0.5, 1.0, 1.0}, F = {0, 100, 300, 500};
  EXPECT_DOUBLE_EQ(value_at(F, locate_first(t, 0.15)), 200.0);
  EXPECT_DOUBLE_EQ(value_at(F, locate_first(z, 1.0)), 300.0);    // first time the depth is reached
  EXPECT_DOUBLE_EQ(value_at(F, locate_first(z, 0.0)), 50.0);
  EXPECT_EQ(locate_first(z, 2.0), -1.0);
  EXPECT_TRUE(std::isnan(value_at(F, -1.0)));

  const std::vector<double> mugm = {0.0, 100.0, 200.0, 400.0, 800.0};
  std::vector<double> drag;
  for (double m : mugm) drag.push_back(1.25 * m + (m == 0 ? 50.0 : 0.0));
  const DragComparison d = compare_drag(mugm, drag);
  ASSERT_TRUE(d.ok) << d.note;
  EXPECT_EQ(d.n, 4u);    // mu g M = 0 left out
  EXPECT_NEAR(d.fit.b, 1.25, 1e-12);
  EXPECT_NEAR(d.fit.se_b, 0.0, 1e-12);
  EXPECT_NEAR(d.ratio_mean, 1.25, 1e-12);
  EXPECT_NEAR(d.ratio_se, 0.0, 1e-12);
  EXPECT_FALSE(compare_drag({1, 2}, {1, 2}).ok);
}

// option before trace before fallback, each origin named; NaN is "not given"
TEST(Parameters, ResolveTakesTheFirstSourceThatGivesIt)
{
  const double nan = std::nan("");
  std::string origin;
  EXPECT_EQ(resolve({2.0, 3.0}, 4.0, "default", origin), 2.0);
  EXPECT_EQ(origin, "option");
  EXPECT_EQ(resolve({nan, 3.0}, 4.0, "default", origin), 3.0);
  EXPECT_EQ(origin, "trace");
  EXPECT_EQ(resolve({nan, nan}, 4.0, "first frame", origin), 4.0);
  EXPECT_EQ(origin, "first frame");
  EXPECT_EQ(resolve({0.0, 3.0}, 4.0, "default", origin), 0.0);    // a zero option is given (mu = 0)
  EXPECT_EQ(origin, "option");
}

// momentum's parameters through the same resolve: D from the option or the trace, mu
// from option, trace or the default 0.3, dt only from option or trace, the classes the
// paper's unless thresholds are given, M_move's bound moved by mthreshold
TEST(Parameters, MomentumStudyParams)
{
  const double nan = std::nan("");
  MomentumParamSources s;
  s.v0 = 320.0, s.g = 981.0, s.D_trace = 2.0;
  MomentumParamOrigins from;
  MomentumStudyParams p = momentum_study_params(s, from);
  EXPECT_EQ(p.D, 2.0);
  EXPECT_EQ(from.D, "trace");
  EXPECT_EQ(p.mu, DEFAULT_MU);
  EXPECT_EQ(from.mu, "default");
  EXPECT_EQ(p.classes.vmove, 1.0);    // v0/320, the paper's
  EXPECT_EQ(from.classes.compare(0, 5, "paper"), 0);
  EXPECT_FALSE(p.by_time);

  s.D = {1.5, nan}, s.mu = {nan, 0.5}, s.mthreshold = 0.25;
  p = momentum_study_params(s, from);
  EXPECT_EQ(p.D, 1.5);
  EXPECT_EQ(from.D, "option");
  EXPECT_EQ(p.mu, 0.5);
  EXPECT_EQ(from.mu, "trace");
  EXPECT_EQ(p.classes.vmove, 80.0);    // 0.25 v0
  EXPECT_EQ(p.classes.bound[0], 32.0);

  const double f[4] = {0.5, 0.25, 0.125, 0.0625};
  s.thresholds = f, s.mthreshold = 0.0;
  p = momentum_study_params(s, from);
  EXPECT_EQ(p.classes.bound[0], 160.0);
  EXPECT_EQ(p.classes.vmove, 40.0);    // F3 v0
  EXPECT_EQ(from.classes, "option");

  s.by_time = true, s.push_step = 1000;
  EXPECT_THROW(momentum_study_params(s, from), std::invalid_argument);    // no dt anywhere
  s.dt = {nan, 1e-6};
  p = momentum_study_params(s, from);
  EXPECT_EQ(p.dt, 1e-6);
  EXPECT_EQ(p.push_step, 1000);
  EXPECT_EQ(from.dt, "trace");
  const double bad[4] = {0.1, 0.2, 0.01, 0.001};
  s.thresholds = bad;
  EXPECT_THROW(momentum_study_params(s, from), std::invalid_argument);
}
