#pragma once
// Whole-record identification: passes of the recursive estimator over (u, y), or over several
// records (record_view.hpp), and, for the output-error and equation-error methods, refinement of the
// result by minimising the free-run simulation error.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "../detail/validate.hpp"
#include "../error.hpp"
#include "../models/rescale.hpp"
#include "estimate_recursively.hpp"
#include "identify_options.hpp"
#include "normalisation.hpp"
#include "output_error.hpp"
#include "record_view.hpp"
#include "recursive_estimator.hpp"

namespace bonl {

namespace detail {

/// The records less (u0, y0) and divided by `scale`, owned, with views for identification. New
/// numbers, so checked (a deviation of finite values can overflow).
template <typename Scalar>
struct ScaledRecords {
  using VectorX = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;
  ScaledRecords(const CheckedRecords<Scalar>& records, DataScale scale, double u0, double y0, Eigen::Index num_params)
      : views(scaled_views(records, scale, u0, y0), num_params) {}
  std::vector<VectorX> inputs, outputs;
  CheckedRecords<Scalar> views;

 private:
  Records<Scalar> scaled_views(const CheckedRecords<Scalar>& records, DataScale scale, double u0, double y0) {
    inputs.reserve(records.size());
    outputs.reserve(records.size());
    for (const auto& record : records) {
      inputs.push_back((record.u.array() - static_cast<Scalar>(u0)).matrix() / static_cast<Scalar>(scale.u));
      outputs.push_back((record.y.array() - static_cast<Scalar>(y0)).matrix() / static_cast<Scalar>(scale.y));
    }
    Records<Scalar> out;
    for (std::size_t i = 0; i < records.size(); ++i) out.emplace_back(inputs[i], outputs[i]);
    return out;
  }
};

/// Does Model give identify() starts of its own (the customisation point below)?
template <class Model, class = void>
struct HasIdentifyStarts : std::false_type {};
template <class Model>
struct HasIdentifyStarts<
    Model, std::void_t<decltype(Model::identify_starts(std::declval<const Model&>(),
                                                       std::declval<const CheckedRecords<typename Model::Scalar>&>()))>>
    : std::true_type {};

/// The options and settings identify() takes, checked (std::invalid_argument naming the bad one).
template <class Settings>
void require_identify_options(const IdentifyOptions& options, const Settings& settings) {
  options.validate();
  settings.validate();
  require(options.passes >= 1, "passes must be >= 1, got " + std::to_string(options.passes));
  require(options.refine_iterations >= 0, "refine_iterations must be >= 0");
  require_initial_state(options.initial_state, options.initialisation_window);
}

/// identify() without the input range, on options and settings identify() has checked.
template <class Model>
Model identify_records(const Model& structure, const CheckedRecords<typename Model::Scalar>& records,
                       const IdentifyOptions& options, const ModelSettings<Model>& settings) {
  const bool least_squares_arx = options.method == Method::EquationError && !Model::kHasInternalVariables;
  if (options.method == Method::Paper || least_squares_arx || options.refine_iterations == 0) {
    return estimate_recursively(structure, records, options, settings);
  }
  // The blocks see the deviations from the operating point, in identify's units: identify those
  // (one copy of the records), then put the operating point and the data's units back.
  const double u0 = structure.u0(), y0 = structure.y0();
  const DataScale scale = options.normalise ? data_scale(records, u0, y0, structure.ni()) : DataScale{};
  if (u0 != 0.0 || y0 != 0.0 || scale.u != 1.0 || scale.y != 1.0) {
    const ScaledRecords<typename Model::Scalar> transformed(records, scale, u0, y0, structure.num_params());
    IdentifyOptions inner = options;
    inner.normalise = false;
    Model at_zero = rescaled(structure, 1.0 / scale.u, 1.0 / scale.y);
    at_zero.set_operating_point(0.0, 0.0);
    const auto inner_settings = settings.rescaled(1.0 / scale.u, 1.0 / scale.y);  // exact: powers of two
    Model model = rescaled(identify_records(at_zero, transformed.views, inner, inner_settings), scale.u, scale.y);
    model.set_operating_point(u0, y0);
    return model;
  }
  // Two starts for the refinement: the method's recursive estimate and the other refined method's
  // (output error and equation error, each with its method's defaults where the options leave them
  // unset). Both are continuous functions of the data, so the result does not jump when the data
  // change in their last digit. The paper method's estimate is not a start: its internal variables
  // come from its own free run and switch with the backlash, and on the cascaded tanks a change of
  // 1e-9 V in the output moved it by O(1) and the refined P-H-W between minima (docs/explanation/algorithm.md).
  // A start whose recursion broke down numerically is dropped; if both did, the error is reported.
  // The starts' recursions run without the window refinement: the refinement below re-simulates
  // the whole record, which the window does for the recent samples only, at a cost.
  IdentifyOptions start_options = options;
  start_options.window.enabled = false;
  IdentifyOptions other_options = start_options;
  other_options.method = options.method == Method::OutputError ? Method::EquationError : Method::OutputError;
  const IdentifyOptions* start_settings[] = {&start_options, &other_options};
  std::vector<Model> starts;
  std::string failures;
  for (const IdentifyOptions* start : start_settings) {
    try {
      starts.push_back(estimate_recursively(structure, records, *start, settings));
    } catch (const NumericalError& error) {
      failures += std::string(failures.empty() ? "" : "; ") + error.what();
    }
  }
  // A model whose recursive estimates alone make poor starts adds its own after them, by a member
  //   static std::vector<Model> identify_starts(const Model& structure, const CheckedRecords<Scalar>& records)
  // that gets the records as here: deviations from the operating point, in identify's units.
  if constexpr (HasIdentifyStarts<Model>::value) {
    for (Model& start : Model::identify_starts(structure, records)) starts.push_back(std::move(start));
  }
  if (starts.empty()) throw NumericalError("bonl: identification failed from every start: " + failures);
  return refine_output_error(starts, records, options.refine_iterations, nullptr, options.initialisation_window, {},
                             options.initial_state);
}
}  // namespace detail

/// Identifies the parameters of `structure` (its orders and its operating point; its parameter values
/// are not used) from records of input u and measured output y (one record or several, each from rest
/// at the operating point). The result has the structure's operating point (or the records' own,
/// IdentifyOptions::operating_point), and the range of the
/// records' inputs as its input range (extrapolated_samples()).
/// - Method::Paper: the recursive estimator of eqs. (21)-(31), `passes` passes.
/// - Method::OutputError (the default) and Method::EquationError: that recursive estimator,
///   `passes` passes; then both its estimate and the other method's are refined by
///   Levenberg-Marquardt on the free-run simulation error over the records, and the one that
///   simulates them better is returned. ARX under Method::EquationError is least squares and
///   keeps that estimate (that is what an ARX model is).
/// Where it refines, the free runs start from rest, or after each record's first
/// IdentifyOptions::initialisation_window samples, measured (as the model will be used after a
/// protocol's state-initialisation window), or with the state at the window's end estimated
/// (IdentifyOptions::initial_state).
/// Where it refines, all of it runs on the data in identify's own units (IdentifyOptions::normalise),
/// and the model comes back in the data's units. Where it does not, the result is what
/// Estimator::update gives over the records, in the data's units. `settings`: the model's own, as
/// Estimator takes them (P-H-W: c0 and backlash_hold), in the data's units.
/// \param structure the model to identify: its orders and operating point (and knots, thresholds); its parameter values
/// are not used
/// \param records the records, checked (CheckedRecords)
/// \param options the method, passes, refinement, normalisation and operating point
/// \param settings the model's own estimator settings, in the data's units
/// \return the identified model, in the data's units, with its operating point and input range
template <class Model>
Model identify(const Model& structure, const CheckedRecords<typename Model::Scalar>& records,
               const IdentifyOptions& options = {}, const ModelSettings<Model>& settings = {}) {
  detail::require(records.samples() > structure.num_params(),
                  "the records must be longer together than the number of parameters (" +
                      std::to_string(structure.num_params()) + "), got " + std::to_string(records.samples()) +
                      " samples");
  detail::require_identify_options(options, settings);
  detail::require_initialisation_window(records.records(), options.initialisation_window);
  const Eigen::Index scored =
      records.samples() - static_cast<Eigen::Index>(records.size()) * options.initialisation_window;
  detail::require(scored > structure.num_params(),
                  "the records after their initialisation_window must be longer together than the number of "
                  "parameters (" +
                      std::to_string(structure.num_params()) + "), got " + std::to_string(scored) + " samples");
  Model at = structure;
  // A structure that was identified before carries its input range, beyond which its input block
  // continues linearly; the identification fits the block itself, on these records.
  at.set_input_range(-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity());
  if (options.operating_point == OperatingPointSource::Mean) {
    double u_sum = 0.0, y_sum = 0.0, samples = 0.0;
    for (const auto& record : records) {
      u_sum += static_cast<double>(record.u.sum());
      y_sum += static_cast<double>(record.y.sum());
      samples += static_cast<double>(record.u.size());
    }
    at.set_operating_point(u_sum / samples, y_sum / samples);
  } else if (options.operating_point == OperatingPointSource::Initial) {
    at.set_operating_point(static_cast<double>(records[0].u[0]), static_cast<double>(records[0].y[0]));
  }
  Model model = detail::identify_records(at, records, options, settings);
  double min = std::numeric_limits<double>::infinity(), max = -min;
  for (const auto& record : records) {
    min = std::min(min, static_cast<double>(record.u.minCoeff()));
    max = std::max(max, static_cast<double>(record.u.maxCoeff()));
  }
  model.set_input_range(min, max);
  return model;
}

/// The same on records checked here (std::invalid_argument naming the bad record).
/// \param structure the model to identify: its orders and operating point (and knots, thresholds); its parameter values
/// are not used
/// \param records the records, each an input u and measured output y of equal length
/// \param options the method, passes, refinement, normalisation and operating point
/// \param settings the model's own estimator settings, in the data's units
/// \return the identified model, in the data's units, with its operating point and input range
template <class Model>
Model identify(const Model& structure, const Records<typename Model::Scalar>& records,
               const IdentifyOptions& options = {}, const ModelSettings<Model>& settings = {}) {
  return identify(structure, CheckedRecords<typename Model::Scalar>(records, structure.num_params()), options,
                  settings);
}

/// The same on one record (u, y).
/// \param structure the model to identify: its orders and operating point (and knots, thresholds); its parameter values
/// are not used
/// \param u the input, one record
/// \param y the measured output, as long as u
/// \param options the method, passes, refinement, normalisation and operating point
/// \param settings the model's own estimator settings, in the data's units
/// \return the identified model, in the data's units, with its operating point and input range
template <class Model, typename U, typename Y>
Model identify(const Model& structure, const Eigen::MatrixBase<U>& u, const Eigen::MatrixBase<Y>& y,
               const IdentifyOptions& options = {}, const ModelSettings<Model>& settings = {}) {
  const typename Model::VectorX input = u, output = y;
  return identify(structure, CheckedRecords<typename Model::Scalar>(input, output, structure.num_params()), options,
                  settings);
}

}  // namespace bonl
