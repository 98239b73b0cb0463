#pragma once
// The paper's experiment (section 5) on the simulated plant, as docs/plant.md specifies it:
// excite, repeat with independent sensor noise, average the angles, low-pass them (first order,
// 10 Hz), differentiate to the angular velocity y [rad/s]; an identification record from the
// paper's multi-sine and a validation record from a different trajectory; then identify ARX,
// Hammerstein, H-W and P-H-W with the paper's orders and settings and validate them by free-run
// simulation.

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "../estimator/method.hpp"
#include "../models.hpp"
#include "simulator.hpp"

namespace bonl::plant {

struct ExperimentOptions {
  double duration = 50.0;     ///< [s], the paper's 50 s
  double sample_time = 0.01;  ///< [s], the paper's 100 Hz
  int repeats = 10;           ///< repeats averaged, each with independent sensor noise
  double cutoff_hz = 10.0;    ///< first-order low-pass on the averaged angle
  /// Identification command; empty: the paper's multi-sine (0.4 V per tone, Schroeder phases).
  Command identification_command;
  /// Validation command; empty: a smooth random signal band-limited to 1 Hz (the highest tone of
  /// the identification input) with the multi-sine's RMS, seed 7. Chosen before any model was
  /// validated on it, and not tuned since.
  Command validation_command;
  std::uint64_t seed = 1;     ///< sensor-noise seeds of the repeats derive from it
  Tolerances tolerances;      ///< the plant's integration tolerances
};

/// One processed record, on the output grid.
struct Record {
  Eigen::VectorXd time;           ///< [s]
  Eigen::VectorXd input;          ///< u = V - V0 [V]
  Eigen::VectorXd angle;          ///< averaged, low-passed measured angle [rad]
  Eigen::VectorXd velocity;       ///< y: its numerical derivative [rad/s] (what models are fitted on)
  Eigen::VectorXd true_velocity;  ///< the plant's joint rate, noise-free and unfiltered [rad/s]
  Trajectory trajectory;          ///< the plant's run (noise-free measured angle)
};

/// First-order low-pass z[k] = z[k-1] + alpha (x[k] - z[k-1]), alpha = 1 - exp(-2 pi fc ts), z[0] = x[0].
Eigen::VectorXd low_pass(const Eigen::VectorXd& x, double cutoff_hz, double ts);

/// Central differences, one-sided at both ends.
Eigen::VectorXd differentiate(const Eigen::VectorXd& x, double ts);

/// Runs the plant under `command` once (it is deterministic), then draws `repeats` independent
/// sensor-noise sequences (seeds seed, seed + 1, ...), averages the measured angles, low-passes and
/// differentiates. Equivalent to repeating the run with fresh noise each time.
Record measure(const Parameters& parameters, const Command& command, const ExperimentOptions& options,
               std::uint64_t seed);

/// The identification and the validation records.
struct ExperimentData {
  Record identification;
  Record validation;
};
ExperimentData acquire(const Parameters& parameters, const ExperimentOptions& options = {});

/// The four models identified with the paper's orders (na = 3, nb = 2, nk = 8, r = r1 = 3) and
/// settings, with their validation MSE of the velocity (free-run simulation). refine_iterations = 0
/// gives the recursive estimator's result alone: what an online estimator has after one pass.
struct IdentifiedModels {
  Method method = Method::OutputError;
  PaperARX arx{3, 2, 8};
  PaperHammerstein hammerstein{3, 2, 8, 3};
  PaperHammersteinWiener hammerstein_wiener{3, 2, 8, 3, 3};
  PaperPseudoHammersteinWiener phw{3, 2, 8, 3};
  double mse_arx = 0.0, mse_hammerstein = 0.0, mse_hammerstein_wiener = 0.0, mse_phw = 0.0;
  /// Free-run simulated validation velocities, in the order ARX, Hammerstein, H-W, P-H-W.
  Eigen::VectorXd simulated_arx, simulated_hammerstein, simulated_hammerstein_wiener, simulated_phw;
};
IdentifiedModels identify_models(const ExperimentData& data, Method method, int refine_iterations = 100);

/// Validation MSE of the four models on another record (free-run simulation; infinity for a model
/// that is unstable on it).
struct ModelErrors {
  double arx = 0.0, hammerstein = 0.0, hammerstein_wiener = 0.0, phw = 0.0;
};
ModelErrors validation_errors(const IdentifiedModels& models, const Record& record);

/// Eight further validation trajectories for a robustness check, fixed in advance: smooth random
/// signals like the default validation one (seeds 100-103), and multi-sines of 0.4 V per tone on
/// other tones (0.15, 0.3, 0.45, 0.7, 0.9 Hz) with four sets of phases.
std::vector<Command> robustness_commands(const Parameters& parameters, const ExperimentOptions& options = {});

}  // namespace bonl::plant
