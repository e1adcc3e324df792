// granpen gap: the diagnosis itself: measured traces read and checked against the
// scenario, simulations taken from the cache (or run), ensembles compared, effects
// fitted and ranked, the top one confirmed on fresh seeds, the report written.
#include "effects.h"
#include "gap_data.h"
#include "gap_diagnosis.h"
#include "gap_fit.h"
#include "gap_plan.h"
#include "gap_result.h"
#include "gap_verdict.h"
#include "bed_info.h"
#include "gap_sims.h"
#include "scenario.h"
#include "text_util.h"
#include "trace_files.h"
#include "trace_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <system_error>
#include <vector>

namespace granpen {

namespace fs = std::filesystem;

namespace {

struct Run {
  std::string path;
  double v0 = 0;
  std::vector<double> t, z, F;
  double onset = NAN;
};
using BySpeed = std::map<double, std::vector<Run>>;    // v0 -> runs

double speed_key(double v0) { return std::round(v0 * 1e6) / 1e6; }

Run load_run(const std::string &path)
{
  const Trace t = to_cgs(read_trace(path));
  Run r;
  r.path = path;
  r.v0 = speed_key(t.v0);
  r.t = t.t;
  r.z = t.z;
  r.F = t.F;
  r.onset = force_onset(r.z, r.F);
  if (!std::isfinite(r.onset)) throw InputError(path + ": no force onset (F never rises above zero)");
  return r;
}

void check_against_scenario(const std::string &path, const Trace &t, const Scenario &sc)
{
  auto differs = [](double a, double b) { return std::abs(a - b) > 0.01 * std::abs(b); };
  const Trace c = to_cgs(t);
  if (differs(c.D, sc.D))
    throw InputError(path + ": header D = " + std::to_string(c.D) + " cm, scenario '" + sc.name + "' has D = " +
                     std::to_string(sc.D) + " cm");
  if (differs(c.g, sc.g))
    throw InputError(path + ": header g = " + std::to_string(c.g) + " cm/s^2, scenario '" + sc.name + "' has g = " +
                     std::to_string(sc.g));
  const double dg = c.number("d_g", sc.d_g);
  if (differs(dg, sc.d_g))
    throw InputError(path + ": header d_g = " + std::to_string(dg) + " cm, scenario '" + sc.name + "' has d_g = " +
                     std::to_string(sc.d_g) + " cm");
}

BySpeed load_sweep(const std::string &cache, const std::string &sweep)
{
  BySpeed out;
  for (const auto &p : finished_traces(cache, sweep)) {
    Run r = load_run(p);
    out[r.v0].push_back(std::move(r));
  }
  return out;
}

// mean phi_0 of a sweep's beds (NaN without any)
double mean_phi0(const std::string &cache, const std::string &sweep)
{
  double s = 0;
  int n = 0;
  std::error_code ec;
  for (const auto &e : fs::directory_iterator(fs::path(cache) / sweep / "beds", ec))
    if (e.path().extension() == ".info") s += read_bed_info(e.path().string()).phi_0, ++n;
  return n ? s / n : NAN;
}

// shift every run so that its onset sits at ref
void align(std::vector<Run> &runs, double ref)
{
  for (auto &r : runs) {
    const double d = ref - r.onset;
    for (auto &z : r.z) z += d;
    r.onset = ref;
  }
}

double deepest(const std::vector<Run> &runs)
{
  double m = INFINITY;
  for (const auto &r : runs) m = std::min(m, r.z.empty() ? -INFINITY : *std::max_element(r.z.begin(), r.z.end()));
  return m;
}

Ensemble ensemble_of(const std::vector<Run> &runs, const GapGrid &grid, double v0)
{
  std::vector<std::vector<double>> x;
  for (const auto &r : runs) {
    const RunFeatures f = run_features(r.t, r.z, r.F, grid);
    if (!f.ok) throw InputError(r.path + ": " + f.note);
    x.push_back(f.x);
  }
  return make_ensemble(v0, x);
}

// variance of the mean per feature from the pooled relative noise model
std::vector<double> model_err(const Ensemble &e, const std::vector<double> &cv2, double scale = 1.0)
{
  std::vector<double> v(e.mean.size());
  for (std::size_t k = 0; k < v.size(); ++k) v[k] = scale * cv2[k] * e.mean[k] * e.mean[k] / std::max<std::size_t>(1, e.n());
  return v;
}

std::string fmt(double v, const char *f = "%.4g") { return printf_number(f, v); }

double mean_of(const std::vector<double> &v)
{
  return v.empty() ? 0.0 : std::accumulate(v.begin(), v.end(), 0.0) / v.size();
}

// The measured side's noise: the model's, scaled up when the measured runs scatter more
// (one run: by its fluctuation level against the baseline's).
double noise_scale(const Ensemble &eR, const Ensemble &eB, const std::vector<double> &cv2, const GapGrid &grid)
{
  const std::size_t P = grid.nfeatures(), nb = grid.nbins();
  if (eR.n() > 1) {
    double r = 0;
    for (std::size_t k = 0; k < P; ++k) r += eR.var[k] / (cv2[k] * eR.mean[k] * eR.mean[k] + 1e-300);
    return std::max(1.0, r / P);
  }
  double fr = 0, fs = 0;
  for (std::size_t k = nb; k < nb + grid.nwindows(); ++k) fr += eR.mean[k], fs += eB.mean[k];
  return fs > 0 ? std::max(1.0, std::pow(fr / fs, 2)) : 1.0;
}

// Every subset of m of n indices (in order).
std::vector<std::vector<std::size_t>> subsets(std::size_t n, std::size_t m)
{
  std::vector<std::vector<std::size_t>> out;
  std::vector<std::size_t> cur;
  std::function<void(std::size_t)> rec = [&](std::size_t i) {
    if (cur.size() == m) return out.push_back(cur);
    for (std::size_t j = i; j < n; ++j) cur.push_back(j), rec(j + 1), cur.pop_back();
  };
  if (m >= 1 && m <= n) rec(0);
  return out;
}

}    // namespace

int run_gap_diagnosis(const GapOptions &opt, const Scenario &sc, const std::vector<const Effect *> &effects,
                      const RunnerOptions &runner)
{
  Diagnosis d;
  d.scenario = sc.name;
  d.real_dir = opt.real;
  const std::string cache = runner.out_root;

  // ---- measured traces: readable, of this scenario, at speeds it can run
  std::vector<std::string> problems;
  d.real_files = expand_trace_paths({opt.real}, problems);
  if (!problems.empty()) throw InputError(problems[0]);
  BySpeed real;
  for (const auto &p : d.real_files) {
    const Trace t = read_trace(p);
    check_against_scenario(p, t, sc);
    Run r = load_run(p);
    const double dt = sc.number("dt_push");
    const double vmax = 0.01 * sc.d_g / dt, vmin = (sc.gap + sc.depth) / (1e6 * dt);
    if (r.v0 > vmax || r.v0 < vmin)
      throw InputError(p + ": v0 = " + fmt(r.v0) + " cm/s is outside what scenario '" + sc.name + "' can run (" +
                       fmt(vmin) + " to " + fmt(vmax) + " cm/s: at most 1e6 push steps, at most 0.01 d_g per step)");
    real[r.v0].push_back(std::move(r));
  }
  std::vector<std::string> v0s;
  for (const auto &[v, runs] : real) {
    v0s.push_back(deck_number(v));
    if (runs.size() == 1) {
      d.notes.push_back("v0 = " + fmt(v) + " cm/s has one measured run: its noise is unknown; it is estimated from "
                        "the simulations' run-to-run scatter, scaled by the measured signal's fluctuation level");
      std::fprintf(stderr, "granpen gap: warning: %s\n", d.notes.back().c_str());
    }
  }
  std::printf("granpen gap: %zu measured runs at %zu speeds (%s cm/s) against scenario %s\n", d.real_files.size(),
              real.size(), [&] { std::string s; for (auto &v : v0s) s += (s.empty() ? "" : " ") + v; return s; }().c_str(),
              sc.name.c_str());

  // ---- simulations: the baseline and every effect knot (cached)
  std::printf("granpen gap: [1/4] simulations of the baseline and %zu candidate effects (cache %s)\n", effects.size(),
              cache.c_str());
  std::fflush(stdout);
  const auto requests = signature_requests(sc.name, v0s, effects);
  const double hours = estimate_core_hours(sc, requests, cache);
  if (hours > 8.0 && !opt.local)
    throw InputError("the simulations this diagnosis still needs cost about " + fmt(hours, "%.0f") + " core-hours (scenario '" +
                     sc.name + "'): write them out for a cluster with --slurm FILE --v0 \"" +
                     [&] { std::string s; for (auto &v : v0s) s += (s.empty() ? "" : " ") + v; return s; }() +
                     "\" (then rerun with the filled cache), or run them here with --local");
  if (hours > 0.0) std::printf("granpen gap: about %.1f core-hours of simulation to run\n", hours);
  if (run_requests(requests, runner) != 0)
    throw InputError("some simulations failed: see the manifests under " + cache + " (rerun to retry them)");

  // ---- alignment and the common grid
  std::printf("granpen gap: [2/4] comparing ensembles\n");
  BySpeed base = load_sweep(cache, "baseline");
  std::map<std::string, BySpeed> knots;    // sweep name -> runs
  for (const Effect *e : effects)
    for (double a : e->knots) knots[effect_sweep_name(*e, a)] = load_sweep(cache, effect_sweep_name(*e, a));
  // the baseline on the reference beds (seeds 11 to 14): what the fits measure the gap
  // against, and the null replicates of the targeted test
  BySpeed fresh = load_sweep(cache, "fresh_baseline");
  std::map<double, double> ref;    // per speed: the baseline's mean onset
  double zdeep = sc.depth;
  for (auto &[v, runs] : real) {
    if (base[v].size() < 2) throw InputError("the baseline has fewer than 2 runs at v0 = " + fmt(v));
    double s = 0;
    for (const auto &r : base[v]) s += r.onset;
    ref[v] = s / base[v].size();
    double shift_max = 0;
    for (const auto &r : runs) shift_max = std::max(shift_max, std::abs(ref[v] - r.onset));
    if (shift_max > 0.01)
      d.notes.push_back("v0 = " + fmt(v) + ": measured depth origins moved by up to " + fmt(shift_max, "%.3f") +
                        " cm to align the force onsets with the simulation's");
    align(runs, ref[v]);
    align(base[v], ref[v]);
    zdeep = std::min({zdeep, deepest(runs), deepest(base[v])});
    if (fresh[v].size() < 2) throw InputError("the fresh baseline has fewer than 2 runs at v0 = " + fmt(v));
    align(fresh[v], ref[v]);
    zdeep = std::min(zdeep, deepest(fresh[v]));
    for (auto &[name, by] : knots) {
      if (by[v].size() < 2) throw InputError("sweep " + name + " has fewer than 2 runs at v0 = " + fmt(v));
      align(by[v], ref[v]);
      zdeep = std::min(zdeep, deepest(by[v]));
    }
  }
  d.grid.zmax = std::floor(zdeep / d.grid.w + 1e-9) * d.grid.w;
  if (d.grid.zmax < 1.0)
    throw InputError("the runs share less than 1 cm of depth (deepest common depth " + fmt(zdeep) + " cm)");
  const GapGrid &grid = d.grid;
  d.peak_end = 0.35 * sc.D;
  const std::size_t nb = grid.nbins(), P = grid.nfeatures();

  // ---- ensembles, the noise model, the targets
  std::vector<double> speeds;
  for (const auto &[v, _] : real) speeds.push_back(v);
  const std::size_t ns = speeds.size();
  std::vector<Ensemble> eR(ns), eB(ns);
  std::map<std::string, std::vector<Ensemble>> eK;
  std::vector<std::vector<double>> cv2(ns);
  Target target;
  std::vector<double> target_scale;    // per speed: measured noise / the model's
  int dof_min = 1 << 30;
  for (std::size_t s = 0; s < ns; ++s) {
    const double v = speeds[s];
    eR[s] = ensemble_of(real[v], grid, v);
    eB[s] = ensemble_of(base[v], grid, v);
    // the noise model pools ensembles on beds of their own: a push-only effect's runs
    // repeat the baseline's beds, and would count the same bed-to-bed difference again
    std::vector<const Ensemble *> pool{&eB[s]};
    for (auto &[name, by] : knots) {
      eK[name].resize(ns);
      eK[name][s] = ensemble_of(by[v], grid, v);
    }
    for (const Effect *e : effects)
      if (e->pour_level)
        for (double a : e->knots) pool.push_back(&eK[effect_sweep_name(*e, a)][s]);
    int dof = 0;
    cv2[s] = pooled_cv2(pool, grid, 1e-4, &dof);
    dof_min = std::min(dof_min, dof);
    const double scale = noise_scale(eR[s], eB[s], cv2[s], grid);
    if (scale > 1.5)
      d.notes.push_back("v0 = " + fmt(v) + ": the measured runs scatter " + fmt(std::sqrt(scale), "%.2f") +
                        " times more than the simulated ones; their noise is taken as that");
    target_scale.push_back(scale);
    target.mean.push_back(eR[s].mean);
    target.err.push_back(model_err(eR[s], cv2[s], scale));
  }
  // The fits see the gap against the baseline on the reference beds (seeds 11 to 14), not
  // against the signature beds (1, 2): an effect's signature is a difference to the
  // signature beds, and a gap measured against those same beds would share their noise
  // with every signature (a pure-noise "gap" would then look like each effect). So every
  // effect's model is referenced to them: M(a) = B_ref + (I(a) - B_sig) (EffectData::
  // ref_err); its residual at magnitude 0 is T - B_ref, independent of the signatures.
  std::vector<Ensemble> eF(ns);
  std::vector<std::vector<double>> errF(ns);
  for (std::size_t s = 0; s < ns; ++s) {
    eF[s] = ensemble_of(fresh[speeds[s]], grid, speeds[s]);
    errF[s] = model_err(eF[s], cv2[s]);
  }
  // null replicates: the reference beds split in two, one part taken as a measurement
  // without any effect (as many runs as the measurement has, leaving at least two), the rest
  // as its reference, processed as the measurement is
  std::vector<Target> nulls;
  {
    std::size_t nf = 1 << 30;
    for (std::size_t s = 0; s < ns; ++s) nf = std::min(nf, fresh[speeds[s]].size());
    if (nf < 3) throw InputError("the reference beds (sweep fresh_baseline) need at least 3 runs per speed for the null replicates");
    d.n_reference = (int) nf;
    const std::size_t m = std::clamp<std::size_t>(d.real_files.size() / std::max<std::size_t>(1, ns), 1, nf - 2);
    for (const auto &pick : subsets(nf, m)) {
      Target t;
      for (std::size_t s = 0; s < ns; ++s) {
        std::vector<std::vector<double>> x, y;
        for (std::size_t i = 0; i < nf; ++i)
          (std::find(pick.begin(), pick.end(), i) != pick.end() ? x : y).push_back(eF[s].runs[i]);
        // against the models referenced to all reference beds: shifted by (all - rest), with the
        // variance of the rest in place of that of all of them
        const Ensemble e = make_ensemble(speeds[s], x), b = make_ensemble(speeds[s], y);
        const auto eb = model_err(b, cv2[s]);
        auto err = model_err(e, cv2[s], noise_scale(e, eB[s], cv2[s], grid));
        std::vector<double> mean(P);
        for (std::size_t k = 0; k < P; ++k)
          mean[k] = e.mean[k] - b.mean[k] + eF[s].mean[k], err[k] += std::max(0.0, eb[k] - errF[s][k]);
        t.mean.push_back(mean);
        t.err.push_back(err);
      }
      nulls.push_back(t);
    }
  }
  if (std::getenv("GRANPEN_GAP_DEBUG"))
    for (std::size_t s = 0; s < ns; ++s) {
      auto row = [&](const char *name, const std::vector<double> &x) {
        std::fprintf(stderr, "%-28s v0 %-5g", name, speeds[s]);
        for (double y : x) std::fprintf(stderr, " %9.4g", y);
        std::fprintf(stderr, "\n");
      };
      row("measured", eR[s].mean);
      row("baseline", eB[s].mean);
      row("reference baseline", eF[s].mean);
      for (auto &[name, es] : eK) row(name.c_str(), es[s].mean);
      row("cv2", cv2[s]);
    }
  d.notes.push_back("noise model: run-to-run scatter of every simulated ensemble pooled per speed and feature (" +
                    std::to_string(dof_min) + " degrees of freedom), relative to the mean, smoothed over neighbouring depths");

  // ---- where: the gap curve, G, the observables per regime, all against the baseline on
  // the reference beds (what the fits see; four beds, as many as the confirmation has, so
  // that G before and after share a noise floor)
  d.n_real_min = 1 << 30;
  double gb = 0;
  for (std::size_t s = 0; s < ns; ++s) {
    SpeedCurves c;
    c.v0 = speeds[s];
    c.n_real = (int) eR[s].n();
    c.n_base = (int) eF[s].n();
    d.n_real_min = std::min(d.n_real_min, c.n_real);
    const auto errB = model_err(eF[s], cv2[s]);
    for (std::size_t b = 0; b < nb; ++b) {
      c.z.push_back(grid.centre(b));
      c.real.push_back(eR[s].mean[b]);
      c.real_se.push_back(std::sqrt(target.err[s][b]));
      c.base.push_back(eF[s].mean[b]);
      c.base_se.push_back(std::sqrt(errB[b]));
      c.gap.push_back(eR[s].mean[b] - eF[s].mean[b]);
      c.band.push_back(2.0 * std::sqrt(target.err[s][b] + errB[b]));
    }
    c.G_before = gap_metric(eR[s], eF[s], 0, nb);
    gb += c.G_before / ns;
    d.speeds.push_back(c);
  }
  d.gap_before = gb;
  d.n_sim = d.n_reference;    // the baseline the gap is measured against: the reference beds

  // regimes from the baseline's crossover (t~* of its runs, mean)
  for (std::size_t s = 0; s < ns; ++s) {
    const double v = speeds[s];
    std::vector<double> ts;
    for (const auto &r : fresh[v]) {
      const auto o = run_observables(r.z, r.F, v, sc.D, sc.g, sc.d_g, grid, grid.zmax);
      if (o.crossed) ts.push_back(o.t_star);
    }
    const double zc = ts.size() == fresh[v].size() && !ts.empty() ? mean_of(ts) * v * std::sqrt(sc.D / sc.g) : grid.zmax;
    d.speeds[s].z_transient_end = std::clamp(zc, 0.35 * sc.D, grid.zmax);
  }
  // observables: each side's mean; standard errors from the run-to-run variance pooled
  // over every simulated ensemble of the speed (two runs alone say little about it),
  // the measured side's scaled by how much more its runs scatter
  const std::map<std::string, std::string> regime = {{"peak_F", "peak"},     {"peak_z", "peak"},
                                                     {"excess", "transient"}, {"t_star", "transient"},
                                                     {"k_z", "linear"},       {"fluct", "linear"},
                                                     {"wavelength", "linear"}};
  for (std::size_t s = 0; s < ns; ++s) {
    const double v = speeds[s], zt = d.speeds[s].z_transient_end;
    using Obs = std::map<std::string, std::vector<double>>;
    auto collect = [&](const std::vector<Run> &runs) {
      Obs o;
      for (const auto &r : runs) {
        const auto x = run_observables(r.z, r.F, v, sc.D, sc.g, sc.d_g, grid, zt);
        o["peak_F"].push_back(x.peak_F);
        o["peak_z"].push_back(x.peak_z);
        o["excess"].push_back(x.excess);
        o["k_z"].push_back(x.k_z);
        if (x.crossed) o["t_star"].push_back(x.t_star);
        o["fluct"].push_back(x.fluct);
        if (x.wavelength > 0) o["wavelength"].push_back(x.wavelength);
      }
      return o;
    };
    const Obs oR = collect(real[v]), oB = collect(fresh[v]);
    std::map<std::string, std::pair<double, int>> pooled;    // sum of squares, dof
    auto pool = [&](const Obs &o) {
      for (const auto &[name, xs] : o) {
        if (xs.size() < 2) continue;
        const double m = mean_of(xs);
        for (double x : xs) pooled[name].first += (x - m) * (x - m);
        pooled[name].second += (int) xs.size() - 1;
      }
    };
    pool(oB);
    for (auto &[name, by] : knots) pool(collect(by[v]));
    const double scale = target_scale[s];
    for (const auto &[name, reg] : regime) {
      if (!oR.count(name) || !oB.count(name) || !pooled.count(name)) continue;
      if (name == "excess" && zt <= 0.35 * sc.D + grid.w) continue;    // no transient regime in range
      const double var1 = pooled[name].first / pooled[name].second;    // one run's variance
      const std::vector<double> &xr = oR.at(name), &xb = oB.at(name);
      Finding f;
      f.regime = reg;
      f.observable = name;
      f.v0 = v;
      f.real = mean_of(xr);
      f.sim = mean_of(xb);
      f.real_se = std::sqrt(scale * var1 / xr.size());
      f.sim_se = std::sqrt(var1 / xb.size());
      f.zscore = (f.real - f.sim) / std::sqrt(f.real_se * f.real_se + f.sim_se * f.sim_se + 1e-300);
      f.significant = std::abs(f.zscore) > 3.0;
      d.where.push_back(f);
    }
  }
  std::sort(d.where.begin(), d.where.end(),
            [](const Finding &a, const Finding &b) { return std::abs(a.zscore) > std::abs(b.zscore); });

  // ---- significance of the gap over every feature
  {
    std::vector<std::size_t> all(ns);
    std::iota(all.begin(), all.end(), 0);
    EffectData null;
    null.knots = {0.0};
    null.mean = {Table()};
    null.err = {Table()};
    for (std::size_t s = 0; s < ns; ++s) {
      null.mean[0].push_back(eF[s].mean);
      null.err[0].push_back(model_err(eF[s], cv2[s]));
    }
    d.chi2_0 = effect_chi2(target, null, 0.0, all);
    d.nfeatures = ns * P;
    d.p_value = chi2_sf(d.chi2_0, (double) d.nfeatures);
    d.significant = d.p_value < 1e-3;
  }

  // ---- which: every effect's magnitude, explained fraction, leave-one-speed-out
  std::printf("granpen gap: [3/4] fitting %zu candidate effects\n", effects.size());
  std::map<std::string, const Effect *> by_name;
  std::map<std::string, EffectData> effect_data;
  for (const Effect *e : effects) {
    by_name[e->name] = e;
    EffectData ed;
    ed.name = e->name;
    ed.paired = !e->pour_level;
    ed.one_sided = e->one_sided;
    std::vector<std::pair<double, std::string>> ks{{0.0, ""}};
    for (double a : e->knots) ks.push_back({a, effect_sweep_name(*e, a)});
    std::sort(ks.begin(), ks.end());
    for (const auto &[a, name] : ks) {
      ed.knots.push_back(a);
      Table m, er, de;
      for (std::size_t s = 0; s < ns; ++s) {
        const Ensemble &en = name.empty() ? eB[s] : eK[name][s];
        m.push_back(en.mean);
        er.push_back(model_err(en, cv2[s]));
        std::vector<double> dv(P, 0.0);
        if (ed.paired && !name.empty()) {
          // paired differences to the baseline run on the same bed (same seed order)
          const std::size_t n = std::min(en.n(), eB[s].n());
          for (std::size_t k = 0; k < P; ++k) {
            std::vector<double> dd;
            for (std::size_t i = 0; i < n; ++i) dd.push_back(en.runs[i][k] - eB[s].runs[i][k]);
            const double md = mean_of(dd);
            double ss = 0;
            for (double x : dd) ss += (x - md) * (x - md);
            const double var = n > 1 ? ss / (n - 1) : 0.0;
            // floor: 1e-4 relative, as for the ensembles
            dv[k] = std::max(var, 1e-4 * en.mean[k] * en.mean[k]) / std::max<std::size_t>(1, n);
          }
        }
        de.push_back(dv);
      }
      ed.mean.push_back(m);
      ed.err.push_back(er);
      ed.diff_err.push_back(de);
    }
    // referenced to the reference beds (above): every knot shifted by B_ref - B_sig, knot
    // 0's variance the reference's, the signature baseline's carried by ref_err
    const std::size_t j0 = (std::size_t) (std::find(ed.knots.begin(), ed.knots.end(), 0.0) - ed.knots.begin());
    ed.ref_err.assign(1, Table());
    for (std::size_t s = 0; s < ns; ++s) {
      for (auto &knot : ed.mean)
        for (std::size_t k = 0; k < P; ++k) knot[s][k] += eF[s].mean[k] - eB[s].mean[k];
      ed.ref_err[0].push_back(ed.err[j0][s]);
      ed.err[j0][s] = errF[s];
    }
    ed.noise_r2 = noise_residual(nulls, ed);
    EffectFit f = fit_effect(target, ed);
    double lsum = 0;
    for (const auto &t : nulls) lsum += effect_lr(t, ed);
    f.lr_null_mean = nulls.empty() ? 0.0 : lsum / nulls.size();
    f.lr_threshold = lr_threshold(f.lr_null_mean);
    f.detected = f.lr > f.lr_threshold && !f.at_edge;
    d.ranking.push_back(f);
    effect_data[e->name] = ed;
    if (e->pour_mu_at) {
      // packing: the phi_0 the fitted pour friction makes, interpolated between the beds'
      std::vector<double> phi;
      for (const auto &[a, name] : ks) phi.push_back(mean_phi0(cache, name.empty() ? "baseline" : name));
      const double a = d.ranking.back().magnitude;
      std::size_t i = 0;
      while (i + 2 < ed.knots.size() && a > ed.knots[i + 1]) ++i;
      const double f = (a - ed.knots[i]) / (ed.knots[i + 1] - ed.knots[i]);
      const double p = (1 - f) * phi[i] + f * phi[i + 1];
      d.magnitude_note[e->name] = "pour friction " + fmt(0.3 + a, "%.3f") + ": phi_0 " + fmt(p, "%.4f") +
                                  " against the baseline's " + fmt(mean_phi0(cache, "baseline"), "%.4f");
    }
  }
  d.n_null = (int) nulls.size();
  decide_verdict(d);
  for (const auto &f : d.ranking)
    std::printf("  %-20s magnitude %-10s explained %5.2f  held-out %5.2f  chi2 %.1f -> %.1f  lr %.1f (threshold %.1f)\n",
                f.name.c_str(), fmt(f.magnitude).c_str(), f.explained, f.heldout_explained, f.chi2_0, f.chi2, f.lr,
                f.lr_threshold);
  const EffectFit *top = d.ranking.empty() ? nullptr : &d.ranking[0];

  // ---- how far it shrinks: the top effect on fresh seeds
  std::printf("granpen gap: [4/4] %s\n", d.verdict != "explained" ? "no effect to confirm"
                                          : opt.fit_only ? "not confirming (--fit-only)"
                                                         : ("confirming " + d.top_effect + " on fresh seeds").c_str());
  std::fflush(stdout);
  for (auto &c : d.speeds) c.corr = c.base, c.corr_se = c.base_se, c.G_after = c.G_before, c.n_corr = c.n_base;
  d.gap_after = d.gap_before;
  for (const auto &r : fresh) for (const auto &x : r.second) d.baseline_files.push_back(x.path);
  std::size_t hs = 0;
  for (std::size_t s = 0; s < ns; ++s)
    if (d.speeds[s].G_before > d.speeds[hs].G_before) hs = s;
  d.heldout_v0 = speeds[hs];
  d.heldout_before = d.heldout_after = d.speeds[hs].G_before;
  if (d.verdict == "explained" && opt.fit_only) {
    d.provisional = true;
    d.magnitude = top->magnitude;
    d.magnitude_unit = by_name[d.top_effect]->unit;
    d.notes.push_back("verdict provisional (--fit-only): " + d.top_effect + " was not simulated on fresh seeds, "
                      "so the gap after is the gap before");
  } else if (d.verdict == "explained") {
    const Effect &e = *by_name[d.top_effect];
    const EffectData &ed = effect_data.at(e.name);
    d.tested_effect = e.name;
    d.magnitude = top->magnitude;
    d.magnitude_unit = e.unit;
    d.heldout_magnitude = top->loso_magnitude[hs];
    auto req = confirm_requests(sc.name, e, d.magnitude, v0s, "confirm");
    const auto [alo, ahi] = magnitude_range(ed);
    const double span = ahi - alo;
    const bool own_heldout = std::abs(d.heldout_magnitude - d.magnitude) > 0.05 * span;
    if (own_heldout) {
      auto h = confirm_requests(sc.name, e, d.heldout_magnitude, {deck_number(speeds[hs])}, "heldout");
      req.insert(req.end(), h.begin(), h.end());
    }
    if (run_requests(req, runner) != 0)
      throw InputError("confirming simulations failed: see the manifests under " + cache + " (rerun to retry)");
    BySpeed corr = load_sweep(cache, "confirm_" + effect_sweep_name(e, d.magnitude));
    BySpeed held = own_heldout ? load_sweep(cache, "heldout_" + effect_sweep_name(e, d.heldout_magnitude)) : corr;
    // the gap along the effect's signature u = model(a) - model(0) against the baseline, and
    // (evaluate) against fresh runs at magnitude a: num / sqrt(uu) standard deviations
    double num0 = 0, uu0 = 0;
    for (std::size_t s = 0; s < ns; ++s) {
      std::vector<double> ma, va, m0, v0;
      effect_predict(ed, d.magnitude, s, ma, va);
      effect_predict(ed, 0.0, s, m0, v0);
      for (std::size_t k = 0; k < P; ++k) {
        const double u = ma[k] - m0[k], w0 = target.err[s][k] + v0[k];
        num0 += u * (eR[s].mean[k] - m0[k]) / w0, uu0 += u * u / w0;
      }
    }
    struct After {
      double G = 0, chi2 = 0, num = 0, uu = 0;
      double sigma() const { return uu > 0 ? num / std::sqrt(uu) : 0.0; }
    };
    // fresh runs at magnitude a against the measurement: G and the curves per speed (what
    // the report calls "after"), chi^2 over every feature, the gap along the signature
    auto evaluate = [&](BySpeed &runs, double a) {
      After r;
      d.corrected_files.clear();
      for (std::size_t s = 0; s < ns; ++s) {
        const double v = speeds[s];
        if (runs[v].empty()) throw InputError("no confirming runs at v0 = " + fmt(v));
        align(runs[v], ref[v]);
        for (const auto &x : runs[v]) d.corrected_files.push_back(x.path);
        const Ensemble eC = ensemble_of(runs[v], grid, v);
        const auto errC = model_err(eC, cv2[s]);
        auto &c = d.speeds[s];
        c.n_corr = (int) eC.n();
        for (std::size_t b = 0; b < nb; ++b) c.corr[b] = eC.mean[b], c.corr_se[b] = std::sqrt(errC[b]);
        c.G_after = gap_metric(eR[s], eC, 0, nb);
        r.G += c.G_after / ns;
        std::vector<double> ma, va, m0, v0;
        effect_predict(ed, a, s, ma, va);
        effect_predict(ed, 0.0, s, m0, v0);
        for (std::size_t k = 0; k < P; ++k) {
          const double w1 = target.err[s][k] + errC[k], u = ma[k] - m0[k];
          r.chi2 += std::pow(eR[s].mean[k] - eC.mean[k], 2) / w1;
          r.num += u * (eR[s].mean[k] - eC.mean[k]) / w1, r.uu += u * u / w1;
        }
      }
      return r;
    };
    const After first = evaluate(corr, d.magnitude);
    {
      const double v = speeds[hs];
      align(held[v], ref[v]);
      d.heldout_after = gap_metric(eR[hs], ensemble_of(held[v], grid, v), 0, nb);
    }
    d.gap_after = first.G;
    double chi2_after = first.chi2;
    // confirmed when the fresh runs bring chi^2 over every feature (bin means, fluctuation
    // levels, spectrum: G sees the bin means only) down by more than its noise (3 sigma of a
    // chi^2 with P degrees of freedom) and by at least a quarter of the gap's excess: a
    // magnitude somewhat off still confirms the effect, a wrong effect does not
    d.chi2_after = chi2_after;
    const double P = (double) d.nfeatures, excess0 = d.chi2_0 - P;
    // the fraction of the gap's chi^2 excess that fresh runs with chi^2 chi2a remove
    auto excess_removed = [&](double chi2a) { return excess0 > 0 ? 1.0 - std::max(0.0, chi2a - P) / excess0 : 0.0; };
    d.confirmed_fraction = excess_removed(chi2_after);
    d.proj_before = uu0 > 0 ? num0 / std::sqrt(uu0) : 0.0;
    d.proj_after = first.sigma();
    // a gap found along one signature (targeted) is confirmed when the fresh runs remove
    // it there: the squared projection drops by at least 9 (3 sigma), and the gap over
    // every feature does not grow beyond its noise
    auto passes = [&](double chi2a, double proj_a) {
      return d.targeted ? d.proj_before * d.proj_before - proj_a * proj_a >= 9.0 && chi2a <= d.chi2_0 + 3.0 * std::sqrt(2.0 * P)
                        : d.chi2_0 - chi2a > 3.0 * std::sqrt(2.0 * P) && excess_removed(chi2a) >= 0.25;
    };
    bool confirmed = passes(chi2_after, d.proj_after);
    // The fresh runs leave a significant gap along the signature: the fit's magnitude rests on
    // signatures of few beds, the confirming runs are a better-resolved point. Correct it by
    // linear response and simulate that on beds no step has seen: when the first runs
    // confirmed the effect, or when they did not but the gap they leave is more of the same
    // effect (c > 0: the magnitude fell short, as a fit on noisy knots does); then those
    // second runs must pass the same test.
    const double c = first.uu > 0 ? first.num / first.uu : 0.0;
    if (std::abs(d.proj_after) >= 3.0 && (confirmed || c > 0.0)) {
      const double a2 = refined_magnitude(ed, d.magnitude, c);
      if (std::abs(a2 - d.magnitude) > 0.05 * span) {
        const auto rreq = confirm_requests(sc.name, e, a2, v0s, "refine", REFINE_SEEDS);
        if (run_requests(rreq, runner) != 0)
          throw InputError("refining simulations failed: see the manifests under " + cache + " (rerun to retry)");
        BySpeed runs2 = load_sweep(cache, "refine_" + effect_sweep_name(e, a2));
        const After second = evaluate(runs2, a2);
        d.refined = true;
        d.refined_from = d.magnitude;
        d.gap_after_first = first.G;
        d.proj_refined = second.sigma();
        std::string how = "the confirming runs at " + fmt(d.magnitude) + " left " + fmt(d.proj_after, "%.2f") +
                          " sigma along the signature (chi^2 " + fmt(chi2_after, "%.1f") + ", G " + fmt(first.G, "%.3f") +
                          (confirmed ? "" : ": not confirmed, the magnitude short") + "); linear response gives " +
                          fmt(a2) + ", simulated on " + std::to_string(REFINE_SEEDS.size()) + " more fresh beds: chi^2 " +
                          fmt(second.chi2, "%.1f") + ", G " + fmt(second.G, "%.3f") + ", " + fmt(d.proj_refined, "%.2f") +
                          " sigma; gap after and the corrected traces are these";
        if (!confirmed) {
          // the second runs decide, and their numbers are the confirmation's
          confirmed = passes(second.chi2, second.sigma());
          d.chi2_after = chi2_after = second.chi2;
          d.confirmed_fraction = excess_removed(second.chi2);
          d.proj_after = second.sigma();
          how += "; they decide the confirmation";
        }
        d.notes.push_back("magnitude refined: " + how);
        d.magnitude = a2;
        d.gap_after = second.G;
      }
    }
    if (!confirmed) {
      d.notes.push_back("verdict: " + d.top_effect + " at magnitude " + fmt(d.magnitude) +
                        " did not shrink the gap on fresh seeds (chi^2 " + fmt(d.chi2_0, "%.1f") + " -> " +
                        fmt(chi2_after, "%.1f") + " over " + std::to_string(d.nfeatures) + " features; along its signature " +
                        fmt(d.proj_before, "%.2f") + " -> " + fmt(d.proj_after, "%.2f") + " sigma; G " +
                        fmt(d.gap_before, "%.3f") + " -> " + fmt(d.gap_after, "%.3f") + "): unexplained");
      d.verdict = "unexplained";
      d.top_effect.clear();
    }
  }
  // per regime, before and after
  for (const char *reg : {"peak", "transient", "linear"}) {
    double sb = 0, sa = 0;
    int n = 0;
    for (std::size_t s = 0; s < ns; ++s) {
      const auto &c = d.speeds[s];
      std::size_t b0 = 0, b1 = 0;
      for (std::size_t b = 0; b < nb; ++b) {
        const double z = grid.centre(b);
        const std::string r = z <= 0.35 * sc.D ? "peak" : (z <= c.z_transient_end ? "transient" : "linear");
        if (r == reg) {
          if (b1 == 0) b0 = b;
          b1 = b + 1;
        }
      }
      if (b1 == 0) continue;
      Ensemble R, B, C;
      R.mean = c.real, B.mean = c.base, C.mean = c.corr;
      R.runs.resize(1), B.runs.resize(1), C.runs.resize(1);    // the debiasing is in the overall G
      sb += gap_metric(R, B, b0, b1);
      sa += gap_metric(R, C, b0, b1);
      ++n;
    }
    if (n) d.gap_by_regime[reg] = {sb / n, sa / n};
  }

  // ---- output: written beside OUT, moved into place when complete
  const fs::path out = opt.out, part = fs::path(opt.out + ".partial");
  std::error_code ec;
  fs::remove_all(part, ec);
  fs::create_directories(part / "baseline");
  fs::create_directories(part / "corrected");
  auto copy_all = [&](const std::vector<std::string> &files, const fs::path &dir, const std::string &prefix) {
    for (const auto &f : files) {
      const fs::path src(f);
      const std::string name = prefix + src.parent_path().parent_path().filename().string() + "_" + src.filename().string();
      fs::copy_file(src, dir / name, fs::copy_options::overwrite_existing);
    }
  };
  copy_all(d.baseline_files, part / "baseline", "");
  copy_all(d.corrected_files.empty() ? d.baseline_files : d.corrected_files, part / "corrected", "");
  write_gap_report(d, part.string());
  if (fs::exists(out)) {
    const fs::path old = fs::path(opt.out + ".old");
    fs::remove_all(old, ec);
    fs::rename(out, old);
    fs::rename(part, out);
    fs::remove_all(old, ec);
  } else {
    fs::rename(part, out);
  }
  std::printf("granpen gap: verdict %s%s; G %.3f -> %.3f (%d measured runs per speed at least, %d simulated); %s\n",
              d.verdict.c_str(), d.top_effect.empty() ? "" : (" (" + d.top_effect + ", magnitude " + fmt(d.magnitude) + ")").c_str(),
              d.gap_before, d.gap_after, d.n_real_min, d.n_sim, (opt.out + "/diagnosis.json").c_str());
  return 0;
}

}    // namespace granpen
