// A stand-in for lmp_granpen that the sweep runner can drive (same command line, same
// files: BED.restart + BED.info for in.pour, a granpen-trace v1 + a log ending "granpen
// push: done" for in.push), simulating a synthetic world in milliseconds, so that
// `granpen gap` can be tested end to end on known effects:
//   F(z) = bed(z) * (k z + P (v0/100)^2 exp(-((z - 0.3) / 0.15)^2)) + grain noise,
// bed(z) a smooth random field of the bed (its seed and its pour's settings), grain noise an
// AR(1) sequence (one sample per 1e-4 s, correlation corr) whose level grows with the contact
// stiffness. k z is the quasi-static depth term (lithostatic: ~ rho_g g phi z), P the
// inertial impact peak (~ rho_g phi v0^2 D^2). The model knobs act as named in inputs/:
//   mu_roll a: k *= 1 + 1.5 a           poly w: P *= 1 - 2 w
//   walls 1, mu_wall a: + 5e4 a z^2 (quasi-static: scales as k does with the packing and rho_g)
//   mu (pour friction) m: the bed's packing phi_0 = 0.58 - 0.05 (m - 0.3) (its .info), and
//       k *= 1 + 30 (phi_0 - 0.58) (= 1 - 1.5 (m - 0.3)), P *= phi_0 / 0.58 (see below)
//   mu_push m (the pour's when not given): k *= 1 + 2 (m - 0.3)
//   kn s*1e9: grain noise *= s^0.5, and it decorrelates faster: corr = 0.6^(s^0.5) (see rho_g)
//   ramp L: the peak moves deeper by (L - 0.5) / 2 once L > 0.5 (the rod is still slow)
//   mount_k, mount_c, mount_m: the signal goes through the mount's spring-damper: the reading is k x + c x' (fix rod/drive mount)
//   cohesion gamma, c = gamma / 60: + 5e3 c exp(-z / 0.6) (a cohesive crust, at any speed);
//       phi_0 -= 1.2e-5 gamma (as bench's beds: -0.035 at gamma 3000; in the .info only: the
//       crust stands for the cohesive bed's whole force). The scale 60 keeps the synthetic
//       signature of the library's top knot (3000 now, 50 before) what it was
//   cohesion_dmt gamma, c = gamma / 48: + 8e3 c (1 - exp(-z / 0.3)) (the DMT law's constant
//       pull-off at every contact: a cohesive strength through the bed's depth, not a crust;
//       it sets in over the first grain layers, at any speed); phi_0 -= 1.4e-5 gamma (tiny's
//       beds: 0.559 -> 0.526 at 2400, docs/gap.md; in the .info only, as cohesion's). At the
//       top knot (2400, c = 50) the strength, 4e5, is the depth term's at 1.3 cm; a quarter
//       of it (2e3 c) left the first knot (800) below the diagnosis's detection limit (889)
//       and the selftest's 1200 fitted at 295 as a near-uniform offset that packing and
//       force_scale explain as well (the look-alike, and not this world's question)
//   dmu_rod m: P *= 1 + 1.5 m, k *= 1 + 0.5 m (the rod's own friction: the tip and the side)
//   layer A, layer_z z_l (an effect outside the library: a bed stratified in depth, a harder
//       layer buried at z_l, 1.3 cm unless given): + A exp(-((z - z_l) / 0.15)^2) at any speed,
//       independent of the grains' packing and density (a stone layer, a compacted band); it
//       is no key of the bed's field, so its beds are those of the same seeds without it
//   strata A, strata_l l (an effect outside the library: a bed of alternating harder and
//       softer strata, l cm apart, under 0.5 cm of loose cover): + A sin(2 pi (z - 0.5) / l)
//       below z = 0.5 at any speed; no key of the bed's field (as the layer). No library
//       signature resembles it: the pour-level ones are smooth in depth (k z, z^2, a crust)
//       or the impact peak, the push-only ones filter or shift the whole trace
//   rho_g r (an effect outside the library; the headers say 3): k, P and the walls *= r / 3,
//       and the grain noise as for kn s * 3 / r (see below)
// Packing (the pour's friction sets phi_0): near jamming the quasi-static resistance of a bed
// is very sensitive to its packing fraction (tens of % per 0.02 in phi in drag and
// penetration experiments; here 60% per 0.02, linear, which keeps the depth term's response
// to the pour friction that this world always had: 1 - 1.5 (m - 0.3), so the library's
// `packing` magnitude, the pour friction less 0.3, means what it meant), while the inertial
// peak ~ rho_g phi v0^2 D^2 is only linear in phi: a few % (+1.6% for a pour at mu 0.12).
// So packing moves k strongly and P weakly, not F uniformly.
// Lighter grains at the same contact law (rho_g r against the header's 3): the lithostatic
// depth term (rho_g g) and the inertial peak (rho_g v0^2) both scale by r / 3, so the mean
// force scales uniformly; but the grains' contacts are shorter: the Hertz contact time
// (gran/hertz/history) is t_c ~ (m^2 / (kn^2 R v))^(1/5) = (m / kn)^(2/5) (R v)^(-1/5), m ~
// rho_g, so the grain-scale force fluctuations decorrelate faster. More generally, F / (rho_g
// g d^3) depends on rho_g and kn only through kn / (rho_g g d) (the grains' stiffness against
// their weight; the damping gamma_n acts per unit mass): lighter grains are, to everything
// but the force scale, stiffer contacts by 3 / r. So the grain noise follows this world's
// stiffness law at s 3 / r: its level *= (3 / r)^0.5 and corr = 0.6^((s 3 / r)^0.5), the
// correlation time tau = -dt / ln(corr) ~ (m / kn)^(1/2) (0.6 -> 0.571 for r = 2.5). The
// world's kn law has the linear spring's exponent 1/2 where Hertz has 2/5 (0.6 -> 0.577; an
// enduring contact's period under the grain's own load, ~ m^(1/3), would give 0.581): kept
// for both, so that lighter grains are exactly what the dimensionless physics says,
// `contact_stiffness` at log10(3 / r) (+0.079 for r = 2.5) with F scaled by r / 3: a
// signature no single library effect has, though packing at +0.1 (k down as much, P by 1%)
// comes within 2 to 3 standard deviations of it in tiny with eight beds a side
// (docs/gap-validation.md, "2026-11-27").
// GRANPEN_FAKE_LMP_PUSH_SECONDS S: a push writes its rows over about S seconds of wall time,
// flushed row by row, as a long LAMMPS push does (the sweep runner's progress lines).
#include "lmp_command_line.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <random>
#include <string>
#include <thread>

// The synthetic world's cost, for bench/gap_cost.sh --synthetic only (off unless
// GRANPEN_FAKE_LMP_WORK is set): a run does a fixed amount of arithmetic, as a LAMMPS run
// does a fixed amount of work, so that it takes longer on a slower or busier machine and
// side by side with another. Its work is LAMMPS's as the plan counts it (analysis/gap/
// gap_plan.h, docs/gap.md "The plan's cost"): atom-steps (grains from the preset's lattice;
// a pour 0.6 s at dt_pour, a push gap + depth + a ramp's travel at v0 and dt_push) times the
// route's measured cost per atom-step (JKR cohesion 2.1, rolling friction 1.5), at
// GRANPEN_FAKE_LMP_WORK iterations per 1e6 of them. So it checks the plan's counting of the
// runs a diagnosis makes and its wall-time model, not the rates, which bench checks on LAMMPS.
static std::map<std::string, std::string> preset_vars(const std::string &path)
{
  std::map<std::string, std::string> v;
  std::ifstream in(path);
  std::string word, name, style, value;
  while (in >> word)
    if (word == "variable" && in >> name >> style >> value && style == "index") v[name] = value;
  return v;
}

static double burn(double iterations)
{
  volatile double x = 1.0;
  for (double i = 0; i < iterations; i += 1) x = x * 1.0000001 + 1e-9;
  return x;
}

static void spend_work(std::map<std::string, std::string> &var, bool pour)
{
  const char *work = std::getenv("GRANPEN_FAKE_LMP_WORK");
  if (!work) return;
  auto p = preset_vars(var["inputs"] + "/presets/" + var["preset"] + ".lmp");
  for (const auto &[k, v] : var) p[k] = v;    // the command line's -var override the preset's
  auto num = [&](const char *k, double d) { return p.count(k) ? std::atof(p[k].c_str()) : d; };
  const double lat = num("lat", 1), box = num("box", 1), lo = num("fill_lo", 0);
  const double across = std::floor((box - 2.0 * lo) / lat + 1.0);
  const double grains = across * across * std::floor((num("zfill_hi", 1) - num("zfill_lo", 0)) / lat + 1.0);
  const double steps = pour ? 0.6 / num("dt_pour", 5e-6)
                            : (num("gap", 0.5) + num("depth", 4) + num("ramp", 0)) / num("v0", 100) / num("dt_push", 2e-6);
  const double route = num("cohesion", 0) != 0 ? 2.1 : num("mu_roll", 0) != 0 ? 1.5 : 1.0;
  burn(std::atof(work) * grains * steps * route / 1e6);
}

// the pour's packing fraction from its friction (docs/calibration.md: 0.594 -> 0.574 for
// mu 0.1 -> 0.5): the .info's phi_0 and the push's packing law share it
static double phi_pour(double mu) { return 0.58 - 0.05 * (mu - 0.3); }

int main(int argc, char **argv)
{
  auto cmd = read_lmp_command_line(argc, argv);
  auto &var = cmd.var;
  const std::string &in = cmd.in, &log = cmd.log;
  auto num = [&](const char *k, double d) { return var.count(k) ? std::atof(var[k].c_str()) : d; };
  std::ofstream L(log.empty() ? "/dev/null" : log);
  L << "LAMMPS (fake_lmp: granpen's synthetic world for tests)\n";
  if (in.size() >= 7 && in.compare(in.size() - 7, 7, "in.pour") == 0) {
    spend_work(var, true);
    const std::string out = var["out"];
    std::ofstream(out + ".restart") << "fake bed\n";
    // the bed field's key: the pour's settings (every variable but where it runs and writes,
    // and the seed): a real pour diverges with any change of its physics, so a pour-level
    // knot's beds are not the baseline's beds again. The buried layer is not the grains'
    // physics (a stone band laid in the bed, not a change of how the grains pour): its keys
    // stay out, so a layer case's beds are the seeds' own, whatever its size and depth, and a
    // scan over them compares one realization (issue 37; before, each size drew other beds)
    unsigned long key = 14695981039346656037ul;
    for (const auto &[k, v] : var)
      if (k != "seed" && k != "out" && k != "inputs" && k != "checkpoint" && k != "layer" && k != "layer_z" && k != "strata" &&
          k != "strata_l")
        for (char c : k + "=" + v + ";") key = (key ^ (unsigned char) c) * 1099511628211ul;
    std::ofstream(out + ".info") << "seed = " << var["seed"] << "\nfield = " << key % 1000003 << "\nmu = " << num("mu", 0.3)
                                 << "\nz_s = 5.7\nphi_0 = " << phi_pour(num("mu", 0.3)) - 1.2e-5 * num("cohesion", 0) - 1.4e-5 * num("cohesion_dmt", 0)
                                 << "\ngrains = 6300\nwall_seconds = 0\n";
    L << "granpen pour: bed " << out << ".restart\n";
    return 0;
  }
  spend_work(var, false);
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
  const double dmu_rod = num("dmu_rod", 0), coh = num("cohesion", 0) / 60.0, coh_dmt = num("cohesion_dmt", 0) / 48.0;
  // packing (the pour's phi_0): the quasi-static terms strongly, the inertial peak linearly;
  // grain density (rho_g against the headers' 3): both terms alike
  const double phi = phi_pour(mu_pour), quasi = 1 + 30 * (phi - 0.58), inertial = phi / 0.58;
  const double dens = num("rho_g", 3.0) / 3.0;
  double k = 3e5 * (1 + 1.5 * num("mu_roll", 0)) * (1 + 2 * (num("mu_push", mu_pour) - 0.3)) * (1 + 0.5 * dmu_rod) * quasi * dens,
         P = 4e5 * std::pow(v0 / 100, 2) * (1 - 2 * num("poly", 0)) * (1 + 1.5 * dmu_rod) * inertial * dens;
  const double peak_z = 0.3 + std::max(0.0, num("ramp", 0) - 0.5) / 2;
  const double wall = num("walls", 0) > 0 ? 5e4 * num("mu_wall", 0.3) * quasi * dens : 0.0;
  // the grains' stiffness against their weight, kn / rho_g, relative to the bench's (see above)
  const double stiff = num("kn", 1e9) / 1e9 / dens;
  const double grain = 0.15 * std::pow(stiff, 0.5), corr = std::pow(0.6, std::pow(stiff, 0.5));
  // the bed (seed, the pour's settings, speed) and the grains (seed, speed, and the model: another realization)
  std::mt19937 bed_rng((unsigned) (1000 * seed + (int) v0 + 7777 * field));
  std::normal_distribution<double> n01(0.0, 1.0);
  double amp[3], ph[3];
  for (int j = 0; j < 3; ++j) amp[j] = 0.06 * n01(bed_rng), ph[j] = 6.283 * std::uniform_real_distribution<>(0, 1)(bed_rng);
  // The grain noise's seed takes the model's magnitudes (int(7 gamma / 60) for cohesion...):
  // a real run diverges with any change of its physics, so runs at 1612 and 1609 draw other
  // grain noise, as LAMMPS's would. GRANPEN_FAKE_LMP_GRAIN_SEED=knobs seeds it by which
  // knobs are on instead, not by their values (issue 37's second design, measured in
  // docs/gap-validation.md: a stand-in kinder than LAMMPS, so not the default)
  const bool by_knobs = std::getenv("GRANPEN_FAKE_LMP_GRAIN_SEED") && std::string(std::getenv("GRANPEN_FAKE_LMP_GRAIN_SEED")) == "knobs";
  const int model_seed = by_knobs ? (num("mu_roll", 0) != 0) + 2 * (coh != 0) + 4 * (coh_dmt != 0)
                                  : (int) (1e3 * num("mu_roll", 0)) + (int) (7 * coh) + (int) (11 * coh_dmt);
  std::mt19937 grain_rng(7919 * seed + (int) v0 + model_seed);
  const double layer = num("layer", 0), layer_z = num("layer_z", 1.3), strata = num("strata", 0), strata_l = num("strata_l", 1.0);
  const double mk = num("mount_k", 0), mc = num("mount_c", 0), mm = num("mount_m", 100);
  double x = 0, xv = 0, ar = 0;    // mount deflection and speed; AR(1) grain noise
  std::ofstream T(var["trace"]);
  T << "# granpen-trace v1\n# units = cgs\n# v0 = " << v0 << "\n# D = " << num("D", 2.0) << "\n# g = 981\n# d_g = 0.4\n"
    << "# rho_g = " << num("rho_g", 3.0) << "\n# run = " << seed << "\n# source = fake_lmp\nt,z,F\n";
  const char *pace = std::getenv("GRANPEN_FAKE_LMP_PUSH_SECONDS");
  const double row_seconds = pace ? std::atof(pace) * v0 * dt / (depth + 0.5) : 0.0;
  for (int i = 0;; ++i) {
    const double t = i * dt, z = -0.5 + v0 * t;
    if (z > depth + 1e-9) break;
    if (row_seconds > 0) {
      T.flush();
      std::this_thread::sleep_for(std::chrono::duration<double>(row_seconds));
    }
    double F = 0;
    if (z > 0) {
      double b = 1;
      for (int j = 0; j < 3; ++j) b += amp[j] * std::sin(6.283 * (j + 1) * z / 4.0 + ph[j]);
      const double stick = 5e3 * coh * std::exp(-z / 0.6) * quasi;    // a static strength; not rho_g's
      const double strength = 8e3 * coh_dmt * (1 - std::exp(-z / 0.3)) * quasi;    // nor this
      const double buried = layer * std::exp(-std::pow((z - layer_z) / 0.15, 2));    // a harder layer: not the grains'
      const double strat = z > 0.5 ? strata * std::sin(6.283185307 * (z - 0.5) / strata_l) : 0.0;    // nor these
      const double mean = b * (k * z + P * std::exp(-std::pow((z - peak_z) / 0.15, 2)) + wall * z * z + stick + strength + buried + strat);
      ar = corr * ar + std::sqrt(1 - corr * corr) * n01(grain_rng);
      F = mean * (1 + grain * ar);
    }
    if (mk > 0) {    // the sensor reads the spring: m x'' = F - k x - c x' (semi-implicit, 20 substeps)
      for (int q = 0; q < 20; ++q) {
        xv += (F - mk * x - mc * xv) / mm * dt / 20;
        x += xv * dt / 20;
      }
      F = mk * x + mc * xv;    // the mount reads spring and damper, as fix rod/drive mount does
    }
    char row[96];
    std::snprintf(row, sizeof row, "%.6f,%.6f,%.6g\n", t, z, F);
    T << row;
  }
  L << "granpen push: done, depth " << depth << " cm\n";
  return 0;
}
