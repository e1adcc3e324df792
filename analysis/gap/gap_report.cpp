// granpen gap: diagnosis.json (exact names; other tools read them), report.md and its
// figures (io/plot_writer.h).
#include "gap_report.h"

#include "gap_plan.h"
#include "json_text.h"
#include "plot_writer.h"
#include "sweep_cache.h"
#include "text_util.h"
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

std::string num(double v, const char *f = "%.6g") { return json_number(f, v); }

std::string f3(double v, const char *f = "%.3f") { return printf_number(f, v); }

void write_json(const Diagnosis &d, const std::string &path)
{
  FILE *f = std::fopen(path.c_str(), "w");
  if (!f) throw InputError(path + ": cannot write");
  auto str_or_null = [](const std::string &s) { return s.empty() ? std::string("null") : json_string(s); };
  std::fprintf(f, "{\n  \"verdict\": %s,\n  \"top_effect\": %s,\n  \"magnitude\": %s,\n  \"magnitude_unit\": %s,\n",
               json_string(d.verdict).c_str(), str_or_null(d.top_effect).c_str(),
               d.top_effect.empty() ? "null" : num(d.magnitude).c_str(), str_or_null(d.magnitude_unit).c_str());
  std::fprintf(f, "  \"tested_effect\": %s,\n  \"scenario\": %s,\n  \"real\": %s,\n",
               str_or_null(d.tested_effect).c_str(), json_string(d.scenario).c_str(), json_string(d.real_dir).c_str());
  std::fprintf(f, "  \"gap_before\": %s,\n  \"gap_after\": %s,\n  \"gap_metric\": \"shared/formats/gap-metric.md v1\",\n",
               num(d.gap_before).c_str(), num(d.gap_after).c_str());
  std::fprintf(f, "  \"runs\": {\"real_min_per_speed\": %d, \"sim_per_speed\": %d},\n", d.n_real_min, d.n_sim);
  std::fprintf(f, "  \"grid\": {\"w\": %s, \"zmax\": %s, \"window\": %s},\n", num(d.grid.w).c_str(),
               num(d.grid.zmax).c_str(), num(d.grid.window).c_str());
  std::fprintf(f, "  \"significance\": {\"chi2\": %s, \"features\": %zu, \"p_value\": %s, \"significant\": %s, "
                  "\"route\": %s, \"null_replicates\": %d},\n",
               num(d.chi2_0).c_str(), d.nfeatures, num(d.p_value, "%.3g").c_str(), d.significant ? "true" : "false",
               !d.significant ? "null" : d.targeted ? "\"targeted\"" : "\"omnibus\"", d.n_null);
  std::fprintf(f, "  \"confirmed\": %s,\n", d.verdict != "explained" ? "null" : d.provisional ? "false" : "true");
  std::fprintf(f, "  \"confirmation\": {\"chi2_after\": %s, \"explained_fraction\": %s, \"signature_sigma_before\": %s, "
                  "\"signature_sigma_after\": %s},\n",
               d.tested_effect.empty() ? "null" : num(d.chi2_after).c_str(),
               d.tested_effect.empty() ? "null" : num(d.confirmed_fraction, "%.4f").c_str(),
               d.tested_effect.empty() ? "null" : num(d.proj_before, "%.4f").c_str(),
               d.tested_effect.empty() ? "null" : num(d.proj_after, "%.4f").c_str());
  if (d.refined)
    std::fprintf(f, "  \"refinement\": {\"from\": %s, \"gap_after_first\": %s, \"signature_sigma_after\": %s},\n",
                 num(d.refined_from).c_str(), num(d.gap_after_first).c_str(), num(d.proj_refined, "%.4f").c_str());
  else
    std::fprintf(f, "  \"refinement\": null,\n");
  std::fprintf(f, "  \"gap_by_regime\": {");
  bool first = true;
  for (const auto &[reg, ba] : d.gap_by_regime) {
    std::fprintf(f, "%s\n    %s: {\"before\": %s, \"after\": %s}", first ? "" : ",", json_string(reg).c_str(),
                 num(ba.first).c_str(), num(ba.second).c_str());
    first = false;
  }
  std::fprintf(f, "\n  },\n  \"heldout\": {\"v0\": %s, \"gap_before\": %s, \"gap_after\": %s, \"magnitude\": %s},\n",
               num(d.heldout_v0).c_str(), num(d.heldout_before).c_str(), num(d.heldout_after).c_str(),
               d.tested_effect.empty() ? "null" : num(d.heldout_magnitude).c_str());
  std::fprintf(f, "  \"per_speed\": [");
  for (std::size_t s = 0; s < d.speeds.size(); ++s) {
    const auto &c = d.speeds[s];
    std::fprintf(f, "%s\n    {\"v0\": %s, \"gap_before\": %s, \"gap_after\": %s, \"n_real\": %d, \"n_sim\": %d, "
                    "\"z_transient_end\": %s}",
                 s ? "," : "", num(c.v0).c_str(), num(c.G_before).c_str(), num(c.G_after).c_str(), c.n_real, c.n_base,
                 num(c.z_transient_end).c_str());
  }
  std::fprintf(f, "\n  ],\n  \"ranking\": [");
  for (std::size_t i = 0; i < d.ranking.size(); ++i) {
    const auto &r = d.ranking[i];
    std::fprintf(f, "%s\n    {\"effect\": %s, \"explained_fraction\": %s, \"score\": %s, \"magnitude\": %s, "
                    "\"heldout_explained\": %s, \"chi2\": %s, \"chi2_baseline\": %s, \"at_edge\": %s, "
                    "\"likelihood_ratio\": %s, \"lr_null_mean\": %s, \"lr_threshold\": %s, \"detected\": %s, "
                    "\"evidence\": %s",
                 i ? "," : "", json_string(r.name).c_str(), num(r.explained, "%.4f").c_str(), num(r.score, "%.4f").c_str(),
                 num(r.magnitude).c_str(), num(r.heldout_explained, "%.4f").c_str(), num(r.chi2, "%.2f").c_str(),
                 num(r.chi2_0, "%.2f").c_str(), r.at_edge ? "true" : "false", num(r.lr, "%.2f").c_str(),
                 num(r.lr_null_mean, "%.3f").c_str(), num(r.lr_threshold, "%.2f").c_str(), r.detected ? "true" : "false",
                 num(lr_evidence(r), "%.2f").c_str());
    auto it = d.magnitude_note.find(r.name);
    if (it != d.magnitude_note.end()) std::fprintf(f, ", \"note\": %s", json_string(it->second).c_str());
    std::fprintf(f, "}");
  }
  std::fprintf(f, "\n  ],\n  \"where\": [");
  for (std::size_t i = 0; i < d.where.size(); ++i) {
    const auto &w = d.where[i];
    std::fprintf(f, "%s\n    {\"regime\": %s, \"observable\": %s, \"v0\": %s, \"real\": %s, \"sim\": %s, \"zscore\": %s, "
                    "\"real_se\": %s, \"sim_se\": %s, \"significant\": %s}",
                 i ? "," : "", json_string(w.regime).c_str(), json_string(w.observable).c_str(), num(w.v0).c_str(),
                 num(w.real).c_str(), num(w.sim).c_str(), num(w.zscore, "%.3f").c_str(), num(w.real_se).c_str(),
                 num(w.sim_se).c_str(), w.significant ? "true" : "false");
  }
  std::fprintf(f, "\n  ],\n  \"gap_curve\": [");
  for (std::size_t s = 0; s < d.speeds.size(); ++s) {
    const auto &c = d.speeds[s];
    std::fprintf(f, "%s\n    {\"v0\": %s, \"z\": [", s ? "," : "", num(c.v0).c_str());
    for (std::size_t b = 0; b < c.z.size(); ++b) std::fprintf(f, "%s%s", b ? ", " : "", num(c.z[b]).c_str());
    std::fprintf(f, "], \"gap\": [");
    for (std::size_t b = 0; b < c.z.size(); ++b) std::fprintf(f, "%s%s", b ? ", " : "", num(c.gap[b]).c_str());
    std::fprintf(f, "], \"band\": [");
    for (std::size_t b = 0; b < c.z.size(); ++b) std::fprintf(f, "%s%s", b ? ", " : "", num(c.band[b]).c_str());
    std::fprintf(f, "]}");
  }
  std::fprintf(f, "\n  ],\n  \"notes\": [");
  for (std::size_t i = 0; i < d.notes.size(); ++i)
    std::fprintf(f, "%s\n    %s", i ? "," : "", json_string(d.notes[i]).c_str());
  std::fprintf(f, "\n  ]\n}\n");
  if (std::fclose(f) != 0) throw InputError(path + ": write failed");
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
}

void write_markdown(const Diagnosis &d, const std::string &path, const std::vector<std::string> &figures,
                    const std::vector<std::string> &failures)
{
  FILE *f = std::fopen(path.c_str(), "w");
  if (!f) throw InputError(path + ": cannot write");
  std::fprintf(f, "# granpen gap: %s\n\n", d.real_dir.c_str());
  std::fprintf(f, "Scenario `%s`; grid 0 < z <= %.2f cm in %.2f cm bins; at least %d measured run(s) per speed; the "
                  "baseline on %d reference beds (before), each effect's signature on %zu beds per magnitude, the "
                  "confirmation on %zu fresh beds (after).\n\n",
               d.scenario.c_str(), d.grid.zmax, d.grid.w, d.n_real_min, d.n_sim, SIGNATURE_SEEDS.size(),
               CONFIRM_SEEDS.size());
  std::fprintf(f, "**Verdict: %s%s**%s.  \n", d.verdict.c_str(), d.provisional ? " (provisional: not confirmed, --fit-only)" : "",
               d.top_effect.empty() ? "" : (" — " + d.top_effect + " at magnitude " + f3(d.magnitude, "%.4g") + " (" + d.magnitude_unit + ")").c_str());
  std::fprintf(f, "Overall gap G (shared/formats/gap-metric.md): %.3f before, %.3f after%s.  \n", d.gap_before,
               d.gap_after, d.tested_effect.empty() ? " (nothing added)" : (" adding " + d.tested_effect + " on fresh seeds").c_str());
  std::fprintf(f, "Held-out speed %.4g cm/s: %.3f before, %.3f after.  \n", d.heldout_v0, d.heldout_before, d.heldout_after);
  std::fprintf(f, "Gap significance: chi^2 = %.1f over %zu features, p = %.3g%s.", d.chi2_0, d.nfeatures, d.p_value,
               d.targeted ? " (not significant over all features; found along one candidate's signature, see Which)" : "");
  if (!d.tested_effect.empty())
    std::fprintf(f, " With %s on fresh seeds: chi^2 = %.1f (%.0f%% of the excess removed); the gap along its signature "
                    "%.2f -> %.2f standard deviations.",
                 d.tested_effect.c_str(), d.chi2_after, 100.0 * d.confirmed_fraction, d.proj_before, d.proj_after);
  if (d.refined)
    std::fprintf(f, " That left the gap significant along the signature, so the magnitude was refined from %.4g to %.4g "
                    "by linear response and simulated on %zu more fresh beds (G %.3f -> %.3f; %.2f standard deviations "
                    "left along the signature): the gap after and the corrected curves are these runs'.",
                 d.refined_from, d.magnitude, REFINE_SEEDS.size(), d.gap_after_first, d.gap_after, d.proj_refined);
  std::fprintf(f, "\n\n");
  std::fprintf(f, "## Where\n\n| regime | observable | v0 (cm/s) | measured | simulated | z-score |\n|---|---|---|---|---|---|\n");
  for (const auto &w : d.where)
    std::fprintf(f, "| %s | %s | %.4g | %.4g +- %.2g | %.4g +- %.2g | %s%.2f%s |\n", w.regime.c_str(), w.observable.c_str(),
                 w.v0, w.real, w.real_se, w.sim, w.sim_se, w.significant ? "**" : "", w.zscore, w.significant ? "**" : "");
  std::fprintf(f, "\nA finding is significant (bold) when |z| > 3, z = (measured - simulated) / sqrt(se_m^2 + se_s^2), "
                  "standard errors from the run-to-run variance pooled over every simulated ensemble of the speed "
                  "(the measured side's scaled by how much more its runs scatter); peak: z <= 0.35 D, transient: up "
                  "to the baseline's crossover depth, linear: beyond.\n\n");
  std::fprintf(f, "| regime | G before | G after |\n|---|---|---|\n");
  for (const auto &[reg, ba] : d.gap_by_regime) std::fprintf(f, "| %s | %.3f | %.3f |\n", reg.c_str(), ba.first, ba.second);
  std::fprintf(f, "\n## Which\n\n| effect | magnitude | explained | held-out explained | chi^2 (reference %.1f) | "
                  "likelihood ratio | its threshold | evidence |\n|---|---|---|---|---|---|---|---|\n",
               d.ranking.empty() ? 0.0 : d.ranking[0].chi2_0);
  for (const auto &r : d.ranking) {
    auto it = d.magnitude_note.find(r.name);
    std::fprintf(f, "| %s | %.4g%s%s | %.2f | %.2f | %.1f | %s%.1f%s | %.1f | %.1f |\n", r.name.c_str(), r.magnitude,
                 r.at_edge ? " (edge)" : "", it == d.magnitude_note.end() ? "" : (" (" + it->second + ")").c_str(),
                 r.explained, r.heldout_explained, r.chi2, r.detected ? "**" : "", r.lr, r.detected ? "**" : "",
                 r.lr_threshold, lr_evidence(r));
  }
  std::fprintf(f, "\nThe fits measure the gap against the baseline on %d reference beds of their own (not the "
                  "signature beds). Explained: the part of the noise-weighted squared gap the fit removes, as a "
                  "fraction of its excess over what noise alone leaves. Likelihood ratio: -2 log of the likelihood "
                  "at magnitude 0 over that at the fitted magnitude (a chi^2 with one degree of freedom without the "
                  "effect, were the noise model exact); its threshold: %.2f (p = 1e-4) times the ratio's mean over "
                  "%d null replicates (some reference beds taken as a measurement, the rest as its reference), at "
                  "least 1. Bold: above it. Evidence: the likelihood ratio less the null mean's excess over 1 (what "
                  "a noisy signature fits of any noise); candidates are ranked by it and told apart by a margin of "
                  "6.\n",
               d.n_reference, LR_CHI2_1_P1E4, d.n_null);
  std::fprintf(f, "\n## Notes\n\n");
  for (const auto &n : d.notes) std::fprintf(f, "- %s\n", n.c_str());
  std::fprintf(f, "\n## Figures\n\n");
  for (const auto &n : figures) std::fprintf(f, "![%s](figures/%s.png)\n\n", n.c_str(), n.c_str());
  for (const auto &e : failures) std::fprintf(f, "- figure not drawn: %s\n", e.c_str());
  std::fprintf(f, "Simulated traces: `baseline/` (before) and `corrected/` (after; the baseline's when nothing was added).\n");
  if (std::fclose(f) != 0) throw InputError(path + ": write failed");
}

}    // namespace

void write_gap_report(const Diagnosis &d, const std::string &dir)
{
  write_json(d, dir + "/diagnosis.json");
  std::vector<std::string> figures, failures;
  draw_figures(d, dir, figures, failures);
  write_markdown(d, dir + "/report.md", figures, failures);
}

void gap_by_regime(const GapGrid &grid, double D, Diagnosis &d)
{
  const std::size_t nb = grid.nbins();
  for (const char *reg : {"peak", "transient", "linear"}) {
    double sb = 0, sa = 0;
    int n = 0;
    for (const auto &c : d.speeds) {
      std::size_t b0 = 0, b1 = 0;
      for (std::size_t b = 0; b < nb; ++b) {
        const double z = grid.centre(b);
        const std::string r = z <= 0.35 * D ? "peak" : (z <= c.z_transient_end ? "transient" : "linear");
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
    copy_all(d.corrected_files.empty() ? d.baseline_files : d.corrected_files, part / "corrected");
    write_gap_report(d, part.string());
  } catch (const fs::filesystem_error &e) {
    fs::remove_all(part, ec);
    throw InputError(part.string() + ": cannot write the output: " + e.code().message());
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
