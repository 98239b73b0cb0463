// The tracking experiment (tracking_experiment.hpp): PI, PI plus each identified model's
// feedforward, and the adaptive P-H-W feedforward under a plant that changes, on the stepping plant.

#include "bonl/experiment/tracking_experiment.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>
#include <utility>

#include "bonl/control/inverse_model.hpp"
#include "bonl/detail/validate.hpp"
#include "bonl/experiment/records.hpp"
#include "bonl/plant/excitation.hpp"
#include "bonl/plant/stepping_plant.hpp"

namespace bonl::experiment {

namespace {

/// Samples in `seconds` at the experiment's sample time (the options make these whole numbers).
Eigen::Index samples_in(double seconds, const TrackingOptions& options) {
  return static_cast<Eigen::Index>(std::llround(seconds / options.sample_time));
}

/// Is `value` a whole multiple of `unit`?
bool whole_multiple(double value, double unit) {
  const double ratio = value / unit;
  return std::abs(ratio - std::round(ratio)) <= 1e-9 * std::max(1.0, std::abs(ratio));
}

double rms(const Eigen::VectorXd& error, Eigen::Index from, Eigen::Index to) {
  return std::sqrt(error.segment(from, to - from).squaredNorm() / static_cast<double>(to - from));
}

/// "PseudoHammersteinWiener (adaptive)" -> "PI + P-H-W (adaptive)"; "PI" stays.
std::string label_of(const std::string& controller) {
  if (controller == "PI") return controller;
  const std::size_t space = controller.find(' ');
  const std::string suffix = space == std::string::npos ? "" : controller.substr(space);
  return "PI + " + paper_label(controller.substr(0, space)) + suffix;
}

/// The PI: u = Kc (e + (1 / tau_I) integral of e), the integral held while the command saturates.
struct PI {
  double gain;
  double integral_time;
  double sample_time;
  double integral = 0.0;

  double command(double error) const { return gain * (error + integral); }
  void integrate(double error) { integral += sample_time / integral_time * error; }
};

/// No feedforward (the PI alone).
struct NoFeedforward {
  double command(Eigen::Index, const Eigen::VectorXd&, control::InverseStatus& status) {
    status = control::InverseStatus::Exact;
    return 0.0;
  }
  void observe(double, double) {}
};

/// A model's inverse on the reference ahead: u_ff(k) from r(k + nk), ..., r(k + preview).
template <class Model>
struct FixedFeedforward {
  control::InverseModel<Model> inverse;

  double command(Eigen::Index k, const Eigen::VectorXd& reference, control::InverseStatus& status) {
    const auto step = inverse.step(reference.segment(k + inverse.nk(), inverse.window_size()));
    status = step.status;
    return step.value;
  }
  void observe(double, double) {}
};

/// The adaptive inverse: the same, and the estimator fed what the plant does.
template <class Model>
struct AdaptiveFeedforward {
  control::AdaptiveInverse<Model> adaptive;

  double command(Eigen::Index k, const Eigen::VectorXd& reference, control::InverseStatus& status) {
    const auto& inverse = adaptive.inverse();
    const auto step = adaptive.step(reference.segment(k + inverse.nk(), inverse.window_size()));
    status = step.status;
    return step.value;
  }
  void observe(double u, double y) { adaptive.update(u, y); }
};

/// One run: the plant from rest, the PI on the measured velocity, `feedforward` on the reference.
template <class Feedforward>
TrackingRun track(const plant::Parameters& parameters, const TrackingResult& setup, const Eigen::VectorXd& reference,
                  bool change, Feedforward& feedforward, std::string controller) {
  const TrackingOptions& options = setup.options;
  const Eigen::Index n = setup.time.size();
  const double ts = options.sample_time;
  plant::SimulationOptions simulation;
  simulation.sample_time = ts;
  simulation.noise_seed = options.noise_seed;
  plant::SteppingPlant stepping(parameters, simulation);
  plant::Parameters changed = parameters;
  changed.pilot_hysteresis *= options.pilot_hysteresis_factor;
  changed.bulk_modulus *= options.bulk_modulus_factor;

  TrackingRun run;
  run.label = label_of(controller);
  run.controller = std::move(controller);
  run.plant_changes = change;
  run.command.resize(n);
  run.feedforward.resize(n);
  run.joint_rate.resize(n);
  PI pi{setup.proportional_gain, setup.integral_time, ts};
  const double alpha = low_pass_gain(options.cutoff_hz, ts);  // the records' filter
  const Eigen::Index change_at = samples_in(options.change_time, options);
  // The low-passed angle at t_k, t_{k-1}, t_{k-2}, and the command applied at t_{k-1}.
  double z = stepping.measurement().measured_angle;
  double z1 = z;
  double z2 = z;
  double u_previous = 0.0;
  for (Eigen::Index k = 0; k < n; ++k) {
    if (change && k == change_at) stepping.set_parameters(changed);
    const plant::Measurement& m = stepping.measurement();
    z2 = z1;
    z1 = z;
    z = z1 + alpha * (m.measured_angle - z1);
    // The feedback: a backward difference (no delay). The estimator: the records' central
    // difference, one sample late, paired with the command of that sample.
    const double velocity = k > 0 ? (z - z1) / ts : 0.0;
    if (k >= 2) feedforward.observe(u_previous, (z - z2) / (2.0 * ts));

    control::InverseStatus status = control::InverseStatus::Exact;
    const double u_ff = feedforward.command(k, reference, status);
    if (status != control::InverseStatus::Exact) ++run.inexact;
    const double error = reference[k] - velocity;
    const double wanted = parameters.neutral_voltage + u_ff + pi.command(error);
    const double applied = std::clamp(wanted, 0.0, parameters.max_voltage);
    if (applied == wanted) pi.integrate(error);  // no wind-up while the command saturates
    run.command[k] = applied;
    run.feedforward[k] = u_ff;
    run.joint_rate[k] = m.joint_rate;
    u_previous = applied - parameters.neutral_voltage;
    stepping.step(applied);
  }
  const Eigen::VectorXd error = setup.reference.head(n) - run.joint_rate;
  const Eigen::Index period = samples_in(options.period, options);
  run.rms = rms(error, period, n);
  run.rms_before_change = rms(error, change_at - period, change_at);
  run.rms_after_change = rms(error, change_at + period, change_at + 2 * period);
  return run;
}

}  // namespace

control::AdaptiveInverseOptions TrackingOptions::adaptive_defaults() {
  control::AdaptiveInverseOptions options;
  options.estimator.method = Method::OutputError;
  options.estimator.forgetting = ForgettingSchedule::constant(0.999);
  options.estimator.p0 = 0.01;
  // The settings this experiment was designed with, on another reference: the recursion alone, in
  // the data's units (p0 is in those units). With the estimator's later defaults (normalised
  // coordinates, the window refinement on) the adaptive feedforward, measured on this reference,
  // no longer recovers within 20% after the change: a finding about those defaults in closed loop,
  // not a reason to retune the experiment on its own reference.
  options.estimator.normalise = false;
  options.estimator.window.enabled = false;
  options.rederive_every = 100;
  options.max_covariance_trace = 10.0;
  return options;
}

void TrackingOptions::validate() const {
  const auto positive = [](double value, const char* name) {
    detail::require(std::isfinite(value) && value > 0.0,
                    std::string("tracking: ") + name + " must be finite and > 0, got " + detail::format_number(value));
  };
  positive(sample_time, "sample_time");
  positive(cutoff_hz, "cutoff_hz");
  positive(reference_bandwidth_hz, "reference_bandwidth_hz");
  positive(reference_rms, "reference_rms");
  positive(period, "period");
  positive(duration, "duration");
  positive(change_time, "change_time");
  positive(pilot_hysteresis_factor, "pilot_hysteresis_factor");
  positive(bulk_modulus_factor, "bulk_modulus_factor");
  detail::require(std::isfinite(ramp) && ramp >= 0.0 && ramp < period,
                  "tracking: ramp must be in [0, period), got " + detail::format_number(ramp));
  detail::require(
      whole_multiple(period, sample_time) && whole_multiple(duration, period) && whole_multiple(change_time, period),
      "tracking: period must be a whole number of samples, and duration and change_time whole numbers "
      "of periods");
  detail::require(change_time >= period && change_time + 2.0 * period <= duration + 1e-9 * duration,
                  "tracking: change_time must leave a period before it and two after it (period before, and the "
                  "recovery window [change_time + period, change_time + 2 period]) within duration");
  detail::require(
      std::isfinite(backlash_band_per_c) && backlash_band_per_c >= 0.0,
      "tracking: backlash_band_per_c must be finite and >= 0, got " + detail::format_number(backlash_band_per_c));
  adaptive.validate();
}

const TrackingRun& TrackingResult::run(const std::string& controller, bool plant_changes) const {
  for (const TrackingRun& r : runs) {
    if (r.controller == controller && r.plant_changes == plant_changes) return r;
  }
  detail::fail("tracking: no run of '" + controller + "'" + (plant_changes ? " under the plant change" : ""));
}

Eigen::VectorXd tracking_reference(const TrackingOptions& options, Eigen::Index samples) {
  options.validate();
  const plant::Command signal = plant::excitation::smooth_random(options.reference_bandwidth_hz, options.reference_rms,
                                                                 options.period, options.reference_seed, 0.0);
  Eigen::VectorXd r(samples);
  for (Eigen::Index k = 0; k < samples; ++k) {
    const double t = static_cast<double>(k) * options.sample_time;
    // A smooth start: the signal times a smoothstep over the ramp (the plant starts at rest).
    const double s = options.ramp > 0.0 ? std::min(t / options.ramp, 1.0) : 1.0;
    r[k] = s * s * (3.0 - 2.0 * s) * signal(t);
  }
  return r;
}

TrackingResult run_tracking_experiment(const plant::Parameters& parameters, const MethodResult& identified,
                                       const TrackingOptions& options) {
  options.validate();
  parameters.validate();
  TrackingResult result;
  result.options = options;
  const Eigen::Index n = samples_in(options.duration, options);
  result.time = Eigen::VectorXd::LinSpaced(n, 0.0, static_cast<double>(n - 1) * options.sample_time);
  // The reference beyond the end, for the last samples' preview (nk plus ZPETC's, at most 2 nb).
  const Eigen::VectorXd reference = tracking_reference(options, n + 64);
  result.reference = reference.head(n);

  // Skogestad's SIMC PI from the ARX model's step response, approximated as a first-order lag with
  // dead time: gain K, dead time theta = nk Ts, time constant T = (time to 63.2%) - theta; with the
  // closed-loop time constant tau_c = theta, Kc = T / (K (tau_c + theta)), tau_I = min(T, 4 (tau_c + theta)).
  const auto& arx = identified.get<PaperARX>().model;
  const Eigen::VectorXd step = arx.simulate(Eigen::VectorXd::Ones(2000)).array() - arx.y0();
  const double gain = step[step.size() - 1];
  detail::require(std::isfinite(gain) && gain > 0.0,
                  "tracking: the ARX model's steady-state gain must be finite and > 0 for the PI design, got " +
                      detail::format_number(gain));
  Eigen::Index rise = 0;
  while (rise < step.size() && step[rise] < 0.632 * gain) ++rise;
  const double dead_time = static_cast<double>(arx.nk()) * options.sample_time;
  const double time_constant =
      std::max(static_cast<double>(rise) * options.sample_time - dead_time, options.sample_time);
  result.proportional_gain = time_constant / (gain * 2.0 * dead_time);
  result.integral_time = std::min(time_constant, 8.0 * dead_time);

  control::InverseOptions inverse;
  inverse.command_min = -parameters.neutral_voltage;  // the valve's 0 V to max_voltage, as u = V - V0
  inverse.command_max = parameters.max_voltage - parameters.neutral_voltage;
  inverse.backlash_band_per_c = options.backlash_band_per_c;

  for (const bool change : {false, true}) {
    NoFeedforward none;
    result.runs.push_back(track(parameters, result, reference, change, none, "PI"));
    identified.for_each([&](const auto& entry) {
      using Model = typename std::decay_t<decltype(entry)>::Model;
      // A model without an inverse (yet) has no feedforward. Under the change: the P-H-W's fixed
      // feedforward only, beside its adaptive one.
      if constexpr (control::has_inverse<Model>::value) {
        if (change && !std::is_same_v<Model, PaperPseudoHammersteinWiener>) return;
        FixedFeedforward<Model> fixed{control::InverseModel<Model>(entry.model, inverse)};
        result.runs.push_back(track(parameters, result, reference, change, fixed, Model::kName));
        if constexpr (control::InverseModel<Model>::kHasBacklash) {
          // Beside it, the backlash inverse's exact switch (band 0), for comparison (docs/how-to/control.md).
          if (change || options.backlash_band_per_c == 0.0) return;
          control::InverseOptions exact = inverse;
          exact.backlash_band_per_c = 0.0;
          FixedFeedforward<Model> switched{control::InverseModel<Model>(entry.model, exact)};
          result.runs.push_back(
              track(parameters, result, reference, false, switched, std::string(Model::kName) + " (exact switch)"));
        }
      }
    });
  }
  control::AdaptiveInverseOptions adaptive_options = options.adaptive;
  adaptive_options.inverse = inverse;
  using Adaptive = PaperPseudoHammersteinWiener;
  AdaptiveFeedforward<Adaptive> adaptive{
      control::AdaptiveInverse<Adaptive>(identified.get<Adaptive>().model, adaptive_options)};
  TrackingRun run = track(parameters, result, reference, true, adaptive, std::string(Adaptive::kName) + " (adaptive)");
  const control::AdaptiveInverseHealth& health = adaptive.adaptive.health();
  run.rederivations = health.rederivations;
  run.refused =
      health.refused_diverged + health.refused_covariance + health.refused_unstable + health.refused_no_inverse;
  result.runs.push_back(std::move(run));
  return result;
}

TrackingResult run_tracking_experiment(const plant::Parameters& parameters, const TrackingOptions& options) {
  options.validate();
  const Records records = acquire(parameters);
  return run_tracking_experiment(parameters, identify_paper_models(records, options.method), options);
}

}  // namespace bonl::experiment
