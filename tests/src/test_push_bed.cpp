// Pushes into the poured tiny bed (made by the pour_tiny ctest fixture; its
// path comes in GRANPEN_TINY_BED): the drag against independent routes, the
// force before contact and with depth. (Restart and decomposition consistency
// are deck-level tests across processes: see tests/inputs/CMakeLists.txt.)
#include "lmp_session.h"
#include "trace_header.h"
#include "trace_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <numeric>
#include <string>

namespace {

std::string bed_path()
{
  const char *p = std::getenv("GRANPEN_TINY_BED");
  return p ? p : "";
}

// the in.push set-up for the tiny preset, with the rod tip `gap` above z_s
void setup_push(LmpSession &s, const std::string &bed, double v0, const std::string &fix_extra,
                double gap = 0.5)
{
  s.cmds({"newton off", "read_restart " + bed, "neighbor 0.08 bin",
          "neigh_modify delay 0 exclude type 2 2", "comm_modify vel yes", "group grains type 1",
          "fix floor grains wall/gran hertz/history 1e9 1e9 1000 1000 0.3 1 zplane 0.0 NULL",
          "fix grav grains gravity 981 vector 0 0 -1", "fix integ grains nve/sphere",
          "compute surf grains bed/surface", "run 0 post no"});
  const double zs = s.compute_vector("surf", 0);
  char line[256];
  std::snprintf(line, sizeof(line), "create_rod 2 2.0 4.0 0.4 0.2 3.0 3.0 %.17g shell density 3.0", zs + gap);
  s.cmds({line, "group rod type 2",
          "fix push rod rod/drive " + std::to_string(v0) + " surface " + std::to_string(zs) +
              " grains grains " + fix_extra,
          "timestep 2e-6"});
}

// with GRANPEN_TEST_VERBOSE set, rank 0 prints the measured numbers the tolerances below
// were chosen from
bool verbose()
{
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank == 0 && std::getenv("GRANPEN_TEST_VERBOSE");
}

class PushBed : public ::testing::Test {
 protected:
  void SetUp() override
  {
    if (bed_path().empty()) GTEST_SKIP() << "GRANPEN_TINY_BED not set (run through ctest)";
  }
};

}    // namespace

TEST_F(PushBed, DragEqualsGroupGroupWithoutFriction)
{
  // compute group/group sums pair->single(), which returns only the central part of a
  // contact force; with mu = 0 granular contact forces are central, so it must agree
  // with the drag to round-off. (With friction it misses the tangential forces: see
  // ThirdLawWithFriction for the check that covers them.)
  LmpSession s;
  setup_push(s, bed_path(), 100.0, "");
  s.cmds({"pair_style gran/hertz/history 1e9 1e9 1000 1000 0.0 1", "pair_coeff * *",
          "compute drag rod rod/drag drive push", "compute on_rod rod group/group grains",
          "compute fz_rod rod reduce sum fz fx", "thermo_style custom step c_drag[1] c_on_rod[3] c_fz_rod[1]",
          "thermo 250", "run 2500"});    // the tip just reaches the surface
  double fmax = 0.0;
  for (int seg = 0; seg < 12; ++seg) {
    // group/group evaluates the contact forces from the end-of-step velocities (after the
    // second half-kick); re-evaluate the forces from the same state (run 0) to compare
    s.cmd("run 250");
    const double gg[3] = {s.compute_vector("on_rod", 0), s.compute_vector("on_rod", 1),
                          s.compute_vector("on_rod", 2)};
    s.cmd("run 0 post no");
    const double fz = s.compute_vector("drag", 0);
    const double scale = std::max(1.0, std::fabs(fz));
    EXPECT_NEAR(fz, gg[2], 1e-9 * scale) << "segment " << seg;
    EXPECT_NEAR(s.compute_vector("drag", 1), gg[0], 1e-9 * scale);
    EXPECT_NEAR(s.compute_vector("drag", 2), gg[1], 1e-9 * scale);
    EXPECT_NEAR(fz, s.compute_vector("fz_rod", 0), 1e-9 * scale);
    // the fix and the compute see the same force
    EXPECT_NEAR(s.fix_vector("push", 4), fz, 1e-9 * scale);
    fmax = std::max(fmax, std::fabs(fz));
  }
  EXPECT_GT(fmax, 1.0e4) << "the rod never pressed on the grains";
}

TEST_F(PushBed, ThirdLawWithFriction)
{
  // With friction, compare the drag with the total pair force on the grains: with gravity
  // and the floor removed, grain-grain forces cancel in the sum over grains, leaving
  // exactly minus the rod's force on them (tangential forces included).
  LmpSession s;
  setup_push(s, bed_path(), 100.0, "");
  s.cmds({"compute drag rod rod/drag drive push", "compute on_rod rod group/group grains",
          "compute f_grains grains reduce sum fx fy fz", "run 4000"});
  const double fz_step = s.compute_vector("drag", 0);
  const double gg = s.compute_vector("on_rod", 2);
  s.cmds({"unfix floor", "unfix grav", "run 0 post no"});
  const double fz = s.compute_vector("drag", 0);
  const double scale = std::max(1.0, std::fabs(fz));
  EXPECT_GT(std::fabs(fz), 1.0e4);
  EXPECT_NEAR(s.compute_vector("f_grains", 2), -fz, 1e-9 * scale);
  EXPECT_NEAR(s.compute_vector("f_grains", 0), -s.compute_vector("drag", 1), 1e-9 * scale);
  EXPECT_NEAR(s.compute_vector("f_grains", 1), -s.compute_vector("drag", 2), 1e-9 * scale);
  if (verbose()) std::printf("third law: group/group %.6g, drag %.6g, ratio %.4f\n", gg, fz_step, gg / fz_step);
  // The central-force route misses the vertical part of the friction forces. At most mu =
  // 0.3 of the drag (every tangential force vertical); at a flat face pushed down they are
  // mostly horizontal: measured |gg / drag - 1| = 0.022, 0.005, 0.009, 0.019, 0.004 on the
  // tiny beds of seeds 4242 (the fixture's), 11, 12, 13, 14. 0.06: about three times the largest.
  EXPECT_NEAR(gg, fz_step, 0.06 * std::fabs(fz_step)) << "group/group with friction";
}

TEST_F(PushBed, SurfaceAutoMeasuresOnTheGridItIsGiven)
{
  // fix rod/drive surface auto surface_grid N takes z_s as compute bed/surface grid N does (the
  // same kernel, src/bed_surface), on 1 and 2 ranks; and N reaches the measurement: the 4 cm
  // tiny box on 2 x 2 columns (2 cm wide) and on 8 x 8 (0.5 cm, about a grain) gives z_s
  // apart by far more than round-off
  int nprocs = 1, rank = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &nprocs);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  double measured[2] = {0.0, 0.0};
  const int grids[2] = {2, 8};
  for (int k = 0; k < 2; ++k) {
    const std::string n = std::to_string(grids[k]);
    const std::string trace = "granpen_surface_grid" + n + "_np" + std::to_string(nprocs) + ".csv";
    double from_compute = 0.0;
    {
      LmpSession s;
      setup_push(s, bed_path(), 100.0, "file " + trace);
      s.cmds({"unfix push", "compute surfn grains bed/surface grid " + n, "run 0 post no"});
      from_compute = s.compute_vector("surfn", 0);
      s.cmds({"fix push rod rod/drive 100 surface auto surface_grid " + n + " grains grains file " + trace,
              "run 1 post no"});
    }
    MPI_Barrier(MPI_COMM_WORLD);
    // the header alone (one step gives too few rows for read_trace), checked as read_trace
    // checks it
    const granpen::Trace header = granpen::read_trace_header(trace);
    const auto surface = header.keys.find("surface");
    ASSERT_TRUE(surface != header.keys.end()) << trace << " has no surface key";
    measured[k] = std::stod(surface->second);
    // the header prints the fix's z_s to 10 significant digits (trace_writer's num): the same
    // number to that rounding, half a unit of the 10th digit at most
    EXPECT_NEAR(measured[k], from_compute, 1e-9 * std::fabs(from_compute)) << "grid " << n;
    MPI_Barrier(MPI_COMM_WORLD);
    if (rank == 0) std::remove(trace.c_str());
  }
  if (verbose()) std::printf("surface auto: z_s %.10g on 2 x 2 columns, %.10g on 8 x 8\n", measured[0], measured[1]);
  // a column's highest grain top rises with the column's width: 2 cm columns sit above 0.5 cm
  // ones by a fraction of a grain (0.4 cm); 1e-3 cm is far above round-off and far below that
  EXPECT_GT(measured[0], measured[1] + 1e-3);
}

TEST_F(PushBed, ZeroBeforeContactAndGrowsWithDepthWhenSlow)
{
  // v0 = 20 cm/s, below v_c = sqrt(2 g d_g) = 28 cm/s
  // in the test's working folder, one name per rank count: np1 and np2 run at once, and
  // other build folders run the same test (a shared /tmp name collided)
  int nprocs = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &nprocs);
  const std::string trace = "granpen_slow_push_np" + std::to_string(nprocs) + ".csv";
  {
    LmpSession s;
    setup_push(s, bed_path(), 20.0, "depth 1.5 at_depth halt file " + trace);
    s.cmd("run 60000");
  }
  MPI_Barrier(MPI_COMM_WORLD);
  auto tr = granpen::read_trace(trace);
  ASSERT_GT(tr.z.back(), 1.49);
  // highest grain top is above z_s by at most a grain diameter: no force while the tip is higher
  for (size_t i = 0; i < tr.z.size(); ++i)
    if (tr.z[i] < -0.45) EXPECT_EQ(tr.F[i], 0.0) << "force at z = " << tr.z[i];
  // least-squares slope of F(z) over the penetration: positive; deep third above shallow third
  double sz = 0, sf = 0, szz = 0, szf = 0, n = 0, shallow = 0, deep = 0;
  int ns = 0, nd = 0;
  for (size_t i = 0; i < tr.z.size(); ++i) {
    const double z = tr.z[i], f = tr.F[i];
    if (z < 0.25) continue;
    sz += z, sf += f, szz += z * z, szf += z * f, n += 1;
    if (z < 0.65) shallow += f, ++ns;
    if (z > 1.1) deep += f, ++nd;
  }
  const double slope = (n * szf - sz * sf) / (n * szz - sz * sz);
  // the slope as the depth law's alpha = slope / (mu rho_g g D^2), mu 0.3, rho_g 3, D 2
  const double alpha = slope / (0.3 * 3.0 * 981.0 * 2.0 * 2.0);
  if (verbose())
    std::printf("slow push: slope %.6g dyne/cm (alpha %.3g), mean F deep %.6g, shallow %.6g, ratio %.4f\n", slope,
                alpha, deep / nd, shallow / ns, (deep / nd) / (shallow / ns));
  // Measured alpha 15.4, 14.6, 37.0, 25.3, 34.6 and deep/shallow 1.45, 1.25, 2.59, 1.64, 2.55
  // on the tiny beds of seeds 4242 (the fixture's), 11, 12, 13, 14: a 3.2 cm bed with the
  // floor 1.7 cm under the final tip, so alpha spreads around and below the paper's 35 +- 5 of
  // deep beds. The bounds: half the lowest and twice the highest alpha (a drag off by a
  // factor 2 fails), and the deep third at least 10% above the shallow one (lowest 25%).
  EXPECT_GT(alpha, 7.0);
  EXPECT_LT(alpha, 75.0);
  EXPECT_GT(deep / nd, 1.1 * shallow / ns);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0) std::remove(trace.c_str());
}

TEST_F(PushBed, MountSensorBalancesRodMomentum)
{
  // With a mount the sensor reads the spring-damper force F (pushing the rod down) and the
  // grains push up with F_grain; the rod (mass m, speed v_rod counted downward) obeys
  // m dv/dt = F - F_grain, so m (v_rod(b) - v_rod(a)) = sum over windows of (F - F_grain) dt.
  // Checked over the whole push; and the sensor must carry the drag on average.
  // in the test's working folder, one name per rank count: np1 and np2 run at once, and
  // other build folders run the same test (a shared /tmp name collided)
  int nprocs = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &nprocs);
  const std::string trace = "granpen_mount_push_np" + std::to_string(nprocs) + ".csv";
  const double m = 50.0;
  {
    LmpSession s;
    setup_push(s, bed_path(), 100.0, "depth 1.5 at_depth halt ramp 0.1 mount 1e8 2e3 50 file " + trace);
    s.cmd("run 20000");
  }
  MPI_Barrier(MPI_COMM_WORLD);
  auto tr = granpen::read_trace(trace);
  ASSERT_TRUE(tr.other.count("F_grain") && tr.other.count("v_rod"));
  const auto &fg = tr.other["F_grain"], &v = tr.other["v_rod"];
  ASSERT_GT(tr.z.back(), 1.49);
  double impulse = 0.0, scale = 0.0;
  for (size_t i = 1; i < tr.t.size(); ++i) {
    const double dt = tr.t[i] - tr.t[i - 1];
    impulse += (tr.F[i] - fg[i]) * dt;
    scale += std::fabs(tr.F[i]) * dt;
  }
  // Velocity Verlet: exact up to half-step boundary terms, each about |F - F_grain| dt (dt =
  // 2e-6 s; F - F_grain is small at the push's ends) against the scale's sum over T = 0.02 s:
  // of order dt / T = 1e-4 at most. Measured 3e-7 to 2.8e-5 of the scale in two runs on each
  // of the tiny beds of seeds 4242 (the fixture's), 11, 12, 13, 14.
  if (verbose())
    std::printf("mount: momentum residual %.4g of the impulse scale\n", (m * (v.back() - v.front()) - impulse) / scale);
  EXPECT_NEAR(m * (v.back() - v.front()), impulse, 1e-4 * scale);
  // The sensor carries the drag over the deep part (z > 0.5) up to the rod's change of
  // momentum there: the sum over its windows of (F - F_grain) dt is m (v(b) - v(a)), v(a)
  // the speed before its first window. The halt at depth 1.5 slows the rod, so the sensor
  // reads less than the grains push: F / F_grain over the part 0.86 to 0.98 on the five beds
  // above (a bound of 10% on that ratio failed on seed 13). The identity holds up to the
  // half-step terms at its two ends, now in the middle of the push where the lightly damped
  // mount rings and |F - F_grain| is of the order of F: about 2 dt / T_part = 4e-4 of the
  // part's impulse scale (T_part = 0.01 s); measured 1.3e-4 to 3.7e-4. Bound 1e-3.
  double sf = 0.0, sg = 0.0, deep_impulse = 0.0, deep_scale = 0.0;
  size_t first = 0;
  for (size_t i = 1; i < tr.t.size(); ++i)
    if (tr.z[i] > 0.5) {
      if (!first) first = i;
      const double dt = tr.t[i] - tr.t[i - 1];
      sf += tr.F[i], sg += fg[i], deep_impulse += (tr.F[i] - fg[i]) * dt, deep_scale += std::fabs(tr.F[i]) * dt;
    }
  ASSERT_GT(first, 0u);
  if (verbose())
    std::printf("mount: over z > 0.5 sensor / grain force %.4f, residual %.4g of its impulse scale\n", sf / sg,
                (m * (v.back() - v[first - 1]) - deep_impulse) / deep_scale);
  EXPECT_NEAR(m * (v.back() - v[first - 1]), deep_impulse, 1e-3 * deep_scale);
  EXPECT_GT(sf, 0.5 * sg) << "the sensor does not carry the drag";
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0) std::remove(trace.c_str());
}

TEST_F(PushBed, HydrostaticColumnCarriesTheWeightAbove)
{
  // A bed at rest in a laterally periodic box: the vertical normal stress at height z is
  // the weight of the grains above per unit area. compute flow/azimuthal gives sigma_zz
  // (column 14) from compute stress/atom and the mass per bin (column 4) in one cylinder.
  LmpSession s;
  s.cmds({"newton off", "read_restart " + bed_path(), "neighbor 0.08 bin", "neigh_modify delay 0",
          "comm_modify vel yes", "group grains type 1",
          "fix floor grains wall/gran hertz/history 1e9 1e9 1000 1000 0.3 1 zplane 0.0 NULL",
          "fix grav grains gravity 981 vector 0 0 -1", "fix integ grains nve/sphere",
          "compute stress grains stress/atom NULL",
          "compute flow grains flow/azimuthal axis 3.0 3.0 rbin 3.0 zbin 0.4 zlo 0.0 zhi 4.0 stress stress",
          "thermo_style custom step c_flow[1][14]", "timestep 2e-6", "run 0"});
  auto a = (double **) lammps_extract_compute(s.lmp, "flow", LMP_STYLE_GLOBAL, LMP_TYPE_ARRAY);
  const int nz = 10;
  const double area = M_PI * 3.0 * 3.0, g = 981.0;
  int checked = 0;
  for (int iz = 2; iz < nz; ++iz) {
    if (a[iz][3] <= 0.0) continue;
    double above = 0.5 * a[iz][3];
    for (int k = iz + 1; k < nz; ++k) above += a[k][3];
    const double weight = g * above / area;
    if (weight < 0.3 * g * a[2][3] / area) continue;    // too near the surface to average
    if (verbose())
      std::printf("hydrostatic: z = %.2f: sigma_zz / weight above = %.4f, p / weight above = %.4f\n", a[iz][1],
                  a[iz][13] / weight, a[iz][10] / weight);
    // Over the whole periodic cross-section the balance is exact; the cylinder (79% of it)
    // trades load with its surroundings through shear on its side, and the bins are one
    // grain high. Measured sigma_zz / weight on the tiny beds of seeds 4242 (the fixture's),
    // 11, 12, 13, 14: 0.94 to 1.02 from z = 1.4 up, 1.05 to 1.14 in the bin at z = 1.0, 2 to
    // 3 grains above the floor, whose layering stiffens the packing there. Bounds: 0.12 (twice
    // the largest deviation, 6%) and 0.25 near the floor (1.7 times its 14%).
    const double tol = a[iz][1] < 1.2 ? 0.25 : 0.12;
    EXPECT_NEAR(a[iz][13], weight, tol * weight) << "z = " << a[iz][1];
    // p = sigma_zz (1 + 2 K) / 3 with the lateral stress ratio K: Jaky's 1 - sin(atan 0.3) =
    // 0.71 for the grains' friction, more in a poured bed; measured p / weight 0.83 to 1.01.
    // K between 0.25 and 1.3 gives 0.5 to 1.2 of the weight.
    EXPECT_GT(a[iz][10], 0.5 * weight) << "z = " << a[iz][1];
    EXPECT_LT(a[iz][10], 1.2 * weight) << "z = " << a[iz][1];
    ++checked;
  }
  EXPECT_GE(checked, 3);
}

TEST_F(PushBed, VoronoiPackingTwoRoutesAgree)
{
  // phi_voronoi of every bin of the poured bed, by compute voronoi/atom and by the
  // compute's own Voro++ tessellation of the binned grains only: the same cells
  LmpSession s;
  s.cmds({"newton off", "read_restart " + bed_path(), "neighbor 0.08 bin", "comm_modify vel yes",
          "group grains type 1", "compute vor grains voronoi/atom",
          "compute a grains flow/azimuthal axis 3.0 3.0 rbin 0.5 zbin 0.4 zlo 0.0 zhi 4.0 voronoi vor",
          "compute b grains flow/azimuthal axis 3.0 3.0 rbin 0.5 zbin 0.4 zlo 0.0 zhi 4.0 voronoi voro++",
          "compute surf grains bed/surface",
          "thermo_style custom step c_a[1][6] c_b[1][6] c_surf[1]", "run 0"});
  const double zs = s.compute_vector("surf", 0);
  auto a = (double **) lammps_extract_compute(s.lmp, "a", LMP_STYLE_GLOBAL, LMP_TYPE_ARRAY);
  auto b = (double **) lammps_extract_compute(s.lmp, "b", LMP_STYLE_GLOBAL, LMP_TYPE_ARRAY);
  // bins inside the bed (2 grain diameters below the surface) agree to round-off; near the
  // free surface compute voronoi/atom's cells open up to the box top, while voro++ closes
  // them 1.5 grain diameters above the highest grain: there its cells are smaller
  int inside = 0;
  for (int k = 0; k < 6 * 10; ++k) {
    if (a[k][1] + 0.2 <= zs - 0.8) {
      ++inside;
      EXPECT_NEAR(a[k][5], b[k][5], 1e-10) << "bin " << k;
    } else {
      EXPECT_GE(b[k][5], a[k][5] * (1.0 - 1e-10)) << "surface bin " << k;
    }
  }
  EXPECT_GE(inside, 30);
}
