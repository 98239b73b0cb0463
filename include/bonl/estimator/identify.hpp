#pragma once
// Whole-record identification: passes of the recursive estimator over (u, y), or over several
// records (record_view.hpp), and, for the output-error and equation-error methods, refinement of the
// result by minimising the free-run simulation error.

#include <Eigen/Core>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>

#include "../detail/validate.hpp"
#include "../error.hpp"
#include "output_error.hpp"
#include "record_view.hpp"
#include "recursive_estimator.hpp"

namespace bonl {

struct IdentifyOptions : EstimatorOptions {
  int passes = 1;              ///< passes of the recursive estimator over the record (paper's step 5)
  int refine_iterations = 100; ///< Levenberg-Marquardt iterations of the refinement (0: none)
};

/// The recursive estimator alone: `options.passes` passes over the records, each continuing from the
/// previous pass's theta and P; every record starts from rest, as a pass does (Estimator::start_pass).
/// Throws NumericalError if an update breaks down.
template <class Model>
Model estimate_recursively(const Model& structure, const Records<typename Model::Scalar>& records,
                           const IdentifyOptions& options) {
  detail::require(options.passes >= 1, "passes must be >= 1, got " + std::to_string(options.passes));
  detail::require_records(records, structure.num_params());
  Estimator<Model> estimator(structure, options);
  for (int pass = 0; pass < options.passes; ++pass) {
    for (std::size_t r = 0; r < records.size(); ++r) {
      if (pass > 0 || r > 0) estimator.start_pass();
      const auto& u = records[r].u;
      const auto& y = records[r].y;
      for (Eigen::Index k = 0; k < u.size(); ++k) {
        if (estimator.update(u[k], y[k]) == UpdateStatus::NumericalFailure) {
          const std::string record = records.size() > 1 ? " of record " + std::to_string(r) : "";
          throw NumericalError("bonl: the covariance lost positiveness at sample " + std::to_string(k) + record +
                               " of pass " + std::to_string(pass + 1) + " (method " + to_string(options.method) +
                               "); try a smaller p0 or better-scaled data");
        }
      }
    }
  }
  return estimator.model();
}

/// The same on one record (u, y).
template <class Model, typename U, typename Y>
Model estimate_recursively(const Model& structure, const Eigen::MatrixBase<U>& u, const Eigen::MatrixBase<Y>& y,
                           const IdentifyOptions& options) {
  detail::require(options.passes >= 1, "passes must be >= 1, got " + std::to_string(options.passes));
  detail::require_record(u, y, structure.num_params());
  const typename Model::VectorX input = u, output = y;
  return estimate_recursively(structure, Records<typename Model::Scalar>{{input, output}}, options);
}

/// Identifies the parameters of `structure` (its orders; its parameter values are not used) from
/// records of input u and measured output y (one record or several, each from rest).
/// - Method::Paper: the recursive estimator of eqs. (21)-(31), `passes` passes.
/// - Method::OutputError (the default) and Method::EquationError: that recursive estimator,
///   `passes` passes; then both its estimate and the paper method's are refined by
///   Levenberg-Marquardt on the free-run simulation error over the records, and the one that
///   simulates them better is returned. ARX under Method::EquationError is least squares and
///   keeps that estimate (that is what an ARX model is).
template <class Model>
Model identify(const Model& structure, const Records<typename Model::Scalar>& records,
               const IdentifyOptions& options = {}) {
  options.validate();
  detail::require(options.passes >= 1, "passes must be >= 1, got " + std::to_string(options.passes));
  detail::require(options.refine_iterations >= 0, "refine_iterations must be >= 0");
  detail::require_records(records, structure.num_params());

  const bool least_squares_arx = options.method == Method::EquationError && !Model::kHasInternalVariables;
  if (options.method == Method::Paper || least_squares_arx || options.refine_iterations == 0) {
    return estimate_recursively(structure, records, options);
  }
  // Two starts for the refinement: the method's recursive estimate and the paper method's (with the
  // paper method's defaults where the options leave them unset). A start whose recursion broke down
  // numerically is dropped; if both did, the error is reported.
  IdentifyOptions paper_options = options;
  paper_options.method = Method::Paper;
  const IdentifyOptions* starts[] = {&options, &paper_options};
  Model best = structure;
  double best_cost = std::numeric_limits<double>::infinity();
  bool found = false;
  std::string failures;
  const typename Model::VectorX y = detail::stacked_outputs(records);
  typename Model::VectorX simulated, scratch;
  for (const IdentifyOptions* start : starts) {
    try {
      const Model refined =
          refine_output_error(estimate_recursively(structure, records, *start), records, options.refine_iterations);
      const double cost = detail::simulation_cost(refined, records, y, simulated, scratch);
      if (!found || cost < best_cost) {
        best = refined;
        best_cost = cost;
        found = true;
      }
    } catch (const NumericalError& error) {
      failures += std::string(failures.empty() ? "" : "; ") + error.what();
    }
  }
  if (!found) throw NumericalError("bonl: identification failed from both starts: " + failures);
  return best;
}

/// The same on one record (u, y).
template <class Model, typename U, typename Y>
Model identify(const Model& structure, const Eigen::MatrixBase<U>& u, const Eigen::MatrixBase<Y>& y,
               const IdentifyOptions& options = {}) {
  options.validate();
  detail::require(options.passes >= 1, "passes must be >= 1, got " + std::to_string(options.passes));
  detail::require(options.refine_iterations >= 0, "refine_iterations must be >= 0");
  detail::require_record(u, y, structure.num_params());
  const typename Model::VectorX input = u, output = y;
  return identify(structure, Records<typename Model::Scalar>{{input, output}}, options);
}

}  // namespace bonl
