// granpen gap: the diagnosis as its stages in order (see gap_diagnosis.h), the cache's
// preparation, and the cluster script.
#include "gap_diagnosis.h"

#include "effects.h"
#include "gap_align.h"
#include "scaling_laws.h"
#include "gap_confirm.h"
#include "gap_errors.h"
#include "gap_features.h"
#include "gap_inputs.h"
#include "gap_plan.h"
#include "gap_limits.h"
#include "gap_report.h"
#include "gap_residual.h"
#include "gap_result.h"
#include "gap_sims.h"
#include "gap_where.h"
#include "gap_which.h"
#include "scenario.h"
#include "errors.h"
#include "slurm_script.h"
#include "text_util.h"

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

// The plan before anything is simulated: printed; false when it exceeds --budget (said).
bool plan_within_budget(const GapOptions &given, const Scenario &sc, const std::vector<SimRequest> &req,
                        const std::string &cache, const Progress &progress)
{
  double probe_grains = 0;
  try {
    probe_grains = preset_grains(read_scenario(given.runner.inputs, "bench"));
  } catch (InputError &) {
    // an inputs folder without the bench preset: the plan in core-hours only
  }
  const PlanCost c = plan_cost(sc, req, cache, probe_grains);
  progress.say(GapProgress::INFO, "plan", "plan: " + plan_summary(c) + " (scenario " + sc.name + ")");
  if (given.budget < 0 || c.core_hours <= given.budget) return true;
  progress.say(GapProgress::INFO, "plan",
               format_text("the plan's %.3g core-hours exceed --budget %.3g: stopping before anything starts "
                           "(raise --budget, narrow --effects or the speeds, or use --slurm)",
                           c.core_hours, given.budget));
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
  const PlanCost c = plan_cost(sc, req, runner.out_root, 0.0);
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
          plan_summary(c) + " at 1.1e7 atom-steps/s/core).",
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

// Stage 9 with stage 3 between its calls: the confirmation asks for its runs, the simulate
// stage runs them, and it is asked again until it needs none.
Confirmation confirm_with_runs(const std::map<std::string, const Effect *> &by_name, const FittedCandidates &fitted,
                               const VerdictDecision &fits_verdict, const WhereResult &where, const Features &f,
                               const Alignment &al, const SimContext &sim, bool fit_only)
{
  StageRuns simulated;
  ConfirmStep step = confirm_top_effect(by_name, fitted, fits_verdict, where, f, al, fit_only, simulated);
  while (step.need) {
    simulate_needed(*step.need, *by_name.at(step.need->effect), sim, simulated);
    step = confirm_top_effect(by_name, fitted, fits_verdict, where, f, al, fit_only, simulated);
  }
  return std::move(step.done);
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
  if (!given.prepare_only && given.slurm.empty()) return run_gap_diagnosis(given, fn);
  const Progress progress{fn};
  const Scenario sc = load_scenario(given);
  const auto effects = choose_effects(given.effects);
  const std::vector<std::string> v0 = checked_speeds(given.v0, sc);
  if (!plan_within_budget(given, sc, signature_requests(sc.name, v0, effects), given.cache + "/" + sc.name, progress))
    return GAP_OVER_BUDGET;
  const GapOptions opt = for_scenario(given, sc);
  const RunnerOptions runner = cache_runner(opt);
  fs::create_directories(runner.out_root);
  const auto req = signature_requests(opt.scenario, v0, effects);
  if (!opt.slurm.empty()) return write_cluster_script(opt, sc, req, runner, progress);
  if (opt.only_task >= 0) return run_array_task(req, runner, opt.only_task);
  progress.say(GapProgress::INFO, "simulate",
               format_text("preparing the %s cache in %s: %zu sweeps", opt.scenario.c_str(), runner.out_root.c_str(), req.size()));
  return run_requests(req, runner) == 0 ? 0 : 1;
}

int run_gap_diagnosis(const GapOptions &given, const GapProgressFn &fn)
{
  const Progress progress{fn};
  // 1 validate: nothing is started or written before the inputs pass
  const Scenario sc = load_scenario(given);
  const auto effects = choose_effects(given.effects);
  MeasuredData measured = read_measured(given.real, sc);
  check_output_path(given.out, given.real, given.cache);
  for (const auto &n : measured.notes) progress.say(GapProgress::WARNING, "validate", n);
  progress.say(GapProgress::INFO, "validate",
               format_text("%zu measured runs at %zu speeds (%s cm/s) against scenario %s", measured.files.size(),
                      measured.runs.size(), joined(measured.v0s).c_str(), sc.name.c_str()));

  // 2 plan, before anything is simulated; nothing more when it exceeds --budget
  if (!plan_within_budget(given, sc, signature_requests(sc.name, measured.v0s, effects), given.cache + "/" + sc.name,
                          progress))
    return GAP_OVER_BUDGET;
  const GapOptions opt = for_scenario(given, sc);

  // 3 simulate: the baseline and every effect knot (cached)
  const RunnerOptions runner = cache_runner(opt);
  const std::string &cache = runner.out_root;
  progress.say(GapProgress::STEP, "simulate",
               format_text("simulations of the baseline and %zu candidate effects (cache %s)", effects.size(), cache.c_str()), 1, 4);
  const SimulationPlan plan = plan_simulations(sc, measured.v0s, effects, cache, opt.local);
  fs::create_directories(cache);
  if (run_requests(plan.requests, runner) != 0)
    throw InputError("some simulations failed: see the manifests under " + cache + " (rerun to retry them)");

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
  for (std::size_t i = 0; i < ranking.size(); ++i) {
    const EffectFit &r = ranking[i];
    progress.say(GapProgress::DETAIL, "which",
                 format_text("%-20s magnitude %-10s explained %5.2f  held-out %5.2f  chi2 %.1f -> %.1f  lr %.1f (threshold %.1f)",
                        r.name.c_str(), printf_number("%.4g", r.magnitude).c_str(), r.explained, r.heldout_explained, r.chi2_0,
                        r.chi2, r.lr, r.lr_threshold),
                 (int) i + 1, (int) ranking.size());
  }

  // 8 verdict on the fits alone: what the confirmation simulates
  const VerdictDecision fits_verdict = decide_verdict(fitted.evidence);

  // 9 confirm: the top effect on fresh seeds (3 simulate runs what it asks for)
  progress.say(GapProgress::STEP, "confirm", confirm_message(fits_verdict, ranking, opt.fit_only), 4, 4);
  const Confirmation confirmation = confirm_with_runs(by_name, fitted, fits_verdict, where, f, al,
                                                      SimContext{sc.name, measured.v0s, runner}, opt.fit_only);

  // 8 verdict that stands: the fits' evidence and the confirmation's result
  const VerdictDecision verdict = decide_verdict(fitted.evidence, &confirmation.outcome);

  // 10 limits: how blind (the next measurement follows the verdict that stands)
  const Blindness blind = how_blind(effects, fitted.data, f, ranking, verdict, confirmation.named_magnitude());

  // 11 residual: what the gap left over
  const double peak_end = peak_regime_end(sc.D);
  std::optional<Residual> residual =
      residual_stage(f, measured.runs, sims.fresh, al.grid, peak_end, where, fitted, verdict, confirmation);

  // 12 record, 13 report
  DiagnosisInputs in{sc.name, opt.real, measured.files, measured.notes, al.grid, peak_end, f.n_reference};
  in.notes.insert(in.notes.end(), al.notes.begin(), al.notes.end());
  in.notes.insert(in.notes.end(), f.notes.begin(), f.notes.end());
  const Diagnosis d = assemble_diagnosis(in, where, fitted, fits_verdict, confirmation, verdict, blind, std::move(residual));
  write_gap_output(d, opt.out);
  progress.say(GapProgress::INFO, "report",
               format_text("verdict %s%s; G_all %.3f -> %.3f (%d measured runs per speed at least, %d simulated); %s",
                      verdict_name(d.verdict),
                      !d.tie.empty() ? (" (" + tie_names(d.tie) + ")").c_str()
                      : d.top_effect.empty() ? ""
                                             : (" (" + d.top_effect + ", magnitude " + printf_number("%.4g", d.magnitude) + ")").c_str(),
                      d.gap_before, d.gap_after, d.n_real_min, d.n_sim, (opt.out + "/diagnosis.json").c_str()));
  return 0;
}

}    // namespace granpen
