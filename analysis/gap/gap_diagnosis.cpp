// granpen gap: the diagnosis as its stages in order (see gap_diagnosis.h), the cache's
// preparation, and the cluster script.
#include "gap_diagnosis.h"

#include "effects.h"
#include "gap_adaptive.h"
#include "gap_align.h"
#include "scaling_laws.h"
#include "gap_confirm.h"
#include "gap_errors.h"
#include "gap_features.h"
#include "gap_inputs.h"
#include "gap_plan.h"
#include "gap_prior.h"
#include "gap_limits.h"
#include "gap_pairs.h"
#include "gap_report.h"
#include "gap_residual.h"
#include "gap_result.h"
#include "gap_sims.h"
#include "gap_thresholds.h"
#include "gap_where.h"
#include "gap_which.h"
#include "scenario.h"
#include "errors.h"
#include "slurm_script.h"
#include "text_util.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace granpen {

namespace fs = std::filesystem;

namespace {

// the progress callback with the stage it is in
struct Progress {
  const GapProgressFn &fn;
  void say(GapProgress::Kind kind, const char *stage, const std::string &message, int done = 0, int total = 0) const
  {
    if (fn) fn(GapProgress{kind, stage, done, total, message});
  }
};

std::string joined(const std::vector<std::string> &words)
{
  std::string s;
  for (const auto &w : words) s += (s.empty() ? "" : " ") + w;
  return s;
}

// --scenario NAME (a preset of inputs/presets) or FILE (a preset of the user's own)
Scenario load_scenario(const GapOptions &opt)
{
  return scenario_is_file(opt.scenario) ? read_scenario_file(opt.runner.inputs, opt.scenario)
                                        : read_scenario(opt.runner.inputs, opt.scenario);
}

// The options the simulating stages use: the scenario by its name and, for a user's file,
// the inputs folder staged in the cache (CACHE/_inputs/NAME: the decks unchanged, the file
// as presets/NAME.lmp). Writes only into the cache.
GapOptions for_scenario(const GapOptions &opt, const Scenario &sc)
{
  GapOptions o = opt;
  o.scenario = sc.name;
  if (scenario_is_file(opt.scenario)) o.runner.inputs = stage_scenario_inputs(sc, opt.runner.inputs, opt.cache + "/_inputs");
  return o;
}

// the grains of the probe pour (bench's bed 1), or 0 when the inputs lack the bench preset
// (plan_cost then takes the probe's .info)
double probe_grains(const std::string &inputs)
{
  try {
    return preset_grains(read_scenario(inputs, "bench"));
  } catch (InputError &) {
    return 0;
  }
}

// The parts of the effects that cost nothing (gap_adaptive.h): the transforms' knots (the
// force scale; the measurement chain up to 2 ms), in library order. With the baseline and the
// reference beds they are the cheap stage, fitted before anything is bought.
std::vector<const Effect *> free_parts(const std::vector<const Effect *> &effects)
{
  std::vector<const Effect *> out;
  for (const Effect *e : effects)
    if (const Effect *part = transform_part(*e)) out.push_back(part);
  return out;
}

// The plan before anything is simulated, printed in its one unit (probe pours of core time,
// wall time at --jobs from it): every knot, and, for a diagnosis, its range (the cheap stage
// alone, to every knot with the costliest confirmation, a pair's included: gap_plan.h,
// confirmation_most). false when its most exceeds --budget.
bool plan_within_budget(const GapOptions &given, const Scenario &sc, const std::vector<std::string> &v0s,
                        const std::vector<const Effect *> &effects, bool diagnosis, const Progress &progress, PlanRecord *record = nullptr)
{
  const std::string cache = given.cache + "/" + sc.name;
  const int jobs = given.runner.jobs;
  const double probe = probe_grains(given.runner.inputs);
  const PlanCost all = plan_cost(sc, signature_requests(sc.name, v0s, effects), cache, probe);
  progress.say(GapProgress::INFO, "plan", "plan: " + plan_summary(all, jobs) + " (scenario " + sc.name + ")");
  PlanCost most = all;
  if (diagnosis) {
    // the cheap stage: the baseline, the reference beds and the transforms (nothing simulated)
    const std::vector<const Effect *> cheap = free_parts(effects);
    // from what the cache lacks (printed, --budget); the record's as a cold cache runs it, to
    // hold what this run spent counted the same way
    auto range = [&](const std::string &from) {
      return std::make_pair(plan_cost(sc, signature_requests(sc.name, v0s, cheap), from, probe),
                            plan_cost(sc, signature_requests(sc.name, v0s, effects), from, probe) +
                                confirmation_most(sc, v0s, effects, from, probe));
    };
    const auto [least, most_now] = range(cache);
    const auto [cold_least, cold_most] = range("");
    most = most_now;
    PlanRecord r;
    r.jobs = jobs;
    r.least = cold_least.probe_pours, r.most = cold_most.probe_pours;
    r.wall_least = wall_probe_pours(cold_least, jobs), r.wall_most = wall_probe_pours(cold_most, jobs);
    r.decides = "which push-only candidates (the measurement chain's simulated knots beyond its filter among them), then "
                "which pour-level candidates, the cheap stage and the push-only candidates bought leave able to change the "
                "verdict (each simulated unless its bound, "
                "with a signature prior the likelihood ratio its prior's knots earn along the fit's path plus the margin of "
                "the diagnosis's own knots, without one the whole squared gap, stays below its threshold), "
                "then whether an effect is confirmed, which, and whether its magnitude is refined, and whether the "
                "pair stage confirms two effects at once";
    progress.say(GapProgress::INFO, "plan",
                 "plan: from " + cost_phrase(least, jobs) + " (the cheap stage alone) to " + cost_phrase(most, jobs) +
                     " (every knot and the costliest confirmation, a pair's included); where a run lands: " + r.decides);
    if (record) *record = r;
  }
  if (given.budget < 0 || most.core_hours <= given.budget) return true;
  progress.say(GapProgress::INFO, "plan",
               format_text("the plan's %.3g core-hours%s exceed --budget %.3g: stopping before anything starts "
                           "(raise --budget, narrow --effects or the speeds, or use --slurm)",
                           most.core_hours, diagnosis ? " at most" : "", given.budget));
  return false;
}

// the runner of a scenario's cache: CACHE/SCENARIO
RunnerOptions cache_runner(const GapOptions &opt)
{
  RunnerOptions runner = opt.runner;
  runner.out_root = opt.cache + "/" + opt.scenario;
  runner.progress_seconds = 30.0;
  return runner;
}

// --slurm: the cache's runs as two job arrays, the pours (one task per pour) and, after
// every pour has succeeded, the pushes (one task per push); each task is
// `gap --prepare-only ... --only K` on --ranks MPI ranks through srun
int write_cluster_script(const GapOptions &opt, const Scenario &sc, const std::vector<SimRequest> &req,
                         const RunnerOptions &runner, const Progress &progress)
{
  const PlanCost c = plan_cost(sc, req, runner.out_root, probe_grains(opt.runner.inputs));
  const ArrayTasks tasks = array_tasks(req);
  const std::string abs_cache = fs::absolute(opt.cache).string(), abs_inputs = fs::absolute(opt.runner.inputs).string();
  const std::string lmp = opt.runner.lmp.find('/') == std::string::npos ? opt.runner.lmp : fs::absolute(opt.runner.lmp).string();
  const std::string cli = this_executable("granpen-cli");
  for (const auto &p : {abs_cache, abs_inputs, lmp, cli, opt.v0, opt.effects.value_or("")})
    if (p.find_first_of("'\"") != std::string::npos)
      throw GapRefused("--slurm: a quote cannot go into a SLURM script: " + p);
  auto q = [](const std::string &s) { return "'" + s + "'"; };
  const std::string task = q(cli) + " gap --prepare-only --scenario " + q(sc.name) + " --v0 " + q(opt.v0) +
                           " --mpirun srun --ranks " + std::to_string(runner.ranks) + " --cache " + q(abs_cache) +
                           " --inputs " + q(abs_inputs) + " --lmp " + q(lmp) +
                           (opt.effects ? " --effects " + q(*opt.effects) : "") + " --only";
  const int np = (int) tasks.pours.size(), nq = (int) tasks.pushes.size();
  const std::vector<std::string> what = {
      "granpen gap: the " + sc.name + " cache (" + std::to_string(req.size()) + " sweeps; still to run: " +
          plan_summary(c, (int) tasks.pours.size() + (int) tasks.pushes.size()) + ").",
      "Submit with `bash " + opt.slurm + "` on the cluster: " + std::to_string(np) + " pours as one job array, then " +
          std::to_string(nq) + " pushes as a second array that starts when every pour has succeeded.",
      "Each task runs one planned run on " + std::to_string(runner.ranks) +
          " MPI ranks; a task whose run is done does nothing, so rerunning this script resumes."};
  write_slurm_arrays(what, {{"granpen-gap-" + sc.name + "-pour", "pours", 0, np - 1, task},
                            {"granpen-gap-" + sc.name + "-push", "pushes", np, np + nq - 1, task}},
                     runner.ranks, opt.slurm);
  progress.say(GapProgress::INFO, "plan",
               format_text("wrote %s: %d pours, then %d pushes, as two SLURM job arrays (%.3g core-hours still to run); "
                           "when they have run, rerun this diagnosis with --cache %s",
                           opt.slurm.c_str(), np, nq, c.core_hours, abs_cache.c_str()));
  return 0;
}

// --only K: task K of the --slurm arrays, alone
int run_array_task(const std::vector<SimRequest> &req, RunnerOptions runner, int k)
{
  const ArrayTasks tasks = array_tasks(req);
  const size_t np = tasks.pours.size(), n = np + tasks.pushes.size();
  if (k < 0 || (size_t) k >= n)
    throw GapRefused("--only " + std::to_string(k) + ": the cache's job arrays have tasks 0 to " + std::to_string(n - 1));
  const ArrayTask t = (size_t) k < np ? tasks.pours[k] : tasks.pushes[k - np];
  runner.only_index = t.run;
  runner.jobs = 1;
  return run_sweeps({req[t.request]}, runner) == 0 ? 0 : 1;
}

// What the stage so far saw (the effects fitted, on a record of its own: the diagnosis fits
// its own later), for the adaptive plan's bounds.
struct StageView {
  CheapStageSeen seen;
  Features f;
  GapGrid grid;
};
StageView see_stage(const Scenario &sc, const MeasuredData &measured, const std::vector<const Effect *> &fitted,
                    const std::string &cache)
{
  SimulatedRuns sims = load_simulations(cache, fitted);
  RunsBySpeed real = measured.runs;    // aligned here on a copy: the diagnosis aligns its own
  const Alignment al = align_and_bin(real, sims, sc.depth);
  StageView v{CheapStageSeen{}, build_features(real, sims, fitted, al.grid, measured.files.size()), al.grid};
  const FittedCandidates fit = fit_candidates(fitted, v.f, [&](const std::string &sweep) { return mean_phi0(cache, sweep); },
                                              gap_significance(v.f, al.grid));
  const std::vector<EffectFit> &rank = fit.evidence.ranking;
  const VerdictDecision verdict = decide_verdict(fit.evidence);
  // the whole squared gap in the fits' weights (no candidate fitted: not known, no bound)
  CheapStageSeen &seen = v.seen;
  seen.chi2_0 = rank.empty() ? INFINITY : 0.0;
  for (const EffectFit &r : rank) seen.chi2_0 = std::max(seen.chi2_0, r.chi2_0);
  if (!rank.empty()) seen.best = rank[0].name, seen.best_evidence = lr_evidence(rank[0]);
  seen.best_explains = verdict.verdict == Verdict::explained || verdict.verdict == Verdict::scale_only;
  seen.best_is_scale = verdict.verdict == Verdict::scale_only;
  seen.unexplained_stands = fit.evidence.omnibus && verdict.verdict == Verdict::unexplained && !verdict.between_knots;
  seen.unexplained = verdict.verdict == Verdict::unexplained;
  return v;
}

// The candidates whose simulated knots are still to buy, each with its cost and, with a
// signature prior, its bound before its knots (gap_prior.h); pairs: the library holds a filter
// the pair stage can pair a push-only partner with (gap_pairs.h)
std::vector<PlanCandidate> plan_candidates(const Scenario &sc, const std::vector<std::string> &v0s,
                                           const std::vector<const Effect *> &which, const std::string &cache,
                                           const StageView &view, const std::optional<SignaturePrior> &prior, double probe,
                                           bool pairs)
{
  std::vector<PlanCandidate> out;
  for (const Effect *e : which) {
    const std::vector<SimRequest> knots = knot_requests(sc.name, v0s, *e);
    PlanCandidate c{e->name, plan_cost(sc, knots, cache, probe).probe_pours, std::nullopt};
    c.cold_cost = cold_cost(sc, knots, probe).probe_pours;
    c.push_only = !e->pour_level;
    c.pair_partner = pairs && pair_partner(*e);
    if (prior) c.prior = candidate_prior_bound(*prior, *e, view.f, view.grid, GapThresholds::calibration_scale_bound, c.no_prior);
    out.push_back(c);
  }
  return out;
}

// The signature simulations, bought adaptively (gap_adaptive.h): the cheap stage first (the
// baseline, the reference beds; the transforms cost nothing), fitted on a record of its own;
// then each push-only candidate (and the chain beyond its filter) whose bound can still change
// the verdict; then, with what those bought fitted in, each pour-level candidate likewise.
// Returns the effects simulated, in library order (the chain as its filtered part when its
// simulated knots were skipped); the decisions go to record.
std::vector<const Effect *> simulate_adaptively(const Scenario &sc, const MeasuredData &measured,
                                                const std::vector<const Effect *> &effects, const RunnerOptions &runner,
                                                const std::optional<SignaturePrior> &prior, PlanRecord &record)
{
  const std::string &cache = runner.out_root;
  auto run = [&](const std::vector<const Effect *> &which) {
    if (run_requests(signature_requests(sc.name, measured.v0s, which), runner) != 0)
      throw InputError("some simulations failed: see the manifests under " + cache + " (rerun to retry them)");
  };
  std::vector<const Effect *> fitted = free_parts(effects), push, pour, bought;
  for (const Effect *e : effects)
    if (has_simulated_knots(*e)) (e->pour_level ? pour : push).push_back(e);
  run(fitted);
  const double probe = probe_grains(runner.inputs);    // the bench preset, read once
  const bool pairs = std::any_of(effects.begin(), effects.end(), [](const Effect *e) { return pair_filter(*e); });
  auto decide = [&](const std::vector<const Effect *> &which, const StageView &view) {
    for (const PurchaseDecision &d : decide_purchases(view.seen, plan_candidates(sc, measured.v0s, which, cache, view, prior, probe, pairs),
                                                      GapThresholds::lr_chi2_1_p1e4, GapThresholds::evidence_margin)) {
      record.decisions.push_back(d);
      if (d.simulate) bought.push_back(find_effect(d.effect));
    }
  };
  if (!push.empty()) {
    decide(push, see_stage(sc, measured, fitted, cache));
    run(bought);
  }
  // every effect as it is now fitted: bought whole, else its part that costs nothing
  auto as_fitted = [&] {
    std::vector<const Effect *> out;
    for (const Effect *e : effects)
      if (std::find(bought.begin(), bought.end(), e) != bought.end()) out.push_back(e);
      else if (const Effect *part = transform_part(*e)) out.push_back(part);
    return out;
  };
  if (!pour.empty()) {
    const std::size_t before = bought.size();
    decide(pour, see_stage(sc, measured, as_fitted(), cache));    // it sees the push-only candidates bought
    run(std::vector<const Effect *>(bought.begin() + before, bought.end()));
  }
  return as_fitted();
}

// What the diagnosis spent, counted as a cold cache runs it: the signature simulations of
// the effects simulated and the confirmation's runs (asked), in the plan's unit.
void record_spent(const Scenario &sc, const GapOptions &opt, const std::vector<std::string> &v0s,
                  const std::vector<const Effect *> &simulated, const std::vector<SimRequest> &asked, PlanRecord &record)
{
  std::vector<SimRequest> all = signature_requests(sc.name, v0s, simulated);
  for (const SimRequest &r : asked)
    if (std::none_of(all.begin(), all.end(), [&](const SimRequest &q) { return q.spec.name == r.spec.name; })) {
      all.push_back(r);
      record.confirmation.push_back(r.spec.name);
    }
  const PlanCost spent = cold_cost(sc, all, probe_grains(opt.runner.inputs));
  record.spent = spent.probe_pours;
  record.wall_spent = wall_probe_pours(spent, record.jobs);
  record.core_hours_spent = spent.core_hours;
}

// Stage 9 with stage 3 between its calls: the confirmation asks for its runs, the simulate
// stage runs them, and it is asked again until it needs none; the runs asked are kept in
// asked (the plan's record counts them).
Confirmation confirm_with_runs(const std::map<std::string, const Effect *> &by_name, const FittedCandidates &fitted,
                               const VerdictDecision &fits_verdict, const WhereResult &where, const Features &f,
                               const Alignment &al, const SimContext &sim, bool fit_only, std::vector<SimRequest> &asked)
{
  StageRuns simulated;
  ConfirmStep step = confirm_top_effect(by_name, fitted, fits_verdict, where, f, al, fit_only, simulated);
  while (step.need) {
    const Effect &e = *by_name.at(step.need->effect);
    for (auto &r : needed_requests(*step.need, e, sim)) asked.push_back(std::move(r));
    simulate_needed(*step.need, e, sim, simulated);
    step = confirm_top_effect(by_name, fitted, fits_verdict, where, f, al, fit_only, simulated);
  }
  return std::move(step.done);
}

// Stage 11b's confirmation with stage 3 between its calls, as confirm_with_runs.
PairConfirmation confirm_pair_with_runs(const PairSearch &search, const WhereResult &where, const Features &f,
                                        const Alignment &al, const SimContext &sim, bool fit_only, std::vector<SimRequest> &asked)
{
  StageRuns simulated;
  PairConfirmStep step = confirm_pair(search, where, f, al, fit_only, simulated);
  while (step.need) {
    const Effect &e = *find_effect(step.need->effect);
    for (auto &r : needed_requests(*step.need, e, sim)) asked.push_back(std::move(r));
    simulate_needed(*step.need, e, sim, simulated);
    step = confirm_pair(search, where, f, al, fit_only, simulated);
  }
  return std::move(step.done);
}

// Stage 11b: the pair search (null when not entered) and, for a named pair, its confirmation;
// then the verdict that stands (stands: given the singles', changed by a confirmed pair).
std::optional<PairStage> pair_stage(const std::vector<const Effect *> &effects, const FittedCandidates &fitted,
                                    const Features &f, const SimulatedRuns &sims, const Alignment &al, const WhereResult &where,
                                    const Confirmation &confirmation, const std::optional<Residual> &residual,
                                    const SimContext &sim, bool fit_only, const Progress &progress,
                                    std::vector<SimRequest> &asked, VerdictDecision &stands)
{
  PairSearch search = search_pairs(effects, fitted, f, sims, al, stands.verdict, residual);
  if (!search.entered) return std::nullopt;
  progress.say(GapProgress::INFO, "pairs", "two effects at once: " + search.why);
  PairStage st{std::move(search), std::nullopt};
  if (st.search.named) {
    st.confirmation = confirm_pair_with_runs(st.search, where, f, al, sim, fit_only, asked);
    stands = decide_verdict(fitted.evidence, &confirmation.outcome, &st.confirmation->outcome);
  }
  return st;
}

// what the confirm stage says it does, from the fits' verdict
std::string confirm_message(const VerdictDecision &fits_verdict, const std::vector<EffectFit> &ranking, bool fit_only)
{
  if (fits_verdict.between_knots && !ranking.empty())
    return "simulating " + ranking[0].name + " between its knots on fresh seeds";
  if (fits_verdict.verdict != Verdict::explained && fits_verdict.verdict != Verdict::scale_only) return "no effect to confirm";
  if (fit_only) return "not confirming (--fit-only)";
  return "confirming " + ranking[0].name + " on fresh seeds";
}

}    // namespace

int run_gap(const GapOptions &given, const GapProgressFn &fn)
{
  if (!given.prepare_only && given.slurm.empty() && given.write_prior.empty()) return run_gap_diagnosis(given, fn);
  const Progress progress{fn};
  const Scenario sc = load_scenario(given);
  const auto effects = choose_effects(given.effects);
  const std::vector<std::string> v0 = checked_speeds(given.v0, sc);
  if (!plan_within_budget(given, sc, v0, effects, false, progress)) return GAP_OVER_BUDGET;
  const GapOptions opt = for_scenario(given, sc);
  const RunnerOptions runner = cache_runner(opt);
  fs::create_directories(runner.out_root);
  const auto req = signature_requests(opt.scenario, v0, effects);
  if (!opt.slurm.empty()) return write_cluster_script(opt, sc, req, runner, progress);
  if (opt.only_task >= 0) return run_array_task(req, runner, opt.only_task);
  if (!opt.write_prior.empty()) return write_signature_prior(opt, sc, v0, runner, fn);
  progress.say(GapProgress::INFO, "simulate",
               format_text("preparing the %s cache in %s: %zu sweeps", opt.scenario.c_str(), runner.out_root.c_str(), req.size()));
  return run_requests(req, runner) == 0 ? 0 : 1;
}

namespace {
// Each candidate's fit, ranked by evidence, as progress lines.
void say_ranking(const Progress &progress, const std::vector<EffectFit> &ranking)
{
  for (std::size_t i = 0; i < ranking.size(); ++i) {
    const EffectFit &r = ranking[i];
    progress.say(GapProgress::DETAIL, "which",
                 format_text("%-20s magnitude %-10s explained %5.2f  held-out %5.2f  chi2 %.1f -> %.1f  lr %.1f (threshold %.1f)",
                        r.name.c_str(), printf_number("%.4g", r.magnitude).c_str(), r.explained, r.heldout_explained, r.chi2_0,
                        r.chi2, r.lr, r.lr_threshold),
                 (int) i + 1, (int) ranking.size());
  }
}
}    // namespace

int run_gap_diagnosis(const GapOptions &given, const GapProgressFn &fn)
{
  const Progress progress{fn};
  // 1 validate: nothing is started or written before the inputs pass
  const Scenario sc = load_scenario(given);
  const auto all_effects = choose_effects(given.effects);
  MeasuredData measured = read_measured(given.real, sc);
  const auto bench_rate = measured_false_alarms(given.runner.inputs, sc.name);    // the scenario's measured rate
  check_output_path(given.out, given.real, given.cache);
  const std::optional<SignaturePrior> prior = find_prior(given.prior, given.runner.inputs, sc.name);
  for (const auto &n : measured.notes) progress.say(GapProgress::WARNING, "validate", n);
  progress.say(GapProgress::INFO, "validate",
               format_text("%zu measured runs at %zu speeds (%s cm/s) against scenario %s", measured.files.size(),
                      measured.runs.size(), joined(measured.v0s).c_str(), sc.name.c_str()));

  // 2 plan, before anything is simulated: its range; nothing more when it exceeds --budget
  PlanRecord plan_record;
  if (!plan_within_budget(given, sc, measured.v0s, all_effects, true, progress, &plan_record)) return GAP_OVER_BUDGET;
  const GapOptions opt = for_scenario(given, sc);

  // 3 simulate: the cheap stage, then the pour-level candidates that can still change the
  // verdict (gap_adaptive.h; cached)
  const RunnerOptions runner = cache_runner(opt);
  const std::string &cache = runner.out_root;
  progress.say(GapProgress::STEP, "simulate",
               format_text("simulations of the baseline and %zu candidate effects (cache %s)", all_effects.size(), cache.c_str()), 1, 4);
  plan_simulations(sc, measured.v0s, all_effects, cache, opt.local);    // refuses a plan for a cluster
  fs::create_directories(cache);
  const std::vector<const Effect *> effects = simulate_adaptively(sc, measured, all_effects, runner, prior, plan_record);
  for (const auto &dec : plan_record.decisions) progress.say(GapProgress::INFO, "plan", dec.effect + ": " + dec.why);

  // 4 align and bin, 5 features and the noise model
  progress.say(GapProgress::STEP, "align", "comparing ensembles", 2, 4);
  SimulatedRuns sims = load_simulations(cache, effects);
  const Alignment al = align_and_bin(measured.runs, sims, sc.depth);
  const Features f = build_features(measured.runs, sims, effects, al.grid, measured.files.size());
  for (const auto &line : feature_dump(f)) progress.say(GapProgress::DEBUG, "features", line);

  // 6 where: the gap curves, the regimes, the observables, the omnibus test
  const WhereResult where = where_stage(f, measured.runs, sims, sc, al.grid);

  // 7 which: every effect's magnitude, explained fraction, leave-one-speed-out
  progress.say(GapProgress::STEP, "which", format_text("fitting %zu candidate effects", effects.size()), 3, 4);
  std::map<std::string, const Effect *> by_name;
  for (const Effect *e : effects) by_name[e->name] = e;
  const FittedCandidates fitted =
      fit_candidates(effects, f, [&](const std::string &sweep) { return mean_phi0(cache, sweep); }, where.omnibus);
  const std::vector<EffectFit> &ranking = fitted.evidence.ranking;
  say_ranking(progress, ranking);

  // 8 verdict on the fits alone: what the confirmation simulates
  const VerdictDecision fits_verdict = decide_verdict(fitted.evidence);

  // 9 confirm: the top effect on fresh seeds (3 simulate runs what it asks for)
  progress.say(GapProgress::STEP, "confirm", confirm_message(fits_verdict, ranking, opt.fit_only), 4, 4);
  std::vector<SimRequest> asked;
  const Confirmation confirmation = confirm_with_runs(by_name, fitted, fits_verdict, where, f, al,
                                                      SimContext{sc.name, measured.v0s, runner}, opt.fit_only, asked);

  // 8 verdict that stands: the fits' evidence and the confirmation's result
  const VerdictDecision verdict = decide_verdict(fitted.evidence, &confirmation.outcome);

  // 10 limits: how blind (the next measurement follows the verdict that stands)
  Blindness blind = how_blind(effects, fitted.data, f, ranking, verdict, confirmation.named_magnitude());
  if (prior) add_prior_limits(*prior, all_effects, effects, f, al.grid, blind.limits);    // the candidates skipped

  // 11 residual: what the gap left over
  const double peak_end = peak_regime_end(sc.D);
  std::optional<Residual> residual =
      residual_stage(f, measured.runs, sims.fresh, al.grid, peak_end, where, fitted, verdict, confirmation);

  // 11b pairs: two effects at once, when no single one explains and the residual moves the
  // spectrum (gap_pairs.h); a named pair confirmed on fresh runs decides the verdict that stands
  VerdictDecision stands = verdict;
  std::optional<PairStage> pairs = pair_stage(effects, fitted, f, sims, al, where, confirmation, residual,
                                              SimContext{sc.name, measured.v0s, runner}, opt.fit_only, progress, asked, stands);
  record_spent(sc, opt, measured.v0s, effects, asked, plan_record);

  // 12 record, 13 report
  DiagnosisInputs in{sc.name, opt.real, measured.files, measured.notes, al.grid, peak_end, f.n_reference};
  in.notes.insert(in.notes.end(), al.notes.begin(), al.notes.end());
  in.notes.insert(in.notes.end(), f.notes.begin(), f.notes.end());
  in.plan = std::move(plan_record);
  in.measured_false_alarms = bench_rate;
  const Diagnosis d =
      assemble_diagnosis(in, where, fitted, fits_verdict, confirmation, stands, blind, std::move(residual), std::move(pairs));
  write_gap_output(d, opt.out);
  progress.say(GapProgress::INFO, "report",
               format_text("verdict %s%s; G_all %.3f -> %.3f (%d measured runs per speed at least, %d simulated); %s",
                      verdict_name(d.verdict),
                      !d.tie.empty()    ? (" (" + tie_names(d.tie) + ")").c_str()
                      : !d.pair.empty() ? (" (" + d.pair[0] + " and " + d.pair[1] + ")").c_str()
                      : d.top_effect.empty() ? ""
                                             : (" (" + d.top_effect + ", magnitude " + printf_number("%.4g", d.magnitude) + ")").c_str(),
                      d.gap_before, d.gap_after, d.n_real_min, d.n_sim, (opt.out + "/diagnosis.json").c_str()));
  return 0;
}

}    // namespace granpen
