// lammps_agree: granpen flow / granpen momentum outputs against the in-LAMMPS computes on
// the same frames (tests/analysis/cli/flow.cmake). Both sides call the same kernels of src/
// (flow_bins, voronoi_cells, momentum_class_limits), so this checks the two data paths:
// the atoms as the compute sees them in the run against the atoms read back from the dump
// (positions, velocities, stress, the rod's axis and tip, the frame, the bed surface).
//   lammps_agree flow COMPUTE.txt TIMESTEP FLOW_FIELDS.csv
//     COMPUTE.txt: fix ave/time mode vector output of compute flow/azimuthal (14 columns,
//     tip frame, stress and voronoi) written with format %.17g; the block of TIMESTEP is
//     compared bin by bin with the CSV of `granpen flow DUMP --steps TIMESTEP`.
//   lammps_agree momentum CLASSES.txt MUGM.txt MOMENTUM_CLASSES.csv MOMENTUM_DRAG.csv
//     CLASSES.txt: fix ave/time mode vector output of compute momentum/vbin (4 rows: count,
//     mass, p_up); MUGM.txt: fix ave/time of f_push[1] f_push[2] c_mom (t, depth, mu g M);
//     compared frame by frame, in order, with the CSVs of `granpen momentum`.
// Tolerances: the dump and the compute files hold 17 significant digits, so both sides
// start from the same doubles; only the order of summation differs. Counts must be equal;
// every other value within RTOL relative to the largest |value| of its column (default
// 1e-9), and the depth within 1e-7 cm (the trace header's surface has 10 digits).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

double RTOL = 1e-9;

// fix ave/time mode vector: "STEP NROWS" then NROWS rows "i v1 v2 ..."
std::map<long long, std::vector<std::vector<double>>> read_blocks(const std::string &path)
{
  std::ifstream in(path);
  if (!in) {
    std::fprintf(stderr, "lammps_agree: cannot read %s\n", path.c_str());
    std::exit(2);
  }
  std::map<long long, std::vector<std::vector<double>>> blocks;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream h(line);
    long long step = 0, n = 0;
    h >> step >> n;
    auto &b = blocks[step];
    b.clear();
    for (long long k = 0; k < n && std::getline(in, line); ++k) {
      std::istringstream r(line);
      std::vector<double> row;
      double v, idx;
      r >> idx;
      while (r >> v) row.push_back(v);
      b.push_back(row);
    }
  }
  return blocks;
}

// plain ave/time rows: "STEP v1 v2 ..."
std::vector<std::vector<double>> read_rows(const std::string &path)
{
  std::ifstream in(path);
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream r(line);
    std::vector<double> row;
    double v;
    while (r >> v) row.push_back(v);
    rows.push_back(row);
  }
  return rows;
}

// CSV with a header line; text fields become NaN
std::vector<std::vector<std::string>> read_csv(const std::string &path)
{
  std::ifstream in(path);
  if (!in) {
    std::fprintf(stderr, "lammps_agree: cannot read %s\n", path.c_str());
    std::exit(2);
  }
  std::vector<std::vector<std::string>> rows;
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::stringstream s(line);
    std::string x;
    while (std::getline(s, x, ',')) f.push_back(x);
    rows.push_back(f);
  }
  return rows;
}

struct Column {
  const char *name;
  int lammps, csv;    // column indices (lammps: after the row index)
  bool exact;
};

int failures = 0;
double worst = 0.0;

void compare(const char *what, const std::vector<double> &a, const std::vector<double> &b, bool exact, double atol = 0)
{
  double scale = 0.0;
  int bad = 0;
  for (double v : a) scale = std::max(scale, std::fabs(v));
  for (std::size_t k = 0; k < a.size(); ++k) {
    const double d = std::fabs(a[k] - b[k]);
    const double tol = exact ? 0.0 : std::max(atol, RTOL * scale);
    if (scale > 0 && !exact) worst = std::max(worst, d / scale);
    if (d > tol) {
      if (failures < 20)
        std::printf("  %s row %zu: LAMMPS %.17g, granpen %.17g (|diff| %.3g > %.3g)\n", what, k + 1, a[k], b[k], d, tol);
      ++failures;
      ++bad;
    }
  }
  if (bad) std::printf("  %-12s %d of %zu values DIFFER (largest |value| %.6g)\n", what, bad, a.size(), scale);
  else std::printf("  %-12s %zu values agree%s (largest |value| %.6g)\n", what, a.size(), exact ? " exactly" : "", scale);
}

}    // namespace

int main(int argc, char **argv)
{
  if (const char *r = std::getenv("LAMMPS_AGREE_RTOL")) RTOL = std::atof(r);
  const std::string mode = argc > 1 ? argv[1] : "";
  if (mode == "flow" && argc == 5) {
    const auto blocks = read_blocks(argv[2]);
    const long long step = std::atoll(argv[3]);
    auto it = blocks.find(step);
    if (it == blocks.end()) {
      std::printf("lammps_agree: no block for timestep %lld in %s\n", step, argv[2]);
      return 1;
    }
    const auto &L = it->second;
    const auto C = read_csv(argv[4]);
    if (C.size() != L.size()) {
      std::printf("lammps_agree: %zu bins in %s, %zu in %s\n", L.size(), argv[2], C.size(), argv[4]);
      return 1;
    }
    // compute: r z count mass phi phi_vor vr vz vt T p gammadot I szz
    // csv:     r z count phi(vor) phi_centre vr vz T gammadot p I
    const Column cols[] = {{"r", 0, 0, false},        {"z", 1, 1, false},      {"count", 2, 2, true},
                           {"phi_centre", 4, 4, false}, {"phi_voronoi", 5, 3, false}, {"vr", 6, 5, false},
                           {"vz", 7, 6, false},       {"T", 9, 7, false},      {"p", 10, 9, false},
                           {"gammadot", 11, 8, false}, {"I", 12, 10, false}};
    std::printf("timestep %lld: %zu bins\n", step, L.size());
    double grains = 0;
    for (const auto &c : cols) {
      std::vector<double> a, b;
      for (std::size_t k = 0; k < L.size(); ++k) {
        a.push_back(L[k][c.lammps]);
        b.push_back(std::atof(C[k][c.csv].c_str()));
      }
      if (!std::string("count").compare(c.name))
        for (double v : a) grains += v;
      compare(c.name, a, b, c.exact);
    }
    std::printf("%s: %.0f grains in the bins; largest relative deviation %.3g (tolerance %.3g)\n",
                failures ? "DIFFER" : "agree", grains, worst, RTOL);
    return failures || grains < 100 ? 1 : 0;
  }
  if (mode == "momentum" && argc == 6) {
    const auto blocks = read_blocks(argv[2]);
    const auto mugm = read_rows(argv[3]);
    const auto cls = read_csv(argv[4]);
    const auto drag = read_csv(argv[5]);
    if (blocks.size() != drag.size() || mugm.size() != drag.size() || cls.size() != 4 * drag.size()) {
      std::printf("lammps_agree: %zu compute blocks, %zu mu g M rows, %zu frames in %s, %zu class rows in %s\n",
                  blocks.size(), mugm.size(), drag.size(), argv[5], cls.size(), argv[4]);
      return 1;
    }
    std::vector<double> cA, cB, pA, pB, mA, mB, zA, zB;
    std::size_t f = 0;
    for (const auto &b : blocks) {
      for (int k = 0; k < 4; ++k) {
        cA.push_back(b.second[k][0]);
        pA.push_back(b.second[k][2]);
        cB.push_back(std::atof(cls[4 * f + k][3].c_str()));
        pB.push_back(std::atof(cls[4 * f + k][4].c_str()));
      }
      zA.push_back(mugm[f][2]);
      mA.push_back(mugm[f][3]);
      zB.push_back(std::atof(drag[f][1].c_str()));
      mB.push_back(std::atof(drag[f][3].c_str()));
      ++f;
    }
    std::printf("%zu frames (timesteps %lld..%lld)\n", f, blocks.begin()->first, blocks.rbegin()->first);
    compare("z_tip", zA, zB, false, 1e-7);
    compare("count", cA, cB, true);
    compare("p_up", pA, pB, false);
    compare("mu_g_M", mA, mB, false);
    double moving = 0;
    for (double m : mA) moving = std::max(moving, m);
    std::printf("%s: largest relative deviation %.3g (tolerance %.3g)\n", failures ? "DIFFER" : "agree", worst, RTOL);
    return failures || f < 3 || !(moving > 0) ? 1 : 0;
  }
  std::fprintf(stderr, "usage: lammps_agree flow COMPUTE.txt TIMESTEP FIELDS.csv\n"
                       "       lammps_agree momentum CLASSES.txt MUGM.txt CLASSES.csv DRAG.csv\n");
  return 2;
}
