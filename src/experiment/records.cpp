// The records of an experiment on the plant (records.hpp): run the plant, add independent sensor
// noise per repeat, average, low-pass, differentiate.

#include "bonl/experiment/records.hpp"

#include <cmath>
#include <random>
#include <string>

#include "bonl/detail/validate.hpp"
#include "bonl/plant/excitation.hpp"

namespace bonl::experiment {

double low_pass_gain(double cutoff_hz, double ts) {
  return 1.0 - std::exp(-2.0 * 3.14159265358979323846 * cutoff_hz * ts);
}

Eigen::VectorXd low_pass(const Eigen::VectorXd& x, double cutoff_hz, double ts) {
  detail::require(std::isfinite(cutoff_hz) && cutoff_hz > 0.0, "low_pass: cutoff_hz must be finite and > 0");
  detail::require(std::isfinite(ts) && ts > 0.0, "low_pass: ts must be finite and > 0");
  detail::require_finite(x, "x");
  Eigen::VectorXd z(x.size());
  if (x.size() == 0) return z;
  const double alpha = low_pass_gain(cutoff_hz, ts);
  z[0] = x[0];
  for (Eigen::Index k = 1; k < x.size(); ++k) z[k] = z[k - 1] + alpha * (x[k] - z[k - 1]);
  return z;
}

Eigen::VectorXd differentiate(const Eigen::VectorXd& x, double ts) {
  detail::require(std::isfinite(ts) && ts > 0.0, "differentiate: ts must be finite and > 0");
  detail::require(x.size() >= 2, "differentiate: x needs at least 2 samples");
  detail::require_finite(x, "x");
  const Eigen::Index n = x.size();
  Eigen::VectorXd d(n);
  d[0] = (x[1] - x[0]) / ts;
  d[n - 1] = (x[n - 1] - x[n - 2]) / ts;
  for (Eigen::Index k = 1; k + 1 < n; ++k) d[k] = (x[k + 1] - x[k - 1]) / (2.0 * ts);
  return d;
}

namespace {

void validate(const MeasurementOptions& options) {
  detail::require(std::isfinite(options.duration) && options.duration > 0.0, "experiment: duration must be > 0");
  detail::require(std::isfinite(options.sample_time) && options.sample_time > 0.0,
                  "experiment: sample_time must be > 0");
  detail::require(options.repeats >= 1, "experiment: repeats must be >= 1, got " + std::to_string(options.repeats));
  detail::require(std::isfinite(options.cutoff_hz) && options.cutoff_hz > 0.0, "experiment: cutoff_hz must be > 0");
}

plant::Command identification_command(const MeasurementOptions& options, const plant::Parameters& parameters) {
  return options.identification_command ? options.identification_command
                                        : plant::excitation::paper_multisine(0.4, parameters.neutral_voltage);
}

plant::Command validation_command(const MeasurementOptions& options, const plant::Parameters& parameters) {
  if (options.validation_command) return options.validation_command;
  const double multisine_rms = 0.4 * std::sqrt(5.0 / 2.0);  // five tones of 0.4 V
  return plant::excitation::smooth_random(1.0, multisine_rms, options.duration, 7, parameters.neutral_voltage);
}

}  // namespace

Record measure(const plant::Parameters& parameters, const plant::Command& command, const MeasurementOptions& options,
               std::uint64_t seed) {
  validate(options);
  plant::SimulationOptions simulation;
  simulation.duration = options.duration;
  simulation.sample_time = options.sample_time;
  simulation.tolerances = options.tolerances;
  simulation.sensor_noise = false;
  Record record;
  record.trajectory = plant::simulate(parameters, command, simulation);
  const plant::Trajectory& run = record.trajectory;
  record.time = run.time;
  record.input = run.input;
  record.true_velocity = run.joint_rate;

  Eigen::VectorXd sum = Eigen::VectorXd::Zero(run.pin_angle.size());
  std::normal_distribution<double> normal(0.0, 1.0);
  for (int repeat = 0; repeat < options.repeats; ++repeat) {
    std::mt19937_64 generator(seed + static_cast<std::uint64_t>(repeat));
    for (Eigen::Index k = 0; k < sum.size(); ++k) {
      sum[k] += run.pin_angle[k] + parameters.sensor_noise * normal(generator);
    }
  }
  record.angle = low_pass(sum / options.repeats, options.cutoff_hz, options.sample_time);
  record.velocity = differentiate(record.angle, options.sample_time);
  return record;
}

Records acquire(const plant::Parameters& parameters, const MeasurementOptions& options) {
  parameters.validate();
  Records records;
  records.identification = measure(parameters, identification_command(options, parameters), options, options.seed);
  records.validation = measure(parameters, validation_command(options, parameters), options, options.seed + 1000);
  return records;
}

}  // namespace bonl::experiment
