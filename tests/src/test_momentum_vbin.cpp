// compute momentum/vbin on hand-placed grains with hand-set velocities and masses:
// every class count, mass, momentum and mu g M_move is known exactly (the values
// are dyadic, so every sum is exact in any order). Runs under 1 and 2 MPI ranks:
// the grains sit on both sides of the rank boundary at z = 8.
#include "lmp_session.h"

#include "compute.h"
#include "granpen_compat.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

struct Grain {
  int type;
  double x, y, z, vz, m;
  double vx, vy;
};

// v0 = 320 below: the default bounds are v0/10 = 32, v0/80 = 4, v0/320 = 1, v0/640 = 0.5.
// The axis is (4, 4) with R = 1.
const std::vector<Grain> GRAINS = {
    {1, 6.0, 4.0, 2.0, 32.0, 1.0, 0, 0},       //  1 fast (exactly v0/10)
    {1, 4.0, 6.5, 12.0, 100.0, 2.0, 0, 0},     //  2 fast
    {1, 1.0, 1.0, 15.0, 40.0, 0.5, 5, -3},     //  3 fast (moving sideways too)
    {1, 6.0, 6.0, 3.0, 4.0, 1.5, 0, 0},        //  4 intermediate (exactly v0/80)
    {1, 2.0, 4.0, 9.0, 31.75, 1.0, 0, 0},      //  5 intermediate
    {1, 7.0, 7.0, 5.0, 3.5, 2.0, 0, 0},        //  6 slow
    {1, 4.0, 2.5, 10.0, 1.25, 0.75, 0, 0},     //  7 slow
    {1, 1.0, 6.0, 12.0, 2.0, 1.0, 0, 0},       //  8 slow
    {1, 6.0, 2.0, 7.5, 1.0, 1.0, 0, 0},        //  9 noise (exactly v0/320)
    {1, 2.0, 2.0, 8.5, 0.75, 3.0, 0, 0},       // 10 noise
    {1, 5.0, 5.0, 4.0, 0.5, 1.0, 0, 0},        // 11 none (exactly v0/640)
    {1, 3.0, 6.0, 11.0, -50.0, 1.0, 0, 0},     // 12 none: moving down
    {1, 7.0, 1.0, 13.0, 0.0, 1.0, 0, 0},       // 13 none: at rest
    {1, 4.5, 4.0, 6.0, 100.0, 1.0, 0, 0},      // 14 inside the cylinder (r = 0.5)
    {1, 5.0, 4.0, 9.0, 10.0, 1.0, 0, 0},       // 15 on the cylinder (r = R exactly): out
    {1, 4.0, 4.0, 1.0, 50.0, 1.0, 0, 0},       // 16 on the axis
    {3, 1.0, 4.0, 11.0, 50.0, 1.0, 0, 0},      // 17 not a grain (type 3)
};

std::string num(double v)
{
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.17g", v);
  return buf;
}

void set_vz(LmpSession &s, int id, double vz)
{
  s.cmd("set atom " + std::to_string(id) + " vz " + num(vz));
}

void build(LmpSession &s)
{
  s.cmds({"units cgs", "atom_style sphere", "atom_modify map array", "boundary p p fm",
          "region box block 0 8 0 8 0 16 units box", "create_box 3 box"});
  for (const auto &g : GRAINS)
    s.cmd("create_atoms " + std::to_string(g.type) + " single " + num(g.x) + " " + num(g.y) + " " +
          num(g.z) + " units box");
  s.cmds({"set group all diameter 0.4"});
  for (size_t i = 0; i < GRAINS.size(); i++) {
    const auto &g = GRAINS[i];
    const std::string id = std::to_string(i + 1);
    s.cmd("set atom " + id + " mass " + num(g.m));
    s.cmd("set atom " + id + " vx " + num(g.vx) + " vy " + num(g.vy) + " vz " + num(g.vz));
  }
  s.cmds({"group grains type 1", "pair_style zero 1.0", "pair_coeff * *", "neighbor 0.1 bin",
          "timestep 1e-5", "thermo_modify norm no"});
}

using Rows = std::vector<std::array<double, 3>>;

void near(double got, double want, const std::string &what)
{
  EXPECT_NEAR(got, want, 1e-12 * std::fabs(want)) << what;
}

void expect_rows(LmpSession &s, const char *id, const Rows &want)
{
  auto nrows = (int *) lammps_extract_compute(s.lmp, id, LMP_STYLE_GLOBAL, LMP_SIZE_ROWS);
  auto ncols = (int *) lammps_extract_compute(s.lmp, id, LMP_STYLE_GLOBAL, LMP_SIZE_COLS);
  ASSERT_NE(nrows, nullptr);
  ASSERT_NE(ncols, nullptr);
  ASSERT_EQ(*nrows, (int) want.size()) << id;
  ASSERT_EQ(*ncols, 3) << id;
  auto a = (double **) lammps_extract_compute(s.lmp, id, LMP_STYLE_GLOBAL, LMP_TYPE_ARRAY);
  ASSERT_NE(a, nullptr);
  const char *col[3] = {"count", "mass", "momentum"};
  for (size_t r = 0; r < want.size(); r++)
    for (int c = 0; c < 3; c++)
      near(a[r][c], want[r][c],
           std::string(id) + " row " + std::to_string(r + 1) + " " + col[c] + " on rank " +
               std::to_string(s.rank()));
}

double scalar(LmpSession &s, const char *id)
{
  auto p = (double *) lammps_extract_compute(s.lmp, id, LMP_STYLE_GLOBAL, LMP_TYPE_SCALAR);
  return p ? *p : NAN;
}

// the default classes with the axis (4, 4) and R = 1, from the table above
const Rows DEFAULT_ROWS = {{{3, 3.5, 32.0 + 200.0 + 20.0}},
                           {{2, 2.5, 6.0 + 31.75}},
                           {{3, 3.75, 7.0 + 0.9375 + 2.0}},
                           {{2, 4.0, 1.0 + 2.25}}};
const double DEFAULT_MMOVE = 3.5 + 2.5 + 3.75;

}    // namespace

TEST(ComputeMomentumVbin, DefaultClassesOutsideTheCylinder)
{
  LmpSession s;
  build(s);
  s.cmds({"fix grav grains gravity 981 vector 0 0 -1",
          "compute mom grains momentum/vbin 320 axis 4 4 rmin 1.0",
          // scalar and array invoked on the same step: one tally serves both
          "thermo_style custom step c_mom c_mom[1][3] c_mom[4][2]", "run 0"});
  expect_rows(s, "mom", DEFAULT_ROWS);
  near(scalar(s, "mom"), 0.3 * 981.0 * DEFAULT_MMOVE, "mu g M_move");

  // on two ranks each holds some of the grains (split at z = 8)
  int nprocs = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &nprocs);
  if (nprocs == 2) {
    EXPECT_GT(s.lmp->atom->nlocal, 5);
    EXPECT_LT(s.lmp->atom->nlocal, 12);
  }

  auto c = LAMMPS_NS::gp::compute_by_id(s.lmp, "mom");
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->array_flag, 1);
  EXPECT_EQ(c->extarray, 1);
  EXPECT_EQ(c->scalar_flag, 1);
  EXPECT_EQ(c->extscalar, 1);

  // a new run at the same timestep sees changed velocities: grain 12 now rises fast
  set_vz(s, 12, 50.0);
  s.cmd("run 0");
  Rows rows = DEFAULT_ROWS;
  rows[0] = {{4, 4.5, 252.0 + 50.0}};
  expect_rows(s, "mom", rows);
  near(scalar(s, "mom"), 0.3 * 981.0 * (DEFAULT_MMOVE + 1.0), "mu g M_move after set");
}

TEST(ComputeMomentumVbin, CustomThresholdsGAndMu)
{
  // bounds v0/4 = 80, v0/16 = 20, v0/128 = 2.5, v0/512 = 0.625; M_move: v_z > 2.5.
  // No fix gravity: g comes from the keyword.
  LmpSession s;
  build(s);
  s.cmds({"compute mom grains momentum/vbin 320 axis 4 4 rmin 1.0 "
          "thresholds 0.25 0.0625 0.0078125 0.001953125 g 1000 mu 0.5",
          "run 0"});
  expect_rows(s, "mom",
              {{{1, 2.0, 200.0}},
               {{3, 2.5, 32.0 + 20.0 + 31.75}},
               {{2, 3.5, 6.0 + 7.0}},
               {{4, 5.75, 0.9375 + 2.0 + 1.0 + 2.25}}});
  near(scalar(s, "mom"), 0.5 * 1000.0 * 8.0, "mu g M_move");
}

TEST(ComputeMomentumVbin, LogBins)
{
  // 4 bins of v_z/v0 from 1/512 to 1/2, i.e. v_z from 0.625 to 160 (edges about 2.5,
  // 10, 40): grain 11 sits exactly on the lowest edge (in), grain 13 exactly on the
  // highest (out of every bin, but still moving for M_move: v_z > v0/320 = 1)
  LmpSession s;
  build(s);
  set_vz(s, 3, 50.0);
  set_vz(s, 11, 0.625);
  set_vz(s, 13, 160.0);
  s.cmds({"fix grav grains gravity 981 vector 0 0 -1",
          "compute lb4 grains momentum/vbin 320 axis 4 4 rmin 1.0 logbins 4 0.001953125 0.5",
          "compute lb3 grains momentum/vbin 320 axis 4 4 rmin 1.0 logbins 3 0.001953125 0.5 "
          "mthreshold 0.0078125",
          "run 0"});
  expect_rows(s, "lb4",
              {{{2, 2.5, 200.0 + 25.0}},
               {{2, 2.0, 32.0 + 31.75}},
               {{2, 3.5, 6.0 + 7.0}},
               {{5, 6.75, 0.9375 + 2.0 + 1.0 + 2.25 + 0.625}}});
  near(scalar(s, "lb4"), 0.3 * 981.0 * (2.5 + 2.0 + 3.5 + 0.75 + 1.0 + 1.0), "lb4 mu g M_move");
  // 3 bins: edges 0.625, 3.97, 25.2, 160; M_move: v_z > v0/128 = 2.5
  expect_rows(s, "lb3",
              {{{4, 4.5, 32.0 + 200.0 + 25.0 + 31.75}},
               {{1, 1.5, 6.0}},
               {{6, 8.75, 7.0 + 0.9375 + 2.0 + 1.0 + 2.25 + 0.625}}});
  near(scalar(s, "lb3"), 0.3 * 981.0 * (4.5 + 1.5 + 2.0 + 1.0), "lb3 mu g M_move");
}

TEST(ComputeMomentumVbin, Region)
{
  // the upper half of the box (z > 8): the other rank's grains on two ranks
  LmpSession s;
  build(s);
  s.cmds({"fix grav grains gravity 981 vector 0 0 -1",
          "region top block 0 8 0 8 8 16 units box",
          "compute top grains momentum/vbin 320 region top",
          "compute top_out grains momentum/vbin 320 region top axis 4 4 rmin 1.0", "run 0"});
  // region only: grain 15 (on the cylinder) counts
  expect_rows(s, "top",
              {{{2, 2.5, 200.0 + 20.0}},
               {{2, 2.0, 31.75 + 10.0}},
               {{2, 1.75, 0.9375 + 2.0}},
               {{1, 3.0, 2.25}}});
  near(scalar(s, "top"), 0.3 * 981.0 * 6.25, "region mu g M_move");
  // region and cylinder: grain 15 does not
  expect_rows(s, "top_out",
              {{{2, 2.5, 220.0}}, {{1, 1.0, 31.75}}, {{2, 1.75, 2.9375}}, {{1, 3.0, 2.25}}});
  near(scalar(s, "top_out"), 0.3 * 981.0 * 5.25, "region+axis mu g M_move");
}

TEST(ComputeMomentumVbin, AxisRadiusAndGFromTheDrive)
{
  // a rod of D = 2 about (4, 4): R = 1 and g = 981 from fix rod/drive, no fix gravity.
  // The measured D may differ from 2 by round-off, so grain 15 (r = 1 exactly) moves down.
  LmpSession s;
  build(s);
  set_vz(s, 15, -10.0);
  s.cmds({"create_rod 2 2.0 6.0 0.4 0.2 4.0 4.0 9.0 shell density 3.0", "group rod type 2",
          "fix push rod rod/drive 100 surface 8.0 g 981",
          "compute mom grains momentum/vbin 320 drive push", "run 0"});
  expect_rows(s, "mom", DEFAULT_ROWS);
  near(scalar(s, "mom"), 0.3 * 981.0 * DEFAULT_MMOVE, "mu g M_move");
}
