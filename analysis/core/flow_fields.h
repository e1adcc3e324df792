/* -*- c++ -*- ----------------------------------------------------------
   granpen analysis: the flow around the rod from grain snapshots (dump frames),
   on plain arrays, accumulated over frames. The definitions are those of
   compute flow/azimuthal (docs/compute_flow_azimuthal.rst); the paper's
   observables built on them ("Inertial Number", "Temporal Flows"). The grid,
   the sums, the moments, the shear rate and I are src/flow_bins.h's kernels,
   the ones the compute calls:

   - FlowAccumulator: (r, z) bins about the rod axis, z measured from a reference
     height (the rod tip: the compute's frame tip, negative below the tip). Per
     bin: count, phi (centre-assigned: grain volume / bin volume), phi_voronoi
     (grain volume / Voronoi cell volume), mass-weighted v_r, v_z, v_theta,
     granular temperature T = (<|v|^2> - v_r^2 - v_z^2 - v_theta^2) / 3,
     p = -sum tr(S_i) / (3 V_bin) from per-grain stress x volume S_i (compute
     stress/atom), sigma_zz, the paper's shear rate
       gammadot = sqrt(1/2 (dvr/dr - dvz/dz)^2 + 1/2 (dvr/dz + dvz/dr)^2)
     by centred differences of bin means between the bins' mass-weighted mean
     positions (one-sided at edges and next to empty bins), and the inertial
     number I = gammadot d_g / sqrt(p / rho_g) (0 where p <= 0).
     Over several frames the sums are pooled: counts, phi and p are means per
     frame, velocities and T mass-weighted over every sample, gammadot and I from
     the pooled means. One frame gives exactly the compute's values.
   - SliceAccumulator: the same means for the grains of an annulus r1 <= r < r2,
     in bins of z - zref: the profile below the rod face (r < D/3, tip frame),
     the near-shaft strip (lab frame, z from the bed surface), the annulus
     r = 2-3 cm of the "Temporal Flows" section (one bin).
   - fit_exponential: v(z) = A exp(z / lambda) (weighted fit of ln|v|); over windows of
     the profile, local_exponential_fits.
   - edge_average: the mean phi and I of the bins at the rod's bottom edge.
------------------------------------------------------------------------- */

#ifndef GRANPEN_FLOW_FIELDS_H
#define GRANPEN_FLOW_FIELDS_H

#include "flow_bins.h"

#include <cstddef>
#include <string>
#include <vector>

namespace granpen {

// One frame's grains (no rod atoms), arrays of length n, lab frame.
struct GrainArrays {
  std::size_t n = 0;
  const double *x = nullptr, *y = nullptr, *z = nullptr;
  const double *vx = nullptr, *vy = nullptr, *vz = nullptr;
  const double *radius = nullptr, *mass = nullptr;
  const double *voronoi = nullptr;    // per-grain Voronoi cell volume, or null
  const double *sxx = nullptr, *syy = nullptr, *szz = nullptr;    // stress x volume, or null
};

// The axis (x, y), the height z is measured from, and the periods of x and y
// (0: not periodic; a grain's distance uses the nearest image of the axis).
struct AxisFrame {
  double x = 0.0, y = 0.0, zref = 0.0;
  double period_x = 0.0, period_y = 0.0;
};

// FlowGrid, make_flow_grid, FlowBin: src/flow_bins.h (the kernels compute flow/azimuthal
// calls too).

struct FlowFields {
  FlowGrid grid;
  int frames = 0;
  bool have_voronoi = false, have_stress = false;    // in every frame
  std::vector<FlowBin> bins;                         // bin iz * nr + ir
  const FlowBin &at(int ir, int iz) const { return bins[(std::size_t) iz * grid.nr + ir]; }
};

class FlowAccumulator {
 public:
  explicit FlowAccumulator(const FlowGrid &grid);
  void add(const GrainArrays &g, const AxisFrame &a);    // one frame
  void merge(const FlowAccumulator &other);              // the same grid
  // d_g, rho_g: for I. Throws std::invalid_argument when they are not positive.
  FlowFields fields(double d_g, double rho_g) const;
  int frames() const { return frames_; }
  const FlowGrid &grid() const { return grid_; }

 private:
  FlowGrid grid_;
  int frames_ = 0, voronoi_frames_ = 0, stress_frames_ = 0;
  std::vector<double> acc_;
};

// ---- slices: r1 <= r < r2, zc = z - zref in [zlo, zhi) in nz = max(1, round((zhi -
// zlo) / dz)) bins (dz adjusted); the annulus volume of a bin for phi_centre.
struct SliceSpec {
  double r1 = 0.0, r2 = 0.0, zlo = 0.0, zhi = 0.0, dz = 0.0;
};

struct SliceBin {
  double z = 0.0;              // bin centre (in z - zref)
  double samples = 0.0;        // grains summed over the frames
  double count = 0.0;          // grains per frame
  double phi_centre = 0.0, phi_voronoi = 0.0;
  double vr = 0.0, vz = 0.0, vtheta = 0.0, T = 0.0;
  double vz_se = 0.0;          // standard error of vz: sqrt(var_m(vz) / (samples - 1)), 0 below 2
};

class SliceAccumulator {
 public:
  // Throws std::invalid_argument for r2 <= r1, r1 < 0, zhi <= zlo or dz <= 0.
  explicit SliceAccumulator(const SliceSpec &spec);
  void add(const GrainArrays &g, const AxisFrame &a);
  std::vector<SliceBin> bins() const;
  int frames() const { return frames_; }
  bool have_voronoi() const { return frames_ > 0 && voronoi_frames_ == frames_; }
  const SliceSpec &spec() const { return spec_; }
  int nz() const { return nz_; }

 private:
  SliceSpec spec_;
  int nz_ = 0, frames_ = 0, voronoi_frames_ = 0;
  std::vector<double> acc_;
};

// ---- v(z) = A exp(z / lambda): least squares of ln|v| = ln|A| + z / lambda with weights
// (v / se)^2 (the variance of ln|v| is (se / v)^2), or v^2 where se is empty. Uses the
// points of the sign of the largest |v| with |v| > 2 se (|v| > 0 without se), at least 3
// of them; the parameters' errors are scaled by the residual variance.
struct ExpFit {
  bool ok = false;
  double A = 0.0, A_se = 0.0;
  double lambda = 0.0, lambda_se = 0.0;
  std::size_t n = 0;
  double zmin = 0.0, zmax = 0.0;    // range of the points used
  std::string note;                 // why not ok
};
ExpFit fit_exponential(const std::vector<double> &z, const std::vector<double> &v,
                       const std::vector<double> &se = {});

// ---- the local decay length of a profile: fit_exponential over each window z_i <= z <= z_i +
// width (cm) that starts at a point and lies within the profile (z_i + width at most the
// largest z), every window's fit in order of z_i (one that does not hold keeps its note: too
// few usable points, or no decay there). One exponential gives one lambda in every window; a
// curved profile shows at what distance from the face it decays slower or faster than a
// single fit over all of it says.
struct LocalExpFit {
  double z_lo = 0.0, z_hi = 0.0;    // the window, z_i to z_i + width
  ExpFit fit;                       // of its points
};
std::vector<LocalExpFit> local_exponential_fits(const std::vector<double> &z, const std::vector<double> &v,
                                                const std::vector<double> &se, double width);

// ---- the rod's bottom edge: mass-weighted means over the bins whose centres satisfy
// |r - R| <= wr and |z| <= wz (tip frame).
struct EdgeAverage {
  int bins = 0;
  double mass = 0.0;
  double phi_centre = 0.0, phi_voronoi = 0.0, I = 0.0, gammadot = 0.0, p = 0.0;
};
EdgeAverage edge_average(const FlowFields &f, double R, double wr, double wz);

// ---- the surface flux's sign change: the time t (linearly interpolated) where v, sampled
// at increasing t, last goes from positive to zero or below (paper: the near-shaft surface
// grains stop rising and start to flow down at t~ = 1); NaN when it never does.
double last_down_crossing(const std::vector<double> &t, const std::vector<double> &v);

}    // namespace granpen

#endif
