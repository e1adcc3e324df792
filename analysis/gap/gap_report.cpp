// granpen gap: diagnosis.json (exact names; other tools read them), report.md and its
// figures (io/plot_writer.h).
#include "gap_report.h"

#include "effects.h"
#include "gap_plan.h"
#include "gap_report_pairs.h"
#include "gap_thresholds.h"
#include "atomic_file.h"
#include "json_writer.h"
#include "plot_writer.h"
#include "sweep_cache.h"
#include "text_util.h"
#include "trace_reader.h"
#include "trace_writer.h"
#include "errors.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <system_error>

namespace granpen {

namespace fs = std::filesystem;

namespace {

Json num(double v, const char *f = "%.6g") { return json_rounded(f, v); }

Json str_or_null(const std::string &s) { return s.empty() ? Json() : Json(s); }

std::string f3(double v, const char *f = "%.3f") { return printf_number(f, v); }

Json confirmation_json(const Diagnosis &d)
{
  const bool tested = !d.tested_effect.empty();
  return Json{{"chi2_before", tested ? num(d.chi2_within_bound) : Json()},
              {"chi2_after", tested ? num(d.chi2_after) : Json()},
              {"explained_fraction", tested ? num(d.confirmed_fraction, "%.4f") : Json()},
              {"signature_sigma_before", tested ? num(d.proj_before, "%.4f") : Json()},
              {"signature_sigma_after", tested ? num(d.proj_after, "%.4f") : Json()}};
}

Json ranking_json(const Diagnosis &d)
{
  Json rows = Json::array();
  for (const auto &r : d.ranking) {
    Json row{{"effect", r.name},
             {"explained_fraction", num(r.explained, "%.4f")},
             {"score", num(r.score, "%.4f")},
             {"magnitude", num(r.magnitude)},
             {"magnitude_error", std::isfinite(r.magnitude_error) ? num(r.magnitude_error) : Json()},
             {"heldout_explained", num(r.heldout_explained, "%.4f")},
             {"chi2", num(r.chi2, "%.2f")},
             {"chi2_baseline", num(r.chi2_0, "%.2f")},
             {"chi2_within_bound", num(r.chi2_within_bound, "%.2f")},
             {"chi2_baseline_within_bound", num(r.chi2_0_within_bound, "%.2f")},
             {"at_edge", r.at_edge},
             {"likelihood_ratio", num(r.lr, "%.2f")},
             {"lr_null_mean", num(r.lr_null_mean, "%.3f")},
             {"lr_threshold", num(r.lr_threshold, "%.2f")},
             {"detected", r.detected},
             {"evidence", num(lr_evidence(r), "%.2f")}};
    const auto it = d.magnitude_note.find(r.name);
    if (it != d.magnitude_note.end()) row["note"] = it->second;
    rows.push_back(row);
  }
  return rows;
}

Json where_json(const Diagnosis &d)
{
  Json rows = Json::array();
  for (const auto &w : d.where)
    rows.push_back(Json{{"regime", w.regime}, {"observable", w.observable}, {"v0", num(w.v0)}, {"real", num(w.real)},
                        {"sim", num(w.sim)}, {"zscore", num(w.zscore, "%.3f")}, {"real_se", num(w.real_se)},
                        {"sim_se", num(w.sim_se)}, {"significant", w.significant}});
  return rows;
}

Json numbers(const std::vector<double> &v)
{
  Json a = Json::array();
  for (double x : v) a.push_back(num(x));
  return a;
}

// per speed: the gap before and after, and the gap curve
void speeds_json(const Diagnosis &d, Json &per_speed, Json &curve)
{
  per_speed = Json::array(), curve = Json::array();
  for (const auto &c : d.speeds) {
    per_speed.push_back(Json{{"v0", num(c.v0)},
                             {"gap_before", num(c.all_before())},
                             {"gap_after", num(c.all_after())},
                             {"n_real", c.n_real},
                             {"n_sim", c.n_base},
                             {"z_transient_end", num(c.z_transient_end)},
                             {"G_before", num(c.G_before)},
                             {"G_spec_before", num(c.Gs_before)},
                             {"G_after", num(c.G_after)},
                             {"G_spec_after", num(c.Gs_after)},
                             {"n_after", c.n_corr}});
    curve.push_back(Json{{"v0", num(c.v0)}, {"z", numbers(c.z)}, {"gap", numbers(c.gap)}, {"band", numbers(c.band)}});
  }
}

Json parts_json(const GapParts &p)
{
  return Json{{"G", num(p.G)}, {"G_spec", num(p.G_spec)}, {"G_all", num(p.all())}, {"runs_real", p.runs_real},
              {"runs_sim", p.runs_sim}};
}

// the plan's record (gap_adaptive.h): its range, what this run spent, what it simulated and skipped
Json plan_json(const PlanRecord &p)
{
  Json decisions = Json::array(), push_only = Json::array();
  for (const auto &x : p.decisions) {
    Json row{{"effect", x.effect}, {"simulated", x.simulate}, {"bound", num(x.bound)}, {"needed", num(x.needed)},
             {"cost", num(x.cost)}, {"cold_cost", num(x.cold_cost)}, {"why", x.why}};
    // the signature prior's bound and its parts (gap_adaptive.h, prior_bound)
    if (x.prior)
      row["prior"] = Json{{"projection2", num(x.prior->projection2)}, {"margin_direction", num(x.prior->margin_direction)},
                          {"margin_noise", num(x.prior->margin_noise)}};
    // the explain gate (gap_adaptive.h): the squared gap its fit can remove, and what a quarter of the gap needs
    if (x.gain_needed > 0) row["gain"] = num(x.gain), row["gain_needed"] = num(x.gain_needed);
    (x.push_only ? push_only : decisions).push_back(row);
  }
  return Json{{"unit", "probe pours of core time"}, {"jobs", p.jobs}, {"least", num(p.least)}, {"most", num(p.most)},
              {"spent", num(p.spent)}, {"wall_least", num(p.wall_least)}, {"wall_most", num(p.wall_most)},
              {"wall_spent", num(p.wall_spent)}, {"core_hours_spent", num(p.core_hours_spent)}, {"decides", p.decides},
              {"push_only", push_only}, {"pour_level", decisions}, {"confirmation", p.confirmation}};
}

Json optional_number(const std::optional<double> &v) { return v ? num(*v) : Json(); }

Json limits_json(const Diagnosis &d)
{
  Json rows = Json::array();
  for (const auto &L : d.limits)
    rows.push_back(Json{{"effect", L.effect},
                        {"limit", optional_number(L.limit)},
                        {"runs_needed", L.runs_needed ? Json(*L.runs_needed) : Json()},
                        {"reference", num(L.reference)},
                        {"limit_other_side", optional_number(L.limit_other_side)},
                        {"lr_threshold", num(L.threshold, "%.2f")},
                        {"unit", L.unit}});
  return rows;
}

Json false_alarms_json(const FalseAlarms &fa)
{
  Json verdicts = Json::object();
  for (const auto &[v, n] : fa.verdicts) verdicts[v] = n;
  return Json{{"null_replicates", fa.replicates}, {"not_none", fa.not_none}, {"rate", num(fa.rate(), "%.4f")},
              {"verdicts", verdicts}};
}

// the rate measured at the scenario's scale (gap_bench_rate.h); null when none is committed
Json measured_false_alarms_json(const std::optional<MeasuredFalseAlarms> &m)
{
  if (!m) return Json();
  return Json{{"sets", m->sets}, {"alarms", m->alarms}, {"rate", num(m->interval.rate, "%.4f")},
              {"low95", num(m->interval.low, "%.4f")}, {"high95", num(m->interval.high, "%.4f")},
              {"file", m->file}, {"source", m->source}};
}

Json look_alikes_json(const Diagnosis &d)
{
  Json rows = Json::array();
  for (const auto &l : d.look_alikes)
    rows.push_back(Json{{"a", l.a}, {"b", l.b}, {"angle_deg", num(l.angle_deg, "%.1f")},
                        {"separation", num(l.separation, "%.3g")}, {"look_alike", l.look_alike},
                        {"fit_separation", num(l.fit_separation, "%.3g")}});
  return rows;
}

Json knot_bends_json(const Diagnosis &d)
{
  Json rows = Json::array();
  for (const auto &b : d.knot_bends)
    rows.push_back(Json{{"effect", b.effect}, {"knot", num(b.knot, "%.6g")}, {"left", num(b.left, "%.6g")},
                        {"right", num(b.right, "%.6g")}, {"bend2", num(b.bend2, "%.3g")},
                        {"noise2", num(b.noise2, "%.3g")}, {"bend2_sd", num(b.bend2_sd, "%.3g")},
                        {"earns_cost", b.earns_cost}, {"resolved", b.resolved}});
  return rows;
}

Json next_json(const std::optional<NextMeasurement> &m)
{
  if (!m) return Json();
  return Json{{"goal", m->goal},          {"effects", m->effects},         {"v0", num(m->v0)},
              {"runs", m->runs},          {"expected_gain", num(m->gain(), "%.3g")}, {"now", num(m->now, "%.3g")},
              {"after", num(m->after, "%.3g")}, {"target", num(m->target, "%.3g")}, {"reaches", m->reaches}};
}

Json scale_only_json(const std::optional<ScaleFinding> &s)
{
  if (!s) return Json();
  Json causes = Json::array();
  for (const auto &c : s->causes)
    causes.push_back(Json{{"cause", c.cause},
                          {"what", c.what},
                          {"magnitude", num(c.magnitude)},
                          {"unit", c.unit},
                          {"separation2", c.separation2 < 0 ? Json() : num(c.separation2)},
                          {"tell_apart", c.tell_apart},
                          {"runs", c.runs && c.runs->reaches ? Json(c.runs->runs) : Json()},
                          {"v0", c.runs && c.runs->reaches ? num(c.runs->v0) : Json()}});
  return Json{{"scale", num(s->scale)},
              {"scale_error", std::isfinite(s->scale_error) ? num(s->scale_error) : Json()},
              {"bound", num(s->bound)},
              {"causes", causes}};
}

Json residual_json(const std::optional<Residual> &r)
{
  if (!r) return Json();
  Json lines = Json::array();
  for (const auto &l : r->lines)
    lines.push_back(Json{{"v0", num(l.v0)}, {"freq", num(l.freq, "%.4g")}, {"ratio", num(l.ratio, "%.3g")},
                         {"sigma", num(l.sigma, "%.3g")}});
  const bool where = !r->regimes.empty();
  return Json{{"against", r->against},
              {"regimes", r->regimes},
              {"z_from", where ? num(r->z_from) : Json()},
              {"z_to", where ? num(r->z_to) : Json()},
              {"bins_beyond_2sigma", r->bins_beyond},
              {"moves", r->moves},
              {"bin_means", Json{{"chi2", num(r->chi2_means, "%.2f")}, {"dof", r->dof_means}, {"p_value", num(r->p_means, "%.3g")}}},
              {"fluctuations", Json{{"chi2", num(r->chi2_fluct, "%.2f")}, {"dof", r->dof_fluct}, {"p_value", num(r->p_fluct, "%.3g")}}},
              {"band", r->band.empty() ? Json() : Json(r->band)},
              {"band_ratio", r->band.empty() ? Json() : num(r->band_ratio, "%.3g")},
              {"lines", lines},
              {"line_scaling", r->line_scaling.empty() ? Json() : Json(r->line_scaling)},
              {"nearest", r->nearest.empty() ? Json() : Json(r->nearest)},
              {"why_rejected", r->why_rejected.empty() ? Json() : Json(r->why_rejected)}};
}

// diagnosis.json: the keys in the order other tools have read them since version 1
Json diagnosis_json(const Diagnosis &d)
{
  Json j;
  j["verdict"] = verdict_name(d.verdict);
  j["top_effect"] = str_or_null(d.top_effect);
  j["magnitude"] = d.top_effect.empty() ? Json() : num(d.magnitude);
  j["magnitude_unit"] = str_or_null(d.magnitude_unit);
  j["tested_effect"] = str_or_null(d.tested_effect);
  j["scenario"] = d.scenario;
  j["real"] = d.real_dir;
  j["gap_before"] = num(d.gap_before);
  j["gap_after"] = num(d.gap_after);
  j["gap_metric"] = "shared/formats/gap-metric.md v2";
  j["gap_parts"] = Json{{"before", parts_json(d.parts_before)},
                        {"after", parts_json(d.parts_after)},
                        {"before_within_bound", Json{{"G_all", num(d.gap_within_bound)}, {"scale", num(d.scale_within_bound)}}}};
  j["tie"] = d.tie.empty() ? Json() : Json(d.tie);
  j["runs"] = Json{{"real_min_per_speed", d.n_real_min}, {"sim_per_speed", d.n_sim}};
  j["grid"] = Json{{"w", num(d.grid.w)}, {"zmax", num(d.grid.zmax)}, {"window", num(d.grid.window)}};
  j["significance"] = Json{{"chi2", num(d.chi2_0)},
                           {"chi2_within_bound", num(d.chi2_within_bound)},
                           {"scale_within_bound", num(d.scale_within_bound)},
                           {"features", d.nfeatures},
                           {"p_value", num(d.p_value, "%.3g")},
                           {"significant", d.significant},
                           {"route", !d.significant ? Json() : Json(d.targeted ? "targeted" : "omnibus")},
                           {"null_replicates", d.n_null}};
  j["confirmed"] = d.verdict != Verdict::explained && d.verdict != Verdict::scale_only && d.verdict != Verdict::pair
                       ? Json()
                       : Json(!d.provisional);
  j["scale_only"] = scale_only_json(d.scale_only);
  j["confirmation"] = confirmation_json(d);
  j["refinement"] = !d.refined ? Json()
                               : Json{{"from", num(d.refined_from)},
                                      {"gap_after_first", num(d.gap_after_first)},
                                      {"signature_sigma_after", num(d.proj_refined, "%.4f")}};
  Json regimes = Json::object();
  for (const auto &[reg, ba] : d.gap_by_regime) regimes[reg] = Json{{"before", num(ba.first)}, {"after", num(ba.second)}};
  j["gap_by_regime"] = regimes;
  j["heldout"] = Json{{"v0", num(d.heldout_v0)},
                      {"gap_before", num(d.heldout_before)},
                      {"gap_after", num(d.heldout_after)},
                      {"magnitude", d.tested_effect.empty() ? Json() : num(d.heldout_magnitude)}};
  Json per_speed, curve;
  speeds_json(d, per_speed, curve);
  j["per_speed"] = per_speed;
  j["ranking"] = ranking_json(d);
  j["where"] = where_json(d);
  j["gap_curve"] = curve;
  j["detection_limits"] = limits_json(d);
  j["false_alarms"] = false_alarms_json(d.false_alarms);
  j["false_alarms_measured"] = measured_false_alarms_json(d.measured_false_alarms);
  j["look_alikes"] = look_alikes_json(d);
  j["knot_bends"] = knot_bends_json(d);
  j["next_measurement"] = next_json(d.next);
  j["residual"] = residual_json(d.residual);
  j["pair"] = d.pair.empty() ? Json() : Json(d.pair);
  j["pairs"] = pair_stage_json(d.pairs);
  j["notes"] = d.notes;
  j["plan"] = plan_json(d.plan);
  // the rules' thresholds the verdict was decided by (gap_thresholds.h)
  Json thresholds = Json::object();
  for (const auto &[name, value] : gap_threshold_table()) thresholds[name] = num(value, "%.6g");
  j["thresholds"] = thresholds;
  return j;
}

std::vector<double> add(const std::vector<double> &a, const std::vector<double> &b, double s)
{
  std::vector<double> r(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) r[i] = a[i] + s * b[i];
  return r;
}

// A figure of one panel per speed, their legend in a column on the right.
SeriesFigure per_speed_figure(const std::string &name, const std::string &title, std::size_t speeds, int height)
{
  SeriesFigure f;
  f.name = name;
  f.title = title;
  f.columns = (int) speeds;
  f.width = 480 * (int) speeds + 300;
  f.height = height;
  f.grid_width = 1.0 - 300.0 / f.width;
  return f;
}

// A series of ensemble means with its +- 2 standard-error band.
PlotSeries mean_with_band(const std::string &title, const std::vector<double> &z, const std::vector<double> &mean,
                          const std::vector<double> &se, const char *colour)
{
  PlotSeries s{title, z, mean};
  s.band_lo = add(mean, se, -2);
  s.band_hi = add(mean, se, 2);
  s.colour = colour;
  return s;
}

// The residual: per speed its bin means against depth with the 2-sigma band, and below the
// ratio of the measured to the model's mean periodogram, the bands' edges and any line marked.
SeriesFigure residual_figure(const Residual &r, const GapGrid &grid)
{
  bool spectra = false;
  for (const auto &c : r.curves) spectra = spectra || !c.freq.empty();
  SeriesFigure fig = per_speed_figure("residual", "the residual (measured minus " + r.against +
                                                      "): bin means, and the fluctuation spectrum's ratio",
                                      r.curves.size(), spectra ? 820 : 460);
  for (const auto &c : r.curves) {
    SeriesPanel p;
    p.title = "v_0 = " + f3(c.v0, "%g") + " cm/s";
    p.xlabel = "depth z (cm)";
    p.ylabel = "F_{real} - F_{model} (dyne)";
    p.key = fig.panels.empty() ? "column" : "off";
    PlotSeries g{"residual of the bin means", c.z, c.resid};
    g.band_lo = add(std::vector<double>(c.z.size(), 0.0), c.band, -1), g.band_hi = c.band;
    g.band_title = "noise band (2 sigma)";
    g.colour = "#000000";
    g.style = "linespoints";
    p.series = {g};
    p.guides = {PlotGuide{"0", ""}};
    fig.panels.push_back(p);
  }
  for (std::size_t s = 0; spectra && s < r.curves.size(); ++s) {
    const auto &c = r.curves[s];
    SeriesPanel p;
    p.title = "v_0 = " + f3(c.v0, "%g") + " cm/s: spectrum";
    p.xlabel = "frequency (Hz)";
    p.ylabel = "power, measured / model";
    p.logx = p.logy = true;
    p.xmin = 40, p.xmax = 5000;
    p.key = "off";
    PlotSeries q{"mean periodogram ratio", c.freq, c.ratio};
    q.colour = "#1f77b4";
    q.line_width = 1.2;
    p.series = {q};
    p.guides = {PlotGuide{"1", ""}};
    for (double e : grid.bands) p.vlines.push_back(PlotVLine{e, f3(e, "%g")});
    for (const auto &l : r.lines)
      if (l.v0 == c.v0) p.vlines.push_back(PlotVLine{l.freq, "line " + f3(l.freq, "%.0f") + " Hz", "#d62728", 1});
    if (c.freq.empty()) p.title += " (no runs)";
    fig.panels.push_back(p);
  }
  return fig;
}

// The figures into dir/figures: the names drawn, and why any was not (said in the report).
void draw_figures(const Diagnosis &d, const std::string &dir, std::vector<std::string> &figures,
                  std::vector<std::string> &failures)
{
  auto draw = [&](const PlotFiles &pf) {
    const PlotResult r = write_plot(dir + "/figures", pf);
    if (!r.ok()) failures.push_back(r.error);
    else figures.push_back(pf.name);
  };

  // measured vs simulated vs corrected F(z), one panel per speed
  SeriesFigure fz = per_speed_figure(
      "force_depth", "F(z): measured, simulated (baseline) and corrected, ensemble means +- 2 s.e.", d.speeds.size(), 500);
  for (const auto &c : d.speeds) {
    SeriesPanel p;
    p.title = "v_0 = " + f3(c.v0, "%g") + " cm/s";
    p.xlabel = "depth z (cm)";
    p.ylabel = "F (dyne)";
    p.key = fz.panels.empty() ? "column" : "off";
    p.series = {mean_with_band("measured (" + std::to_string(c.n_real) + ")", c.z, c.real, c.real_se, "#000000"),
                mean_with_band("baseline (" + std::to_string(c.n_base) + ")", c.z, c.base, c.base_se, "#d62728")};
    if (!d.tested_effect.empty()) {
      std::string effect = d.tested_effect;
      std::replace(effect.begin(), effect.end(), '_', ' ');
      p.series.push_back(
          mean_with_band("with " + effect + " (" + std::to_string(c.n_corr) + ")", c.z, c.corr, c.corr_se, "#1f77b4"));
    }
    fz.panels.push_back(p);
  }
  draw(series_figure(fz));

  // the gap curve with its band
  SeriesFigure gc = per_speed_figure(
      "gap_curve", "measured minus simulated F, with the 2-sigma noise band of the difference", d.speeds.size(), 460);
  for (const auto &c : d.speeds) {
    SeriesPanel p;
    p.title = "v_0 = " + f3(c.v0, "%g") + " cm/s, G = " + f3(c.G_before);
    p.xlabel = "depth z (cm)";
    p.ylabel = "F_{real} - F_{sim} (dyne)";
    p.key = gc.panels.empty() ? "column" : "off";
    PlotSeries g{"gap", c.z, c.gap};
    std::vector<double> zero(c.z.size(), 0.0);
    g.band_lo = add(zero, c.band, -1), g.band_hi = c.band;
    g.band_title = "noise band (2 sigma)";
    g.colour = "#000000";
    p.series = {g};
    p.guides = {PlotGuide{"0", ""}};
    p.vlines = {PlotVLine{d.peak_end, "peak"}};
    if (c.z_transient_end < d.grid.zmax) p.vlines.push_back(PlotVLine{c.z_transient_end, "linear"});
    gc.panels.push_back(p);
  }
  draw(series_figure(gc));

  // each candidate's explained fraction
  BarChart bc;
  bc.name = "explained";
  bc.title = "fraction of the gap each candidate explains at its fitted magnitude";
  bc.ylabel = "explained fraction";
  bc.ymin = 0;
  bc.ymax = 1.05;
  for (const auto &r : d.ranking) {
    bc.labels.push_back(r.name);
    bc.values.push_back(std::max(0.0, r.explained));
  }
  bc.guides = {PlotGuide{"0.5", "0.5: needed for explained"}};
  if (!bc.labels.empty()) draw(bar_chart(bc));
  if (d.residual && !d.residual->curves.empty()) draw(series_figure(residual_figure(*d.residual, d.grid)));
}

// the verdict in plain words (first screen)
std::string plain_verdict(const Diagnosis &d)
{
  const EffectFit *named = nullptr;
  for (const auto &r : d.ranking)
    if (r.name == d.top_effect) named = &r;
  switch (d.verdict) {
  case Verdict::none: return "No gap beyond the noise: as far as these traces can tell, the simulation matches them.";
  case Verdict::tie: return "The gap is explained by one of " + tie_names(d.tie) + ", which these traces cannot tell apart.";
  case Verdict::scale_only:
    return format_text("The force is %.1f%% %s at every depth and speed: a uniform scale, not a physical effect (a "
                       "calibration, the grains' density, or a look-alike: see Scale only).",
                       100.0 * std::fabs(d.scale_only ? d.scale_only->scale : d.magnitude),
                       (d.scale_only ? d.scale_only->scale : d.magnitude) >= 0 ? "high" : "low");
  case Verdict::unexplained:
    return "There is a gap that no candidate effect explains" +
           (d.residual && !d.residual->nearest.empty() ? " (nearest: " + d.residual->nearest + ", see Residual)." : std::string("."));
  case Verdict::pair: return d.pairs ? pair_plain_verdict(*d.pairs, d.provisional) : "Two effects at once.";
  case Verdict::explained: break;
  }
  const Effect *e = find_effect(d.top_effect);
  std::string s = "The gap is explained by " + d.top_effect + (e ? " (" + e->what + ")" : "") + ": " +
                  f3(d.magnitude, "%.4g") + " " + d.magnitude_unit;
  if (named && std::isfinite(named->magnitude_error)) s += format_text(", standard error %.2g", named->magnitude_error);
  return s + (d.provisional ? "; provisional (--fit-only: not confirmed)." : "; confirmed on fresh seeds.");
}

// the candidate whose evidence the first screen quotes: the named one, else the top
const EffectFit *quoted_candidate(const Diagnosis &d)
{
  const std::string &name = !d.top_effect.empty() ? d.top_effect : !d.scale_effect.empty() ? d.scale_effect
                                                                   : !d.tie.empty()          ? d.tie[0]
                                                                                             : std::string();
  for (const auto &r : d.ranking)
    if (r.name == name || (name.empty() && &r == &d.ranking[0])) return &r;
  return nullptr;
}

// report.md's first screen: what a user needs first, every number one of diagnosis.json's
std::string md_first_screen(const Diagnosis &d)
{
  std::string md = "## In short\n\n- **" + std::string(verdict_name(d.verdict)) + "**: " + plain_verdict(d) + "\n";
  if (const EffectFit *q = quoted_candidate(d))
    md += format_text("- Evidence: %s's likelihood ratio %.1f is %s its threshold %.1f; the gap over all %zu features "
                      "chi^2 %.1f (p = %.2g, significant below %g, the tests' family-wise false-alarm rate). On this data's "
                      "%d null replicates: %d verdict(s) other than none (rate %.2f).\n",
                      q->name.c_str(), q->lr, q->lr > q->lr_threshold ? "above" : "not above", q->lr_threshold, d.nfeatures, d.chi2_0, d.p_value, GapThresholds::significance_p,
                      d.false_alarms.replicates, d.false_alarms.not_none, d.false_alarms.rate());
  // a tie's confirmation simulates one of its candidates: its runs shrink the gap as the others
  // would, so the line says whose runs they are and that they do not separate the tie
  std::string with = d.tested_effect.empty() ? " (nothing added)" : " with " + d.tested_effect + " on fresh seeds";
  if (d.verdict == Verdict::tie && !d.tested_effect.empty()) {
    std::vector<std::string> others;
    for (const auto &t : d.tie)
      if (t != d.tested_effect) others.push_back(t);
    if (!others.empty()) with += " (one of the tie: these runs cannot tell it from " + tie_names(others) + ")";
  }
  md += format_text("- Gap G_all %.3f before, %.3f after%s; at the held-out speed %g cm/s %.3f -> %.3f.\n", d.gap_before,
                    d.gap_after, with.c_str(), d.heldout_v0, d.heldout_before, d.heldout_after);
  if (d.verdict == Verdict::none) {
    std::string lims;
    for (const auto &L : d.limits) {
      const Effect *e = find_effect(L.effect);
      if (!e || !common_in_labs(*e)) continue;
      lims += (lims.empty() ? "" : "; ") + L.effect + " " + (L.limit ? f3(*L.limit, "%.3g") : std::string("beyond its knots")) +
              " (reference " + f3(L.reference, "%.3g") + ")";
    }
    if (!lims.empty()) md += "- How blind: detection limits of the effects commonest in labs: " + lims + ". Below its limit an effect can be there unseen.\n";
  }
  if (d.verdict == Verdict::scale_only && d.scale_only && !d.scale_only->causes.empty())
    md += "- Next: " + d.scale_only->causes[0].tell_apart + " (no run, no simulation); then " + d.scale_only->causes[1].tell_apart + ".\n";
  else if (d.next && d.next->after > 0) {
    const NextMeasurement &m = *d.next;
    const std::string what = std::string(m.reaches ? "" : "go furthest to ") +
                             (m.goal == "separate" ? "separate " + m.effects[0] + " from " + m.effects[1] : "detect " + m.effects[0]);
    md += format_text("- Next: %d more measured run(s) at %g cm/s would %s (%s %.2f -> %.2f, %s %.2f)%s; cost: those "
                      "runs in the lab, no new simulation (the cache holds every signature).\n",
                      m.runs, m.v0, what.c_str(),
                      m.goal == "separate" ? "squared separation" : "expected likelihood ratio", m.now, m.after,
                      m.goal == "separate" ? "margin" : "threshold", m.target, m.reaches ? "" : ", not reached within 64 runs");
  } else if (d.verdict == Verdict::explained)
    md += "- Next: nothing needed to stand by this answer; the simulation with it added is in `corrected/`.\n";
  return md + "\n";
}

// report.md's top: the verdict and the gap before and after
std::string md_summary(const Diagnosis &d)
{
  std::string md;
  md += format_text("# granpen gap: %s\n\n", d.real_dir.c_str());
  md += md_first_screen(d);
  md += format_text("Scenario `%s`; grid 0 < z <= %.2f cm in %.2f cm bins; at least %d measured run(s) per speed; the "
                  "baseline on %d reference beds (before), each effect's signature on %zu beds per magnitude, the "
                  "confirmation on %zu fresh beds (after).\n\n",
               d.scenario.c_str(), d.grid.zmax, d.grid.w, d.n_real_min, d.n_sim, SIGNATURE_SEEDS.size(),
               CONFIRM_SEEDS.size());
  const std::string named = !d.tie.empty() ? " — " + tie_names(d.tie) + ": they cannot be told apart here"
                            : d.scale_only ? format_text(" — the force is %.1f%% %s at every depth and speed, no physical effect named",
                                                         100.0 * std::fabs(d.scale_only->scale), d.scale_only->scale >= 0 ? "high" : "low")
                            : d.top_effect.empty()
                                ? ""
                                : " — " + d.top_effect + " at magnitude " + f3(d.magnitude, "%.4g") + " (" + d.magnitude_unit + ")";
  md += format_text("**Verdict: %s%s**%s.  \n", verdict_name(d.verdict), d.provisional ? " (provisional: not confirmed, --fit-only)" : "",
                    named.c_str());
  const GapParts &b = d.parts_before, &a = d.parts_after;
  md += format_text("Overall gap G_all (shared/formats/gap-metric.md v2): %.3f before, %.3f after%s; its parts: G (bin "
                    "means) %.3f -> %.3f, G_spec (fluctuation spectrum) %.3f -> %.3f (%d measured runs per speed against "
                    "%d simulated before, %d after).  \n",
                    d.gap_before, d.gap_after,
                    d.tested_effect.empty() ? " (nothing added)" : (" adding " + d.tested_effect + " on fresh seeds").c_str(),
                    b.G, a.G, b.G_spec, a.G_spec, b.runs_real, b.runs_sim, a.runs_sim);
  md += format_text("Against the baseline within the calibration bound (its force times 1 + c0, c0 = %.4g the scale a "
                    "lab's calibration allows that brings it nearest the data in the chi^2's weights: the footing of the "
                    "\"after\", whose runs are compared times 1 + the scale fitted with the effect): G_all %.3f.  \n",
                    d.scale_within_bound, d.gap_within_bound);
  md += format_text("Held-out speed %.4g cm/s: %.3f before, %.3f after.  \n", d.heldout_v0, d.heldout_before, d.heldout_after);
  md += format_text("Gap significance: chi^2 = %.1f over %zu features, p = %.3g%s.", d.chi2_0, d.nfeatures, d.p_value,
               d.targeted ? " (not significant over all features; found along one candidate's signature, see Which)" : "");
  if (!d.tested_effect.empty())
    md += format_text(" With %s on fresh seeds: chi^2 %.1f (against the baseline within the calibration bound) -> %.1f "
                    "(%.0f%% of the excess removed); the gap along its signature %.2f -> %.2f standard deviations.",
                 d.tested_effect.c_str(), d.chi2_within_bound, d.chi2_after, 100.0 * d.confirmed_fraction, d.proj_before,
                 d.proj_after);
  if (d.refined)
    md += format_text(" That left the gap significant along the signature, so the magnitude was refined from %.4g to %.4g "
                    "by linear response and simulated on %zu more fresh beds (G_all %.3f -> %.3f; %.2f standard deviations "
                    "left along the signature): the gap after and the corrected curves are these runs'.",
                 d.refined_from, d.magnitude, REFINE_SEEDS.size(), d.gap_after_first, d.gap_after, d.proj_refined);
  md += format_text("\n\n");
  return md;
}
// report.md's Where: the observables per regime and G per regime
std::string md_where(const Diagnosis &d)
{
  std::string md;
  md += format_text("## Where\n\n| regime | observable | v0 (cm/s) | measured | simulated | z-score |\n|---|---|---|---|---|---|\n");
  for (const auto &w : d.where)
    md += format_text("| %s | %s | %.4g | %.4g +- %.2g | %.4g +- %.2g | %s%.2f%s |\n", w.regime.c_str(), w.observable.c_str(),
                 w.v0, w.real, w.real_se, w.sim, w.sim_se, w.significant ? "**" : "", w.zscore, w.significant ? "**" : "");
  md += format_text("\nA finding is significant (bold) when |z| > 3, z = (measured - simulated) / sqrt(se_m^2 + se_s^2), "
                  "standard errors from the run-to-run variance pooled over every simulated ensemble of the speed "
                  "(the measured side's scaled by how much more its runs scatter); peak: z <= 0.35 D, transient: up "
                  "to the baseline's crossover depth, linear: beyond.\n\n");
  md += format_text("| regime | G before | G after |\n|---|---|---|\n");
  for (const auto &[reg, ba] : d.gap_by_regime) md += format_text("| %s | %.3f | %.3f |\n", reg.c_str(), ba.first, ba.second);
  return md;
}

// report.md's Which: every candidate's fit and test
std::string md_which(const Diagnosis &d)
{
  std::string md;
  md += format_text("\n## Which\n\n| effect | magnitude | explained | held-out explained | chi^2 as simulated (baseline "
                    "%.1f) | chi^2 within the calibration bound (baseline %.1f) | likelihood ratio | its threshold | "
                    "evidence |\n|---|---|---|---|---|---|---|---|---|\n",
                    d.ranking.empty() ? 0.0 : d.ranking[0].chi2_0, d.ranking.empty() ? 0.0 : d.ranking[0].chi2_0_within_bound);
  for (const auto &r : d.ranking) {
    auto it = d.magnitude_note.find(r.name);
    md += format_text("| %s | %.4g%s%s | %.2f | %.2f | %.1f | %.1f | %s%.1f%s | %.1f | %.1f |\n", r.name.c_str(), r.magnitude,
                      r.at_edge ? " (edge)" : "", it == d.magnitude_note.end() ? "" : (" (" + it->second + ")").c_str(),
                      r.explained, r.heldout_explained, r.chi2, r.chi2_within_bound, r.detected ? "**" : "", r.lr,
                      r.detected ? "**" : "", r.lr_threshold, lr_evidence(r));
  }
  md += format_text("\nchi^2 over every feature at the fitted magnitude (baseline: at magnitude 0), as simulated and "
                    "within the calibration bound: the prediction times 1 + the force scale fitted with it (|c| <= "
                    "%g%%; at magnitude 0 the baseline's c0), the footing of the verdict's chi^2 before and after. The "
                    "baselines are Gap significance's raw chi^2 and the chi^2 before of its confirmation.\n",
                    100.0 * GapThresholds::calibration_scale_bound);
  md += format_text("\nThe fits measure the gap against the baseline on %d reference beds of their own (not the "
                  "signature beds). Explained: the part of the noise-weighted squared gap the fit removes, as a "
                  "fraction of its excess over what noise alone leaves. Likelihood ratio: -2 log of the likelihood "
                  "at magnitude 0 over that at the fitted magnitude (a chi^2 with one degree of freedom without the "
                  "effect, were the noise model exact); its threshold: %.2f (`thresholds.lr_chi2_1_p1e4`, "
                  "the point that chi^2 exceeds with the probability its name gives) times the ratio's mean over "
                  "%d null replicates (some reference beds taken as a measurement, the rest as its reference), at "
                  "least 1. Bold: above it. Evidence: the likelihood ratio less the null mean's excess over 1 (what "
                  "a noisy signature fits of any noise); candidates are ranked by it and told apart by a margin of "
                  "6.\n",
               d.n_reference, GapThresholds::lr_chi2_1_p1e4, d.n_null);
  return md;
}

// report.md's How blind: detection limits, false alarms, look-alikes, the next measurement
std::string md_blind(const Diagnosis &d)
{
  auto opt = [](const std::optional<double> &v) { return v ? f3(*v, "%.3g") : std::string("beyond the knots"); };
  std::string md = "\n## How blind\n\n| effect | first reference value | detection limit | other side | measured runs "
                   "per speed for the limit to reach the reference | threshold |\n|---|---|---|---|---|---|\n";
  for (const auto &L : d.limits)
    md += format_text("| %s | %.3g (%s) | %s | %s | %s | %.1f |\n", L.effect.c_str(), L.reference, L.unit.c_str(),
                      opt(L.limit).c_str(), L.limit_other_side ? opt(L.limit_other_side).c_str() : "-",
                      L.runs_needed ? std::to_string(*L.runs_needed).c_str() : "more than 64", L.threshold);
  md += format_text("\nDetection limit: the smallest magnitude whose simulated signature (the knots, interpolated, "
                    "less what their own noise adds) reaches the effect's likelihood-ratio threshold at this data's "
                    "noise: the test then detects it half the time. A `none` for an effect below its limit is a right "
                    "answer. Runs needed: measured runs per speed (their standard errors scale as 1/sqrt(n), the "
                    "%d reference beds' stay) that bring the limit down to the first reference value.\n\n",
                    d.n_reference);
  const FalseAlarms &fa = d.false_alarms;
  md += format_text("False alarms on the %d null replicates (reference beds taken as a measurement without any effect, "
                    "each tested with thresholds calibrated on the others): %d verdict(s) other than none (rate %.2f).\n",
                    fa.replicates, fa.not_none, fa.rate());
  if (const auto &m = d.measured_false_alarms)
    md += format_text("At scenario %s's scale on real LAMMPS (%s): %d verdict(s) other than none in %d data sets without an "
                      "effect, a false-alarm rate of %.3f (95%% interval %.3f to %.3f, exact).\n",
                      d.scenario.c_str(), m->file.c_str(), m->alarms, m->sets, m->interval.rate, m->interval.low, m->interval.high);
  else
    md += format_text("No false-alarm rate measured at scenario %s's scale on real LAMMPS yet (validation/gap_bench.sh).\n",
                      d.scenario.c_str());
  if (!d.look_alikes.empty()) {
    md += "\n| candidates | angle between signatures (deg) | separation at the reference values (sigma) | look alike "
          "| separation of the fits (sigma) |\n|---|---|---|---|---|\n";
    const std::string top = d.ranking.empty() ? "" : d.ranking[0].name;
    const std::string second = d.ranking.size() > 1 ? d.ranking[1].name : "";
    for (const auto &l : d.look_alikes)
      if (l.look_alike || l.a == top || l.b == top || l.a == second || l.b == second)
        md += format_text("| %s, %s | %.0f | %.2f | %s | %.2f |\n", l.a.c_str(), l.b.c_str(), l.angle_deg, l.separation,
                          l.look_alike ? "**yes**" : "no", l.fit_separation);
    md += format_text("\nThe pairs with one of the top two candidates, and every look-alike (all pairs: diagnosis.json). "
                      "Angle: between the two signatures at their first reference values, in features whitened by this "
                      "data's noise (0: the same shape, 180: opposite). Separation: how many standard deviations the one "
                      "at its reference value stands off the other's best multiple, the smaller way round; below "
                      "sqrt(%g) the evidence cannot tell them apart (a look-alike). Separation of the fits: between the "
                      "two fitted predictions.\n",
                      GapThresholds::evidence_margin);
  }
  if (d.next && d.next->goal == "separate" && !(d.next->after > 0)) {
    md += format_text("\n**Next measurement**: no number of measured runs separates %s from %s: their fitted "
                      "predictions differ by less than the noise of their signatures' knots (more beds per knot, or "
                      "an observable that tells them apart, would).\n",
                      d.next->effects[0].c_str(), d.next->effects[1].c_str());
  } else if (d.next) {
    const NextMeasurement &m = *d.next;
    const std::string what = m.goal == "separate" ? "separate " + m.effects[0] + " from " + m.effects[1]
                                                  : "detect " + m.effects[0] + " (at the magnitude its likelihood ratio says)";
    md += format_text("\n**Next measurement**: %d more run(s) at v0 = %g cm/s would %s%s%s: %s %.2f -> %.2f (gain "
                      "%.2f; %s %.2f).\n",
                      m.runs, m.v0, m.reaches ? "" : "go furthest to ", what.c_str(),
                      m.reaches ? "" : " (it is not reached within 64 runs)",
                      m.goal == "separate" ? "squared separation" : "expected likelihood ratio", m.now, m.after, m.gain(),
                      m.goal == "separate" ? "the evidence margin" : "its threshold", m.target);
  }
  return md;
}

// report.md's Scale only: what can make a uniform scale, and what tells each apart
std::string md_scale_only(const Diagnosis &d)
{
  if (!d.scale_only) return "";
  const ScaleFinding &s = *d.scale_only;
  std::string md = format_text("\n## Scale only\n\nThe force is %.1f%% %s at every depth and speed (relative scale %+.3f%s), "
                               "beyond the +-%g%% a lab's calibration allows. A uniform scale names no physical cause; what can "
                               "do it:\n\n| cause | what | magnitude | separation from the scale (sigma^2) | what tells it apart "
                               "|\n|---|---|---|---|---|\n",
                               100.0 * std::fabs(s.scale), s.scale >= 0 ? "high" : "low", s.scale,
                               std::isfinite(s.scale_error) ? format_text(" +- %.3f", s.scale_error).c_str() : "",
                               100.0 * s.bound);
  for (const auto &c : s.causes)
    md += format_text("| %s | %s | %.4g (%s) | %s | %s |\n", c.cause.c_str(), c.what.c_str(), c.magnitude, c.unit.c_str(),
                      c.separation2 < 0 ? "-" : f3(c.separation2, "%.1f").c_str(), c.tell_apart.c_str());
  md += format_text("\nThe effects listed are those whose fitted prediction lies within the evidence margin (%g squared "
                    "standard deviations, the knots' noise subtracted) of the scale's: at this noise their signatures "
                    "look like a uniform scale at the magnitude that would give this gap; and those detected on their "
                    "own that fit the data as well as the scale (chi^2 within the calibration bound at most the margin "
                    "above the scale's), however far apart the two predictions stand.\n\n",
                    GapThresholds::evidence_margin);
  return md;
}

// report.md's Residual: what the gap left over
std::string md_residual(const Diagnosis &d)
{
  if (!d.residual) return "";
  const Residual &r = *d.residual;
  const char *against = r.against == "corrected" ? "the confirming runs" : r.against == "fitted" ? "the fitted model"
                                                                                                   : "the baseline";
  std::string md = format_text("\n## Residual\n\nAgainst %s: ", against);
  std::string regimes;
  for (const auto &g : r.regimes) regimes += (regimes.empty() ? "" : ", ") + g;
  md += r.regimes.empty() ? std::string("no bin mean differs by more than 2 standard errors")
                          : format_text("%d of %d bin means differ by more than 2 standard errors (noise alone: about "
                                        "%.1f), at %.2f < z <= %.2f cm (%s)",
                                        r.bins_beyond, r.dof_means, 0.0455 * r.dof_means, r.z_from, r.z_to, regimes.c_str());
  md += format_text(". It moves %s (chi^2 %.1f over %d bin means, p = %.2g; %.1f over %d fluctuation features, p = %.2g)",
                    r.moves == "neither" ? "neither the bin means nor the spectrum beyond the noise" : r.moves.c_str(),
                    r.chi2_means, r.dof_means, r.p_means, r.chi2_fluct, r.dof_fluct, r.p_fluct);
  if (!r.band.empty()) md += format_text("; the spectrum carries it most in %s (measured / model amplitude %.2f)", r.band.c_str(), r.band_ratio);
  md += ".";
  for (const auto &l : r.lines)
    md += format_text(" A narrow line at %.0f Hz at v0 = %g cm/s (%.1f times the model's power, %.1f sigma).", l.freq,
                      l.v0, l.ratio, l.sigma);
  if (!r.line_scaling.empty())
    md += r.line_scaling == "scales with v0" ? " Its frequency scales with v0: a wavelength of the bed or the grains."
                                             : " Its frequency stays put across speeds: a property of the set-up (a resonance).";
  if (!r.nearest.empty())
    md += format_text(" Nearest candidate: %s%s%s.", r.nearest.c_str(), r.why_rejected.empty() ? "" : ", rejected because ",
                      r.why_rejected.c_str());
  return md + " (figure `residual`)\n";
}

std::string report_markdown(const Diagnosis &d, const std::vector<std::string> &figures,
                            const std::vector<std::string> &failures)
{
  std::string md = md_summary(d) + md_scale_only(d) + md_where(d) + md_which(d) + md_blind(d) + md_residual(d) +
                   pair_stage_markdown(d.pairs);
  md += "\n## Cost\n\n" + plan_record_text(d.plan) + "\n";
  md += format_text("\n## Notes\n\n");
  for (const auto &n : d.notes) md += format_text("- %s\n", n.c_str());
  md += format_text("\n## Figures\n\n");
  for (const auto &n : figures) md += format_text("![%s](figures/%s.png)\n\n", n.c_str(), n.c_str());
  for (const auto &e : failures) md += format_text("- figure not drawn: %s\n", e.c_str());
  md += format_text("Simulated traces: `baseline/` (before) and `corrected/` (after, as the verdict compared them: a transform "
                    "effect's filtered, and times 1 + the force scale fitted with the effect, each file's `derived` line says "
                    "which; the baseline's when nothing was added).\n");
  return md;
}

}    // namespace

void write_gap_report(const Diagnosis &d, const std::string &dir)
{
  write_json(dir + "/diagnosis.json", diagnosis_json(d), 1);
  std::vector<std::string> figures, failures;
  draw_figures(d, dir, figures, failures);
  write_file_atomic(dir + "/report.md", report_markdown(d, figures, failures));
}

void write_gap_output(const Diagnosis &d, const std::string &out_dir)
{
  const fs::path out = out_dir, part = fs::path(out_dir + ".partial");
  std::error_code ec;
  fs::remove_all(part, ec);
  // each simulated trace as SWEEP_FILE
  auto copy_all = [&](const std::vector<std::string> &files, const fs::path &dir) {
    for (const auto &f : files) {
      const std::string name = sweep_of_trace(f) + "_" + fs::path(f).filename().string();
      fs::copy_file(f, dir / name, fs::copy_options::overwrite_existing);
    }
  };
  try {
    fs::create_directories(part / "baseline");
    fs::create_directories(part / "corrected");
    copy_all(d.baseline_files, part / "baseline");
    // the corrected runs as compared (transformed, scaled) were computed by the confirmation
    // (corrected_traces); otherwise they are the runs as simulated
    if (!d.corrected_traces.empty())
      for (const auto &[name, text] : d.corrected_traces) write_file_atomic((part / "corrected" / name).string(), text);
    else
      copy_all(d.corrected_files.empty() ? d.baseline_files : d.corrected_files, part / "corrected");
    write_gap_report(d, part.string());
  } catch (const fs::filesystem_error &e) {
    fs::remove_all(part, ec);
    throw InputError(part.string() + ": cannot write the output: " + e.code().message());
  } catch (const OutputError &e) {
    fs::remove_all(part, ec);
    throw InputError(e.what());
  } catch (const InputError &) {
    fs::remove_all(part, ec);
    throw;
  }
  // an older OUT is replaced only now, when the new one is complete
  try {
    if (fs::exists(out)) {
      const fs::path old = fs::path(out_dir + ".old");
      fs::remove_all(old, ec);
      fs::rename(out, old);
      fs::rename(part, out);
      fs::remove_all(old, ec);
    } else {
      fs::rename(part, out);
    }
  } catch (const fs::filesystem_error &e) {
    throw InputError(out_dir + ": cannot move the output into place (it is complete in " + part.string() +
                     "): " + e.code().message());
  }
}

}    // namespace granpen
