// A stand-in for lmp_granpen that the sweep runner can drive (same command line, same
// files: BED.restart + BED.info for in.pour, a granpen-trace v1 + a log ending "granpen
// push: done" for in.push), simulating a synthetic world in milliseconds, so that
// `granpen gap` can be tested end to end on known effects:
//   F(z) = bed(z) * (k z + P (v0/100)^2 exp(-((z - 0.3) / 0.15)^2)) + grain noise,
// bed(z) a smooth random field of the bed (its seed and its pour's settings), grain noise an AR(1) sequence whose
// level grows with the contact stiffness. The model knobs act as named in inputs/:
//   mu_roll a: k *= 1 + 1.5 a           poly w: P *= 1 - 2 w
//   walls 1, mu_wall a: + 5e4 a z^2     mu (pour friction) m: F *= 1 - 1.5 (m - 0.3)
//   mu_push m (the pour's when not given): k *= 1 + 2 (m - 0.3)
//   kn s*1e9: grain noise *= s^0.5, and it decorrelates faster
//   ramp L: the peak moves deeper by (L - 0.5) / 2 once L > 0.5 (the rod is still slow)
//   mount_k, mount_c, mount_m: the signal goes through the mount's spring-damper
//   cohesion c: + 5e3 c exp(-z / 0.6) (a cohesive crust, at any speed); phi_0 -= 0.002 c
//   dmu_rod m: P *= 1 + 1.5 m, k *= 1 + 0.5 m (the rod's own friction: the tip and the side)
//   rho_g r: F *= r / 3 (an effect outside the library)
#include "lmp_command_line.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <random>
#include <string>

int main(int argc, char **argv)
{
  auto cmd = read_lmp_command_line(argc, argv);
  auto &var = cmd.var;
  const std::string &in = cmd.in, &log = cmd.log;
  auto num = [&](const char *k, double d) { return var.count(k) ? std::atof(var[k].c_str()) : d; };
  std::ofstream L(log.empty() ? "/dev/null" : log);
  L << "LAMMPS (fake_lmp: granpen's synthetic world for tests)\n";
  if (in.size() >= 7 && in.compare(in.size() - 7, 7, "in.pour") == 0) {
    const std::string out = var["out"];
    std::ofstream(out + ".restart") << "fake bed\n";
    // the bed field's key: the pour's settings (every variable but where it runs and writes,
    // and the seed): a real pour diverges with any change of its physics, so a pour-level
    // knot's beds are not the baseline's beds again
    unsigned long key = 14695981039346656037ul;
    for (const auto &[k, v] : var)
      if (k != "seed" && k != "out" && k != "inputs" && k != "checkpoint")
        for (char c : k + "=" + v + ";") key = (key ^ (unsigned char) c) * 1099511628211ul;
    std::ofstream(out + ".info") << "seed = " << var["seed"] << "\nfield = " << key % 1000003 << "\nmu = " << num("mu", 0.3)
                                 << "\nz_s = 5.7\nphi_0 = " << 0.58 - 0.05 * (num("mu", 0.3) - 0.3) - 0.002 * num("cohesion", 0)
                                 << "\ngrains = 6300\nwall_seconds = 0\n";
    L << "granpen pour: bed " << out << ".restart\n";
    return 0;
  }
  // a push: the bed's seed from its file name (..._sSEED.restart), the pour friction from its .info
  const std::string bed = var["bed"];
  const auto s = bed.rfind("_s");
  const int seed = std::atoi(bed.c_str() + s + 2);
  double mu_pour = 0.3;
  long field = 0;
  {
    std::ifstream info(bed.substr(0, bed.size() - 8) + ".info");
    std::string line;
    while (std::getline(info, line))
      if (line.rfind("mu = ", 0) == 0) mu_pour = std::atof(line.c_str() + 5);
      else if (line.rfind("field = ", 0) == 0) field = std::atol(line.c_str() + 8);
  }
  const double v0 = num("v0", 100), depth = num("depth", 4.0), dt = 1e-4;
  const double dmu_rod = num("dmu_rod", 0), coh = num("cohesion", 0);
  double k = 3e5 * (1 + 1.5 * num("mu_roll", 0)) * (1 + 2 * (num("mu_push", mu_pour) - 0.3)) * (1 + 0.5 * dmu_rod),
         P = 4e5 * std::pow(v0 / 100, 2) * (1 - 2 * num("poly", 0)) * (1 + 1.5 * dmu_rod);
  const double peak_z = 0.3 + std::max(0.0, num("ramp", 0) - 0.5) / 2;
  const double wall = num("walls", 0) > 0 ? 5e4 * num("mu_wall", 0.3) : 0.0;
  const double scale = (1 - 1.5 * (mu_pour - 0.3)) * num("rho_g", 3.0) / 3.0;
  const double stiff = num("kn", 1e9) / 1e9;
  const double grain = 0.15 * std::pow(stiff, 0.5), corr = std::pow(0.6, std::pow(stiff, 0.5));
  // the bed (seed, the pour's settings, speed) and the grains (seed, speed, and the model: another realization)
  std::mt19937 bed_rng((unsigned) (1000 * seed + (int) v0 + 7777 * field));
  std::normal_distribution<double> n01(0.0, 1.0);
  double amp[3], ph[3];
  for (int j = 0; j < 3; ++j) amp[j] = 0.06 * n01(bed_rng), ph[j] = 6.283 * std::uniform_real_distribution<>(0, 1)(bed_rng);
  std::mt19937 grain_rng(7919 * seed + (int) v0 + (int) (1e3 * num("mu_roll", 0)) + (int) (7 * coh));
  const double mk = num("mount_k", 0), mc = num("mount_c", 0), mm = num("mount_m", 100);
  double x = 0, xv = 0, ar = 0;    // mount deflection and speed; AR(1) grain noise
  std::ofstream T(var["trace"]);
  T << "# granpen-trace v1\n# units = cgs\n# v0 = " << v0 << "\n# D = " << num("D", 2.0) << "\n# g = 981\n# d_g = 0.4\n"
    << "# rho_g = " << num("rho_g", 3.0) << "\n# run = " << seed << "\n# source = fake_lmp\nt,z,F\n";
  for (int i = 0;; ++i) {
    const double t = i * dt, z = -0.5 + v0 * t;
    if (z > depth + 1e-9) break;
    double F = 0;
    if (z > 0) {
      double b = 1;
      for (int j = 0; j < 3; ++j) b += amp[j] * std::sin(6.283 * (j + 1) * z / 4.0 + ph[j]);
      const double stick = 5e3 * coh * std::exp(-z / 0.6);
      const double mean = b * (k * z + P * std::exp(-std::pow((z - peak_z) / 0.15, 2)) + wall * z * z + stick) * scale;
      ar = corr * ar + std::sqrt(1 - corr * corr) * n01(grain_rng);
      F = mean * (1 + grain * ar);
    }
    if (mk > 0) {    // the sensor reads the spring: m x'' = F - k x - c x' (semi-implicit, 20 substeps)
      for (int q = 0; q < 20; ++q) {
        xv += (F - mk * x - mc * xv) / mm * dt / 20;
        x += xv * dt / 20;
      }
      F = mk * x;
    }
    char row[96];
    std::snprintf(row, sizeof row, "%.6f,%.6f,%.6g\n", t, z, F);
    T << row;
  }
  L << "granpen push: done, depth " << depth << " cm\n";
  return 0;
}
