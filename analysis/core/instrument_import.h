// granpen analysis: the numerics of `granpen import` (a lab's instrument file -> a force
// trace), as kernels on chunks of rows so that a file of any length is streamed:
//   units       -> factors from an instrument's units to the trace's (cgs or si);
//   PushScan    (pass 1) tare, force onset, the surface, the end of the push, the mean speed;
//   SpeedProfile(pass 2) the speed in blocks of rows: ramp-up, and the deceleration to cut;
//   TraceBuilder(pass 3) the trace rows (tared, at depth, optionally window-averaged) and
//                the speed statistics (mean, ripple, constant or two speeds).
// Nothing here knows files or prints; a rejection is an ImportRejected naming the row's
// line, which the reader's caller turns into FILE:LINE.
#ifndef GRANPEN_INSTRUMENT_IMPORT_H
#define GRANPEN_INSTRUMENT_IMPORT_H

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace granpen {

// A rejected row or file: line is the instrument file's line (0: the file as a whole).
class ImportRejected : public std::runtime_error {
 public:
  ImportRejected(long line, const std::string &what) : std::runtime_error(what), line(line) {}
  long line;
};

// ---- units: factor * value in `unit` = value in the trace's units (si: N, m, s;
// cgs: dyne, cm, s). false when the unit is not known.
bool force_unit_factor(const std::string &unit, bool si, double &factor);
// kPa or MPa: stress * area; area_m2 > 0 in m^2
bool stress_unit_factor(const std::string &unit, double area_m2, bool si, double &factor);
bool length_unit_factor(const std::string &unit, bool si, double &factor);
// an area in m^2 from m2, cm2, mm2 or in2
bool area_unit_factor_m2(const std::string &unit, double &factor);
bool time_unit_factor(const std::string &unit, double &factor);    // s, ms, us, min -> s
// LENGTH/TIME, e.g. mm/s, cm/s, mm/min, in/s
bool speed_unit_factor(const std::string &unit, bool si, double &factor);

// One instrument row in the trace's units, signs applied. x: position along the push
// (NaN when the file has none), v: measured speed (NaN when none), line: the file's line.
struct ImportRow {
  double t = NAN, x = NAN, F = NAN, v = NAN;
  long line = 0;
};

// t of a depth-sampled log (a row per depth step, a measured speed, no time): the
// integral of dz / v over the rows, each step at the mean speed of its two rows,
// t_i = t_(i-1) + (x_i - x_(i-1)) / ((v_i + v_(i-1)) / 2); t = 0 at the first row. The
// mean of the two speeds keeps a step finite when one of its rows stands still.
class DepthClock {
 public:
  // the row's t; throws ImportRejected(line) when the depth does not advance or the
  // step's mean speed is not positive
  double next(double x, double v, long line);

 private:
  bool started_ = false;
  double x_ = 0.0, v_ = 0.0, t_ = 0.0;
};

// How a push is read (all in the trace's units).
struct ImportRules {
  bool has_position = false;      // a displacement/depth column (else depth = v0 (t - t_surface))
  bool has_speed = false;         // a measured-speed column
  bool has_time = true;           // false: t is the row index (ordering only), no speed is measured
  std::size_t tare_rows = 50;     // force offset = mean force of the first tare_rows rows (0: none)
  double onset_force = NAN;       // contact: first row with tared F >= this (> 0)
  bool surface_given = false;     // surface: the position (or, without one, the time) below
  double surface = 0.0;
  double v0 = NAN;                // nominal speed (needed without a position column)
  double position_noise = 0.0;    // a position within this of the furthest is not a retreat
  double end_time = NAN;          // rows after this raw time are cut (NaN: by the rule)
  std::size_t speed_rows = 50;    // rows per block of the speed profile
  double speed_tolerance = 0.05;  // relative: speed constant within this
  double end_tolerance = 0.15;    // relative: a block this far below the mean is stopping (the end cut)
  double window = 0.0;            // > 0: average into windows of this length (s)
};

// ---- pass 1
struct PushLimits {
  std::size_t rows = 0;
  double tare = 0.0;              // subtracted from F
  long onset_line = 0;            // first row at contact (0: no contact)
  double surface = NAN;           // raw position (or raw time, without one) of z = 0
  long end_line = 0;              // last row of the push before the speed rule's cut
  double t_first = NAN;           // raw time of the first row (t = 0 in the trace)
  double t_onset = NAN, x_onset = NAN, t_end = NAN, x_end = NAN;
  double mean_speed = NAN;        // (x_end - x_onset) / (t_end - t_onset), with a position
};

class PushScan {
 public:
  explicit PushScan(const ImportRules &rules) : rules_(rules) {}
  // rows in file order; throws ImportRejected (time not increasing, a retreat followed by
  // an advance past it, non-finite values)
  void add(const std::vector<ImportRow> &rows);
  PushLimits finish();

 private:
  void row(const ImportRow &r);
  ImportRules rules_;
  PushLimits lim_;
  std::vector<ImportRow> tare_buffer_;    // the first tare_rows rows, until the tare is known
  bool tared_ = false;
  double last_t_ = NAN;
  long last_line_ = 0;
  double first_t_ = NAN, first_x_ = NAN;
  double furthest_ = -INFINITY;
  long retreat_line_ = 0;                 // first row behind the furthest position
  double retreat_x_ = NAN;
  long last_contact_line_ = 0;            // without a position: last row with F >= onset
  double last_contact_t_ = NAN;
};

// ---- pass 2 (with a position or a speed column)
struct SpeedRamp {
  double ramp_depth = NAN;        // depth at the end of the first of two blocks at speed (NaN: never)
  double ramp_t = NAN;            // raw time there
  long cut_line = 0;              // last row kept: the end of the last block still moving (within
                                  // end_tolerance of the mean) after the ramp, <= end_line
  double cut_t = NAN;             // raw time of that row
  std::size_t blocks = 0;
};

class SpeedProfile {
 public:
  SpeedProfile(const ImportRules &rules, const PushLimits &lim) : rules_(rules), lim_(lim) {}
  void add(const std::vector<ImportRow> &rows);
  SpeedRamp finish();

 private:
  void close_block();
  ImportRules rules_;
  PushLimits lim_;
  SpeedRamp ramp_;
  std::size_t n_ = 0;
  ImportRow first_, last_, prev_;
  bool has_prev_ = false;
  int run_ = 0;                 // blocks at speed in a row
  double run_t_ = NAN, run_depth_ = NAN;
  double v_sum_ = 0.0;
  bool done_ = false;
};

// ---- pass 3
struct TracePoint {
  double t, z, F;
};

struct SpeedStats {
  bool measured = false;          // a position or speed column existed
  double mean = NAN;              // over the push at speed (after the ramp, before the cut)
  double ripple = NAN;            // standard deviation of the block speeds / mean
  double worst = NAN;             // largest |segment speed - mean| / mean
  bool constant = true;           // worst <= tolerance and ripple <= tolerance
  // the speed against depth: each of the SEGMENTS equal times of the push at speed (those
  // of at least two rows), its depth range and speed
  struct Segment {
    double z_from, z_to, speed;
  };
  std::vector<Segment> profile;
};

struct ImportSummary {
  std::size_t rows_read = 0, rows_cut = 0, points = 0;
  std::size_t rows_pushed = 0;           // rows kept
  std::size_t rows_cut_by_speed = 0;     // of rows_cut, those before the furthest advance
  double z_first = NAN, z_last = NAN;
  PushLimits limits;
  SpeedRamp ramp;
  SpeedStats speed;
};

class TraceBuilder {
 public:
  static constexpr int SEGMENTS = 16;    // the push at speed in this many equal times
  TraceBuilder(const ImportRules &rules, const PushLimits &lim, const SpeedRamp &ramp);
  // the trace points of these rows go to out (appended); rows after the cut are counted
  void add(const std::vector<ImportRow> &rows, std::vector<TracePoint> &out);
  // the last window's point (when complete) to out, and the speed statistics; throws
  // ImportRejected "two speeds in one file" at the line where the second begins
  ImportSummary finish(std::vector<TracePoint> &out);

 private:
  void emit(const ImportRow &r, std::vector<TracePoint> &out);
  double depth(const ImportRow &r) const;
  ImportRules rules_;
  ImportSummary sum_;
  long cut_line_;
  double seg_t0_, seg_t1_;
  // windows
  long window_ = 0;
  bool window_open_ = false;
  std::size_t window_n_ = 0;
  double window_F_ = 0.0, window_z_ = 0.0, window_t_ = 0.0;
  // block speeds at speed (Welford)
  bool at_speed_ = false;
  ImportRow range_first_, range_last_;
  double range_v_ = 0.0;
  std::size_t range_n_ = 0;
  std::size_t blk_n_ = 0, blocks_ = 0;
  ImportRow blk_first_, blk_last_;
  double blk_v_ = 0.0, mean_b_ = 0.0, m2_b_ = 0.0;
  // segments
  struct Segment {
    ImportRow first, last;
    double v_sum = 0.0;
    std::size_t n = 0;
  } seg_[SEGMENTS];
};

// the speed of rows first..last: measured-speed mean (has_speed) or the position's slope
double block_speed(const ImportRow &first, const ImportRow &last, double v_sum, std::size_t n, bool has_speed);

}    // namespace granpen

#endif
