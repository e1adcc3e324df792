// compute flow/azimuthal on constructed configurations with known answers:
// rigid translation and rotation, radial expansion, the shear v_z = a r, an FCC
// lattice's Voronoi packing. Runs under 1 and 2 MPI ranks.
#include "lmp_session.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace {

// 16 x 16 x 16 grains on a 0.5 cm simple-cubic lattice in a fully periodic 8 cm box
void sc_box(LmpSession &s)
{
  s.cmds({"units cgs", "atom_style sphere", "atom_modify map array", "boundary p p p",
          "newton off", "comm_modify vel yes", "region box block 0 8 0 8 0 8 units box",
          "create_box 1 box", "lattice sc 0.5 origin 0.5 0.5 0.5", "create_atoms 1 box",
          "set type 1 diameter 0.4", "set type 1 density 3.0", "pair_style zero 1.0",
          "pair_coeff * *", "neighbor 0.1 bin"});
}

const char *FLOW = "compute flow all flow/azimuthal axis 4.0 4.0 rbin 0.5 rmax 3.5 zbin 1.0";

double cell(LmpSession &s, int row, int col)
{
  auto a = (double **) lammps_extract_compute(s.lmp, "flow", LMP_STYLE_GLOBAL, LMP_TYPE_ARRAY);
  return a[row][col];
}

int rows(LmpSession &s) { return 7 * 8; }

// mass-weighted mean over the atoms of bin (ir, iz) of f(r), from gathered positions
template <typename F> double bin_mean(LmpSession &s, int ir, int iz, F f)
{
  auto x = s.gather("x", 3);
  double sum = 0.0, n = 0.0;
  for (size_t i = 0; i < x.size(); i += 3) {
    const double r = std::hypot(x[i] - 4.0, x[i + 1] - 4.0);
    if (r >= 3.5 || (int) (r / 0.5) != ir || (int) (x[i + 2] / 1.0) != iz) continue;
    sum += f(r);
    n += 1.0;
  }
  return n > 0 ? sum / n : 0.0;
}

}    // namespace

TEST(FlowAzimuthal, RigidTranslationAlongTheAxis)
{
  LmpSession s;
  sc_box(s);
  s.cmds({"velocity all set 0 0 -3 units box", FLOW, "run 0"});
  int filled = 0;
  for (int b = 0; b < rows(s); ++b) {
    if (cell(s, b, 2) == 0.0) continue;
    ++filled;
    EXPECT_NEAR(cell(s, b, 7), -3.0, 1e-12);
    EXPECT_NEAR(cell(s, b, 6), 0.0, 1e-14);
    EXPECT_NEAR(cell(s, b, 8), 0.0, 1e-14);
    EXPECT_NEAR(cell(s, b, 9), 0.0, 1e-12);    // no fluctuation
    EXPECT_NEAR(cell(s, b, 11), 0.0, 1e-12);   // no shear
  }
  EXPECT_EQ(filled, rows(s));
}

TEST(FlowAzimuthal, RigidRotationAndRadialExpansion)
{
  const double w = 5.0, a = 2.0;
  LmpSession s;
  sc_box(s);
  s.cmds({"variable vx atom " + std::to_string(-w) + "*(y-4.0)+" + std::to_string(a) + "*(x-4.0)",
          "variable vy atom " + std::to_string(w) + "*(x-4.0)+" + std::to_string(a) + "*(y-4.0)",
          "velocity all set v_vx v_vy 0.0 units box", FLOW, "run 0"});
  for (int iz : {0, 3}) {
    for (int ir = 0; ir < 7; ++ir) {
      const int b = iz * 7 + ir;
      const double rbar = bin_mean(s, ir, iz, [](double r) { return r; });
      const double r2bar = bin_mean(s, ir, iz, [](double r) { return r * r; });
      EXPECT_NEAR(cell(s, b, 8), w * rbar, 1e-12) << "v_theta, bin " << b;
      EXPECT_NEAR(cell(s, b, 6), a * rbar, 1e-12) << "v_r, bin " << b;
      EXPECT_NEAR(cell(s, b, 7), 0.0, 1e-14);
      // T = (<|v|^2> - |<v>|^2) / 3 with |v|^2 = (w^2 + a^2) r^2
      EXPECT_NEAR(cell(s, b, 9), (w * w + a * a) * (r2bar - rbar * rbar) / 3.0, 1e-10);
      // v_r = a r: dvr/dr = a, so gammadot = a / sqrt(2) (rotation adds no strain rate here)
      EXPECT_NEAR(cell(s, b, 11), a / std::sqrt(2.0), 1e-10) << "bin " << b;
    }
  }
}

TEST(FlowAzimuthal, ShearVzProportionalToRadius)
{
  const double a = 4.0;
  LmpSession s;
  sc_box(s);
  s.cmds({"variable vz atom " + std::to_string(a) + "*sqrt((x-4.0)^2+(y-4.0)^2)",
          "velocity all set 0.0 0.0 v_vz units box", FLOW, "run 0"});
  for (int b = 0; b < rows(s); ++b) {
    ASSERT_GT(cell(s, b, 2), 0.0);
    EXPECT_NEAR(cell(s, b, 11), a / std::sqrt(2.0), 1e-10) << "bin " << b;
  }
}

TEST(FlowAzimuthal, FccLatticeVoronoiPackingIs07405)
{
  // touching spheres on an FCC lattice: phi = pi / (3 sqrt 2) = 0.74048 exactly per cell
  LmpSession s;
  s.cmds({"units cgs", "atom_style sphere", "atom_modify map array", "boundary p p p",
          "newton off", "comm_modify vel yes", "region box block 0 8 0 8 0 8 units box",
          "create_box 1 box", "lattice fcc 0.5", "create_atoms 1 box",
          "set type 1 diameter " + std::to_string(0.5 / std::sqrt(2.0)), "set type 1 density 3.0",
          "pair_style zero 1.0", "pair_coeff * *", "neighbor 0.1 bin",
          "compute vor all voronoi/atom",
          "compute flow all flow/azimuthal axis 4.0 4.0 rbin 0.5 rmax 3.5 zbin 1.0 voronoi vor",
          "run 0"});
  const double exact = M_PI / (3.0 * std::sqrt(2.0));
  const double d = 0.5 / std::sqrt(2.0);
  // the diameter went through a decimal string: compare with the sphere actually used
  const double used = std::stod(std::to_string(d));
  const double phi = exact * std::pow(used / d, 3);
  double vol = 0.0, vbins = 0.0;
  for (int b = 0; b < rows(s); ++b) {
    ASSERT_GT(cell(s, b, 2), 0.0);
    EXPECT_NEAR(cell(s, b, 5), phi, 1e-10) << "bin " << b;
    const double r1 = cell(s, b, 0) - 0.25, r2 = r1 + 0.5;
    const double vb = M_PI * (r2 * r2 - r1 * r1) * 1.0;
    vol += cell(s, b, 4) * vb;
    vbins += vb;
  }
  // grains assigned by centre: annuli cut the lattice unevenly, so only the whole matches
  EXPECT_NEAR(vol / vbins, phi, 0.02 * phi);
}

TEST(FlowAzimuthal, FccLatticeDirectVoroPlusPlus)
{
  // the same lattice through the compute's own Voro++ tessellation
  LmpSession s;
  s.cmds({"units cgs", "atom_style sphere", "atom_modify map array", "boundary p p p",
          "newton off", "comm_modify vel yes", "region box block 0 8 0 8 0 8 units box",
          "create_box 1 box", "lattice fcc 0.5", "create_atoms 1 box",
          "set type 1 diameter " + std::to_string(0.5 / std::sqrt(2.0)), "set type 1 density 3.0",
          "pair_style zero 1.0", "pair_coeff * *", "neighbor 0.1 bin",
          "compute flow all flow/azimuthal axis 4.0 4.0 rbin 0.5 rmax 3.5 zbin 1.0 voronoi voro++",
          "run 0"});
  const double d = 0.5 / std::sqrt(2.0), used = std::stod(std::to_string(d));
  const double phi = M_PI / (3.0 * std::sqrt(2.0)) * std::pow(used / d, 3);
  for (int b = 0; b < rows(s); ++b) EXPECT_NEAR(cell(s, b, 5), phi, 1e-10) << "bin " << b;
}
