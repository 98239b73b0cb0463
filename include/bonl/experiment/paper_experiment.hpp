#pragma once
// The paper's experiment (section 5) on the simulated plant: the records of records.hpp, then
// every model of PaperModels identified with the paper's orders and settings by both methods
// (bonl's default, output error, and the paper's), validated by free-run simulation, the online
// estimate (one pass, the estimator's defaults, no offline refinement) validated the same way, and
// a robustness check on eight further trajectories. One call, run_paper_experiment, gives all of it
// in one PaperExperimentResult; bonl_demo and `python -m bonl demo` only format that result.

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "../estimator/method.hpp"
#include "../models.hpp"
#include "records.hpp"

namespace bonl::experiment {

/// The models of the paper's experiment, in the order of its equations (the paper's tables list
/// them the other way round), and beside them the Prandtl-Ishlinskii Hammerstein model, which the
/// paper does not have: input hysteresis as play operators, where P-H-W puts a backlash after the
/// linear block. The proposed model, P-H-W, stays last (published_score, the tables' first column).
/// Adding a model to the experiment is one entry here.
using PaperModels = ModelList<PaperARX, PaperHammerstein, PaperHammersteinWiener, PrandtlIshlinskiiHammersteind,
                              PaperPseudoHammersteinWiener>;

/// The methods the experiment compares: bonl's default and the paper's (eqs. 21-31).
inline constexpr std::array<Method, 2> kPaperMethods = {Method::OutputError, Method::Paper};

/// The paper's order called `name` (na = 3, nb = 2, nk = 8, r = r1 = 3, ni = 0: the velocity has no
/// integrator); std::invalid_argument for an order the experiment does not give. The paper has no
/// play operators; for the Prandtl-Ishlinskii Hammerstein model the experiment takes np = 3, as many
/// plays as the input polynomial has powers (r = 3), fixed before that model ran on the plant.
/// \param name an order's name as the models' descriptions give it ("na", "r1", ...)
/// \return the order's value
Eigen::Index paper_order(const std::string& name);

/// A model of type Model at the paper's orders, each looked up by its name in the model's description.
/// What the model leaves to the data (the plays' thresholds) is its default here:
/// identify_paper_models places it from the identification record (structure_from_data).
/// \return the model, its parameters zero
template <class Model>
Model paper_model() {
  std::array<Eigen::Index, Model::kDescription.orders.size()> orders{};
  for (std::size_t i = 0; i < orders.size(); ++i) orders[i] = paper_order(Model::kDescription.orders[i].name);
  return make_model<Model>(orders);
}

/// The paper's Table 2 (the real excavator) for a model: its validation MSE as published
/// [(rad/s)^2], and how much lower the proposed model's (the last of PaperModels) is, in percent, as
/// the paper states it from its unrounded values (0 for the proposed model itself).
struct PublishedScore {
  double mse = 0.0;                ///< the published validation MSE [(rad/s)^2]
  int proposed_lower_percent = 0;  ///< how much lower the proposed model's MSE is [%]
};

/// The paper's published score of the model called `name`; empty for a model the paper does not report.
/// \param name the model's name (kName)
/// \return the score, or empty
std::optional<PublishedScore> published_score(const std::string& name);

/// How the paper writes a model's name in its tables, derived from the name itself: the initials of
/// a name of several words joined by '-' ("PseudoHammersteinWiener": "P-H-W"), a one-word name as it
/// is ("Hammerstein", "ARX").
/// \param name the model's name (kName)
/// \return the label
std::string paper_label(const std::string& name);

/// A model's parameters as the rows of the paper's Table 1: ("b0", b_0), ("a1", a_1), ..., ("c", c).
/// \param model an identified model
/// \return (label, value) pairs in the table's order
template <class Model>
std::vector<std::pair<std::string, double>> labelled_parameters(const Model& model) {
  std::vector<std::pair<std::string, double>> rows;
  for (std::size_t i = 0; i < Model::kDescription.parameters.size(); ++i) {
    const ParameterDescription& parameter = Model::kDescription.parameters[i];
    const auto values = model.parameter(i);
    if (parameter.shape == ParameterShape::Number) {
      rows.emplace_back(parameter.name, static_cast<double>(values[0]));
      continue;
    }
    for (Eigen::Index k = 0; k < values.size(); ++k) {
      rows.emplace_back(parameter.name + std::to_string(parameter.first_index + k), static_cast<double>(values[k]));
    }
  }
  return rows;
}

/// What the experiment measured of one identified model, whatever its type.
struct ModelScores {
  double mse = 0.0;                    ///< validation MSE of the velocity, free-run [(rad/s)^2]; inf: unstable on it
  Eigen::VectorXd simulated;           ///< the free-run validation velocity [rad/s]; NaN when unstable
  double online_mse = 0.0;             ///< the same for the online estimate (one pass, the estimator's defaults)
  std::vector<double> robustness_mse;  ///< validation MSE on each robustness trajectory, in order
  double seconds = 0.0;                ///< wall time of identify() [s]
  double online_seconds = 0.0;         ///< wall time of the one-pass recursive estimate [s]
};

/// One model of the experiment: the identified model, the online estimate and their scores.
template <class Model_>
struct ModelResult : ModelScores {
  using Model = Model_;                               ///< the model's type
  static constexpr const char* kName = Model::kName;  ///< the model's name
  Model model = paper_model<Model>();                 ///< identify(): the recursive estimate refined
  Model online_model = paper_model<Model>();          ///< the recursive estimator alone after one pass
};

/// One method's results: a ModelResult for every model of PaperModels, in its order.
struct MethodResult {
  using ModelResults =
      typename ApplyModels<typename MapModels<PaperModels, ModelResult>::type,
                           std::tuple>::type;  ///< a std::tuple of one ModelResult per model of PaperModels

  Method method = Method::OutputError;  ///< the estimation method
  ModelResults models;                  ///< the results, one per model of PaperModels

  /// The result of Model (a model of PaperModels).
  /// \return the result, valid while this MethodResult lives
  template <class Model>
  const ModelResult<Model>& get() const {
    return std::get<ModelResult<Model>>(models);
  }
  /// The result of Model (a model of PaperModels), to modify.
  /// \return the result, valid while this MethodResult lives
  template <class Model>
  ModelResult<Model>& get() {
    return std::get<ModelResult<Model>>(models);
  }
  /// f(model_result) for every model, in PaperModels' order.
  /// \param f called with each const ModelResult
  template <class F>
  void for_each(F&& f) const {
    std::apply([&](const auto&... result) { (f(result), ...); }, models);
  }
  /// f(model_result) for every model, in PaperModels' order, each result modifiable.
  /// \param f called with each ModelResult
  template <class F>
  void for_each(F&& f) {
    std::apply([&](auto&... result) { (f(result), ...); }, models);
  }
};

/// What the paper's experiment runs: the records' measurement, the robustness check, the refinement.
struct PaperExperimentOptions {
  MeasurementOptions measurement;  ///< the identification and validation records
  bool robustness = true;          ///< also validate on robustness_commands' trajectories
  int refine_iterations = 100;     ///< identify()'s refinement (IdentifyOptions::refine_iterations)
};

/// Wall times of the stages [s].
struct Timings {
  double plant = 0.0;           ///< simulation and processing of the two records
  double identification = 0.0;  ///< identification and validation, both methods, identify() and online
  double robustness = 0.0;      ///< the robustness check (0 when it was not run)
};

/// Everything the paper's experiment gives.
struct PaperExperimentResult {
  plant::Parameters parameters;             ///< the plant's parameters
  PaperExperimentOptions options;           ///< the options the experiment ran with
  Records records;                          ///< the identification and validation records
  std::vector<MethodResult> methods;        ///< one per entry of kPaperMethods, in its order
  std::size_t robustness_trajectories = 0;  ///< trajectories of the robustness check (0: not run)
  Timings seconds;                          ///< the stages' wall times

  /// The results of `method`; std::invalid_argument for a method the experiment did not run.
  /// \param method one of kPaperMethods
  /// \return the method's results
  const MethodResult& method(Method method) const;
};

/// Eight further validation trajectories for a robustness check, fixed in advance: smooth random
/// signals like the default validation one (seeds 100-103), and multi-sines of 0.4 V per tone on
/// other tones (0.15, 0.3, 0.45, 0.7, 0.9 Hz) with four sets of phases.
/// \param parameters the plant; its neutral voltage is the signals' offset
/// \param options the records' options; the smooth random signals last options.duration
/// \return the eight commands
std::vector<plant::Command> robustness_commands(const plant::Parameters& parameters,
                                                const MeasurementOptions& options = {});

/// Every model of PaperModels identified on records.identification by `method` (identify() with the
/// method's default settings and `refine_iterations`, and the online estimate alone) and validated
/// on records.validation. Each starts from paper_model with what it leaves to the data placed from
/// the identification record (structure_from_data: the plays' thresholds spread over the input's
/// half-range), so both methods and the online estimate use the same structure. Leaves the
/// robustness scores empty.
/// \param records the identification and validation records
/// \param method the identification method
/// \param refine_iterations identify()'s refinement iterations
/// \return every model's identified and online results and scores
MethodResult identify_paper_models(const Records& records, Method method, int refine_iterations = 100);

/// Adds to every model of `result` its validation MSE on `record` (robustness_mse).
/// \param result the results to add to
/// \param record a robustness record
void add_robustness_scores(MethodResult& result, const Record& record);

/// The paper's experiment: acquire, identify_paper_models for every method of kPaperMethods, and the
/// robustness check (measured with the records' options, seeds 5000, 5001, ...).
/// \param parameters the plant
/// \param options the records' measurement, the robustness check, the refinement
/// \return every method's results, with the stages' wall times
PaperExperimentResult run_paper_experiment(const plant::Parameters& parameters = {},
                                           const PaperExperimentOptions& options = {});

}  // namespace bonl::experiment
