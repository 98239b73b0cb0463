#pragma once
// Command signals V(t) for the plant, on the 0-5 V scale around the neutral voltage.

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "simulator.hpp"

namespace bonl::plant::excitation {

/// `before` until t_step, then `level` [V] (at t_step itself: `level`).
/// \param level the command after t_step [V]
/// \param t_step the time of the step [s]
/// \param before the command before t_step [V]
/// \return the command V(t) [V], a function of the time t [s]
Command step(double level, double t_step = 0.0, double before = 2.5);

/// offset + amplitude * sum_i sin(2 pi f_i t + phase_i); phases default to Schroeder's
/// (phi_k = -pi k (k + 1) / n). `amplitude` is per tone [V].
/// \param frequencies_hz the tones f_i [Hz]
/// \param amplitude each tone's amplitude [V]
/// \param offset the level the signal varies around [V] (2.5: the valve's neutral)
/// \param phases phase_i [rad], one per tone; empty: Schroeder's
/// \return the command V(t) [V], a function of the time t [s]
Command multisine(const std::vector<double>& frequencies_hz, double amplitude, double offset = 2.5,
                  std::vector<double> phases = {});

/// The paper's identification input: tones 0.1, 0.2, 0.4, 0.5, 1 Hz, Schroeder phases, 0.4 V each.
/// \param amplitude each tone's amplitude [V]
/// \param offset the level the signal varies around [V] (2.5: the valve's neutral)
/// \return the command V(t) [V], a function of the time t [s]
Command paper_multisine(double amplitude = 0.4, double offset = 2.5);

/// Smooth random signal band-limited to `bandwidth_hz`: equal sines at k / duration Hz for
/// k = 1..floor(bandwidth_hz duration) with random phases, scaled so that its RMS over [0, duration]
/// (one period) is exactly `rms` [V], around `offset`. Throws when bandwidth_hz duration < 1 or
/// > 10^6.
/// Reproducible from the seed with the same standard library (std::uniform_real_distribution is
/// implementation-defined). One call costs floor(bandwidth_hz duration) sines.
/// \param bandwidth_hz the highest tone [Hz]
/// \param rms the RMS over one period [V]
/// \param duration the period [s]
/// \param seed the phases' seed
/// \param offset the level the signal varies around [V] (2.5: the valve's neutral)
/// \return the command V(t) [V], a function of the time t [s]
Command smooth_random(double bandwidth_hz, double rms, double duration, std::uint64_t seed, double offset = 2.5);

/// Linear chirp from f0 to f1 over [0, duration], then continuing at f1 with a continuous phase
/// (before t = 0 at f0); amplitude [V].
/// \param f0_hz the start frequency [Hz]
/// \param f1_hz the end frequency [Hz]
/// \param duration the sweep's length [s]
/// \param amplitude the amplitude [V]
/// \param offset the level the signal varies around [V] (2.5: the valve's neutral)
/// \return the command V(t) [V], a function of the time t [s]
Command chirp(double f0_hz, double f1_hz, double duration, double amplitude, double offset = 2.5);

/// A sampled sequence held between samples (zero-order hold): values[k] on [t0 + k ts, t0 + (k+1) ts);
/// before t0 the first value, after the end the last. A time within a few ulps below a sample edge
/// counts as on it (so k * ts computed in floating point lands on sample k); a NaN time gives NaN.
/// \param values the samples [V]
/// \param ts the sampling period [s]
/// \param t0 the first sample's time [s]
/// \return the command V(t) [V], a function of the time t [s]
Command sampled(const Eigen::VectorXd& values, double ts, double t0 = 0.0);

}  // namespace bonl::plant::excitation
