#pragma once
// Discrete-time excitation signals for identification experiments, reproducible from a seed.

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "detail/validate.hpp"

namespace bonl::signals {

/// Levels drawn uniformly from [-amplitude, amplitude], each held for `hold` samples.
/// \param n the number of samples, >= 0
/// \param hold samples per level, >= 1
/// \param amplitude the levels' bound, >= 0
/// \param seed the generator's seed (std::mt19937_64): the same seed, the same signal
/// \return n samples
inline Eigen::VectorXd random_levels(Eigen::Index n, Eigen::Index hold, double amplitude, std::uint64_t seed) {
  detail::require(n >= 0, "n must be >= 0");
  detail::require(hold >= 1, "hold must be >= 1");
  detail::require(std::isfinite(amplitude) && amplitude >= 0.0, "amplitude must be finite and >= 0");
  // The distribution draws from a range of width 2 amplitude, which must itself be finite.
  detail::require(amplitude <= 0.5 * std::numeric_limits<double>::max(),
                  "amplitude must be <= 8.9e307 (half the largest double)");
  std::mt19937_64 generator(seed);
  std::uniform_real_distribution<double> level(-amplitude, amplitude);
  Eigen::VectorXd u(n);
  double value = 0.0;
  for (Eigen::Index k = 0; k < n; ++k) {
    if (k % hold == 0) value = level(generator);
    u[k] = value;
  }
  return u;
}

/// Schroeder phases phi_k = -pi k (k + 1) / n, k = 1..n: a low crest factor for a flat spectrum.
/// \param tones n, the number of tones
/// \return n phases, in radians
inline Eigen::VectorXd schroeder_phases(Eigen::Index tones) {
  detail::require(tones >= 1, "tones must be >= 1");
  Eigen::VectorXd phases(tones);
  const double pi = 3.14159265358979323846;
  for (Eigen::Index k = 1; k <= tones; ++k) {
    phases[k - 1] = -pi * static_cast<double>(k * (k + 1)) / static_cast<double>(tones);
  }
  return phases;
}

/// u(k) = amplitude * sum_i sin(2 pi f_i k ts + phase_i).
/// \param n the number of samples, >= 0
/// \param ts the sampling period, s
/// \param frequencies_hz the tones' frequencies f_i, Hz
/// \param amplitude each tone's amplitude
/// \param phases the tones' phases, radians, one per tone
/// \return n samples
inline Eigen::VectorXd multisine(Eigen::Index n, double ts, const Eigen::VectorXd& frequencies_hz, double amplitude,
                                 const Eigen::VectorXd& phases) {
  detail::require(n >= 0, "n must be >= 0");
  detail::require(std::isfinite(ts) && ts > 0.0, "ts (sample time) must be finite and > 0");
  detail::require_same_length(frequencies_hz, "frequencies_hz", phases, "phases");
  detail::require_finite(frequencies_hz, "frequencies_hz");
  detail::require_finite(phases, "phases");
  detail::require(std::isfinite(amplitude), "amplitude must be finite");
  const double two_pi = 6.28318530717958647692;
  Eigen::VectorXd u = Eigen::VectorXd::Zero(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const double t = static_cast<double>(k) * ts;
    for (Eigen::Index i = 0; i < frequencies_hz.size(); ++i)
      u[k] += std::sin(two_pi * frequencies_hz[i] * t + phases[i]);
  }
  u *= amplitude;
  detail::require(u.allFinite(),
                  "the multi-sine is not finite: amplitude, frequencies_hz or n ts too large for double");
  return u;
}

/// The tones of the paper's identification experiment: 0.1, 0.2, 0.4, 0.5 and 1 Hz.
/// \return five frequencies, Hz
inline Eigen::VectorXd paper_tones() { return (Eigen::VectorXd(5) << 0.1, 0.2, 0.4, 0.5, 1.0).finished(); }

/// The paper's multi-sine: its five tones with Schroeder phases, `amplitude` per tone.
/// \param n the number of samples, >= 0
/// \param ts the sampling period, s
/// \param amplitude each tone's amplitude
/// \return n samples
inline Eigen::VectorXd paper_multisine(Eigen::Index n = 5000, double ts = 0.01, double amplitude = 0.4) {
  return multisine(n, ts, paper_tones(), amplitude, schroeder_phases(5));
}

/// Gaussian white noise with standard deviation sigma.
/// \param n the number of samples, >= 0
/// \param sigma the standard deviation, >= 0
/// \param seed the generator's seed (std::mt19937_64): the same seed, the same signal
/// \return n samples
inline Eigen::VectorXd white_noise(Eigen::Index n, double sigma, std::uint64_t seed) {
  detail::require(n >= 0, "n must be >= 0");
  detail::require(std::isfinite(sigma) && sigma >= 0.0, "sigma must be finite and >= 0");
  std::mt19937_64 generator(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::VectorXd e(n);
  for (Eigen::Index k = 0; k < n; ++k) e[k] = sigma * normal(generator);
  detail::require(e.allFinite(), "sigma is too large: sigma times a standard normal sample overflows");
  return e;
}

}  // namespace bonl::signals
