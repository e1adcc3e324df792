// Driver of bench/voronoi_frame.sh: makes one dense frame of grains as a LAMMPS data file,
// times analysis/core/voronoi_volumes on it (what `granpen flow` does per frame of a dump
// without a Voronoi column), and checks its volumes against compute voronoi/atom's.
//   voronoi_frame_bench make OUT GRAINS [PHI D ZBOX SEED]
//       a jittered FCC packing of about GRAINS grains of diameter D (0.4 cm) at packing
//       fraction PHI (0.58), x and y periodic with a whole number of lattice cells, the
//       floor at z = 0, the box top at ZBOX (34 cm, the paper preset's box); every grain
//       moved by a random vector of length up to half the gap between lattice neighbours
//       (no overlaps). atom_style sphere (id type diameter density x y z), %.17g.
//   voronoi_frame_bench time DATA
//       reads DATA, then times one voronoi_volumes call on it as `granpen flow` makes it
//       (x, y periodic, z bounded: closed 3 radii above the highest grain); prints
//       "grains N seconds S total V lid Z cells C missing M"
//   voronoi_frame_bench check DATA DUMP
//       compares voronoi_volumes with the per-grain c_vor[1] of a LAMMPS dump of the same
//       frame (columns id, c_vor[1], optionally c_vor[2]); prints totals, the box volumes
//       they should equal, and per-grain differences inside the bed and at its top;
//       exit status 1 when a check fails: voronoi_volumes' total not its container's
//       volume to 1e-9, compute voronoi/atom's not the box's to TOTAL_TOL (1e-9), a cell
//       inside the bed (2 d_g below the highest grain) differing by more than 1e-9, or a
//       top cell larger in voronoi_volumes
#include "dump_reader.h"
#include "voronoi_volumes.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

struct Frame {
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  std::vector<double> x, y, z, r;    // grain i has id i + 1
};

int make(const char *out, long target, double phi, double d, double zbox, unsigned seed)
{
  // FCC nearest-neighbour distance for packing fraction phi; cubic cell a = sqrt(2) a_nn
  const double ann = d * std::cbrt(M_PI / (3.0 * std::sqrt(2.0)) / phi), a = std::sqrt(2.0) * ann;
  const double jmax = 0.5 * (ann - d) * (1.0 - 1e-9);
  if (!(jmax > 0)) {
    std::fprintf(stderr, "make: packing fraction %g is not below FCC's 0.7405\n", phi);
    return 2;
  }
  // bed about 0.75 box sides high, as a poured bed in the paper's 20 x 20 cm box
  const long nxy = std::max(1L, std::lround(std::cbrt(target / 3.0)));
  const long nz = std::max(1L, std::lround(target / (4.0 * nxy * nxy)));
  const double L = nxy * a, z0 = 0.5 * d + jmax;
  const double basis[4][3] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Frame f;
  double ztop = 0;
  for (long k = 0; k < nz; ++k)
    for (long j = 0; j < nxy; ++j)
      for (long i = 0; i < nxy; ++i)
        for (auto &b : basis) {
          double dx, dy, dz;
          do dx = u(rng), dy = u(rng), dz = u(rng);
          while (dx * dx + dy * dy + dz * dz > 1.0);
          double x = (i + b[0] + 0.25) * a + jmax * dx, y = (j + b[1] + 0.25) * a + jmax * dy;
          x -= L * std::floor(x / L), y -= L * std::floor(y / L);    // in [0, L)
          if (x >= L) x = 0;
          if (y >= L) y = 0;
          f.x.push_back(x), f.y.push_back(y), f.z.push_back(z0 + (k + b[2]) * a + jmax * dz);
          ztop = std::max(ztop, f.z.back());
        }
  if (!(zbox > ztop + d)) zbox = std::ceil(ztop + 2 * d);
  FILE *o = std::fopen(out, "w");
  if (!o) {
    std::perror(out);
    return 1;
  }
  const std::size_t n = f.x.size();
  std::fprintf(o,
               "LAMMPS data file: granpen voronoi_frame_bench, jittered FCC, phi %g, d %g, seed %u\n\n"
               "%zu atoms\n1 atom types\n\n%.17g %.17g xlo xhi\n%.17g %.17g ylo yhi\n%.17g %.17g zlo zhi\n\n"
               "Atoms # sphere\n\n",
               phi, d, seed, n, 0.0, L, 0.0, L, 0.0, zbox);
  for (std::size_t i = 0; i < n; ++i)
    std::fprintf(o, "%zu 1 %.17g 3 %.17g %.17g %.17g\n", i + 1, d, f.x[i], f.y[i], f.z[i]);
  if (std::fclose(o) != 0) {
    std::perror(out);
    return 1;
  }
  std::printf("wrote %s: %zu grains, box %.6g x %.6g x %.6g cm, bed top %.6g cm, lattice %ld x %ld x %ld cells "
              "of %.6g cm, jitter up to %.4g cm, phi %.4g\n",
              out, n, L, L, zbox, ztop + 0.5 * d, nxy, nxy, nz, a, jmax,
              n * M_PI / 6 * d * d * d / (L * L * (ztop + 0.5 * d)));
  return 0;
}

// reads what make writes (atom_style sphere data file, one atom type, ids 1..N)
Frame read_data(const std::string &path)
{
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open");
  Frame f;
  std::string line;
  long n = -1, lineno = 0;
  const char *bounds[3] = {"xlo xhi", "ylo yhi", "zlo zhi"};
  while (std::getline(in, line)) {
    ++lineno;
    if (line.find(" atoms") != std::string::npos && n < 0) n = std::atol(line.c_str());
    for (int d = 0; d < 3; ++d)
      if (line.find(bounds[d]) != std::string::npos) std::sscanf(line.c_str(), "%lf %lf", &f.lo[d], &f.hi[d]);
    if (line.rfind("Atoms", 0) == 0) break;
  }
  if (n <= 0) throw std::runtime_error(path + ": no atom count");
  f.x.assign(n, 0), f.y.assign(n, 0), f.z.assign(n, 0), f.r.assign(n, -1);
  long seen = 0;
  while (seen < n && std::getline(in, line)) {
    ++lineno;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    long id, type;
    double dia, rho, x, y, z;
    if (std::sscanf(line.c_str(), "%ld %ld %lf %lf %lf %lf %lf", &id, &type, &dia, &rho, &x, &y, &z) != 7 || id < 1 ||
        id > n || f.r[id - 1] >= 0)
      throw std::runtime_error(path + ":" + std::to_string(lineno) + ": bad atom line");
    f.x[id - 1] = x, f.y[id - 1] = y, f.z[id - 1] = z, f.r[id - 1] = 0.5 * dia;
    ++seen;
  }
  if (seen != n) throw std::runtime_error(path + ": " + std::to_string(seen) + " of " + std::to_string(n) + " atoms");
  return f;
}

// `granpen flow`'s call (analysis/cli/flow_cmd.cpp): the dump's box, x and y periodic
std::vector<double> volumes(const Frame &f, granpen::VoronoiInfo &info)
{
  granpen::VoronoiBox box;
  for (int d = 0; d < 3; ++d) box.lo[d] = f.lo[d], box.hi[d] = f.hi[d];
  box.periodic[0] = box.periodic[1] = true, box.periodic[2] = false;
  return granpen::voronoi_volumes(f.x.data(), f.y.data(), f.z.data(), f.r.data(), f.x.size(), box, nullptr, &info);
}

double sum(const std::vector<double> &v)
{
  long double s = 0;
  for (double x : v) s += x;
  return (double) s;
}

int time_frame(const std::string &path)
{
  Frame f = read_data(path);
  granpen::VoronoiInfo info;
  auto t0 = std::chrono::steady_clock::now();
  std::vector<double> vol = volumes(f, info);
  double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("grains %zu seconds %.6f total %.15g lid %.15g cells %zu missing %zu\n", f.x.size(), s, sum(vol),
              info.hi[2], info.cells, info.missing);
  return 0;
}

int check(const std::string &data, const std::string &dump, double total_tol)
{
  Frame f = read_data(data);
  granpen::VoronoiInfo info;
  std::vector<double> va = volumes(f, info);
  const std::size_t n = f.x.size();
  granpen::DumpReader reader({dump}, {"id", "c_vor[1]"});
  granpen::DumpFrame df;
  if (!reader.next(df)) throw std::runtime_error(dump + ": no frame");
  if (df.natoms() != n)
    throw std::runtime_error(dump + ": " + std::to_string(df.natoms()) + " atoms, the frame has " + std::to_string(n));
  std::vector<double> vb(n, -1), faces(n, 0);
  const auto &id = df.col("id"), &cv = df.col("c_vor[1]");
  const bool have_faces = df.has("c_vor[2]");
  for (std::size_t k = 0; k < n; ++k) {
    long i = std::lround(id[k]) - 1;
    if (i < 0 || (std::size_t) i >= n || vb[i] >= 0) throw std::runtime_error(dump + ": bad or repeated id");
    vb[i] = cv[k];
    if (have_faces) faces[i] = df.col("c_vor[2]")[k];
  }
  const double area = (f.hi[0] - f.lo[0]) * (f.hi[1] - f.lo[1]);
  const double sa = sum(va), sb = sum(vb), box_a = area * (info.hi[2] - info.lo[2]), box_b = area * (f.hi[2] - f.lo[2]);
  double ztop = -1e300, rmax = 0;
  for (std::size_t i = 0; i < n; ++i) ztop = std::max(ztop, f.z[i]), rmax = std::max(rmax, f.r[i]);
  // inside: at least 2 grain diameters below the highest grain centre, where no cell
  // reaches the lid (a) or the box top (b); top: the rest
  const double zcut = ztop - 4 * rmax, tol = 1e-9;
  double max_in = 0, top_diff = 0, zbad = -1e300;
  std::size_t nin = 0, ntop = 0, bad_in = 0, top_changed = 0, top_smaller = 0;
  double deepest_changed = 0, faces_in = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double rel = std::fabs(va[i] - vb[i]) / vb[i];
    const bool changed = rel > tol;
    if (f.z[i] < zcut) {
      ++nin;
      faces_in += faces[i];
      max_in = std::max(max_in, rel);
      if (changed) ++bad_in, zbad = std::max(zbad, f.z[i]);
    } else {
      ++ntop;
      top_diff += vb[i] - va[i];
      if (changed) ++top_changed, deepest_changed = std::max(deepest_changed, ztop - f.z[i]);
      if (va[i] > vb[i] * (1 + tol)) ++top_smaller;
    }
  }
  const double want_diff = area * (f.hi[2] - info.hi[2]);
  std::printf("total volume: voronoi_volumes %.12g (box floor to lid at %.6g cm: %.12g, rel. diff %.2e); "
              "compute voronoi/atom %.12g (box floor to top at %.6g cm: %.12g, rel. diff %.2e)\n",
              sa, info.hi[2], box_a, std::fabs(sa - box_a) / box_a, sb, f.hi[2], box_b, std::fabs(sb - box_b) / box_b);
  std::printf("inside the bed (%zu grains with z < top grain - 2 d_g = %.4g cm): max |a-b|/b %.2e, %zu above %.0e%s; "
              "mean faces per cell %.3f\n",
              nin, zcut, max_in, bad_in, tol, bad_in ? (", highest at z " + std::to_string(zbad)).c_str() : "",
              have_faces ? faces_in / nin : 0.0);
  std::printf("top 2 d_g (%zu grains): %zu cells differ by more than %.0e (the deepest %.3g cm below the top grain), "
              "%zu larger in voronoi_volumes; sum of (b - a) %.12g, area x (box top - lid) %.12g, rel. diff %.2e\n",
              ntop, top_changed, tol, top_changed ? deepest_changed : 0.0, top_smaller, top_diff, want_diff,
              std::fabs(top_diff - want_diff) / want_diff);
  const bool ok = info.missing == 0 && std::fabs(sa - box_a) < 1e-9 * box_a && std::fabs(sb - box_b) <= total_tol * box_b &&
                  bad_in == 0 && top_smaller == 0 && std::fabs(top_diff - want_diff) <= 2 * total_tol * box_b;
  std::printf("check %s\n", ok ? "passed" : "FAILED");
  return ok ? 0 : 1;
}

}    // namespace

int main(int argc, char **argv)
{
  try {
    std::string cmd = argc > 1 ? argv[1] : "";
    if (cmd == "make" && argc >= 4 && argc <= 8)
      return make(argv[2], std::atol(argv[3]), argc > 4 ? std::atof(argv[4]) : 0.58,
                  argc > 5 ? std::atof(argv[5]) : 0.4, argc > 6 ? std::atof(argv[6]) : 34.0,
                  argc > 7 ? (unsigned) std::atol(argv[7]) : 1u);
    if (cmd == "time" && argc == 3) return time_frame(argv[2]);
    if (cmd == "check" && (argc == 4 || argc == 5)) return check(argv[2], argv[3], argc == 5 ? std::atof(argv[4]) : 1e-9);
  } catch (std::exception &e) {
    std::fprintf(stderr, "voronoi_frame_bench: %s\n", e.what());
    return 1;
  }
  std::fprintf(stderr, "usage: voronoi_frame_bench make OUT GRAINS [PHI D ZBOX SEED] | time DATA | check DATA DUMP [TOTAL_TOL]\n");
  return 2;
}
