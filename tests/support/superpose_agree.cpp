// superpose_agree --v0 V --base B1.csv,B2.csv --direct D1.csv,D2.csv
//                 [--push P1.csv,P2.csv --pack K1.csv,K2.csv --w W] [--zmax Z]
// Issue 21's design 2 for the gap diagnosis's cost, measured with the diagnosis's own
// kernels (core/gap_metric.h, core/onset_alignment.h, gap/gap_data.h): is an effect that acts
// in the pour and the push the sum of its push part and its preparation part?
//   B  the baseline's runs at one speed, one per bed (the signature beds)
//   D  the effect's own knot: beds poured and pushed with it ("direct")
//   P  its push part: B's beds pushed with the effect (paired with B bed by bed)
//   K  the packing knot's runs (beds poured at the matching friction, pushed as B)
//   S  the superposed prediction per bed i: S_i = P_i + w (K_i - B_i), on the bin means
// Every run's depths are moved so that its force onset sits at the first B's (as the
// diagnosis aligns runs); the grid is 0.25 cm bins over 0 < z <= zmax (default 4). Printed:
// the mean force over the bins of every set and its change against B, then G of
// ../shared/formats/gap-metric.md (bin means, standard errors subtracted) of D against B
// (the signature's size), of D against P (the push part alone) and of D against S (the
// superposition), with G_spec and G_all where the set is made of runs (S is not: a sum of
// bin means has no fluctuation spectrum of its own, so its G_spec is not defined).
// Without --push: the signature of D against B alone (cohesion's knots at bench).
// Exit 2 on bad input.
#include "gap_data.h"
#include "gap_metric.h"
#include "onset_alignment.h"
#include "trace_reader.h"

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

struct Set {
  std::vector<Run> runs;
  std::vector<std::vector<double>> bins, bands;    // per run: bin means, fluctuation bands
};

std::vector<std::string> split_paths(const std::string &list)
{
  std::vector<std::string> out;
  std::stringstream ss(list);
  for (std::string p; std::getline(ss, p, ',');)
    if (!p.empty()) out.push_back(p);
  return out;
}

Set read_set(const std::string &list, const char *what)
{
  Set s;
  for (const auto &p : split_paths(list)) {
    const Trace tr = to_cgs(read_trace(p));
    s.runs.push_back({tr.t, tr.z, tr.F});
  }
  if (s.runs.empty()) throw InputError(std::string("--") + what + " names no trace");
  return s;
}

void features(Set &s, double onset, const GapGrid &grid)
{
  for (auto &r : s.runs) {
    shift_depths(r.z, onset - force_onset(r.z, r.F));
    const RunFeatures f = run_features(r.t, r.z, r.F, grid);
    if (!f.ok) throw InputError("a run is too short for the grid: " + f.note);
    s.bins.emplace_back(f.x.begin(), f.x.begin() + (long) grid.nbins());
    s.bands.push_back(fluctuation_bands(r.t, r.z, r.F, grid.w, grid.zmax));
  }
}

double mean_force(const std::vector<std::vector<double>> &bins)
{
  const EnsembleMoments m = ensemble_moments(bins);
  double sum = 0.0;
  for (double x : m.mean) sum += x;
  return sum / (double) m.mean.size();
}

// G (bin means) of a against b, both given as per-run bin means; G_spec when both have bands
void print_gap(const char *what, const std::vector<std::vector<double>> &a, const std::vector<std::vector<double>> &b,
               const std::vector<std::vector<double>> *abands, const std::vector<std::vector<double>> *bbands)
{
  const double G = debiased_gap(ensemble_moments(a), ensemble_moments(b));
  if (abands && bbands) {
    const double Gs = debiased_gap(ensemble_moments(*abands), ensemble_moments(*bbands));
    std::printf("  %-34s G %.3f  G_spec %.3f  G_all %.3f\n", what, G, Gs, gap_all(G, Gs));
  } else {
    std::printf("  %-34s G %.3f  (G_spec not defined)\n", what, G);
  }
}

[[noreturn]] void usage(const std::string &why)
{
  std::fprintf(stderr, "superpose_agree: %s\nusage: superpose_agree --v0 V --base B.csv,... --direct D.csv,... "
                       "[--push P.csv,... --pack K.csv,... --w W] [--zmax Z]\n", why.c_str());
  std::exit(2);
}

}    // namespace

int main(int argc, char **argv)
{
  std::string v0, base, direct, push, pack;
  double w = NAN, zmax = 4.0;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (i + 1 >= argc) usage("option " + a + " needs a value");
    const std::string val = argv[++i];
    char *end = nullptr;
    if (a == "--v0") v0 = val;
    else if (a == "--base") base = val;
    else if (a == "--direct") direct = val;
    else if (a == "--push") push = val;
    else if (a == "--pack") pack = val;
    else if (a == "--w" || a == "--zmax") {
      const double x = std::strtod(val.c_str(), &end);
      if (end == val.c_str() || *end || !std::isfinite(x)) usage("option " + a + ": " + val + " is not a number");
      (a == "--w" ? w : zmax) = x;
    } else usage("unknown option " + a);
  }
  if (base.empty() || direct.empty()) usage("--base and --direct are needed");
  if (push.empty() != pack.empty() || (!push.empty() && !std::isfinite(w))) usage("--push, --pack and --w go together");
  if (!(zmax > 0.0 && zmax <= 100.0)) usage("--zmax must lie in (0, 100] cm");
  try {
    GapGrid grid;
    grid.zmax = zmax;
    Set B = read_set(base, "base"), D = read_set(direct, "direct"), P, K;
    const double onset = force_onset(B.runs[0].z, B.runs[0].F);
    features(B, onset, grid);
    features(D, onset, grid);
    const bool superpose = !push.empty();
    std::vector<std::vector<double>> S;
    if (superpose) {
      P = read_set(push, "push"), K = read_set(pack, "pack");
      features(P, onset, grid);
      features(K, onset, grid);
      if (P.runs.size() != B.runs.size() || K.runs.size() != B.runs.size())
        throw InputError("--push and --pack need one run per --base bed, in the same order");
      for (std::size_t i = 0; i < B.runs.size(); ++i) {
        S.push_back(P.bins[i]);
        for (std::size_t b = 0; b < S[i].size(); ++b) S[i][b] += w * (K.bins[i][b] - B.bins[i][b]);
      }
    }
    const double fB = mean_force(B.bins);
    std::printf("v0 %s: mean F over 0-%g cm (runs), change against the baseline\n", v0.c_str(), zmax);
    auto line = [&](const char *name, const std::vector<std::vector<double>> &x) {
      const double f = mean_force(x);
      std::printf("  %-9s %10.4g dyne (%zu)  %+6.1f%%\n", name, f, x.size(), 100.0 * (f / fB - 1.0));
    };
    line("baseline", B.bins);
    line("direct", D.bins);
    if (superpose) {
      line("push", P.bins);
      line("packing", K.bins);
      std::vector<std::vector<double>> Kw = B.bins;    // packing's part at weight w
      for (std::size_t i = 0; i < Kw.size(); ++i)
        for (std::size_t b = 0; b < Kw[i].size(); ++b) Kw[i][b] += w * (K.bins[i][b] - B.bins[i][b]);
      line("pack(w)", Kw);
      line("superposed", S);
    }
    print_gap("direct against baseline (signature)", D.bins, B.bins, &D.bands, &B.bands);
    if (superpose) {
      print_gap("direct against push part alone", D.bins, P.bins, &D.bands, &P.bands);
      print_gap("direct against superposed", D.bins, S, nullptr, nullptr);
    }
  } catch (const std::exception &e) {
    std::fprintf(stderr, "superpose_agree: %s\n", e.what());
    return 2;
  }
  return 0;
}
