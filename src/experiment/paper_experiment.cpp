// The paper's experiment (paper_experiment.hpp): every model of PaperModels identified by both
// methods on the identification record and validated by free-run simulation.

#include "bonl/experiment/paper_experiment.hpp"

#include <cctype>
#include <chrono>
#include <cmath>
#include <limits>

#include "bonl/detail/validate.hpp"
#include "bonl/estimator/identify.hpp"
#include "bonl/estimator/structure_from_data.hpp"
#include "bonl/metrics.hpp"
#include "bonl/plant/excitation.hpp"

namespace bonl::experiment {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// The free-run validation MSE of `model` on `record`, with the simulated output in `simulated`.
template <class Model>
double free_run_mse(const Model& model, const Record& record, Eigen::VectorXd& simulated) {
  if (model.try_simulate(record.input, simulated)) return metrics::mse(record.velocity, simulated);
  // An identified model that is unstable on this input: its error is unbounded.
  simulated = Eigen::VectorXd::Constant(record.velocity.size(), std::numeric_limits<double>::quiet_NaN());
  return std::numeric_limits<double>::infinity();
}

/// identify() with the method's default settings (for paper and equation_error, the paper's).
template <class Model>
Model fit(const Model& model, const Record& record, Method method, int refine_iterations, double& seconds) {
  IdentifyOptions options;
  options.method = method;
  options.refine_iterations = refine_iterations;
  const auto start = std::chrono::steady_clock::now();
  Model identified = identify(model, record.input, record.velocity, options);
  seconds = seconds_since(start);
  return identified;
}

}  // namespace

Eigen::Index paper_order(const std::string& name) {
  struct Order {
    const char* name;
    Eigen::Index value;
  };
  // ni: the velocity has no integrator. np: not the paper's (it has no plays), see the header.
  static constexpr Order kOrders[] = {{"na", 3}, {"nb", 2}, {"nk", 8}, {"r", 3}, {"r1", 3}, {"ni", 0}, {"np", 3}};
  for (const Order& order : kOrders) {
    if (name == order.name) return order.value;
  }
  detail::fail("experiment: the paper gives no order '" + name + "' (it gives na, nb, nk, r, r1, ni; and np)");
}

std::optional<PublishedScore> published_score(const std::string& name) {
  struct Published {
    const char* model;
    PublishedScore score;
  };
  static constexpr Published kTable2[] = {{PaperPseudoHammersteinWiener::kName, {0.0289, 0}},
                                          {PaperHammersteinWiener::kName, {0.0334, 14}},
                                          {PaperHammerstein::kName, {0.0415, 30}},
                                          {PaperARX::kName, {0.1136, 75}}};
  for (const Published& entry : kTable2) {
    if (name == entry.model) return entry.score;
  }
  return std::nullopt;
}

std::string paper_label(const std::string& name) {
  // A word starts at a capital followed by a small letter; an acronym such as ARX is one word.
  std::string initials;
  for (std::size_t i = 0; i + 1 < name.size(); ++i) {
    if (std::isupper(static_cast<unsigned char>(name[i])) && std::islower(static_cast<unsigned char>(name[i + 1]))) {
      initials += initials.empty() ? std::string(1, name[i]) : std::string("-") + name[i];
    }
  }
  return initials.size() > 1 ? initials : name;
}

const MethodResult& PaperExperimentResult::method(Method method) const {
  for (const MethodResult& result : methods) {
    if (result.method == method) return result;
  }
  detail::fail(std::string("experiment: the method ") + to_string(method) +
               " was not run (the paper's experiment runs output_error and paper)");
}

std::vector<plant::Command> robustness_commands(const plant::Parameters& parameters,
                                                const MeasurementOptions& options) {
  const double multisine_rms = 0.4 * std::sqrt(5.0 / 2.0);
  std::vector<plant::Command> commands;
  for (std::uint64_t seed = 100; seed < 104; ++seed) {
    commands.push_back(
        plant::excitation::smooth_random(1.0, multisine_rms, options.duration, seed, parameters.neutral_voltage));
  }
  for (int set = 1; set <= 4; ++set) {
    std::vector<double> phases;
    for (int k = 1; k <= 5; ++k) phases.push_back(0.7 * set * k);
    commands.push_back(
        plant::excitation::multisine({0.15, 0.3, 0.45, 0.7, 0.9}, 0.4, parameters.neutral_voltage, phases));
  }
  return commands;
}

MethodResult identify_paper_models(const Records& records, Method method, int refine_iterations) {
  detail::require(refine_iterations >= 0,
                  "experiment: refine_iterations must be >= 0, got " + std::to_string(refine_iterations));
  MethodResult result;
  result.method = method;
  const bonl::Records<double> identification{{records.identification.input, records.identification.velocity}};
  result.for_each([&](auto& entry) {
    const auto initial = structure_from_data(entry.model, identification);
    entry.model = fit(initial, records.identification, method, refine_iterations, entry.seconds);
    entry.mse = free_run_mse(entry.model, records.validation, entry.simulated);
    entry.online_model = fit(initial, records.identification, method, 0, entry.online_seconds);
    Eigen::VectorXd online_simulated;
    entry.online_mse = free_run_mse(entry.online_model, records.validation, online_simulated);
  });
  return result;
}

void add_robustness_scores(MethodResult& result, const Record& record) {
  Eigen::VectorXd simulated;
  result.for_each([&](auto& entry) { entry.robustness_mse.push_back(free_run_mse(entry.model, record, simulated)); });
}

PaperExperimentResult run_paper_experiment(const plant::Parameters& parameters, const PaperExperimentOptions& options) {
  PaperExperimentResult result;
  result.parameters = parameters;
  result.options = options;
  auto start = std::chrono::steady_clock::now();
  result.records = acquire(parameters, options.measurement);
  result.seconds.plant = seconds_since(start);

  start = std::chrono::steady_clock::now();
  for (Method method : kPaperMethods) {
    result.methods.push_back(identify_paper_models(result.records, method, options.refine_iterations));
  }
  result.seconds.identification = seconds_since(start);

  if (options.robustness) {
    start = std::chrono::steady_clock::now();
    const auto commands = robustness_commands(parameters, options.measurement);
    for (std::size_t i = 0; i < commands.size(); ++i) {
      const Record record = measure(parameters, commands[i], options.measurement, 5000 + i);
      for (MethodResult& method : result.methods) add_robustness_scores(method, record);
    }
    result.robustness_trajectories = commands.size();
    result.seconds.robustness = seconds_since(start);
  }
  return result;
}

}  // namespace bonl::experiment
