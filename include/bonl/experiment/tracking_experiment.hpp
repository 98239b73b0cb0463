#pragma once
// From model to controller on the simulated plant (docs/how-to/control.md, "Tracking on the plant"): the
// dipper joint tracks a reference joint velocity under
//   (a) a PI loop alone,
//   (b) the PI loop plus the feedforward of each model of the paper's experiment that has an inverse
//       (control::has_inverse; not yet the Prandtl-Ishlinskii Hammerstein model),
//   (c) the PI loop plus the adaptive P-H-W feedforward (AdaptiveInverse), while the plant changes
//       mid-run (the pilot hysteresis doubles, the oil's bulk modulus drops by 30%), beside the fixed
//       P-H-W feedforward and the PI loop alone under the same change.
// The plant is the SteppingPlant with its sensor noise; the controllers see only the measured angle,
// low-passed as the records are and differenced into a velocity. Tracking errors are against the
// true joint rate.

#include <Eigen/Core>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "../control/adaptive_inverse.hpp"
#include "../estimator/method.hpp"
#include "../plant/parameters.hpp"
#include "paper_experiment.hpp"

namespace bonl::experiment {

/// What the tracking experiment runs (docs/how-to/control.md): the reference, the duration, the plant's
/// change and the identification method of the models that feed forward.
struct TrackingOptions {
  double sample_time = 0.01;  ///< [s], the experiment's 100 Hz
  double cutoff_hz = 10.0;    ///< the measured angle's first-order low-pass (the records')
  /// The reference joint velocity: a smooth random signal (plant::excitation::smooth_random) of this
  /// bandwidth and RMS with period `period`, repeated, and started smoothly over `ramp`. Fixed before
  /// any controller was run on it (docs/how-to/control.md).
  double reference_bandwidth_hz = 0.5;  ///< half the identification multi-sine's top tone
  double reference_rms = 0.1;           ///< [rad/s], about the validation record's velocity RMS
  double period = 20.0;                 ///< [s]
  std::uint64_t reference_seed = 2020;  ///< the reference's seed
  double ramp = 2.0;                    ///< [s]
  double duration = 80.0;               ///< [s], a whole number of periods
  /// When the plant changes (runs under change only), and how.
  double change_time = 40.0;             ///< [s], a whole number of periods
  double pilot_hysteresis_factor = 2.0;  ///< the pilot valve's hysteresis multiplied by this at change_time
  double bulk_modulus_factor = 0.7;      ///< the oil's bulk modulus multiplied by this at change_time
  std::uint64_t noise_seed = 99;         ///< the plant's sensor noise
  /// The models that feed forward: the paper experiment's, identified by this method.
  Method method = Method::Paper;
  /// P-H-W: the backlash inverse's transition band, per unit of the model's c (docs/how-to/control.md).
  double backlash_band_per_c = 1.0;
  /// The adaptive feedforward's estimator and guard (defaults: adaptive_defaults()); its `inverse`
  /// is replaced by the experiment's (the valve's command range, the band of backlash_band_per_c).
  control::AdaptiveInverseOptions adaptive = adaptive_defaults();

  /// The output-error estimator (bonl's default method), its recursion alone in the data's units
  /// (normalise and the window refinement off), with a constant forgetting of 0.999 (a memory of
  /// 10 s), P(0) = 0.01 I around the identified model, the inverse derived every second.
  /// \return the options
  static control::AdaptiveInverseOptions adaptive_defaults();
  /// Throws std::invalid_argument naming the first bad option.
  void validate() const;
};

/// One controller's run.
struct TrackingRun {
  /// "PI", a model's name (PI plus its inverse as feedforward), "<model> (adaptive)", or
  /// "<model> (exact switch)" (P-H-W with the backlash inverse's band 0).
  std::string controller;
  /// As the tables write it: "PI", "PI + P-H-W", "PI + P-H-W (adaptive)" (paper_label of the model).
  std::string label;
  bool plant_changes = false;      ///< the plant changed at change_time
  double rms = 0.0;                ///< RMS of reference - joint rate over [period, duration] [rad/s]
  double rms_before_change = 0.0;  ///< over the period before change_time
  double rms_after_change = 0.0;   ///< over the period from change_time + period on
  Eigen::VectorXd command;         ///< V(k) applied [V]
  Eigen::VectorXd feedforward;     ///< the feedforward's part of it [V] (0 for PI)
  Eigen::VectorXd joint_rate;      ///< the plant's true joint rate at t_k [rad/s]
  Eigen::Index inexact = 0;        ///< feedforward samples whose InverseStatus was not Exact
  Eigen::Index rederivations = 0;  ///< adaptive: inverses derived from the estimate
  Eigen::Index refused = 0;        ///< adaptive: estimates the guard refused
};

/// What the tracking experiment gives: the reference, each controller's command and output, and the
/// tracking errors.
struct TrackingResult {
  TrackingOptions options;         ///< the options it ran with
  Eigen::VectorXd time;            ///< t_k [s]
  Eigen::VectorXd reference;       ///< r(t_k) [rad/s]
  double proportional_gain = 0.0;  ///< the PI's Kc [V / (rad/s)]
  double integral_time = 0.0;      ///< the PI's tau_I [s]
  /// PI, each invertible model's feedforward (and the P-H-W's with the backlash inverse's exact switch, band 0);
  /// then PI, P-H-W and P-H-W adaptive under the change.
  std::vector<TrackingRun> runs;

  /// The run of `controller` with or without the plant change; std::invalid_argument if there is none.
  /// \param controller the run's controller name (TrackingRun::controller)
  /// \param plant_changes true for the run under the plant change
  /// \return the run
  const TrackingRun& run(const std::string& controller, bool plant_changes = false) const;
};

/// The reference joint velocity r(t_k), k = 0..samples-1 (TrackingOptions).
/// \param options the reference's bandwidth, RMS, period and ramp
/// \param samples the number of samples
/// \return r [rad/s], samples values
Eigen::VectorXd tracking_reference(const TrackingOptions& options, Eigen::Index samples);

/// The experiment with the models of `identified` (identify_paper_models' result) on the plant
/// `parameters`. The PI is designed from the identified ARX model by Skogestad's SIMC rule (docs/how-to/control.md).
/// \param parameters the plant
/// \param identified the identified models
/// \param options the reference, duration, plant change and feedforward settings
/// \return the reference, every controller's run and its tracking errors
TrackingResult run_tracking_experiment(const plant::Parameters& parameters, const MethodResult& identified,
                                       const TrackingOptions& options = {});

/// The same, identifying the models first (acquire and identify_paper_models with options.method).
/// \param parameters the plant
/// \param options the reference, duration, plant change, method and feedforward settings
/// \return the reference, every controller's run and its tracking errors
TrackingResult run_tracking_experiment(const plant::Parameters& parameters = {}, const TrackingOptions& options = {});

}  // namespace bonl::experiment
