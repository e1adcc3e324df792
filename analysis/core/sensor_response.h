// granpen analysis: the measurement chain as a linear filter on a force trace (plain arrays
// in, no files). A force sensor behind a compliant mount, and a DAQ's anti-alias low-pass,
// act on the force the grains exert on the rod. While the rod's own motion does not feed
// back into the grains (docs/gap.md, "The measurement chain as a filter": with a 100 g rod
// up to mount periods of about 2 ms, the rod's speed swinging by at most 4% of v0), the
// reading is that force through a linear filter:
//   mount: a rod of mass m on a spring k and a dashpot c in parallel (fix rod/drive mount;
//     x the spring's compression): m x'' + c x' + k x = F. fix rod/drive reads the force on
//     the actuator's side, k x + c x':
//       H(s) = (2 zeta w s + w^2) / (s^2 + 2 zeta w s + w^2),  w = sqrt(k/m) = 2 pi / T,
//       zeta = c / (2 sqrt(k m));
//     a gauge on the spring alone reads k x: H(s) = w^2 / (s^2 + 2 zeta w s + w^2);
//   low-pass: a Butterworth of order 1 (an RC stage) or 2, -3 dB at the cut-off f_c.
// The stages in series are one linear system H(s), applied to the sampled force one of three
// ways:
//   BandLimited (the default): the samples taken as a signal band-limited below the Nyquist
//     frequency 1 / (2 dt): their discrete Fourier transform times H(i 2 pi f), exact up to
//     Nyquist (a sampled sine at any f < 1 / (2 dt) comes out as H(f) times it). The record
//     is extended past its end (its last value held, then a smooth return to its first, the
//     chain left to rest for 20 of its decay times) so that the transform's periodicity
//     wraps nothing back; before the first sample the chain rests with F[0], and until the
//     force first departs from F[0] the reading is F[0] (a band-limited signal is not
//     causal: a sharp rise rings back into the samples before it, measured up to 0.5% of
//     the largest force at 0.2 ms and 0.03% at 1 ms on a LAMMPS trace; later rises keep it).
//   LinearHold, ConstantHold: exact time-domain discretisations (the matrix exponential of
//     the system augmented with the input and its slope) for a force linear between samples,
//     or held from one sample to the next: causal, exact for such inputs, but a sampled sine
//     of frequency f comes out low by about sinc^2(f dt) (linear: 3% at 1 kHz, 19% at
//     2.5 kHz, 60% at 5 kHz for 1e-4 s samples).
// A trace's samples are means over their 1e-4 s windows (fix rod/drive); the mean over a
// window is itself a linear filter, so the chain commutes with it: the chain applied to the
// window means is the window means of the chain's reading wherever the windowed force is
// carried by its samples. Measured against LAMMPS's own mount on its own grain force (tiny,
// 8 beds, 3 speeds, bench/gap_mount_filter.sh, docs/gap.md): median G_all 0.0003 (20 ms) to
// 0.021 (0.2 ms) band-limited, against 0.0005 to 0.146 with the linear hold. The limit:
// content of the force above the Nyquist frequency is in the window means only as what the
// window lets through, aliased; a chain that rings there amplifies what the samples no
// longer carry (a single bed reached 0.14 at 0.2 ms).
#ifndef GRANPEN_SENSOR_RESPONSE_H
#define GRANPEN_SENSOR_RESPONSE_H

#include <complex>
#include <vector>

namespace granpen {

// A spring-damper mount: natural period (s; <= 0: rigid, no mount) and damping ratio.
struct MountFilter {
  double period = 0.0;
  double zeta = 0.2;
  bool reads_damper = true;    // the reading k x + c x' (fix rod/drive mount), else k x
};

// The mount of fix rod/drive's `mount k c m`: period 2 pi sqrt(m / k), zeta c / (2 sqrt(k m)).
MountFilter mount_of(double k, double c, double m);

// A Butterworth low-pass: cut-off (Hz, -3 dB; <= 0: none) and order 1 or 2.
struct LowPass {
  double cutoff = 0.0;
  int order = 2;
};

// The chain: the mount, then the low-pass (either may be absent).
struct SensorChain {
  MountFilter mount;
  LowPass lowpass;
};

// How the samples are taken between sample times (see above).
enum class Discretisation { BandLimited, LinearHold, ConstantHold };

// The chain's reading at every sample of the force F sampled every dt seconds, the chain at
// rest with F[0] before the first sample (a trace starts before contact, F[0] = 0). F
// unchanged for an empty chain; empty when dt <= 0 or F is empty.
std::vector<double> sensor_response(const std::vector<double> &F, double dt, const SensorChain &chain,
                                    Discretisation how = Discretisation::BandLimited);

// The slowest decay time of the chain (s): 1 / min |Re(pole)|; 0 for an empty chain.
double sensor_decay_time(const SensorChain &chain);

// The chain's continuous-time gain H(i 2 pi f) at frequency f (Hz): 1 at f = 0; a
// Butterworth's modulus is 1 / sqrt(2) at its cut-off.
std::complex<double> sensor_gain(const SensorChain &chain, double f);

}    // namespace granpen

#endif
