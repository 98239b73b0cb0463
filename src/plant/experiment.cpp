#include "bonl/plant/experiment.hpp"

#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "bonl/detail/validate.hpp"
#include "bonl/estimator/identify.hpp"
#include "bonl/metrics.hpp"
#include "bonl/plant/excitation.hpp"

namespace bonl::plant {

Eigen::VectorXd low_pass(const Eigen::VectorXd& x, double cutoff_hz, double ts) {
  detail::require(std::isfinite(cutoff_hz) && cutoff_hz > 0.0, "low_pass: cutoff_hz must be finite and > 0");
  detail::require(std::isfinite(ts) && ts > 0.0, "low_pass: ts must be finite and > 0");
  detail::require_finite(x, "x");
  Eigen::VectorXd z(x.size());
  if (x.size() == 0) return z;
  const double alpha = 1.0 - std::exp(-2.0 * 3.14159265358979323846 * cutoff_hz * ts);
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

void validate(const ExperimentOptions& options) {
  detail::require(std::isfinite(options.duration) && options.duration > 0.0, "experiment: duration must be > 0");
  detail::require(std::isfinite(options.sample_time) && options.sample_time > 0.0,
                  "experiment: sample_time must be > 0");
  detail::require(options.repeats >= 1, "experiment: repeats must be >= 1, got " + std::to_string(options.repeats));
  detail::require(std::isfinite(options.cutoff_hz) && options.cutoff_hz > 0.0, "experiment: cutoff_hz must be > 0");
}

Command identification_command(const ExperimentOptions& options, const Parameters& parameters) {
  return options.identification_command ? options.identification_command
                                        : excitation::paper_multisine(0.4, parameters.neutral_voltage);
}

Command validation_command(const ExperimentOptions& options, const Parameters& parameters) {
  if (options.validation_command) return options.validation_command;
  const double multisine_rms = 0.4 * std::sqrt(5.0 / 2.0);  // five tones of 0.4 V
  return excitation::smooth_random(1.0, multisine_rms, options.duration, 7, parameters.neutral_voltage);
}

}  // namespace

Record measure(const Parameters& parameters, const Command& command, const ExperimentOptions& options,
               std::uint64_t seed) {
  validate(options);
  SimulationOptions simulation;
  simulation.duration = options.duration;
  simulation.sample_time = options.sample_time;
  simulation.tolerances = options.tolerances;
  simulation.sensor_noise = false;
  Record record;
  record.trajectory = simulate(parameters, command, simulation);
  const Trajectory& run = record.trajectory;
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

ExperimentData acquire(const Parameters& parameters, const ExperimentOptions& options) {
  parameters.validate();
  ExperimentData data;
  data.identification = measure(parameters, identification_command(options, parameters), options, options.seed);
  data.validation = measure(parameters, validation_command(options, parameters), options, options.seed + 1000);
  return data;
}

namespace {

template <class Model>
double free_run_mse(const Model& model, const Record& record, Eigen::VectorXd& simulated) {
  if (model.try_simulate(record.input, simulated)) return metrics::mse(record.velocity, simulated);
  // An identified model that is unstable on this input: its error is unbounded.
  simulated = Eigen::VectorXd::Constant(record.velocity.size(), std::numeric_limits<double>::quiet_NaN());
  return std::numeric_limits<double>::infinity();
}

template <class Model>
void fit(const ExperimentData& data, Method method, int refine_iterations, Model& model, double& mse,
         Eigen::VectorXd& simulated) {
  IdentifyOptions options;  // the method's default settings (for paper and equation_error, the paper's)
  options.method = method;
  options.refine_iterations = refine_iterations;
  model = identify(model, data.identification.input, data.identification.velocity, options);
  mse = free_run_mse(model, data.validation, simulated);
}

}  // namespace

IdentifiedModels identify_models(const ExperimentData& data, Method method, int refine_iterations) {
  IdentifiedModels result;
  result.method = method;
  fit(data, method, refine_iterations, result.arx, result.mse_arx, result.simulated_arx);
  fit(data, method, refine_iterations, result.hammerstein, result.mse_hammerstein, result.simulated_hammerstein);
  fit(data, method, refine_iterations, result.hammerstein_wiener, result.mse_hammerstein_wiener,
      result.simulated_hammerstein_wiener);
  fit(data, method, refine_iterations, result.phw, result.mse_phw, result.simulated_phw);
  return result;
}

ModelErrors validation_errors(const IdentifiedModels& models, const Record& record) {
  Eigen::VectorXd simulated;
  ModelErrors errors;
  errors.arx = free_run_mse(models.arx, record, simulated);
  errors.hammerstein = free_run_mse(models.hammerstein, record, simulated);
  errors.hammerstein_wiener = free_run_mse(models.hammerstein_wiener, record, simulated);
  errors.phw = free_run_mse(models.phw, record, simulated);
  return errors;
}

std::vector<Command> robustness_commands(const Parameters& parameters, const ExperimentOptions& options) {
  const double multisine_rms = 0.4 * std::sqrt(5.0 / 2.0);
  std::vector<Command> commands;
  for (std::uint64_t seed = 100; seed < 104; ++seed) {
    commands.push_back(excitation::smooth_random(1.0, multisine_rms, options.duration, seed, parameters.neutral_voltage));
  }
  for (int set = 1; set <= 4; ++set) {
    std::vector<double> phases;
    for (int k = 1; k <= 5; ++k) phases.push_back(0.7 * set * k);
    commands.push_back(excitation::multisine({0.15, 0.3, 0.45, 0.7, 0.9}, 0.4, parameters.neutral_voltage, phases));
  }
  return commands;
}

}  // namespace bonl::plant
