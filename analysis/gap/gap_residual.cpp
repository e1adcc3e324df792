// granpen gap, stage 11 (residual): see gap_residual.h.
#include "gap_residual.h"

#include "gap_features.h"
#include "gap_metric.h"
#include "text_util.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace granpen {

namespace {

std::string fmt(double v, const char *f = "%.3g") { return printf_number(f, v); }

// trigamma(x) for x > 0: recurrence up to 6, then the asymptotic series
double trigamma(double x)
{
  double acc = 0.0;
  while (x < 6.0) acc += 1.0 / (x * x), x += 1.0;
  const double xi = 1.0 / x, x2 = xi * xi;
  return acc + xi + x2 / 2.0 + xi * x2 * (1.0 / 6.0 - x2 * (1.0 / 30.0 - x2 * (1.0 / 42.0 - x2 / 30.0)));
}

// the run's first n samples in 0 < z <= zmax
void first_in_range(const TraceRun &r, double zmax, std::size_t n, std::vector<double> &t, std::vector<double> &z,
                    std::vector<double> &F)
{
  for (std::size_t i = 0; i < r.z.size() && i < r.F.size() && i < r.t.size() && z.size() < n; ++i)
    if (r.z[i] > 0.0 && r.z[i] <= zmax) t.push_back(r.t[i]), z.push_back(r.z[i]), F.push_back(r.F[i]);
}

std::size_t in_range(const TraceRun &r, double zmax)
{
  std::size_t n = 0;
  for (double z : r.z) n += (z > 0.0 && z <= zmax);
  return n;
}

// the mean periodogram (fluctuation about the line through the bin centres) of runs cut to n samples
std::vector<double> mean_power(const std::vector<const TraceRun *> &runs, const GapGrid &grid, std::size_t n,
                               std::vector<double> &freq)
{
  std::vector<double> mean;
  for (const TraceRun *r : runs) {
    std::vector<double> t, z, F;
    first_in_range(*r, grid.zmax, n, t, z, F);
    const Periodogram p = fluctuation_periodogram(t, z, F, grid.w, grid.zmax, Detrend::BinCentreLine);
    if (mean.empty()) mean.assign(p.power.size(), 0.0), freq = p.freq;
    for (std::size_t j = 0; j < mean.size() && j < p.power.size(); ++j) mean[j] += p.power[j] / runs.size();
  }
  return mean;
}

double median(std::vector<double> v)
{
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

}    // namespace

bool find_line(const std::vector<const TraceRun *> &real, const std::vector<const TraceRun *> &model,
               const GapGrid &grid, SpectralLine &line, std::vector<double> &freq, std::vector<double> &ratio)
{
  freq.clear(), ratio.clear();
  if (real.empty() || model.empty() || grid.bands.size() < 2) return false;
  std::size_t n = (std::size_t) -1;
  for (const auto *set : {&real, &model})
    for (const TraceRun *r : *set) n = std::min(n, in_range(*r, grid.zmax));
  if (n < 64) return false;
  std::vector<double> fm;
  const std::vector<double> pr = mean_power(real, grid, n, freq), ps = mean_power(model, grid, n, fm);
  // the log ratio over the bands' span
  std::vector<double> f, L;
  for (std::size_t j = 0; j < freq.size() && j < ps.size(); ++j)
    if (freq[j] >= grid.bands.front() && freq[j] < grid.bands.back() && pr[j] > 0 && ps[j] > 0)
      f.push_back(freq[j]), L.push_back(std::log(pr[j] / ps[j]));
  freq = f;
  for (double l : L) ratio.push_back(std::exp(l));
  // a log ratio of means of n_R and n_S exponential periodogram bins: variance trigamma(n) each
  const double sd = std::sqrt(trigamma((double) real.size()) + trigamma((double) model.size()));
  const int half = 8, core = 2;
  std::vector<double> excess(L.size(), 0.0);
  for (std::size_t j = 0; j < L.size(); ++j) {
    std::vector<double> around;
    for (int d = -half; d <= half; ++d) {
      const long i = (long) j + d;
      if (std::abs(d) > core && i >= 0 && i < (long) L.size()) around.push_back(L[i]);
    }
    excess[j] = L[j] - median(around);
  }
  if (excess.size() < 2 * (std::size_t) half) return false;
  const std::size_t jb = (std::size_t) (std::max_element(excess.begin(), excess.end()) - excess.begin());
  if (excess[jb] < 5.0 * sd) return false;
  // narrow: down to half its excess (in the log) 3 bins away on both sides
  for (long d : {-3L, 3L}) {
    const long i = (long) jb + d;
    if (i >= 0 && i < (long) L.size() && excess[i] > 0.5 * excess[jb]) return false;
  }
  line.freq = f[jb], line.ratio = std::exp(excess[jb]), line.sigma = excess[jb] / sd;
  return true;
}

std::string line_scaling(const std::vector<SpectralLine> &lines)
{
  if (lines.size() < 2) return "";
  auto spread = [&](auto value) {
    double lo = 1e300, hi = -1e300, sum = 0;
    for (const auto &l : lines) {
      const double x = value(l);
      lo = std::min(lo, x), hi = std::max(hi, x), sum += x;
    }
    return (hi - lo) / (sum / lines.size());
  };
  const double fixed = spread([](const SpectralLine &l) { return l.freq; });
  const double scaled = spread([](const SpectralLine &l) { return l.freq / l.v0; });
  return scaled < fixed ? "scales with v0" : "fixed";
}

std::string why_rejected(const EffectFit &fit, const ResidualContext &ctx)
{
  // the verdict's own record: the rules this candidate fell short of, with their numbers
  std::vector<std::string> why;
  for (const auto &r : ctx.records)
    if (r.name == fit.name)
      for (const auto &s : r.shortfalls) why.push_back(shortfall_text(s));
  if (why.empty() && !ctx.ranking.empty() && ctx.ranking[0].name == fit.name && ctx.ranking.size() > 1)
    why.push_back(ctx.ranking[1].name + " explains the gap about as well (evidence " +
                  fmt(lr_evidence(ctx.ranking[0]), "%.1f") + " against " + fmt(lr_evidence(ctx.ranking[1]), "%.1f") + ")");
  std::string s;
  for (const auto &w : why) s += (s.empty() ? "" : "; ") + w;
  return s;
}

namespace {

// the regime of a bin centre at speed s
std::string regime_of(double z, std::size_t s, const ResidualContext &ctx)
{
  if (z <= ctx.peak_end) return "peak";
  return s < ctx.z_transient_end.size() && z <= ctx.z_transient_end[s] ? "transient" : "linear";
}

// chi^2 over the bins (where the residual lies, and the curves) and over the fluctuation
// features (and which band carries most of it)
void residual_chi2(const ResidualSide &R, const ResidualSide &M, const GapGrid &grid, const ResidualContext &ctx,
                   Residual &out, std::vector<double> &band_chi2, std::vector<double> &band_ratio)
{
  const std::size_t nb = grid.nbins(), nw = grid.nwindows(), P = grid.nfeatures();
  band_chi2.assign(grid.nbands(), 0.0), band_ratio.assign(grid.nbands(), 0.0);
  bool any = false;
  for (std::size_t s = 0; s < ctx.speeds.size(); ++s) {
    ResidualCurves c;
    c.v0 = ctx.speeds[s];
    for (std::size_t k = 0; k < P; ++k) {
      const double r = R.mean[s][k] - M.mean[s][k], var = R.err[s][k] + M.err[s][k], x2 = r * r / (var + 1e-300);
      if (k >= nb) {
        out.chi2_fluct += x2, ++out.dof_fluct;
        if (k >= nb + nw) {
          band_chi2[k - nb - nw] += x2;
          band_ratio[k - nb - nw] += M.mean[s][k] > 0 ? R.mean[s][k] / M.mean[s][k] / ctx.speeds.size() : 0.0;
        }
        continue;
      }
      out.chi2_means += x2, ++out.dof_means;
      const double z = grid.centre(k);
      c.z.push_back(z), c.resid.push_back(r), c.band.push_back(2.0 * std::sqrt(var));
      if (std::abs(r) <= 2.0 * std::sqrt(var)) continue;
      ++out.bins_beyond;
      const std::string reg = regime_of(z, s, ctx);
      if (std::find(out.regimes.begin(), out.regimes.end(), reg) == out.regimes.end()) out.regimes.push_back(reg);
      out.z_from = any ? std::min(out.z_from, z - 0.5 * grid.w) : z - 0.5 * grid.w;
      out.z_to = any ? std::max(out.z_to, z + 0.5 * grid.w) : z + 0.5 * grid.w;
      any = true;
    }
    out.curves.push_back(c);
  }
  // regimes in depth order
  const std::vector<std::string> order = {"peak", "transient", "linear"};
  std::sort(out.regimes.begin(), out.regimes.end(), [&](const std::string &a, const std::string &b) {
    return std::find(order.begin(), order.end(), a) < std::find(order.begin(), order.end(), b);
  });
}

}    // namespace

Residual describe_residual(const ResidualSide &R, const ResidualSide &M, const GapGrid &grid, const ResidualContext &ctx)
{
  Residual out;
  out.against = ctx.against;
  std::vector<double> band_chi2, band_ratio;
  residual_chi2(R, M, grid, ctx, out, band_chi2, band_ratio);
  out.p_means = out.dof_means ? chi2_sf(out.chi2_means, out.dof_means) : 1.0;
  out.p_fluct = out.dof_fluct ? chi2_sf(out.chi2_fluct, out.dof_fluct) : 1.0;
  const bool means = out.p_means < GapThresholds::significance_p, spec = out.p_fluct < GapThresholds::significance_p;
  out.moves = means && spec ? "both" : means ? "bin means" : spec ? "spectrum" : "neither";
  if (spec && !band_chi2.empty()) {
    const std::size_t k = (std::size_t) (std::max_element(band_chi2.begin(), band_chi2.end()) - band_chi2.begin());
    out.band = fmt(grid.bands[k], "%g") + "-" + fmt(grid.bands[k + 1], "%g") + " Hz";
    out.band_ratio = band_ratio[k];
  }
  for (std::size_t s = 0; s < ctx.speeds.size(); ++s) {
    SpectralLine line;
    line.v0 = ctx.speeds[s];
    if (s < R.runs.size() && s < M.runs.size() && find_line(R.runs[s], M.runs[s], grid, line, out.curves[s].freq, out.curves[s].ratio))
      out.lines.push_back(line);
  }
  out.line_scaling = line_scaling(out.lines);
  // the nearest candidate: the one that explains most (after an explained verdict, of the others)
  const EffectFit *near = nullptr;
  for (const auto &r : ctx.ranking)
    if (!((ctx.verdict == Verdict::explained || ctx.verdict == Verdict::scale_only) && r.name == ctx.top_effect) &&
        (!near || r.explained > near->explained))
      near = &r;
  if (near) out.nearest = near->name, out.why_rejected = why_rejected(*near, ctx);
  return out;
}

}    // namespace granpen

namespace granpen {

namespace {

std::vector<const TraceRun *> pointers(const std::vector<TraceRun> &runs)
{
  std::vector<const TraceRun *> p;
  for (const auto &r : runs) p.push_back(&r);
  return p;
}

}    // namespace

std::optional<Residual> residual_stage(const Features &f, const RunsBySpeed &real, const RunsBySpeed &fresh,
                                       const GapGrid &grid, double peak_end, const WhereResult &where,
                                       const FittedCandidates &fitted, const VerdictDecision &verdict,
                                       const Confirmation &confirmation)
{
  if (verdict.verdict == Verdict::none) return std::nullopt;
  std::vector<double> z_transient_end;
  for (const auto &c : where.before.speeds) z_transient_end.push_back(c.z_transient_end);
  // a scale_only verdict is judged against its confirming runs as an explained one
  const bool explained = verdict.verdict == Verdict::explained || verdict.verdict == Verdict::scale_only;
  // after scale_only the scale candidate is the one the residual is left by
  const std::string &named = verdict.verdict == Verdict::scale_only ? verdict.scale_effect : verdict.top_effect;
  const std::map<std::string, EffectData> &data = fitted.data;
  const RunsBySpeed &after = confirmation.after_runs;
  ResidualContext ctx{f.speeds,          z_transient_end,           peak_end,
                      "",                verdict.verdict,           named,
                      confirmation.tested_effect, fitted.evidence.ranking, fitted.evidence.n_null,
                      verdict.candidates};
  const bool fitted_model = explained && after.empty() && data.count(named);
  ctx.against = explained && !after.empty() ? "corrected" : fitted_model ? "fitted" : "baseline";
  ResidualSide R, M;
  for (std::size_t s = 0; s < f.nspeeds(); ++s) {
    const double v = f.speeds[s];
    R.mean.push_back(f.real[s].mean), R.err.push_back(f.target.err[s]), R.runs.push_back(pointers(real.at(v)));
    if (ctx.against == "corrected") {
      const Ensemble eC = ensemble_of(after.at(v), grid, v);
      M.mean.push_back(eC.mean), M.err.push_back(model_err(eC, f.cv2[s])), M.runs.push_back(pointers(after.at(v)));
    } else if (fitted_model) {
      // --fit-only: the fitted model's prediction (no runs: no periodogram)
      std::vector<double> m, var;
      effect_predict(data.at(named), confirmation.named_magnitude(), s, m, var);
      M.mean.push_back(m), M.err.push_back(var);
    } else {
      M.mean.push_back(f.fresh[s].mean), M.err.push_back(f.fresh_err[s]), M.runs.push_back(pointers(fresh.at(v)));
    }
  }
  return describe_residual(R, M, grid, ctx);
}

}    // namespace granpen
