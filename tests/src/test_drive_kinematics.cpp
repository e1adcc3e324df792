// fix rod/drive kinematics, create_rod and compute bed/surface on constructed
// systems with known answers. Runs under 1 and 2 MPI ranks (the rod crosses
// the rank boundary at z = 8 on two ranks).
#include "lmp_session.h"

#include "fix_rod_drive.h"
#include "granpen_compat.h"
#include "rod_geometry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace {

const std::vector<std::string> BOX = {
    "units cgs", "atom_style sphere", "atom_modify map array", "boundary p p fm",
    "newton off", "comm_modify vel yes", "region box block 0 8 0 8 0 16 units box",
    "create_box 2 box", "pair_style gran/hertz/history 1e9 1e9 1000 1000 0.3 1",
    "pair_coeff * *", "neighbor 0.08 bin", "neigh_modify delay 0 exclude type 2 2",
    "timestep 2e-6"};

void add_rod(LmpSession &s, double ztip)
{
  s.cmd("create_rod 2 2.0 6.0 0.4 0.2 4.0 4.0 " + std::to_string(ztip) + " shell density 3.0");
  s.cmd("group rod type 2");
}

double lowest_z(LmpSession &s)
{
  auto x = s.gather("x", 3);
  double zmin = 1e30;
  for (size_t i = 2; i < x.size(); i += 3) zmin = std::min(zmin, x[i]);
  return zmin;
}

}    // namespace

TEST(CreateRod, BenchRodHas764SpheresInPlace)
{
  LmpSession s;
  s.cmds(BOX);
  add_rod(s, 8.0);
  EXPECT_EQ(s.lmp->atom->natoms, 764);
  EXPECT_NEAR(lowest_z(s) - 0.2, 8.0, 1e-12);
  auto x = s.gather("x", 3);
  double rmax = 0.0, zmax = -1e30;
  for (size_t i = 0; i < x.size(); i += 3) {
    rmax = std::max(rmax, std::hypot(x[i] - 4.0, x[i + 1] - 4.0));
    zmax = std::max(zmax, x[i + 2]);
  }
  EXPECT_NEAR(rmax + 0.2, 1.0, 1e-12);
  EXPECT_NEAR(zmax + 0.2, 14.0, 1e-12);
  auto r = s.gather("radius", 1);
  auto m = s.gather("rmass", 1);
  EXPECT_DOUBLE_EQ(r[100], 0.2);
  EXPECT_NEAR(m[100], 3.0 * 4.0 / 3.0 * M_PI * 0.008, 1e-14);
}

// shaft_type: the tip layer (the bottom disc and the ring that closes it) keeps the rod's type,
// every sphere above it takes the shaft's; the same spheres in the same places. The bench rod
// (764 spheres) has a tip layer of 64: the shell ring's 25 at radius 0.8 and the disc's rings
// of radius 0, 0.2, 0.4, 0.6 (1 + 6 + 13 + 19). A rod driven by fix rod/drive over both types
// moves as one.
TEST(CreateRod, ShaftTypeTakesEverySphereAboveTheTipLayer)
{
  LmpSession s;
  std::vector<std::string> box3 = BOX;
  std::replace(box3.begin(), box3.end(), std::string("create_box 2 box"), std::string("create_box 3 box"));
  s.cmds(box3);
  s.cmd("create_rod 2 2.0 6.0 0.4 0.2 4.0 4.0 8.0 shell density 3.0 shaft_type 3");
  ASSERT_EQ(s.lmp->atom->natoms, 764);
  granpen::RodSpec spec;    // the bench rod, as above
  const auto rod = granpen::build_rod(spec);
  const auto tip = std::count_if(rod.begin(), rod.end(), [](const granpen::RodSphere &p) { return p.layer == 0; });
  auto type = s.gather_int("type", 1);
  auto x = s.gather("x", 3);
  long ntip = 0, nshaft = 0;
  for (size_t i = 0; i < type.size(); ++i) {
    if (type[i] == 2) {
      ++ntip;
      EXPECT_NEAR(x[3 * i + 2], 8.2, 1e-12) << "a tip sphere above the tip layer";    // ztip + d/2
    } else if (type[i] == 3) {
      ++nshaft;
      EXPECT_GT(x[3 * i + 2], 8.2 + 0.1) << "a shaft sphere in the tip layer";    // a spacing up
    }
  }
  EXPECT_EQ(tip, 64);
  EXPECT_EQ(ntip, tip);
  EXPECT_EQ(ntip + nshaft, 764);
  // driven over both types at 100 cm/s for 100 steps of 2e-6 s: every sphere 0.02 cm lower
  s.cmds({"group rod type 2 3", "fix push rod rod/drive 100 surface 7.0 g 981", "run 100"});
  auto x2 = s.gather("x", 3);
  for (size_t i = 0; i < type.size(); ++i)
    EXPECT_NEAR(x2[3 * i + 2], x[3 * i + 2] - 0.02, 1e-12) << "sphere " << i << " of type " << type[i];
}

// A rod across the periodic boundary in x (axis at x = 0.1 of a box 8 wide: half its atoms
// wrapped to x near 8) is measured whole, as granpen flow's find_rod measures it: D = 2, the
// axis at x = 0.1 (an image of it), and compute rod/drag's t~ with that D. Tolerances: the
// shell's positions come from cosines, a few ulps of numbers near 1.
TEST(FixRodDrive, RodAcrossThePeriodicBoundaryIsMeasuredWhole)
{
  LmpSession s;
  s.cmds(BOX);
  s.cmd("create_rod 2 2.0 6.0 0.4 0.2 0.1 4.0 8.0 shell density 3.0");
  s.cmd("group rod type 2");
  s.cmd("fix push rod rod/drive 100 surface 9.0 g 981");
  auto *drive = static_cast<LAMMPS_NS::FixRodDrive *>(LAMMPS_NS::gp::fix_by_id(s.lmp, "push"));
  ASSERT_NE(drive, nullptr);
  EXPECT_NEAR(drive->rod_diameter(), 2.0, 1e-12);
  EXPECT_NEAR(std::remainder(drive->axis_x() - 0.1, 8.0), 0.0, 1e-12);
  EXPECT_NEAR(drive->axis_y(), 4.0, 1e-12);
  // compute rod/drag without the fix measures D the same way: depth 1 at v0 100, g 981
  s.cmds({"compute drag rod rod/drag surface 9.0 v0 100 g 981", "run 0"});
  EXPECT_NEAR(s.compute_vector("drag", 4), 1.0, 1e-12);
  EXPECT_NEAR(s.compute_vector("drag", 5), 0.01 * std::sqrt(981.0 / 2.0), 1e-12);
}

TEST(FixRodDrive, TipMovesExactlyV0T)
{
  LmpSession s;
  s.cmds(BOX);
  add_rod(s, 8.0);
  auto x0 = s.gather("x", 3);
  s.cmd("fix push rod rod/drive 100 surface 7.0 g 981");
  s.cmd("run 1500");    // t = 3e-3 s: the rod moves 0.3 cm, crossing z = 8 between ranks
  const double t = 1500 * 2e-6;
  EXPECT_DOUBLE_EQ(s.fix_vector("push", 0), t);
  EXPECT_NEAR(s.fix_vector("push", 1), (7.0 - 8.0) + 100.0 * t, 1e-12);
  EXPECT_DOUBLE_EQ(s.fix_vector("push", 2), 100.0);
  EXPECT_NEAR(s.fix_vector("push", 3), 100.0 * t, 1e-12);
  auto x = s.gather("x", 3);
  auto v = s.gather("v", 3);
  ASSERT_EQ(x.size(), x0.size());
  double err = 0.0;
  for (size_t i = 0; i < x.size(); i += 3) {
    err = std::max(err, std::fabs(x[i] - x0[i]) + std::fabs(x[i + 1] - x0[i + 1]));
    err = std::max(err, std::fabs(x[i + 2] - (x0[i + 2] - 100.0 * t)));
    EXPECT_EQ(v[i + 2], -100.0);
  }
  EXPECT_LT(err, 1e-12);
  // no grains: no force
  EXPECT_EQ(s.fix_vector("push", 4), 0.0);
}

TEST(FixRodDrive, LinearVelocityRampCoversItsTravel)
{
  LmpSession s;
  s.cmds(BOX);
  add_rod(s, 8.0);
  // v0 = 100 reached over 0.1 cm: t_ramp = 2 L / v0 = 2e-3 s = 1000 steps
  s.cmd("fix push rod rod/drive 100 surface 7.0 ramp 0.1");
  s.cmd("run 500");
  double t = 1e-3, a = 100.0 / 2e-3;
  EXPECT_NEAR(s.fix_vector("push", 3), 0.5 * a * t * t, 1e-12);
  EXPECT_NEAR(s.fix_vector("push", 2), a * t, 1e-9);
  s.cmd("run 1000");
  t = 3e-3;
  EXPECT_NEAR(s.fix_vector("push", 3), 0.1 + 100.0 * (t - 2e-3), 1e-12);
  EXPECT_NEAR(s.fix_vector("push", 2), 100.0, 1e-9);
  EXPECT_NEAR(lowest_z(s) - 0.2, 8.0 - s.fix_vector("push", 3), 1e-12);
}

TEST(FixRodDrive, StopsExactlyAtDepth)
{
  LmpSession s;
  s.cmds(BOX);
  add_rod(s, 8.0);
  // from 1 cm above the surface to 0.25 cm below: 1.25 cm at 100 cm/s = 6250 steps
  s.cmd("fix push rod rod/drive 100 surface 7.0 depth 0.25 at_depth stop");
  s.cmd("run 7000");
  EXPECT_NEAR(s.fix_vector("push", 1), 0.25, 1e-12);
  EXPECT_EQ(s.fix_vector("push", 2), 0.0);
  EXPECT_NEAR(lowest_z(s) - 0.2, 6.75, 1e-12);
}

TEST(FixRodDrive, HaltEndsTheRunAtDepth)
{
  LmpSession s;
  s.cmds(BOX);
  add_rod(s, 8.0);
  s.cmd("fix push rod rod/drive 100 surface 7.0 depth 0.25 at_depth halt");
  s.cmd("run 20000");
  // 1.25 cm at 100 cm/s is step 6250, or 6251 when 6250 dt rounds just short
  EXPECT_NEAR((double) s.lmp->update->ntimestep, 6250.0, 1.0);
  const auto halted_at = s.lmp->update->ntimestep;
  EXPECT_NEAR(s.fix_vector("push", 1), 0.25, 1e-12);
  // a later run is not cut short, and the rod stays put
  s.cmd("run 100");
  EXPECT_EQ(s.lmp->update->ntimestep, halted_at + 100);
  EXPECT_NEAR(s.fix_vector("push", 1), 0.25, 1e-12);
}

TEST(FixRodDrive, MountFollowsTheSpringMassSolution)
{
  // No grains: rod mass m on spring k and damper c behind an actuator that ramps up
  // with acceleration a. The lag e = A - Z obeys m e'' + c e' + k e = m a, e(0) = e'(0) = 0.
  LmpSession s;
  s.cmds(BOX);
  add_rod(s, 8.0);
  const double k = 1.0e6, c = 200.0, m = 100.0, v0 = 100.0, L = 0.5;
  s.cmd("fix push rod rod/drive 100 surface 7.0 ramp 0.5 mount 1e6 200 100");
  s.cmd("run 2000");    // t = 4e-3 s, inside the ramp (t_ramp = 1e-2 s)
  const double t = 4e-3, a = v0 * v0 / (2.0 * L);
  const double w = std::sqrt(k / m), z = c / (2.0 * std::sqrt(k * m)), wd = w * std::sqrt(1 - z * z);
  const double e = m * a / k * (1.0 - std::exp(-z * w * t) * (std::cos(wd * t) + z / std::sqrt(1 - z * z) * std::sin(wd * t)));
  // rod displacement = depth - (surface - tip height at start) = depth + 1
  const double lag = s.fix_vector("push", 3) - (s.fix_vector("push", 1) + 1.0);
  EXPECT_NEAR(s.fix_vector("push", 3), 0.5 * a * t * t, 1e-12);
  EXPECT_NEAR(lag, e, 1e-3 * m * a / k);
  // the sensor reads the spring-damper force
  const double edot = m * a / k * std::exp(-z * w * t) * (w / std::sqrt(1 - z * z)) * std::sin(wd * t);
  EXPECT_NEAR(s.fix_vector("push", 7), k * e + c * edot, 2e-3 * m * a);
}

TEST(ComputeBedSurface, SimpleCubicLatticeGivesExactSurfaceAndPacking)
{
  LmpSession s;
  s.cmds(BOX);
  // 16 x 16 x 6 grains of d = 0.4 on a 0.5 cm lattice: tops at 2.75 + 0.2
  s.cmds({"lattice sc 0.5 origin 0.5 0.5 0.5", "region bed block 0 8 0 8 0 3 units box",
          "create_atoms 1 region bed", "set type 1 diameter 0.4", "set type 1 density 3.0",
          "group grains type 1", "compute surf grains bed/surface", "run 0"});
  const double zs = 2.75 + 0.2;
  const double n = 16 * 16 * 6;
  EXPECT_EQ(s.compute_vector("surf", 2), n);
  EXPECT_NEAR(s.compute_vector("surf", 0), zs, 1e-12);
  EXPECT_NEAR(s.compute_vector("surf", 1), n * 4.0 / 3.0 * M_PI * 0.008 / (64.0 * zs), 1e-12);
  EXPECT_NEAR(s.compute_vector("surf", 3), zs, 1e-12);
  EXPECT_EQ(s.compute_vector("surf", 4), 0.0);
}

TEST(ComputeRodDrag, CountsHandPlacedContactsOnce)
{
  // a rod of two overlapping spheres A (z 7.9) and B (z 8.1), moved by no fix, and four
  // grains: g1 touches A only, g2 touches both, g3 touches B only, g4 touches nothing.
  // On two ranks A and B sit on different ranks (split at z = 8).
  for (const char *newton : {"off", "on"}) {
    LmpSession s;
    s.cmds({"units cgs", "atom_style sphere", "atom_modify map array", "boundary p p p",
            std::string("newton ") + newton, "comm_modify vel yes",
            "region box block 0 8 0 8 0 16 units box", "create_box 2 box",
            "create_atoms 2 single 4.0 4.0 7.9 units box", "create_atoms 2 single 4.0 4.0 8.1 units box",
            "create_atoms 1 single 4.0 4.35 7.9 units box", "create_atoms 1 single 4.3 4.0 8.0 units box",
            "create_atoms 1 single 4.0 3.65 8.1 units box", "create_atoms 1 single 5.0 5.0 8.0 units box",
            "set group all diameter 0.4", "set group all density 3.0", "group rod type 2",
            "group grains type 1", "pair_style gran/hertz/history 1e9 1e9 1000 1000 0.3 1",
            "pair_coeff * *", "neighbor 0.08 bin", "neigh_modify exclude type 2 2",
            "compute drag rod rod/drag surface 8.5 v0 100 g 981", "run 0"});
    EXPECT_EQ(s.compute_vector("drag", 3), 4.0) << "newton " << newton;
    EXPECT_NEAR(s.compute_vector("drag", 4), 8.5 - 7.7, 1e-12);
  }
}
