#pragma once
// The records of an experiment on the simulated plant, as docs/explanation/plant.md specifies them: excite,
// repeat with independent sensor noise, average the angles, low-pass them (first order, 10 Hz),
// differentiate to the angular velocity y [rad/s]; an identification record from the paper's
// multi-sine and a validation record from a different trajectory.

#include <Eigen/Core>
#include <cstdint>

#include "../plant/parameters.hpp"
#include "../plant/simulator.hpp"

namespace bonl::experiment {

/// How a record is measured on the plant.
struct MeasurementOptions {
  double duration = 50.0;     ///< [s], the paper's 50 s
  double sample_time = 0.01;  ///< [s], the paper's 100 Hz
  int repeats = 10;           ///< repeats averaged, each with independent sensor noise
  double cutoff_hz = 10.0;    ///< first-order low-pass on the averaged angle
  /// Identification command; empty: the paper's multi-sine (0.4 V per tone, Schroeder phases).
  plant::Command identification_command;
  /// Validation command; empty: a smooth random signal band-limited to 1 Hz (the highest tone of
  /// the identification input) with the multi-sine's RMS, seed 7. Chosen before any model was
  /// validated on it, and not tuned since.
  plant::Command validation_command;
  std::uint64_t seed = 1;        ///< sensor-noise seeds of the repeats derive from it
  plant::Tolerances tolerances;  ///< the plant's integration tolerances
};

/// One processed record, on the output grid.
struct Record {
  Eigen::VectorXd time;           ///< [s]
  Eigen::VectorXd input;          ///< u = V - V0 [V]
  Eigen::VectorXd angle;          ///< averaged, low-passed measured angle [rad]
  Eigen::VectorXd velocity;       ///< y: its numerical derivative [rad/s] (what models are fitted on)
  Eigen::VectorXd true_velocity;  ///< the plant's joint rate, noise-free and unfiltered [rad/s]
  plant::Trajectory trajectory;   ///< the plant's run (noise-free measured angle)
};

/// First-order low-pass z[k] = z[k-1] + alpha (x[k] - z[k-1]), alpha = 1 - exp(-2 pi fc ts), z[0] = x[0].
/// \param x the signal
/// \param cutoff_hz fc [Hz]
/// \param ts the sampling period [s]
/// \return z, as long as x
Eigen::VectorXd low_pass(const Eigen::VectorXd& x, double cutoff_hz, double ts);
/// low_pass's alpha = 1 - exp(-2 pi fc ts), for a filter run sample by sample (the tracking experiment's).
/// \param cutoff_hz fc [Hz]
/// \param ts the sampling period [s]
/// \return alpha, in (0, 1]
double low_pass_gain(double cutoff_hz, double ts);

/// Central differences, one-sided at both ends.
/// \param x the signal, at least 2 samples
/// \param ts the sampling period [s]
/// \return dx/dt, as long as x, in x's units per second
Eigen::VectorXd differentiate(const Eigen::VectorXd& x, double ts);

/// Runs the plant under `command` once (it is deterministic), then draws `repeats` independent
/// sensor-noise sequences (seeds seed, seed + 1, ...), averages the measured angles, low-passes and
/// differentiates. Equivalent to repeating the run with fresh noise each time.
/// \param parameters the plant
/// \param command V(t) [V]
/// \param options the duration, sample time, repeats, cutoff and tolerances
/// \param seed the first repeat's noise seed
/// \return the record on the output grid
Record measure(const plant::Parameters& parameters, const plant::Command& command, const MeasurementOptions& options,
               std::uint64_t seed);

/// The identification and the validation records.
struct Records {
  Record identification;  ///< the record the models are identified on
  Record validation;      ///< the record they are validated on
};

/// Both records: the identification command with seed options.seed, the validation command with
/// options.seed + 1000. Validates the parameters before anything runs.
/// \param parameters the plant
/// \param options the commands, duration, sample time, repeats, cutoff, seed and tolerances
/// \return the identification and the validation record
Records acquire(const plant::Parameters& parameters, const MeasurementOptions& options = {});

}  // namespace bonl::experiment
