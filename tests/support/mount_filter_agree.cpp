// mount_filter_agree --pair M.csv B.csv [--pair M2.csv B2.csv]... [--how band|linear|constant]
//                    [--max-kernel X] [--max-route X] [--max-rod-swing PCT] [--min-rod-swing PCT]
// The measurement chain two ways: each M a push with fix rod/drive's dynamic mount (header
// `mount = k c m`, columns t,z,F,F_grain,v_rod), B the rigid push on the same bed, filtered by
// core/sensor_response.h at M's mount (granpen gap's measurement_chain). Each run's depths are
// moved so that its force onset sits at the first B's (as the diagnosis aligns runs); the
// grid is 0.25 cm bins over 0 < z <= the deepest depth all reach. Printed per pair, each as
// G, G_spec and G_all of ../shared/formats/gap-metric.md (one run a side, M the measured one):
//   kernel     M's F against its own F_grain column filtered: the filter alone, no feedback
//   route      M's F against B filtered: what the diagnosis uses instead of M (feedback, and
//              the grains' chaos: M's grains follow other paths than B's on the same bed)
//   signature  M's F against B unfiltered: the mount's effect, for scale
//   grains     M's F_grain against B: the grains' force itself, changed by the rod's motion
//              (feedback) and by chaos, with no filter in between
//   rod        the rod's speed about v0 (RMS and largest, over the rows in contact) and the
//              spring's largest deflection F/k: the feedback the filter neglects
// and over all pairs (two or more): the systematic part of route, signature and grains, the
// paired differences' mean less their noise (sqrt(max(0, sum(mean d^2 - var d / n)) / sum
// m_M^2)); the scatter from bed to bed of the signature as simulated (M - B) and as filtered
// (B filtered - B): the noise of a knot that rests on one bed, each way; and beds, the
// single-run gap of each M against every other (the mount's reading from bed to bed: the
// noise the route's per-pair differences compare with).
// Exit 1 when a pair's kernel or route G_all exceeds the given bound, or its rod's largest
// speed swing (% of v0) lies outside the given bounds; 2 on bad input.
#include "gap_data.h"
#include "gap_metric.h"
#include "onset_alignment.h"
#include "sensor_response.h"
#include "trace_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

using namespace granpen;

namespace {

struct Run {
  std::vector<double> t, z, F;
};

struct Gap {
  double G = 0, G_spec = 0;
  double all() const { return gap_all(G, G_spec); }
};

double mean_dt(const std::vector<double> &t) { return (t.back() - t.front()) / (double) (t.size() - 1); }

Run aligned(const std::vector<double> &t, const std::vector<double> &z, const std::vector<double> &F, double onset)
{
  Run r{t, z, F};
  shift_depths(r.z, onset - force_onset(r.z, r.F));
  return r;
}

// G and G_spec of one run against another (measured m, simulated s) on the grid
Gap gap_of(const Run &m, const Run &s, const GapGrid &grid)
{
  auto moments = [&](const Run &r, bool bins) {
    std::vector<double> x;
    if (bins) {
      const RunFeatures f = run_features(r.t, r.z, r.F, grid);
      if (!f.ok) throw InputError("a run is too short for the grid: " + f.note);
      x.assign(f.x.begin(), f.x.begin() + (long) grid.nbins());
    } else {
      x = fluctuation_bands(r.t, r.z, r.F, grid.w, grid.zmax);
    }
    return ensemble_moments({x});
  };
  return {debiased_gap(moments(m, true), moments(s, true)), debiased_gap(moments(m, false), moments(s, false))};
}

std::string show(const char *what, const Gap &g)
{
  char buf[160];
  std::snprintf(buf, sizeof buf, "%s G %.4f G_spec %.4f G_all %.4f", what, g.G, g.G_spec, g.all());
  return buf;
}


// the features of one run: bin means, then the spectrum's band amplitudes
std::vector<double> features(const Run &r, const GapGrid &grid)
{
  const RunFeatures f = run_features(r.t, r.z, r.F, grid);
  if (!f.ok) throw InputError("a run is too short for the grid: " + f.note);
  std::vector<double> x(f.x.begin(), f.x.begin() + (long) grid.nbins());
  for (double b : fluctuation_bands(r.t, r.z, r.F, grid.w, grid.zmax)) x.push_back(b);
  return x;
}

// the paired differences' systematic part over features [k0, k1), relative to m's means
double paired_gap(const std::vector<std::vector<double>> &m, const std::vector<std::vector<double>> &s, std::size_t k0,
                  std::size_t k1)
{
  const double n = (double) m.size();
  double num = 0, den = 0;
  for (std::size_t k = k0; k < k1; ++k) {
    double md = 0, mm = 0, vd = 0;
    for (std::size_t i = 0; i < m.size(); ++i) md += (m[i][k] - s[i][k]) / n, mm += m[i][k] / n;
    for (std::size_t i = 0; i < m.size(); ++i) vd += std::pow(m[i][k] - s[i][k] - md, 2) / std::max(1.0, n - 1);
    num += md * md - (n > 1 ? vd / n : 0.0), den += mm * mm;
  }
  return den > 0 ? std::sqrt(std::max(0.0, num) / den) : 0.0;
}

// one bed's scatter of the paired differences m - s over features [k0, k1), relative to m's
// means: sqrt(sum var d / sum m^2) (the noise of a signature that rests on one bed)
double paired_scatter(const std::vector<std::vector<double>> &m, const std::vector<std::vector<double>> &s, std::size_t k0,
                      std::size_t k1)
{
  const double n = (double) m.size();
  double num = 0, den = 0;
  for (std::size_t k = k0; k < k1; ++k) {
    double md = 0, mm = 0;
    for (std::size_t i = 0; i < m.size(); ++i) md += (m[i][k] - s[i][k]) / n, mm += m[i][k] / n;
    for (std::size_t i = 0; i < m.size(); ++i) num += std::pow(m[i][k] - s[i][k] - md, 2) / std::max(1.0, n - 1);
    den += mm * mm;
  }
  return den > 0 ? std::sqrt(num / den) : 0.0;
}

struct Pair {
  Trace M, B;
  SensorChain chain;
};

Pair read_pair(const std::string &mount_path, const std::string &base_path)
{
  Pair p{to_cgs(read_trace(mount_path)), to_cgs(read_trace(base_path)), {}};
  const auto mk = p.M.keys.find("mount");
  if (mk == p.M.keys.end() || !p.M.other.count("F_grain") || !p.M.other.count("v_rod"))
    throw InputError(mount_path + ": not a push with fix rod/drive mount (header mount, columns F_grain, v_rod)");
  double k = 0, c = 0, m = 0;
  std::istringstream(mk->second) >> k >> c >> m;
  p.chain.mount = mount_of(k, c, m);
  return p;
}

// the rod while in contact: RMS and largest |speed - v0| (swing: the largest, % of v0); the
// largest deflection F / k
std::string rod_feedback(const Trace &M, double &swing)
{
  const auto &vr = M.other.at("v_rod");
  double k = 0;
  std::istringstream(M.keys.at("mount")) >> k;
  double ss = 0, dv = 0, fmax = 0;
  int n = 0;
  for (std::size_t i = 0; i < M.t.size(); ++i) {
    fmax = std::max(fmax, std::fabs(M.F[i]));
    if (M.z[i] <= 0) continue;
    ss += std::pow(vr[i] - M.v0, 2), dv = std::max(dv, std::fabs(vr[i] - M.v0)), ++n;
  }
  swing = 100.0 * dv / M.v0;
  char buf[200];
  std::snprintf(buf, sizeof buf, "rod speed - v0: RMS %.3g, largest %.3g cm/s (%.3g%% of v0); largest deflection F/k %.3g cm",
                n ? std::sqrt(ss / n) : 0.0, dv, 100.0 * dv / M.v0, fmax / k);
  return buf;
}

}    // namespace

int main(int argc, char **argv)
{
  std::vector<std::pair<std::string, std::string>> paths;
  Discretisation hold = Discretisation::BandLimited;
  double max_kernel = INFINITY, max_route = INFINITY, max_swing = INFINITY, min_swing = -1.0;
  for (int i = 1; i < argc; ++i) {
    const std::string k = argv[i];
    if (k == "--pair" && i + 2 < argc) paths.emplace_back(argv[i + 1], argv[i + 2]), i += 2;
    else if (k == "--how" && i + 1 < argc) {
      const std::string h = argv[++i];
      hold = h == "linear" ? Discretisation::LinearHold : h == "constant" ? Discretisation::ConstantHold : Discretisation::BandLimited;
    }
    else if (k == "--max-kernel" && i + 1 < argc) max_kernel = std::atof(argv[++i]);
    else if (k == "--max-route" && i + 1 < argc) max_route = std::atof(argv[++i]);
    else if (k == "--max-rod-swing" && i + 1 < argc) max_swing = std::atof(argv[++i]);
    else if (k == "--min-rod-swing" && i + 1 < argc) min_swing = std::atof(argv[++i]);
    else {
      std::fprintf(stderr, "mount_filter_agree: unknown option or missing value: %s\n", k.c_str());
      return 2;
    }
  }
  if (paths.empty()) {
    std::fprintf(stderr, "usage: mount_filter_agree --pair M.csv B.csv [--pair ...] [--how band|linear|constant] "
                         "[--max-kernel X] [--max-route X] [--max-rod-swing PCT] [--min-rod-swing PCT]\n");
    return 2;
  }
  try {
    std::vector<Pair> pairs;
    for (const auto &[m, b] : paths) pairs.push_back(read_pair(m, b));
    const double onset = force_onset(pairs[0].B.z, pairs[0].B.F);
    std::vector<Run> rm, kern, filt, base, grain;
    for (const Pair &p : pairs) {
      const std::vector<double> &Fg = p.M.other.at("F_grain");
      rm.push_back(aligned(p.M.t, p.M.z, p.M.F, onset));
      kern.push_back(aligned(p.M.t, p.M.z, sensor_response(Fg, mean_dt(p.M.t), p.chain, hold), onset));
      filt.push_back(aligned(p.B.t, p.B.z, sensor_response(p.B.F, mean_dt(p.B.t), p.chain, hold), onset));
      base.push_back(aligned(p.B.t, p.B.z, p.B.F, onset));
      grain.push_back(aligned(p.M.t, p.M.z, Fg, onset));
    }
    double zdeep = INFINITY;
    for (const auto *set : {&rm, &kern, &filt, &base, &grain})
      for (const Run &r : *set) zdeep = std::min(zdeep, r.z.back());
    GapGrid grid;
    grid.zmax = std::floor(zdeep / grid.w + 1e-9) * grid.w;
    const SensorChain &c0 = pairs[0].chain;
    std::printf("mount_filter_agree: T %.4g ms zeta %.3g v0 %g, %zu pair(s), zmax %g cm, %s\n", 1e3 * c0.mount.period,
                c0.mount.zeta, pairs[0].M.v0, pairs.size(), grid.zmax, hold == Discretisation::BandLimited ? "band-limited" : hold == Discretisation::LinearHold ? "linear hold" : "constant hold");
    bool ok = true;
    std::vector<std::vector<double>> xm, xf, xb, xg;
    for (std::size_t i = 0; i < pairs.size(); ++i) {
      const Gap gk = gap_of(rm[i], kern[i], grid), gr = gap_of(rm[i], filt[i], grid), gs = gap_of(rm[i], base[i], grid);
      double swing = 0;
      const std::string rod = rod_feedback(pairs[i].M, swing);
      std::printf("  pair %zu: %s\n    %s\n    %s\n    %s\n    %s\n", i + 1, show("kernel   ", gk).c_str(),
                  show("route    ", gr).c_str(), show("signature", gs).c_str(), show("grains   ", gap_of(grain[i], base[i], grid)).c_str(),
                  rod.c_str());
      ok = ok && gk.all() <= max_kernel && gr.all() <= max_route && swing <= max_swing && swing >= min_swing;
      xm.push_back(features(rm[i], grid)), xf.push_back(features(filt[i], grid)), xb.push_back(features(base[i], grid));
      xg.push_back(features(grain[i], grid));
    }
    if (pairs.size() > 1) {
      const std::size_t nb = grid.nbins(), P = xm[0].size();
      auto systematic = [&](const char *what, const std::vector<std::vector<double>> &a, const std::vector<std::vector<double>> &b) {
        std::printf("  systematic over %zu beds: %s\n", pairs.size(), show(what, {paired_gap(a, b, 0, nb), paired_gap(a, b, nb, P)}).c_str());
      };
      systematic("route    ", xm, xf);
      systematic("signature", xm, xb);
      systematic("grains   ", xg, xb);
      std::printf("  signature scatter, one bed: simulated %s\n  signature scatter, one bed: filtered  %s\n",
                  show("", {paired_scatter(xm, xb, 0, nb), paired_scatter(xm, xb, nb, P)}).c_str(),
                  show("", {paired_scatter(xf, xb, 0, nb), paired_scatter(xf, xb, nb, P)}).c_str());
      Gap beds;
      int nbeds = 0;
      for (std::size_t i = 0; i < rm.size(); ++i)
        for (std::size_t j = 0; j < rm.size(); ++j)
          if (i != j) {
            const Gap g = gap_of(rm[i], rm[j], grid);
            beds.G += g.G, beds.G_spec += g.G_spec, ++nbeds;
          }
      beds.G /= nbeds, beds.G_spec /= nbeds;
      std::printf("  bed to bed, one run a side: %s\n", show("", beds).c_str());
    }
    std::printf("mount_filter_agree: %s\n", ok ? "OK" : "FAIL");
    return ok ? 0 : 1;
  } catch (const InputError &e) {
    std::fprintf(stderr, "mount_filter_agree: %s\n", e.what());
    return 2;
  }
}
