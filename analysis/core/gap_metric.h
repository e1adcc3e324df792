/* -*- c++ -*- ----------------------------------------------------------
   granpen analysis: the overall gap between two ensembles of force traces,
   shared/formats/gap-metric.md version 2, on plain arrays:
   - G, the gap in 0.25 cm bin means, and G_spec, the gap in the fluctuation
     spectrum's four bands, both of the noise-subtracted form
       sqrt( max(0, sum_k [(m_R(k) - m_S(k))^2 - e_R(k) - e_S(k)]) / sum_k m_R(k)^2 )
     (m: ensemble means, e: squared standard errors s^2 / n, 0 for one run);
   - G_all = sqrt(G^2 + G_spec^2);
   - the spectrum of one run: its fluctuation about the bin means over
     0 < z <= z_max, Hann-windowed, as a one-sided periodogram, and the RMS
     amplitude per band (a_k^2 = sum over the band's bins of
     2 |X_j|^2 / (N^2 mean(window^2)), so that a sine of amplitude A well
     inside a band gives A / sqrt(2) there).
   The metric takes the fluctuation about the run's own bin means (a step
   function); the gap diagnosis's spectral features take it about the line
   through the bin centres (Detrend::BinCentreLine), which leaves out the
   sawtooth a rising F makes against its bin means (at v0 / w Hz and its
   harmonics: k_z w / sqrt(12) RMS).
------------------------------------------------------------------------- */

#ifndef GRANPEN_GAP_METRIC_H
#define GRANPEN_GAP_METRIC_H

#include <cstddef>
#include <vector>

namespace granpen {

// The metric's frequency bands, Hz: 50-150, 150-450, 450-1350, 1350-4050.
const std::vector<double> &gap_spectrum_bands();

// About what the fluctuation is taken: each sample's bin mean (the metric), or the line
// through the bin centres' means (constant beyond the outer centres).
enum class Detrend { BinMeans, BinCentreLine };

// One run's fluctuation spectrum over 0 < z <= zmax, bins (b w, (b + 1) w]: freq (Hz) and
// power per one-sided bin j = 1 .. N/2 (2 |X_j|^2 / (N^2 mean(window^2)): the bins sum to
// the mean square of the fluctuation), N the samples in range (in sample order, their
// spacing taken uniform: (t_last - t_first) / (N - 1)). Empty (n < 8) when fewer than 8
// samples lie in range or their times do not increase.
struct Periodogram {
  std::size_t n = 0;
  double dt = 0.0;
  std::vector<double> freq, power;
};
Periodogram fluctuation_periodogram(const std::vector<double> &t, const std::vector<double> &z,
                                    const std::vector<double> &F, double w, double zmax,
                                    Detrend detrend = Detrend::BinMeans);

// RMS amplitude per band [edges[k], edges[k + 1]) of a periodogram (0 where it has no bin).
std::vector<double> band_rms(const Periodogram &p, const std::vector<double> &edges);

// Both at once: the metric's band amplitudes of one run.
std::vector<double> fluctuation_bands(const std::vector<double> &t, const std::vector<double> &z,
                                      const std::vector<double> &F, double w, double zmax,
                                      const std::vector<double> &edges = gap_spectrum_bands(),
                                      Detrend detrend = Detrend::BinMeans);

// Per feature of an ensemble of runs (each a vector of the same length): the mean and the
// squared standard error s^2 / n (0 for one run).
struct EnsembleMoments {
  std::size_t runs = 0;
  std::vector<double> mean, sq_se;
};
EnsembleMoments ensemble_moments(const std::vector<std::vector<double>> &runs);

// The noise-subtracted gap of the measured ensemble R against the simulated S over features
// [k0, k1) (k1 past the end: to the end); 0 when R's means are all 0.
double debiased_gap(const EnsembleMoments &real, const EnsembleMoments &sim, std::size_t k0 = 0,
                    std::size_t k1 = (std::size_t) -1);

// G_all from its parts.
double gap_all(double G, double G_spec);

}    // namespace granpen

#endif
