// granpen gap: the signature prior (see gap_prior.h).
#include "gap_prior.h"

#include "atomic_file.h"
#include "errors.h"
#include "gap_errors.h"
#include "gap_inputs.h"
#include "gap_plan.h"
#include "gap_sims.h"
#include "gap_thresholds.h"
#include "gap_which.h"
#include "json_path.h"
#include "json_writer.h"
#include "onset_alignment.h"
#include "text_util.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace granpen {

namespace fs = std::filesystem;

namespace {

std::vector<double> onsets_of(const std::vector<TraceRun> &runs)
{
  std::vector<double> o;
  for (const auto &r : runs) o.push_back(r.onset);
  return o;
}

const std::vector<TraceRun> &runs_at(const RunsBySpeed &by, double v, const std::string &what)
{
  const auto it = by.find(v);
  if (it == by.end() || it->second.size() < 2)
    throw InputError("the prior's " + what + " has fewer than 2 runs at v0 = " + printf_number("%.4g", v));
  return it->second;
}

// the simulated knots' signatures of every effect on one grid (a transform's knots are the
// diagnosis's own: nothing to hold)
PriorGrid grid_signatures(const RunsBySpeed &base, const std::map<std::string, RunsBySpeed> &knots,
                          const std::vector<const Effect *> &effects, const GapGrid &grid)
{
  PriorGrid g;
  g.zmax = grid.zmax;
  for (const Effect *e : effects) {
    std::vector<PriorKnot> ks;
    for (double a : e->knots) {
      if (by_transform(*e, a)) continue;
      const std::string name = effect_sweep_name(*e, a);
      PriorKnot k;
      k.magnitude = a;
      for (const auto &[v, runs] : base) {
        const Ensemble eb = ensemble_of(runs, grid, v), ek = ensemble_of(runs_at(knots.at(name), v, "sweep " + name), grid, v);
        std::vector<double> sig(eb.mean.size()), var(eb.mean.size());
        for (std::size_t i = 0; i < sig.size(); ++i)
          sig[i] = ek.mean[i] - eb.mean[i], var[i] = ek.var[i] / ek.n() + eb.var[i] / eb.n();
        k.signature.push_back(sig);
        k.variance.push_back(var);
      }
      ks.push_back(k);
    }
    std::sort(ks.begin(), ks.end(), [](const PriorKnot &x, const PriorKnot &y) { return x.magnitude < y.magnitude; });
    g.effects[e->name] = ks;
  }
  return g;
}

Json table_json(const std::vector<std::vector<double>> &t)
{
  Json rows = Json::array();
  for (const auto &row : t) {
    Json r = Json::array();
    for (double x : row) r.push_back(json_rounded("%.9g", x));
    rows.push_back(r);
  }
  return rows;
}

// a value of the prior file, or GapRefused naming the file and the key
const Json &member(const Json &j, const std::string &key, const std::string &path)
{
  if (!j.is_object() || !j.contains(key)) throw GapRefused(path + ": not a signature prior (no key '" + key + "')");
  return j.at(key);
}

std::vector<std::vector<double>> table_of(const Json &j, const std::string &key, const std::string &path)
{
  try {
    return member(j, key, path).get<std::vector<std::vector<double>>>();
  } catch (const nlohmann::json::exception &) {
    throw GapRefused(path + ": key '" + key + "' is not a table of numbers");
  }
}

}    // namespace

SignaturePrior prior_from_runs(const std::string &scenario, const std::vector<std::string> &seeds, const RunsBySpeed &base_in,
                               const std::map<std::string, RunsBySpeed> &knots_in, const std::vector<const Effect *> &effects,
                               double max_depth)
{
  SignaturePrior p;
  p.scenario = scenario, p.seeds = seeds, p.beds = (int) seeds.size();
  RunsBySpeed base = base_in;
  std::map<std::string, RunsBySpeed> knots = knots_in;
  GapGrid grid;
  p.w = grid.w, p.window = grid.window, p.bands = grid.bands;
  // aligned as the diagnosis aligns: every run's onset at the baseline's mean onset
  double zdeep = max_depth;
  for (auto &[v, runs] : base) {
    p.speeds.push_back(v);
    runs_at(base, v, "baseline");
    const double ref = align_onsets(onsets_of(runs)).reference;
    align_runs(runs, ref);
    zdeep = std::min(zdeep, deepest_common(runs));
    for (auto &[name, by] : knots) {
      if (!by.count(v)) continue;
      align_runs(by[v], ref);
      zdeep = std::min(zdeep, deepest_common(by[v]));
    }
  }
  const double zmax0 = std::floor(zdeep / grid.w + 1e-9) * grid.w;
  for (int i = 0; i < PRIOR_DEPTHS; ++i) {
    grid.zmax = zmax0 - i * grid.w;
    if (grid.zmax < 1.0) break;
    p.grids.push_back(grid_signatures(base, knots, effects, grid));
  }
  if (p.grids.empty()) throw InputError("the prior's runs share less than 1 cm of depth");
  return p;
}

void write_prior(const std::string &path, const SignaturePrior &p)
{
  Json grids = Json::array();
  for (const PriorGrid &g : p.grids) {
    Json effects = Json::array();
    for (const auto &[name, ks] : g.effects) {
      Json knots = Json::array();
      for (const PriorKnot &k : ks)
        knots.push_back(Json{{"magnitude", json_rounded("%.9g", k.magnitude)}, {"signature", table_json(k.signature)},
                             {"variance", table_json(k.variance)}});
      effects.push_back(Json{{"effect", name}, {"knots", knots}});
    }
    grids.push_back(Json{{"zmax", json_rounded("%.9g", g.zmax)}, {"effects", effects}});
  }
  const Json j{{"format", "granpen-gap-prior"}, {"version", PRIOR_FORMAT}, {"scenario", p.scenario}, {"source", p.source},
               {"seeds", p.seeds}, {"beds", p.beds}, {"speeds", p.speeds}, {"w", p.w}, {"window", p.window},
               {"bands", p.bands}, {"what", "per grid depth, per effect and simulated knot (pour-level and push-only): the knot ensemble's binned "
                                            "features minus the baseline's on the same seeds, per speed and feature "
                                            "(physical units), and its variance of the mean"},
               {"grids", grids}};
  write_json(path, j, 1);
}

SignaturePrior read_prior(const std::string &path)
{
  Json j;
  try {
    j = read_json_file(path);
  } catch (const InputError &e) {
    throw GapRefused(std::string("--prior: ") + e.what());
  }
  if (!j.is_object() || j.value("format", "") != "granpen-gap-prior")
    throw GapRefused(path + ": not a signature prior (key 'format' is not \"granpen-gap-prior\")");
  if (member(j, "version", path) != PRIOR_FORMAT)
    throw GapRefused(path + ": key 'version': this granpen reads prior version " + std::to_string(PRIOR_FORMAT));
  SignaturePrior p;
  try {
    p.scenario = member(j, "scenario", path).get<std::string>();
    p.seeds = member(j, "seeds", path).get<std::vector<std::string>>();
    p.beds = member(j, "beds", path).get<int>();
    p.speeds = member(j, "speeds", path).get<std::vector<double>>();
    p.w = member(j, "w", path).get<double>(), p.window = member(j, "window", path).get<double>();
    p.bands = member(j, "bands", path).get<std::vector<double>>();
    for (const Json &g : member(j, "grids", path)) {
      PriorGrid pg;
      pg.zmax = member(g, "zmax", path).get<double>();
      for (const Json &e : member(g, "effects", path)) {
        std::vector<PriorKnot> ks;
        for (const Json &k : member(e, "knots", path))
          ks.push_back(PriorKnot{member(k, "magnitude", path).get<double>(), table_of(k, "signature", path),
                                 table_of(k, "variance", path)});
        pg.effects[member(e, "effect", path).get<std::string>()] = ks;
      }
      p.grids.push_back(pg);
    }
  } catch (const nlohmann::json::exception &) {
    throw GapRefused(path + ": a key of the signature prior has a value of the wrong type");
  }
  if (p.beds < 1) throw GapRefused(path + ": key 'beds' must be 1 or more");
  p.source = path;
  return p;
}

std::optional<SignaturePrior> find_prior(const std::string &option, const std::string &inputs, const std::string &scenario)
{
  if (option == "none") return std::nullopt;
  std::string path = option;
  if (path.empty()) {
    path = inputs + "/priors/" + scenario + ".json";
    if (!fs::exists(path)) return std::nullopt;
  }
  SignaturePrior p = read_prior(path);
  if (p.scenario != scenario)
    throw GapRefused("--prior " + path + ": a prior of scenario " + p.scenario + ", not of " + scenario);
  return p;
}

PriorSignatures prior_signatures(const SignaturePrior &p, const std::string &effect, const GapGrid &grid,
                                 const std::vector<double> &speeds)
{
  PriorSignatures out;
  if (p.w != grid.w || p.window != grid.window || p.bands != grid.bands) {
    out.missing = "the prior's bins are not the diagnosis's";
    return out;
  }
  const auto g = std::find_if(p.grids.begin(), p.grids.end(), [&](const PriorGrid &x) { return std::abs(x.zmax - grid.zmax) < 1e-6; });
  if (g == p.grids.end()) {
    out.missing = "the prior holds no grid " + printf_number("%.4g", grid.zmax) + " cm deep";
    return out;
  }
  const auto e = g->effects.find(effect);
  if (e == g->effects.end()) {
    out.missing = "the prior has no signature of " + effect;
    return out;
  }
  std::vector<std::size_t> at;
  for (double v : speeds) {
    const auto it = std::find_if(p.speeds.begin(), p.speeds.end(), [&](double x) { return std::abs(x - v) < 1e-9 * std::max(1.0, v); });
    if (it == p.speeds.end()) {
      out.missing = "the prior has no speed " + printf_number("%.4g", v) + " cm/s";
      return out;
    }
    at.push_back((std::size_t) (it - p.speeds.begin()));
  }
  for (const PriorKnot &k : e->second) {
    PriorKnot kk;
    kk.magnitude = k.magnitude;
    for (std::size_t i : at) {
      if (i >= k.signature.size() || i >= k.variance.size() || k.signature[i].size() != grid.nfeatures() ||
          k.variance[i].size() != grid.nfeatures()) {
        out.missing = "the prior's features of " + effect + " are not the grid's " + std::to_string(grid.nfeatures());
        return out;
      }
      kk.signature.push_back(k.signature[i]), kk.variance.push_back(k.variance[i]);
    }
    out.knots.push_back(kk);
  }
  return out;
}

namespace {

// e's model data with the prior's signatures as its knots (gap_which.h, effect_data's layout)
EffectData prior_effect_data(const Effect &e, const PriorSignatures &ps, const Features &f, double beds)
{
  EffectData ed;
  ed.name = e.name;
  ed.one_sided = e.one_sided;
  std::vector<std::pair<double, const PriorKnot *>> ks{{0.0, nullptr}};
  for (const PriorKnot &k : ps.knots) ks.push_back({k.magnitude, &k});
  std::sort(ks.begin(), ks.end(), [](const auto &a, const auto &b) { return a.first < b.first; });
  ed.ref_err.assign(1, Table());
  for (const auto &[a, k] : ks) {
    ed.knots.push_back(a);
    Table m, er, de;
    for (std::size_t s = 0; s < f.nspeeds(); ++s) {
      std::vector<double> mean = f.fresh[s].mean, var(mean.size());
      for (std::size_t i = 0; k && i < mean.size(); ++i) mean[i] += k->signature[s][i];
      for (std::size_t i = 0; i < mean.size(); ++i) var[i] = f.cv2[s][i] * mean[i] * mean[i] / beds;
      if (!k) ed.ref_err[0].push_back(var), var = f.fresh_err[s];
      m.push_back(mean), er.push_back(var), de.push_back(std::vector<double>(mean.size(), 0.0));
    }
    ed.mean.push_back(m), ed.err.push_back(er), ed.diff_err.push_back(de);
  }
  ed.scale_bound = GapThresholds::calibration_scale_bound;
  ed.noise_r2 = noise_residual(f.nulls, ed);
  return ed;
}

}    // namespace

std::optional<PriorBound> candidate_prior_bound(const SignaturePrior &p, const Effect &e, const Features &f,
                                                const GapGrid &grid, double scale_bound, std::string &missing)
{
  PriorSignatures ps = prior_signatures(p, e.name, grid, f.speeds);
  missing = ps.missing;
  if (!missing.empty()) return std::nullopt;
  PriorBoundInput in;
  // the knots its transform realises (the chain up to 2 ms) are the diagnosis's own, fitted
  // already: on the path as they are, and the bound over what lies beyond them
  const std::size_t n_prior = ps.knots.size();
  if (e.transform && has_simulated_knots(e)) {
    in.beyond = e.transform_max;
    for (double a : e.knots) {
      const auto own = f.knots.find(effect_sweep_name(e, a));
      if (!by_transform(e, a) || own == f.knots.end()) continue;
      PriorKnot k;
      k.magnitude = a;
      for (std::size_t s = 0; s < f.nspeeds(); ++s) {
        std::vector<double> sig(f.base[s].mean.size());
        for (std::size_t i = 0; i < sig.size(); ++i) sig[i] = own->second[s].mean[i] - f.base[s].mean[i];
        k.signature.push_back(sig), k.variance.push_back(std::vector<double>(sig.size(), 0.0));
      }
      ps.knots.push_back(k);
    }
  }
  in.scale_bound = scale_bound;
  in.one_sided = e.one_sided;    // the path of the fit (gap_fit.h): its knots, side and reach
  in.reach = EffectData().reach;
  const double own_beds = (double) SIGNATURE_SEEDS.size(), prior_beds = (double) p.beds;
  for (std::size_t s = 0; s < f.nspeeds(); ++s) {
    const auto &B = f.fresh[s].mean;
    std::vector<double> y(B.size()), V(B.size());
    for (std::size_t k = 0; k < B.size(); ++k) y[k] = f.target.mean[s][k] - B[k], V[k] = f.target.err[s][k] + f.fresh_err[s][k];
    in.gap.push_back(y), in.var.push_back(V), in.scale_dir.push_back(B);
  }
  for (std::size_t j = 0; j < ps.knots.size(); ++j) {
    const PriorKnot &k = ps.knots[j];
    const bool own = j >= n_prior;
    std::vector<std::vector<double>> U, W;
    for (std::size_t s = 0; s < f.nspeeds(); ++s) {
      const auto &B = f.fresh[s].mean;
      std::vector<double> u(B.size()), w(B.size());
      // a signature K - B on n beds each: cv2 (K^2 + B^2) / n, the noise model's
      for (std::size_t i = 0; i < B.size(); ++i) {
        const double two = f.cv2[s][i] * (std::pow(B[i] + k.signature[s][i], 2) + B[i] * B[i]);
        u[i] = two / own_beds, w[i] = own ? 0.0 : two / prior_beds;
      }
      U.push_back(u), W.push_back(w);
    }
    in.signature.push_back(k.signature), in.knot_var.push_back(U), in.prior_var.push_back(W), in.magnitude.push_back(k.magnitude);
    in.own.push_back(own);
  }
  PriorBound b = prior_bound(in);
  // the gap's noise share, as the candidate's own fit would take it (explained_fraction's n:
  // the null replicates' squared gap at magnitude 0, with the reference beds its knot 0)
  std::vector<std::size_t> all(f.nspeeds());
  for (std::size_t s = 0; s < all.size(); ++s) all[s] = s;
  b.noise = noise_of(prior_effect_data(e, ps, f, prior_beds), all);
  return b;
}


void add_prior_limits(const SignaturePrior &p, const std::vector<const Effect *> &all_effects,
                      const std::vector<const Effect *> &simulated, const Features &f, const GapGrid &grid,
                      std::vector<DetectionLimit> &limits)
{
  for (const Effect *e : all_effects) {
    // a candidate the plan skipped, pour-level or push-only (the chain fitted on its filter's
    // knots alone is simulated: its limit is its fit's)
    if (std::any_of(simulated.begin(), simulated.end(), [&](const Effect *x) { return x->name == e->name; })) continue;
    const PriorSignatures ps = prior_signatures(p, e->name, grid, f.speeds);
    if (!ps.missing.empty()) continue;
    const EffectData ed = prior_effect_data(*e, ps, f, (double) p.beds);
    limits.push_back(detection_limit(*e, ed, fit_candidate(ed, f), f));
  }
}

int write_signature_prior(const GapOptions &opt, const Scenario &sc, const std::vector<std::string> &v0,
                          const RunnerOptions &runner, const GapProgressFn &fn)
{
  const std::vector<std::string> seeds = opt.prior_seeds.empty() ? SIGNATURE_SEEDS : opt.prior_seeds;
  // The signature seeds (1 2) are the cache's own sweeps, the ones a cold diagnosis simulates
  // its knots on; other seeds, sweeps of their own beside them (prefix "prior41-42_"). Both
  // may be given ("1 2 41 42"): the prior then pools the two groups' runs, 4 beds whose cache's
  // own half costs nothing more (the prior's noise W halves: docs/gap.md, "The signature prior").
  std::vector<std::string> others;
  std::size_t own = 0;
  for (const std::string &s : seeds)
    if (std::find(SIGNATURE_SEEDS.begin(), SIGNATURE_SEEDS.end(), s) != SIGNATURE_SEEDS.end()) ++own;
    else others.push_back(s);
  if (own != 0 && own != SIGNATURE_SEEDS.size())
    throw InputError("--prior-seeds: the signature seeds (1 2, the cache's own sweeps) come all or none");
  std::vector<std::pair<std::vector<std::string>, std::string>> groups;    // seeds, sweep prefix
  if (own) groups.push_back({SIGNATURE_SEEDS, ""});
  if (!others.empty()) {
    std::string prefix = "prior";
    for (std::size_t i = 0; i < others.size(); ++i) prefix += (i ? "-" : "") + others[i];
    groups.push_back({others, prefix + "_"});
  }
  // every effect with simulated knots: the pour-level ones on beds of their own, the push-only
  // ones (and the chain beyond its filter) pushed into the prior's baseline beds
  std::vector<const Effect *> held;
  for (const Effect *e : choose_effects(opt.effects))
    if (has_simulated_knots(*e)) held.push_back(e);
  std::vector<SimRequest> req;
  std::string names;
  for (const auto &[g, prefix] : groups) {
    req.push_back(baseline_request(sc.name, v0, g, prefix + "baseline"));
    for (const Effect *e : held)
      for (SimRequest &r : knot_requests(sc.name, v0, *e, g, prefix)) req.push_back(std::move(r));
    names += (names.empty() ? "" : " and ") + (prefix.empty() ? std::string("1 2 (the cache's own)") : prefix);
  }
  if (fn)
    fn(GapProgress{GapProgress::INFO, "simulate", 0, 0,
                   format_text("the signature prior of %s: %zu sweeps on seeds %s in %s", sc.name.c_str(), req.size(),
                               names.c_str(), runner.out_root.c_str())});
  fs::create_directories(runner.out_root);
  if (run_requests(req, runner) != 0) return 1;
  // each group's runs, pooled per speed
  auto pooled = [&](const std::string &sweep) {
    RunsBySpeed out;
    for (const auto &[g, prefix] : groups)
      for (auto &[v, runs] : load_sweep_runs(runner.out_root, prefix + sweep))
        for (TraceRun &r : runs) out[v].push_back(std::move(r));
    return out;
  };
  std::map<std::string, RunsBySpeed> knots;
  for (const Effect *e : held)
    for (double a : e->knots)
      if (!by_transform(*e, a)) knots[effect_sweep_name(*e, a)] = pooled(effect_sweep_name(*e, a));
  SignaturePrior p = prior_from_runs(sc.name, seeds, pooled("baseline"), knots, held, sc.depth);
  std::string sweeps;
  for (const auto &[g, prefix] : groups) sweeps += (sweeps.empty() ? "" : ", ") + prefix + "baseline and " + prefix + "EFFECT_MAGNITUDE";
  p.source = "granpen gap --write-prior from the cache " + runner.out_root + " (sweeps " + sweeps + ")";
  write_prior(opt.write_prior, p);
  if (fn) {
    std::string list;
    for (const std::string &s : seeds) list += (list.empty() ? "" : " ") + s;
    fn(GapProgress{GapProgress::INFO, "report", 0, 0,
                   format_text("wrote the signature prior %s: %zu effects with simulated knots, %zu grid depths, seeds %s (%d beds)",
                               opt.write_prior.c_str(), held.size(), p.grids.size(), list.c_str(), p.beds)});
  }
  return 0;
}

}    // namespace granpen
