// granpen gap, stage 10 (limits): see gap_limits.h.
#include "gap_limits.h"

#include "gap_which.h"

#include "text_util.h"

#include <algorithm>
#include <cmath>

namespace granpen {

namespace {

std::size_t zero_knot(const EffectData &e)
{
  const auto it = std::find(e.knots.begin(), e.knots.end(), 0.0);
  return it == e.knots.end() ? 0 : (std::size_t) (it - e.knots.begin());
}

// the fit's weight of feature k at speed s: the measured mean's variance (times its factor)
// plus the reference's
double weight(const EffectData &e, const Target &t, const NoiseFactors &fac, std::size_t s, std::size_t k)
{
  return t.err[s][k] * (s < fac.size() ? fac[s] : 1.0) + e.err[zero_knot(e)][s][k];
}

NoiseFactors ones(const Target &t) { return NoiseFactors(t.mean.size(), 1.0); }

// The farthest simulated magnitude on the side of sign: the outermost knot there, or for a
// two-sided effect simulated on the other side only, the mirror of its farthest knot (the
// fit's linear response through the baseline); 0 when the effect has no such side.
double side_end(const Effect &e, const EffectData &ed, double sign)
{
  double end = 0.0;
  for (double k : ed.knots)
    if (k * sign > end * sign) end = k;
  if (end == 0.0 && !e.one_sided)
    for (double k : ed.knots)
      if (-k * sign > end * sign) end = -k;
  return end;
}

// The smallest |a| on 0 -> end at which the signature reaches the threshold: a scan of 200
// steps, then bisection inside the first step that reaches it.
std::optional<double> first_detected(const EffectData &ed, const Target &t, double threshold, double end,
                                     const NoiseFactors &fac)
{
  if (end == 0.0) return std::nullopt;
  const int n = 200;
  for (int i = 1; i <= n; ++i) {
    const double a = end * i / n;
    if (signature_strength(ed, t, a, fac) < threshold) continue;
    double lo = end * (i - 1) / n, hi = a;
    for (int it = 0; it < 40; ++it) {
      const double mid = 0.5 * (lo + hi);
      (signature_strength(ed, t, mid, fac) >= threshold ? hi : lo) = mid;
    }
    return hi;
  }
  return std::nullopt;
}

// The noise factors of n measured runs per speed instead of today's.
NoiseFactors factors_for(const Features &f, double n)
{
  NoiseFactors fac;
  for (const auto &e : f.real) fac.push_back((double) std::max<std::size_t>(1, e.n()) / n);
  return fac;
}

}    // namespace

double signature_strength(const EffectData &ed, const Target &t, double a, const NoiseFactors &factors)
{
  // data M(a) against the baseline within the calibration bound: the fit's gap at magnitude 0
  // is min over |c| <= scale_bound of |u - c M(0)|^2 (gap_fit.h, nuisance_scale), so the part
  // of the signature a uniform scale that small takes is no evidence
  double uu = 0.0, noise = 0.0, uR = 0.0, RR = 0.0;
  std::vector<double> u, var, R, vR;
  for (std::size_t s = 0; s < t.mean.size(); ++s) {
    effect_signature(ed, a, s, u, var);
    effect_predict(ed, 0.0, s, R, vR);
    for (std::size_t k = 0; k < u.size(); ++k) {
      const double w = weight(ed, t, factors, s, k);
      uu += u[k] * u[k] / w, noise += var[k] / w, uR += u[k] * R[k] / w, RR += R[k] * R[k] / w;
    }
  }
  const double c = ed.scale_bound > 0.0 && RR > 0.0 ? std::clamp(uR / RR, -ed.scale_bound, ed.scale_bound) : 0.0;
  return std::max(0.0, uu - 2.0 * c * uR + c * c * RR - noise);
}

DetectionLimit detection_limit(const Effect &e, const EffectData &ed, const EffectFit &fit, const Features &f)
{
  DetectionLimit L;
  L.effect = e.name;
  L.unit = e.unit;
  L.reference = reference_magnitude(e);
  L.threshold = fit.lr_threshold;
  const double sign = L.reference < 0 ? -1.0 : 1.0;
  const NoiseFactors now = ones(f.target);
  L.limit = first_detected(ed, f.target, L.threshold, side_end(e, ed, sign), now);
  if (!e.one_sided) L.limit_other_side = first_detected(ed, f.target, L.threshold, side_end(e, ed, -sign), now);
  for (int n = 1; n <= MAX_RUNS_PER_SPEED; ++n)
    if (signature_strength(ed, f.target, L.reference, factors_for(f, n)) >= L.threshold) {
      L.runs_needed = n;
      break;
    }
  return L;
}

double prediction_separation2(const EffectData &a, double ma, double sa, const EffectData &b, double mb, double sb,
                              const Target &t, const NoiseFactors &factors)
{
  // both models are the reference R at magnitude 0, so the fitted predictions differ by
  // (1 + sa) M_a(ma) - (1 + sb) M_b(mb) = (sa - sb) R + (1 + sa) u_a(ma) - (1 + sb) u_b(mb);
  // its knot noise: both signatures', less the shared signature baseline's counted twice
  // (u_a - u_b carries it with c_a - c_b: variance (c_a^2 + c_b^2 - 2 c_a c_b) var(B_sig))
  double d2 = 0.0;
  const double ga = 1.0 + sa, gb = 1.0 + sb;
  const double shared = 2 * signature_baseline_share(a, ma) * signature_baseline_share(b, mb) * ga * gb;
  std::vector<double> ua, va, ub, vb, R, vR;
  for (std::size_t s = 0; s < t.mean.size(); ++s) {
    effect_signature(a, ma, s, ua, va);
    effect_signature(b, mb, s, ub, vb);
    effect_predict(a, 0.0, s, R, vR);
    for (std::size_t k = 0; k < ua.size(); ++k) {
      const double noise = ga * ga * va[k] + gb * gb * vb[k] - (shared > 0 ? shared * a.ref_err[0][s][k] : 0.0);
      d2 += (std::pow((sa - sb) * R[k] + ga * ua[k] - gb * ub[k], 2) - noise) / weight(a, t, factors, s, k);
    }
  }
  return std::max(0.0, d2);
}

BelowLimitMimic below_limit_mimic(const EffectData &top, const EffectFit &top_fit, const EffectData &other,
                                  const EffectFit &other_fit, const Target &t)
{
  const NoiseFactors now = ones(t);
  // x: the top's fitted prediction less the baseline, s R + (1 + s) u_top(a); per magnitude m
  // of the other, min over |c| <= bound of |x - c R - (1 + c) u(m)|^2 = |r - c q|^2 with
  // r = x - u(m), q = R + u(m): c = r.q / q.q, clamped
  std::vector<double> x, w, R, u, var, vR;
  for (std::size_t s = 0; s < t.mean.size(); ++s) {
    effect_signature(top, top_fit.magnitude, s, u, var);
    effect_predict(top, 0.0, s, R, vR);
    for (std::size_t k = 0; k < u.size(); ++k) {
      x.push_back(top_fit.scale * R[k] + (1.0 + top_fit.scale) * u[k]);
      w.push_back(weight(top, t, now, s, k));
    }
  }
  const double bound = other.scale_bound;
  BelowLimitMimic best;
  const auto [lo, hi] = magnitude_range(other);
  const int n = 200;    // a scan of the range: the interpolated model is piecewise, not linear
  for (int i = 0; i <= n; ++i) {
    const double m = lo + (hi - lo) * i / n;
    if (m == 0.0 || signature_strength(other, t, m, now) >= other_fit.lr_threshold) continue;
    double rq = 0, qq = 0, rr = 0;
    std::size_t j = 0;
    for (std::size_t s = 0; s < t.mean.size(); ++s) {
      effect_signature(other, m, s, u, var);
      effect_predict(other, 0.0, s, R, vR);
      for (std::size_t k = 0; k < u.size(); ++k, ++j) {
        const double r = x[j] - u[k], q = R[k] + u[k];
        rq += r * q / w[j], qq += q * q / w[j], rr += r * r / w[j];
      }
    }
    const double c = qq > 0 ? std::clamp(rq / qq, -bound, bound) : 0.0;
    const double d2 = rr - 2 * c * rq + c * c * qq;
    if (!(d2 >= best.separation2)) best = {std::max(0.0, d2), m};
  }
  return best;
}

double off_span2(const SpanProducts &p, double bound)
{
  // f(beta, c) = xx - 2 beta xy - 2 c xR + beta^2 yy + 2 beta c yR + c^2 RR, convex: its
  // minimum with |c| <= bound is the free one, or else on the edge c = +-bound its side
  if (!(p.yy > 0.0)) return p.xx;
  const auto at = [&](double c) {
    const double beta = (p.xy - c * p.yR) / p.yy;
    return p.xx - 2 * beta * p.xy - 2 * c * p.xR + beta * beta * p.yy + 2 * beta * c * p.yR + c * c * p.RR;
  };
  const double det = p.yy * p.RR - p.yR * p.yR;
  // R along y (a uniform scale's own signature): the scale adds nothing to the span
  if (!(bound > 0.0) || !(det > 1e-12 * p.yy * p.RR)) return std::max(0.0, at(0.0));
  const double c = (p.yy * p.xR - p.yR * p.xy) / det;
  return std::max(0.0, at(std::clamp(c, -bound, bound)));
}

std::vector<LookAlike> look_alikes(const std::vector<EffectFit> &ranking, const std::map<std::string, EffectData> &data,
                                   const std::map<std::string, const Effect *> &effects, const Features &f)
{
  std::vector<LookAlike> out;
  const NoiseFactors now = ones(f.target);
  for (std::size_t i = 0; i < ranking.size(); ++i)
    for (std::size_t j = i + 1; j < ranking.size(); ++j) {
      const EffectData &A = data.at(ranking[i].name), &B = data.at(ranking[j].name);
      const double ra = reference_magnitude(*effects.at(A.name)), rb = reference_magnitude(*effects.at(B.name));
      double ab = 0, aa = 0, bb = 0, aR = 0, bR = 0, RR = 0;
      std::vector<double> ua, va, ub, vb, R, vR;
      for (std::size_t s = 0; s < f.nspeeds(); ++s) {
        effect_signature(A, ra, s, ua, va);
        effect_signature(B, rb, s, ub, vb);
        effect_predict(A, 0.0, s, R, vR);
        for (std::size_t k = 0; k < ua.size(); ++k) {
          const double w = weight(A, f.target, now, s, k);
          ab += ua[k] * ub[k] / w, aa += ua[k] * ua[k] / w, bb += ub[k] * ub[k] / w;
          aR += ua[k] * R[k] / w, bR += ub[k] * R[k] / w, RR += R[k] * R[k] / w;
        }
      }
      LookAlike l;
      l.a = A.name, l.b = B.name;
      if (aa > 0 && bb > 0) {
        const double c = std::clamp(ab / std::sqrt(aa * bb), -1.0, 1.0);
        l.angle_deg = std::acos(c) * 180.0 / M_PI;
        // the one at its reference stands off the other's best multiple and the fit's nuisance
        // scale (|c| <= the calibration bound, as every fit has it), the smaller of the two ways
        // round; without the scale, |u| sin(angle)
        const double bound = std::min(A.scale_bound, B.scale_bound);
        l.separation = std::sqrt(std::min(off_span2({aa, ab, bb, aR, bR, RR}, bound), off_span2({bb, ab, aa, bR, aR, RR}, bound)));
      }
      l.look_alike = l.separation * l.separation < GapThresholds::evidence_margin;
      l.fit_separation = std::sqrt(prediction_separation2(A, ranking[i].magnitude, ranking[i].scale, B, ranking[j].magnitude,
                                                          ranking[j].scale, f.target, now));
      out.push_back(l);
    }
  return out;
}

std::vector<KnotBend> knot_bends(const EffectData &ed, const Target &t)
{
  std::vector<KnotBend> out;
  const std::size_t nk = ed.knots.size();
  const NoiseFactors now = ones(t);
  for (std::size_t j = 1; j + 1 < nk; ++j) {
    KnotBend b;
    b.effect = ed.name;
    b.knot = ed.knots[j];
    b.left = ed.knots[j - 1];
    b.right = ed.knots[j + 1];
    const double w = (b.knot - b.left) / (b.right - b.left);
    // d = mean[j] - (1 - w) mean[j-1] - w mean[j+1]; the coefficients sum to 0, so the
    // reference common to a paired or referenced knot's mean cancels
    std::vector<double> c(nk, 0.0), var;
    c[j] = 1.0, c[j - 1] = -(1.0 - w), c[j + 1] = -w;
    for (std::size_t s = 0; s < t.mean.size(); ++s) {
      knot_combination_var(ed, c, s, true, var);
      for (std::size_t k = 0; k < t.mean[s].size(); ++k) {
        double d = 0.0;
        for (std::size_t i = j - 1; i <= j + 1; ++i) d += c[i] * ed.mean[i][s][k];
        const double wt = weight(ed, t, now, s, k);
        b.bend2 += (d * d - var[k]) / wt;
        b.noise2 += var[k] / wt;
        b.bend2_sd += (2.0 * var[k] * var[k] + 4.0 * std::max(0.0, d * d - var[k]) * var[k]) / (wt * wt);
      }
    }
    b.bend2_sd = std::sqrt(b.bend2_sd);
    b.earns_cost = b.bend2 >= GapThresholds::evidence_margin;
    b.resolved = b.bend2 + 2.0 * b.bend2_sd < GapThresholds::evidence_margin || b.bend2 - 2.0 * b.bend2_sd >= GapThresholds::evidence_margin;
    out.push_back(b);
  }
  return out;
}

namespace {

// The speed and fewest further runs there (up to MAX_RUNS_PER_SPEED) at which value(factors)
// reaches target; unreached: the speed where MAX_RUNS_PER_SPEED runs gain the most.
template <class Value>
NextMeasurement best_runs(const Features &f, double target, Value value)
{
  NextMeasurement m;
  m.target = target;
  m.now = value(ones(f.target));
  int best_runs = MAX_RUNS_PER_SPEED + 1;
  double best_after = -1.0;
  for (std::size_t s = 0; s < f.nspeeds(); ++s) {
    NoiseFactors fac = ones(f.target);
    const double n = (double) std::max<std::size_t>(1, f.real[s].n());
    int runs = MAX_RUNS_PER_SPEED;
    double after = 0.0;
    for (int r = 1; r <= MAX_RUNS_PER_SPEED; ++r) {
      fac[s] = n / (n + r);
      after = value(fac);
      if (after >= target) {
        runs = r;
        break;
      }
    }
    const bool reaches = after >= target;
    const int key = reaches ? runs : MAX_RUNS_PER_SPEED + 1;
    // fewer runs first; among equals, a clearly larger result (else the slower speed stays)
    if (key < best_runs || (key == best_runs && after > best_after * (1 + 1e-9) + 1e-12)) {
      best_runs = key, best_after = after;
      m.v0 = f.speeds[s], m.runs = runs, m.after = after, m.reaches = reaches;
    }
  }
  return m;
}

}    // namespace

std::optional<NextMeasurement> next_measurement(const std::vector<EffectFit> &ranking,
                                                const std::map<std::string, EffectData> &data, const Features &f,
                                                Verdict verdict)
{
  // after scale_only the next measurement is off the rig's data (ScaleFinding: a weighed calibration)
  if (ranking.empty() || f.nspeeds() == 0 || verdict == Verdict::explained || verdict == Verdict::scale_only) return std::nullopt;
  const EffectFit &top = ranking[0];
  if (ranking.size() > 1) {
    const EffectFit &second = ranking[1];
    const EffectData &A = data.at(top.name), &B = data.at(second.name);
    const bool contest = verdict == Verdict::tie || top.detected || second.detected;
    auto sep = [&](const NoiseFactors &fac) {
      return prediction_separation2(A, top.magnitude, top.scale, B, second.magnitude, second.scale, f.target, fac);
    };
    if (contest && sep(ones(f.target)) < GapThresholds::evidence_margin) {
      NextMeasurement m = best_runs(f, GapThresholds::evidence_margin, sep);
      m.goal = "separate";
      m.effects = {top.name, second.name};
      return m;
    }
  }
  // the undetected candidate nearest its threshold
  const EffectFit *near = nullptr;
  for (const auto &r : ranking)
    if (!r.detected && r.lr_threshold > 0 && (!near || r.lr / r.lr_threshold > near->lr / near->lr_threshold)) near = &r;
  if (!near) return std::nullopt;
  // the magnitude whose signature's expected likelihood ratio is the measured one, on the side
  // of the fit: the fitted magnitude itself may be where a compromise with another gap sits
  const EffectData &E = data.at(near->name);
  const auto [lo, hi] = magnitude_range(E);
  const double end = near->magnitude < 0 ? lo : hi;
  const double a = near->lr > 0 ? first_detected(E, f.target, near->lr, end, ones(f.target)).value_or(end) : 0.0;
  NextMeasurement m = best_runs(f, near->lr_threshold, [&](const NoiseFactors &fac) { return signature_strength(E, f.target, a, fac); });
  m.goal = "detect";
  m.effects = {near->name};
  return m;
}

ScaleFinding scale_finding(const EffectFit &scale, double magnitude, const std::vector<EffectFit> &ranking,
                           const std::map<std::string, EffectData> &data, const std::map<std::string, const Effect *> &effects,
                           const Features &f)
{
  ScaleFinding out;
  out.scale = magnitude;
  out.scale_error = scale.magnitude_error;
  out.bound = GapThresholds::calibration_scale_bound;
  // the two causes no trace tells apart: the same uniform scale of F
  out.causes.push_back({"calibration", "the force sensor's gain or calibration factor off by this much", magnitude,
                        "relative scale error", -1,
                        "a weighed calibration: known masses hung on the sensor through the rod's mount, its reading "
                        "against their weight",
                        std::nullopt});
  out.causes.push_back({"density", "grains of density (1 + scale) times the header's rho_g (the lithostatic term and the "
                                   "impact peak both go as rho_g)",
                        magnitude, "relative density error", -1,
                        "the grains weighed: a known volume of them (a pycnometer, or a graduated cylinder of water) on a "
                        "balance",
                        std::nullopt});
  const EffectData &S = data.at(scale.name);
  // what an effect no measured runs separate from the scale leaves to the lab
  const std::string what_is_left = "once the calibration and the density are checked, it is what is left (or a "
                                   "change of the rig that moves it and not a scale: another rod diameter, box width "
                                   "or speed range)";
  for (const auto &c : ranking) {
    if (c.is_scale || c.name == scale.name || !data.count(c.name)) continue;
    const EffectData &C = data.at(c.name);
    // each prediction with its fit's nuisance scale (the scale candidate's own is its magnitude)
    const auto sep = [&](const NoiseFactors &fac) {
      return prediction_separation2(C, c.magnitude, c.scale, S, magnitude, 0.0, f.target, fac);
    };
    const double sep2 = sep(ones(f.target));
    // an effect detected on its own that fits the data as well as the scale (its chi^2 within
    // the calibration bound at most the evidence margin above the scale's) can do it too,
    // however far its prediction stands from the scale's: it lost on evidence by its knots'
    // noise, not by its fit (bench packing at -0.18: chi^2 36.4 against 43.3, 2.46 sigma apart)
    const bool fits_as_well =
        c.detected && c.chi2_within_bound <= scale.chi2_within_bound + GapThresholds::evidence_margin;
    const bool look_alike = sep2 < GapThresholds::evidence_margin;
    if (!look_alike && !fits_as_well) continue;
    ScaleCause cause{c.name, effects.count(c.name) ? effects.at(c.name)->what : c.name, c.magnitude,
                     effects.count(c.name) ? effects.at(c.name)->unit : "", sep2, "", std::nullopt};
    if (!look_alike) {
      cause.tell_apart = "it fits these data as well as the scale (chi^2 " + printf_number("%.1f", c.chi2_within_bound) +
                         " against " + printf_number("%.1f", scale.chi2_within_bound) +
                         " within the calibration bound), its prediction " + printf_number("%.2f", std::sqrt(sep2)) +
                         " standard deviations from the scale's: " + what_is_left;
      out.causes.push_back(cause);
      continue;
    }
    NextMeasurement m = best_runs(f, GapThresholds::evidence_margin, sep);
    m.goal = "separate", m.effects = {c.name, scale.name};
    cause.tell_apart = m.reaches && m.after > 0
                           ? "measured runs: " + std::to_string(m.runs) + " more at v0 = " + printf_number("%g", m.v0) +
                                 " cm/s bring its prediction and the scale's the evidence margin apart"
                           : "no number of measured runs at these speeds: " + what_is_left;
    cause.runs = m;
    out.causes.push_back(cause);
  }
  return out;
}

Blindness how_blind(const std::vector<const Effect *> &effects, const std::map<std::string, EffectData> &data,
                    const Features &f, const std::vector<EffectFit> &ranking, const VerdictDecision &verdict,
                    double magnitude)
{
  Blindness out;
  std::map<std::string, const Effect *> by_name;
  for (const Effect *e : effects) {
    by_name[e->name] = e;
    const auto it = std::find_if(ranking.begin(), ranking.end(), [&](const EffectFit &x) { return x.name == e->name; });
    if (it != ranking.end()) out.limits.push_back(detection_limit(*e, data.at(e->name), *it, f));
    if (data.count(e->name))
      for (const KnotBend &b : knot_bends(data.at(e->name), f.target)) out.knot_bends.push_back(b);
  }
  out.look_alikes = look_alikes(ranking, data, by_name, f);
  out.next = next_measurement(ranking, data, f, verdict.verdict);
  out.false_alarms = null_false_alarms(effects, data, ranking, f);
  const auto scale = std::find_if(ranking.begin(), ranking.end(), [&](const EffectFit &x) { return x.name == verdict.scale_effect; });
  if (verdict.verdict == Verdict::scale_only && scale != ranking.end())
    out.scale_only = scale_finding(*scale, magnitude, ranking, data, by_name, f);
  return out;
}

}    // namespace granpen
