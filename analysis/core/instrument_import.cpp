// granpen analysis: the numerics of `granpen import` (see instrument_import.h).
#include "instrument_import.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace granpen {

namespace {

std::string num(double v)
{
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.6g", v);
  return buf;
}

bool lookup(const std::map<std::string, double> &table, const std::string &unit, double &factor)
{
  const auto it = table.find(unit);
  if (it == table.end()) return false;
  factor = it->second;
  return true;
}

}    // namespace

// ---- units
bool force_unit_factor(const std::string &unit, bool si, double &factor)
{
  static const std::map<std::string, double> newtons = {
      {"N", 1.0}, {"kN", 1e3}, {"mN", 1e-3}, {"lbf", 4.4482216152605}, {"dyne", 1e-5}, {"dyn", 1e-5}};
  if (!lookup(newtons, unit, factor)) return false;
  if (!si) factor *= 1e5;    // N -> dyne
  return true;
}

bool stress_unit_factor(const std::string &unit, double area_m2, bool si, double &factor)
{
  static const std::map<std::string, double> pascals = {{"Pa", 1.0}, {"kPa", 1e3}, {"MPa", 1e6}};
  if (!lookup(pascals, unit, factor) || !(area_m2 > 0.0)) return false;
  factor *= area_m2 * (si ? 1.0 : 1e5);
  return true;
}

bool length_unit_factor(const std::string &unit, bool si, double &factor)
{
  static const std::map<std::string, double> metres = {
      {"m", 1.0}, {"cm", 1e-2}, {"mm", 1e-3}, {"um", 1e-6}, {"in", 0.0254}};
  if (!lookup(metres, unit, factor)) return false;
  if (!si) factor *= 100.0;
  return true;
}

bool area_unit_factor_m2(const std::string &unit, double &factor)
{
  static const std::map<std::string, double> m2 = {
      {"m2", 1.0}, {"cm2", 1e-4}, {"mm2", 1e-6}, {"in2", 0.0254 * 0.0254}};
  return lookup(m2, unit, factor);
}

bool time_unit_factor(const std::string &unit, double &factor)
{
  static const std::map<std::string, double> seconds = {{"s", 1.0}, {"ms", 1e-3}, {"us", 1e-6}, {"min", 60.0}};
  return lookup(seconds, unit, factor);
}

bool speed_unit_factor(const std::string &unit, bool si, double &factor)
{
  const auto slash = unit.find('/');
  if (slash == std::string::npos) return false;
  double l, t;
  if (!length_unit_factor(unit.substr(0, slash), si, l) || !time_unit_factor(unit.substr(slash + 1), t)) return false;
  factor = l / t;
  return true;
}

double block_speed(const ImportRow &first, const ImportRow &last, double v_sum, std::size_t n, bool has_speed)
{
  if (has_speed) return n ? v_sum / (double) n : NAN;
  return last.t > first.t ? (last.x - first.x) / (last.t - first.t) : NAN;
}

double DepthClock::next(double x, double v, long line)
{
  if (!std::isfinite(x) || !std::isfinite(v)) throw ImportRejected(line, "a value is not finite");
  if (!started_) {
    started_ = true;
    x_ = x, v_ = v;
    return t_;
  }
  const double dx = x - x_, vm = 0.5 * (v + v_);
  if (!(dx > 0.0))
    throw ImportRejected(line, "depth does not advance (" + num(x) + " after " + num(x_) +
                                   "): t = the integral of dz / v needs a row per depth step, going down");
  if (!(vm > 0.0))
    throw ImportRejected(line, "speed " + num(v) + " after " + num(v_) +
                                   ": t = the integral of dz / v needs a positive speed");
  t_ += dx / vm;
  x_ = x, v_ = v;
  return t_;
}

// ---- pass 1
void PushScan::add(const std::vector<ImportRow> &rows)
{
  for (const auto &r : rows) {
    if (!std::isfinite(r.t) || !std::isfinite(r.F) || (rules_.has_position && !std::isfinite(r.x)) ||
        (rules_.has_speed && !std::isfinite(r.v)))
      throw ImportRejected(r.line, "a value is not finite");
    if (last_line_ && !(r.t > last_t_))
      throw ImportRejected(r.line, "time does not increase (" + num(r.t) + " s after " + num(last_t_) + " s)");
    last_t_ = r.t;
    last_line_ = r.line;
    if (tared_ || rules_.tare_rows == 0) {    // tare_rows = 0: no offset (tare stays 0)
      tared_ = true;
      row(r);
      continue;
    }
    tare_buffer_.push_back(r);
    if (tare_buffer_.size() < rules_.tare_rows) continue;
    double sum = 0.0;
    for (const auto &b : tare_buffer_) sum += b.F;
    lim_.tare = tare_buffer_.empty() ? 0.0 : sum / (double) tare_buffer_.size();
    tared_ = true;
    for (const auto &b : tare_buffer_) row(b);
    // contact inside the rows that set the tare: the offset would include the bed's force
    if (lim_.onset_line && lim_.rows <= rules_.tare_rows && rules_.tare_rows > 0)
      throw ImportRejected(lim_.onset_line, "contact (tared force >= onset_force) within the first tare_rows = " +
                                                std::to_string(rules_.tare_rows) + " rows, which set the force offset");
    tare_buffer_.clear();
    tare_buffer_.shrink_to_fit();
  }
}

void PushScan::row(const ImportRow &r)
{
  if (!lim_.rows++) lim_.t_first = r.t;
  const bool in_time = std::isnan(rules_.end_time) || r.t <= rules_.end_time;
  const double f = r.F - lim_.tare;
  const bool contact = std::isfinite(rules_.onset_force) && f >= rules_.onset_force;
  if (!lim_.onset_line && contact && in_time) {
    lim_.onset_line = r.line;
    lim_.t_onset = r.t;
    lim_.x_onset = r.x;
  }
  if (!in_time) return;
  if (!rules_.has_position) {
    // without a position the push ends where the force last stood at contact (retraction
    // unloads the rod), or at the last row when there is no threshold
    if (contact || !std::isfinite(rules_.onset_force)) {
      lim_.end_line = r.line;
      lim_.t_end = r.t;
    }
    return;
  }
  if (retreat_line_ && r.x > retreat_x_ + rules_.position_noise)
    throw ImportRejected(retreat_line_, "displacement goes backwards (below its furthest, " + num(retreat_x_) +
                                            ") and advances past it again at line " + std::to_string(r.line) +
                                            " (a sensor's noise: set position_noise above it)");
  if (!retreat_line_ && r.x < furthest_ - rules_.position_noise) {
    retreat_line_ = r.line;
    retreat_x_ = furthest_;
  }
  if (!retreat_line_ && r.x > furthest_) {
    lim_.end_line = r.line;
    lim_.t_end = r.t;
    lim_.x_end = r.x;
  }
  furthest_ = std::max(furthest_, r.x);
  if (lim_.rows == 1) {
    first_t_ = r.t;
    first_x_ = r.x;
  }
}

PushLimits PushScan::finish()
{
  if (!tared_) {
    if (tare_buffer_.empty()) throw ImportRejected(0, "no data rows");
    throw ImportRejected(0, "only " + std::to_string(tare_buffer_.size()) + " data rows, fewer than tare_rows = " +
                                std::to_string(rules_.tare_rows));
  }
  if (rules_.surface_given)
    lim_.surface = rules_.surface;
  else if (!lim_.onset_line)
    throw ImportRejected(0, "no contact: the tared force never reaches onset_force = " + num(rules_.onset_force));
  else
    lim_.surface = rules_.has_position ? lim_.x_onset : lim_.t_onset;
  if (!lim_.end_line) throw ImportRejected(0, rules_.has_position ? "the position never advances" : "no rows to keep");
  if (rules_.has_position) {
    const double t0 = lim_.onset_line ? lim_.t_onset : first_t_, x0 = lim_.onset_line ? lim_.x_onset : first_x_;
    if (lim_.t_end > t0) lim_.mean_speed = (lim_.x_end - x0) / (lim_.t_end - t0);
  }
  return lim_;
}

// ---- pass 2
void SpeedProfile::add(const std::vector<ImportRow> &rows)
{
  for (const auto &r : rows) {
    if (done_ || r.line > lim_.end_line) {
      if (!done_ && n_) close_block();
      done_ = true;
      return;
    }
    if (!n_) first_ = r;
    last_ = r;
    v_sum_ += r.v;
    if (++n_ == rules_.speed_rows) close_block();
  }
}

void SpeedProfile::close_block()
{
  const double ref = std::isfinite(lim_.mean_speed) ? lim_.mean_speed : rules_.v0;
  // blocks are chained (each from the last row of the one before), so no advance between
  // them goes unseen and a last block of one row still has a speed
  const double s = block_speed(has_prev_ ? prev_ : first_, last_, v_sum_, n_, rules_.has_speed);
  prev_ = last_;
  has_prev_ = true;
  ++ramp_.blocks;
  // at speed: two blocks running within the tolerance of the mean (one block alone may be
  // the mixture of two speeds that happens to average to it)
  if (std::isfinite(s) && std::fabs(s - ref) <= rules_.speed_tolerance * std::fabs(ref)) {
    if (!run_++) {
      run_t_ = last_.t;
      run_depth_ = rules_.has_position ? last_.x - lim_.surface : rules_.v0 * (last_.t - lim_.surface);
    }
    if (run_ >= 2 && std::isnan(ramp_.ramp_t)) {
      ramp_.ramp_t = run_t_;
      ramp_.ramp_depth = run_depth_;
    }
  } else {
    run_ = 0;
  }
  // still moving, once at speed: not below the mean by end_tolerance. The push ends after
  // the last such block, so a deceleration (a fall that does not come back) is cut and a
  // slow drift of a few percent is kept (and reported by the speed statistics)
  if (std::isfinite(ramp_.ramp_t) && std::isfinite(s) && s >= (1.0 - rules_.end_tolerance) * std::fabs(ref)) {
    ramp_.cut_line = last_.line;
    ramp_.cut_t = last_.t;
  }
  n_ = 0;
  v_sum_ = 0.0;
}

SpeedRamp SpeedProfile::finish()
{
  if (!done_ && n_) close_block();
  done_ = true;
  if (!ramp_.cut_line) {    // never at speed: nothing cut by the speed rule
    ramp_.cut_line = lim_.end_line;
    ramp_.cut_t = lim_.t_end;
  }
  return ramp_;
}

// ---- pass 3
TraceBuilder::TraceBuilder(const ImportRules &rules, const PushLimits &lim, const SpeedRamp &ramp)
    : rules_(rules), cut_line_(ramp.cut_line ? ramp.cut_line : lim.end_line), seg_t0_(ramp.ramp_t),
      seg_t1_(ramp.cut_t)
{
  // never at the mean speed (two speeds, or no steady one): the whole push is examined
  if (std::isnan(seg_t0_)) {
    seg_t0_ = lim.onset_line ? lim.t_onset : lim.t_first;
    seg_t1_ = lim.t_end;
  }
  sum_.limits = lim;
  sum_.ramp = ramp;
  sum_.speed.measured = (rules.has_position || rules.has_speed) && rules.has_time;
}

double TraceBuilder::depth(const ImportRow &r) const
{
  return rules_.has_position ? r.x - sum_.limits.surface : rules_.v0 * (r.t - sum_.limits.surface);
}

void TraceBuilder::add(const std::vector<ImportRow> &rows, std::vector<TracePoint> &out)
{
  for (const auto &r : rows) {
    ++sum_.rows_read;
    if (r.line > cut_line_) {
      ++sum_.rows_cut;
      if (r.line <= sum_.limits.end_line) ++sum_.rows_cut_by_speed;
      continue;
    }
    ++sum_.rows_pushed;
    emit(r, out);
    if (!sum_.speed.measured || !(r.t >= seg_t0_) || !(seg_t1_ > seg_t0_)) continue;
    // the push at speed: its blocks (ripple) and its segments (constant, or two speeds)
    if (!at_speed_) range_first_ = r;
    at_speed_ = true;
    range_last_ = r;
    range_v_ += r.v;
    ++range_n_;
    if (!blk_n_) blk_first_ = r;
    blk_last_ = r;
    blk_v_ += r.v;
    if (++blk_n_ == rules_.speed_rows) {
      const double s = block_speed(blk_first_, blk_last_, blk_v_, blk_n_, rules_.has_speed);
      if (std::isfinite(s)) {
        ++blocks_;
        const double d = s - mean_b_;
        mean_b_ += d / (double) blocks_;
        m2_b_ += d * (s - mean_b_);
      }
      blk_n_ = 0;
      blk_v_ = 0.0;
    }
    const int k = std::min(SEGMENTS - 1, std::max(0, (int) ((r.t - seg_t0_) / (seg_t1_ - seg_t0_) * SEGMENTS)));
    Segment &sg = seg_[k];
    if (!sg.n) sg.first = r;
    sg.last = r;
    sg.v_sum += r.v;
    ++sg.n;
  }
}

namespace {

// A trace's every value stays finite in cgs units (the trace reader scales si by up to
// 1e5 and refuses what overflows): beyond this, a row of the import would fail `check`.
constexpr double kLargestTraceValue = 1.0e300;

std::string num_g(double v)
{
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}

void check_trace_value(double v, const char *what, long line)
{
  if (!(std::fabs(v) <= kLargestTraceValue))
    throw ImportRejected(line, std::string("the trace's ") + what + " = " + num_g(v) +
                                   " at this row is not finite, or too large for a trace (|" + what +
                                   "| <= 1e300): a unit, surface, sample_rate or offset out of range?");
}

}    // namespace

void TraceBuilder::emit(const ImportRow &r, std::vector<TracePoint> &out)
{
  const double t = r.t - sum_.limits.t_first, z = depth(r), F = r.F - sum_.limits.tare;
  check_trace_value(t, "t", r.line);
  check_trace_value(z, "z", r.line);
  check_trace_value(F, "F", r.line);
  if (!(rules_.window > 0.0)) {
    if (std::isnan(sum_.z_first)) sum_.z_first = z;
    out.push_back({t, z, F});
    ++sum_.points;
    sum_.z_last = z;
    return;
  }
  // window k holds the rows with k w < t <= (k+1) w and is written at its end, as the
  // simulations' fix ave/time writes; 1e-9 of a window absorbs the rounding of t / w
  const double windows = std::ceil(t / rules_.window - 1e-9) - 1;
  // a window index beyond 1e15 overflows a long's exactness (and rows land at negative t)
  if (!(windows < 1e15))
    throw ImportRejected(r.line, "window = " + num_g(rules_.window) + " s is too short for t = " + num_g(t) +
                                     " s (window number " + num_g(windows) +
                                     ", more than 1e15)");
  const long k = (long) windows;
  if (window_open_ && k != window_) {
    if (window_ >= 0) {    // window -1 holds only the first row: it began before the data
      if (std::isnan(sum_.z_first)) sum_.z_first = window_z_;
      out.push_back({(window_ + 1) * rules_.window, window_z_, window_F_ / (double) window_n_});
      ++sum_.points;
      sum_.z_last = window_z_;
    }
    window_open_ = false;
  }
  if (!window_open_) {
    window_open_ = true;
    window_ = k;
    window_n_ = 0;
    window_F_ = 0.0;
  }
  ++window_n_;
  window_F_ += F;
  window_z_ = z;
  window_t_ = t;
}

ImportSummary TraceBuilder::finish(std::vector<TracePoint> &out)
{
  // the last window counts only when the data reach its end
  if (window_open_ && window_ >= 0 && window_t_ >= (window_ + 1 - 1e-6) * rules_.window) {
    if (std::isnan(sum_.z_first)) sum_.z_first = window_z_;
    out.push_back({(window_ + 1) * rules_.window, window_z_, window_F_ / (double) window_n_});
    ++sum_.points;
    sum_.z_last = window_z_;
  }
  window_open_ = false;
  SpeedStats &st = sum_.speed;
  if (!st.measured || range_n_ < 2) return sum_;
  st.mean = block_speed(range_first_, range_last_, range_v_, range_n_, rules_.has_speed);
  if (!(std::fabs(st.mean) > 0.0)) return sum_;
  st.ripple = blocks_ >= 2 ? std::sqrt(m2_b_ / (double) (blocks_ - 1)) / std::fabs(st.mean) : 0.0;
  std::vector<double> s;
  std::vector<long> line;
  for (const auto &sg : seg_)
    if (sg.n >= 2) {
      s.push_back(block_speed(sg.first, sg.last, sg.v_sum, sg.n, rules_.has_speed));
      line.push_back(sg.first.line);
      st.profile.push_back({depth(sg.first), depth(sg.last), s.back()});
    }
  const double tol = rules_.speed_tolerance;
  st.worst = 0.0;
  for (double v : s) st.worst = std::max(st.worst, std::fabs(v - st.mean) / std::fabs(st.mean));
  // two speeds: the segments before segment j and those after it (j itself may hold the
  // change) each constant within the tolerance about their own means, and those means
  // apart by more than it, and so are the two segments beside j: a step, where a slow
  // drift (a few percent over several segments) changes little from one segment to the
  // next; each side at least two segments, so that what is left of a ramp or a
  // deceleration is not a second speed
  for (std::size_t j = 2; j + 3 <= s.size() && st.worst > tol; ++j) {
    double a = 0.0, b = 0.0;
    for (std::size_t i = 0; i < s.size(); ++i)
      if (i != j) (i < j ? a : b) += s[i];
    a /= (double) j;
    b /= (double) (s.size() - j - 1);
    bool flat = true;
    for (std::size_t i = 0; i < s.size(); ++i)
      if (i != j) flat = flat && std::fabs(s[i] - (i < j ? a : b)) <= tol * std::fabs(i < j ? a : b);
    const bool step = std::fabs(s[j + 1] - s[j - 1]) > tol * 0.5 * std::fabs(s[j + 1] + s[j - 1]);
    if (flat && step && std::fabs(a - b) > tol * 0.5 * std::fabs(a + b))
      throw ImportRejected(line[j], "two speeds in one file: " + num(a) + " until about this line, " + num(b) +
                                        " after it (one push speed per trace)");
  }
  st.constant = st.worst <= tol && st.ripple <= tol;
  return sum_;
}

}    // namespace granpen
