// granpen analysis: the measurement chain as a linear filter (see sensor_response.h).
#include "sensor_response.h"

#include <Eigen/Dense>
#include <unsupported/Eigen/FFT>
#include <unsupported/Eigen/MatrixFunctions>

#include <algorithm>
#include <cmath>

namespace granpen {

namespace {

using Mat = Eigen::MatrixXd;
using Vec = Eigen::VectorXd;

// The chain as x' = A x + B u, reading C x (no direct feed-through: the mount's reading is
// its states, the low-pass's its first state). States scaled to force units: the mount's
// p = k x and q = p' / w, the low-pass's y and y' / w_c.
struct StateSpace {
  Mat A;
  Vec B, C;
  int n() const { return (int) B.size(); }
};

StateSpace chain_system(const SensorChain &c)
{
  const bool mount = c.mount.period > 0.0, lp = c.lowpass.cutoff > 0.0;
  const int nm = mount ? 2 : 0, nl = lp ? (c.lowpass.order == 1 ? 1 : 2) : 0, n = nm + nl;
  StateSpace s{Mat::Zero(n, n), Vec::Zero(n), Vec::Zero(n)};
  // the mount's reading as a row over the states (with u as input when there is no mount)
  Vec out = Vec::Zero(n);
  if (mount) {
    const double w = 2.0 * M_PI / c.mount.period, z = c.mount.zeta;
    s.A(0, 1) = w;                          // p' = w q
    s.A(1, 0) = -w, s.A(1, 1) = -2.0 * z * w, s.B(1) = w;    // q' = w (u - p) - 2 zeta w q
    out(0) = 1.0;
    if (c.mount.reads_damper) out(1) = 2.0 * z;    // k x + c x' = p + (2 zeta / w) p'
  }
  if (lp) {
    const double w = 2.0 * M_PI * c.lowpass.cutoff;
    const int y = nm;
    // the low-pass's input: the mount's reading, or u itself
    auto drive = [&](int row, double gain) {
      if (mount) s.A.row(row) += gain * out.transpose();
      else s.B(row) += gain;
    };
    if (nl == 1) {    // y' = w (in - y)
      s.A(y, y) = -w;
      drive(y, w);
    } else {          // y'' = w^2 (in - y) - sqrt(2) w y', with v = y' / w
      s.A(y, y + 1) = w;
      s.A(y + 1, y) = -w, s.A(y + 1, y + 1) = -std::sqrt(2.0) * w;
      drive(y + 1, w);
    }
    s.C(y) = 1.0;
  } else {
    s.C = out;
  }
  return s;
}

// the exact discretisation for an input linear (or constant) between samples
std::vector<double> held_response(const std::vector<double> &F, double dt, const StateSpace &s, bool linear)
{
  const int n = s.n();
  // exp of [[A, B, 0], [0, 0, 1], [0, 0, 0]] dt acting on (x, u, u'): exact for u linear over
  // the step; E(0:n, 0:n) propagates the state, E(0:n, n) the sample, E(0:n, n+1) the slope
  Mat M = Mat::Zero(n + 2, n + 2);
  M.topLeftCorner(n, n) = s.A;
  M.block(0, n, n, 1) = s.B;
  M(n, n + 1) = 1.0;
  const Mat E = (M * dt).exp();
  const Mat Phi = E.topLeftCorner(n, n);
  const Vec G0 = E.block(0, n, n, 1), G1 = E.block(0, n + 1, n, 1);
  // at rest with F[0]: A x + B F[0] = 0
  Vec x = s.A.colPivHouseholderQr().solve(-s.B * F[0]);
  std::vector<double> y(F.size());
  for (std::size_t k = 0; k < F.size(); ++k) {
    y[k] = s.C.dot(x);
    if (k + 1 == F.size()) break;
    const double slope = linear ? (F[k + 1] - F[k]) / dt : 0.0;
    x = Phi * x + G0 * F[k] + G1 * slope;
  }
  return y;
}

std::complex<double> gain_of(const StateSpace &s, double f)
{
  const std::complex<double> iw(0.0, 2.0 * M_PI * f);
  const Eigen::MatrixXcd K = iw * Eigen::MatrixXcd::Identity(s.n(), s.n()) - s.A.cast<std::complex<double>>();
  const Eigen::VectorXcd x = K.colPivHouseholderQr().solve(s.B.cast<std::complex<double>>());
  return s.C.cast<std::complex<double>>().dot(x);
}

// the samples as a band-limited signal: DFT, times H, inverse; the record extended so that
// the transform's period wraps nothing back (see sensor_response.h)
std::vector<double> band_limited_response(const std::vector<double> &F, double dt, const StateSpace &s, double tau)
{
  const std::size_t n = F.size(), m = (std::size_t) std::ceil(10.0 * tau / dt) + 8;
  std::size_t N = 64;
  while (N < n + 4 * m) N *= 2;
  std::vector<double> x(N, F[0]);
  std::copy(F.begin(), F.end(), x.begin());
  // hold the last value m samples, return to the first over m (a raised cosine), rest after
  for (std::size_t i = 0; i < 2 * m && n + i < N; ++i)
    x[n + i] = i < m ? F.back() : F[0] + (F.back() - F[0]) * 0.5 * (1.0 + std::cos(M_PI * (double) (i - m) / (double) m));
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> X;
  fft.fwd(X, x);
  for (std::size_t j = 0; j < X.size(); ++j) {
    const double f = (j <= N / 2 ? (double) j : (double) j - (double) N) / ((double) N * dt);
    const std::complex<double> h = gain_of(s, f);
    X[j] *= j == N / 2 ? std::complex<double>(h.real(), 0.0) : h;    // Nyquist: a real bin stays real
  }
  std::vector<double> y;
  fft.inv(y, X);
  y.resize(n);
  // the chain is causal where the band-limited signal is not: before the force first
  // departs from F[0] the reading is F[0] (a sharp rise rings back into them, measured up
  // to 0.5% of the largest force at 0.2 ms on a LAMMPS trace)
  for (std::size_t k = 0; k < n && F[k] == F[0]; ++k) y[k] = F[0];
  return y;
}

}    // namespace

double sensor_decay_time(const SensorChain &chain)
{
  double tau = 0.0;
  if (chain.mount.period > 0.0) {
    // poles -w (zeta -+ sqrt(zeta^2 - 1)): the slower one's rate w zeta when underdamped
    const double w = 2.0 * M_PI / chain.mount.period, z = std::max(1e-6, chain.mount.zeta);
    tau = 1.0 / (w * (z > 1.0 ? z - std::sqrt(z * z - 1.0) : z));
  }
  if (chain.lowpass.cutoff > 0.0)
    tau = std::max(tau, (chain.lowpass.order == 1 ? 1.0 : std::sqrt(2.0)) / (2.0 * M_PI * chain.lowpass.cutoff));
  return tau;
}

MountFilter mount_of(double k, double c, double m)
{
  MountFilter f;
  f.period = 2.0 * M_PI * std::sqrt(m / k);
  f.zeta = c / (2.0 * std::sqrt(k * m));
  return f;
}

std::vector<double> sensor_response(const std::vector<double> &F, double dt, const SensorChain &chain,
                                    Discretisation how)
{
  if (F.empty() || !(dt > 0.0)) return {};
  const StateSpace s = chain_system(chain);
  if (s.n() == 0) return F;
  if (how == Discretisation::BandLimited) return band_limited_response(F, dt, s, sensor_decay_time(chain));
  return held_response(F, dt, s, how == Discretisation::LinearHold);
}

std::complex<double> sensor_gain(const SensorChain &chain, double f)
{
  const StateSpace s = chain_system(chain);
  return s.n() == 0 ? 1.0 : gain_of(s, f);
}

}    // namespace granpen
