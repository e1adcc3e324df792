// granpen gap: the numerics of comparing two ensembles of force traces (plain arrays in,
// no files): the common depth grid (runs aligned by core/onset_alignment.h), per-run features
// (bin means of F and the fluctuation level about them), ensembles with run-to-run
// scatter, a pooled noise model, the overall gap G of shared/formats/gap-metric.md, and
// the paper's observables per regime.
#ifndef GRANPEN_GAP_DATA_H
#define GRANPEN_GAP_DATA_H

#include "gap_metric.h"
#include "onset_alignment.h"

#include <cstddef>
#include <string>
#include <vector>

namespace granpen {

// force_onset: core/onset_alignment.h.

// The common grid: bins of width w over 0 < z <= zmax, fluctuation windows of `window` cm,
// and frequency bands (Hz) of the fluctuation spectrum.
struct GapGrid {
  double w = 0.25, zmax = 4.0, window = 1.0;
  std::vector<double> bands = {50, 150, 450, 1350, 4050};    // edges: 4 bands, factor 3 wide
  std::size_t nbins() const;
  std::size_t nwindows() const;     // floor(zmax / window) (the bins they cover)
  std::size_t nbands() const { return bands.size() > 1 ? bands.size() - 1 : 0; }
  std::size_t nfeatures() const { return nbins() + nwindows() + nbands(); }
  double centre(std::size_t b) const { return (b + 0.5) * w; }
};

// Features of one run: the mean of F in each bin; per window the mean within-bin standard
// deviation of F (the fluctuation level: grain-scale force chains, sensor dynamics); per
// frequency band the RMS amplitude of F about its bin means (interpolated between bin
// centres) over 0 < z <= zmax, from a Hann-windowed periodogram (a sensor's resonance or
// filtering shows here first). t in s, sampled uniformly. ok is false (with a note) when a
// bin is empty: the run is too short.
struct RunFeatures {
  bool ok = false;
  std::string note;
  std::vector<double> x;    // nbins bin means, then nwindows fluctuation levels
};
RunFeatures run_features(const std::vector<double> &t, const std::vector<double> &z, const std::vector<double> &F,
                         const GapGrid &grid);

// An ensemble of runs at one speed: per feature the mean, the sample variance (0 for one
// run) and the runs themselves.
struct Ensemble {
  double v0 = 0.0;
  std::vector<std::vector<double>> runs;
  std::vector<double> mean, var;
  std::size_t n() const { return runs.size(); }
};
Ensemble make_ensemble(double v0, const std::vector<std::vector<double>> &runs);

// Pooled relative run-to-run variance per feature over ensembles of the same speed:
// sum over ensembles and runs of ((x - mean) / mean)^2 over the sum of (n - 1), smoothed
// over neighbouring features of the same kind; floor min_cv2. Returns also the degrees of
// freedom it rests on.
std::vector<double> pooled_cv2(const std::vector<const Ensemble *> &ensembles, const GapGrid &grid,
                               double min_cv2, int *dof = nullptr);

// The ensemble's means and squared standard errors (var / n, 0 for one run), as the metric
// kernels take them (core/gap_metric.h).
EnsembleMoments moments_of(const Ensemble &e);

// G(v0) of shared/formats/gap-metric.md over bins [b0, b1) of two ensembles' bin means.
double gap_metric(const Ensemble &real, const Ensemble &sim, std::size_t b0, std::size_t b1);

// The paper's observables of one run (cgs), on the grid's depth range.
struct RunObservables {
  double peak_F = 0, peak_z = 0;     // max F over 0 < z < 0.7 R
  double k_z = 0;                    // slope over the deep window [zmax / 2, zmax]
  double excess = 0;                 // integral of F - k_z z over the transient regime, dyne cm
  double t_star = 0;                 // crossover t~* (first t~ after which F / F_z stays in 1 +- 0.2)
  bool crossed = false;
  double fluct = 0;                  // RMS of F about the deep linear fit over its mean
  double wavelength = 0;             // dominant wavelength of those fluctuations, cm
};
RunObservables run_observables(const std::vector<double> &z, const std::vector<double> &F, double v0, double D,
                               double g, double d_g, const GapGrid &grid, double z_transient_end);

}    // namespace granpen

#endif
