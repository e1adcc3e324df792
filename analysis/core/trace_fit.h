/* -*- c++ -*- ----------------------------------------------------------
   granpen analysis: the paper's observables of one force trace, from plain
   arrays z (cm) and F (dyne):
   - the depth term: k_z = slope of F on z over a depth window (the paper fits
     z >= 3 cm) and alpha = k_z / (mu rho_g g D^2) (paper: 35 +- 5 at 40 cm/s);
   - the transient peak: largest F over 0 < z < 0.7 R, R = D / 2;
   - the fluctuation wavelength: dominant wavelength of F about the linear fit
     in the window (the paper sees fluctuations of wavelength about d_g).
   Every result is finite: an undefined quantity is 0 with its *_ok flag false
   and a note saying why.
------------------------------------------------------------------------- */

#ifndef GRANPEN_TRACE_FIT_H
#define GRANPEN_TRACE_FIT_H

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace granpen {

struct TraceFitParams {
  double zlo = 3.0;                                          // fit window, cm
  double zhi = std::numeric_limits<double>::infinity();      // (inclusive both ends)
  double v0 = 0.0;       // cm/s (reported only)
  double D = 0.0;        // rod diameter, cm
  double g = 0.0;        // cm/s^2
  double mu = 0.0;       // grain friction coefficient
  double rho_g = 0.0;    // grain density, g/cm^3
  double d_g = 0.0;      // grain diameter, cm (the wavelength's natural unit)
  // A window the data do not fill: when it holds fewer than 3 distinct depths and the trace
  // reaches z > 0, the fit uses the deeper half of the trace, z = zdeep/2 .. zdeep (the
  // depth term dominates at depth); window_shortened and a note say so. A window end beyond
  // the deepest depth gets a note. Off: such a window leaves k_z undefined.
  bool shorten_window = false;
};

// Bounds of the wavelength's grid (docs/reliability.md). The grid is never finer than a
// quarter of the mean depth step (a 1e-7 cm jitter on repeated depths makes the median dz
// tiny: that grid would have ~1e7 points and more) nor than kMaxSpectrumPoints points; its
// FFT (Eigen's kissfft, O(n p) for a prime factor p of n) costs at most kMaxFftWork, else
// n is lowered to the next 5-smooth number (the span kept, dz slightly larger).
constexpr std::size_t kMaxSpectrumPoints = std::size_t(1) << 21;    // 2097152 points, 64 MB of buffers
constexpr double kMaxFftWork = 1.0e9;                                // n times n's largest prime factor

// Dominant wavelength of y(z): y resampled by linear interpolation onto a uniform
// grid of spacing the median dz (after sorting by z and averaging repeated z; raised to
// the bounds above when it is finer), mean
// removed, Hann window, FFT power spectrum; the bin of largest power among the
// frequency bins k >= 2 (bins 0 and 1, the mean and the record-length trend, are
// excluded), refined between bins by a parabola through the log power of the bin
// and its neighbours when it is a local maximum.
struct Wavelength {
  bool ok = false;
  double wavelength = 0.0;    // same unit as z
  double dz = 0.0;            // grid spacing (median dz, unless grid_limited)
  bool grid_limited = false;  // dz raised above the median dz by the bounds above
  double length = 0.0;        // record length n * dz: bin k is at wavelength length / k
  std::size_t n = 0;          // grid points
  std::size_t bin = 0;        // FFT bin of the peak
  double power_fraction = 0.0;    // peak bin's power / total power at bins >= 1
  bool lowest_bin = false;        // the peak is bin 2: the window is too short to say more
  std::string note;               // why not ok
};
Wavelength dominant_wavelength(const std::vector<double> &z, const std::vector<double> &y);

struct TraceFit {
  TraceFitParams params;            // as given (params.zhi may be infinite)
  double zlo = 0.0, zhi = 0.0;      // the window; an infinite end is the data's end
  bool window_shortened = false;    // params.shorten_window moved it onto the data

  // depth term: F = intercept + k_z z over the window
  bool slope_ok = false;
  std::size_t n_window = 0;            // points in the window
  double z_first = 0.0, z_last = 0.0;  // depth range of those points
  double k_z = 0.0, k_z_se = 0.0;      // dyne/cm
  double intercept = 0.0, intercept_se = 0.0;    // dyne
  double rms = 0.0;                    // residual RMS, dyne

  bool alpha_ok = false;
  double alpha = 0.0, alpha_se = 0.0;    // k_z / (mu rho_g g D^2), se from k_z's

  // the paper's form F_z = k_z0 z, through the origin, over the same window (with slope_ok):
  // the depth term F / F_z is measured against in the collapse; it differs from k_z by
  // the intercept's share
  double k_z0 = 0.0, k_z0_se = 0.0;      // sum F z / sum z^2, dyne/cm
  double alpha0 = 0.0, alpha0_se = 0.0;  // k_z0 / (mu rho_g g D^2) (with alpha_ok)

  // F = a z + b z^2 over the same window (through the origin): a depth-linear term and a
  // depth-squared one, as a side friction on the buried shaft grows (D z^2 against the
  // tip's D^2 z); alpha_a = a / (mu rho_g g D^2) is alpha's kind, beta_b = b / (mu rho_g g D)
  // the shaft-like term per unit of perimeter's scale (with alpha_ok)
  bool quad_ok = false;
  double quad_a = 0.0, quad_a_se = 0.0;    // dyne/cm
  double quad_b = 0.0, quad_b_se = 0.0;    // dyne/cm^2
  double alpha_a = 0.0, alpha_a_se = 0.0;
  double beta_b = 0.0, beta_b_se = 0.0;

  // transient peak over 0 < z < 0.7 R
  bool peak_ok = false;
  std::size_t n_peak = 0;              // points in that range
  double peak_zmax = 0.0;              // 0.7 R, cm
  double peak_F = 0.0, peak_z = 0.0;   // dyne, cm

  // fluctuations about the linear fit in the window
  bool wavelength_ok = false;
  double wavelength = 0.0;             // cm
  double wavelength_dg = 0.0;          // wavelength / d_g (0 when d_g <= 0)
  Wavelength spectrum;                 // details

  std::vector<std::string> notes;      // one line per undefined quantity
};

// Throws std::invalid_argument when z and F differ in length.
TraceFit fit_trace(const std::vector<double> &z, const std::vector<double> &F,
                   const TraceFitParams &p);

}    // namespace granpen

#endif
