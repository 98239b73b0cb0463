#pragma once
// Whole-record identification: passes of the recursive estimator over (u, y) and, for the
// output-error and equation-error methods, refinement of the result by minimising the free-run
// simulation error.

#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <string>

#include "../detail/validate.hpp"
#include "../error.hpp"
#include "output_error.hpp"
#include "recursive_estimator.hpp"

namespace bonl {

struct IdentifyOptions : EstimatorOptions {
  int passes = 1;              ///< passes of the recursive estimator over the record (paper's step 5)
  int refine_iterations = 100; ///< Levenberg-Marquardt iterations of the refinement (0: none)
};

/// The recursive estimator alone: `options.passes` passes over the record, each continuing from the
/// previous pass's theta and P. Throws NumericalError if an update breaks down.
template <class Model, typename U, typename Y>
Model estimate_recursively(const Model& structure, const Eigen::MatrixBase<U>& u, const Eigen::MatrixBase<Y>& y,
                           const IdentifyOptions& options) {
  detail::require(options.passes >= 1, "passes must be >= 1, got " + std::to_string(options.passes));
  detail::require_record(u, y, structure.num_params());
  Estimator<Model> estimator(structure, options);
  for (int pass = 0; pass < options.passes; ++pass) {
    if (pass > 0) estimator.start_pass();
    for (Eigen::Index k = 0; k < u.size(); ++k) {
      if (estimator.update(u[k], y[k]) == UpdateStatus::NumericalFailure) {
        throw NumericalError("bonl: the covariance lost positiveness at sample " + std::to_string(k) + " of pass " +
                             std::to_string(pass + 1) + " (method " + to_string(options.method) +
                             "); try a smaller p0 or better-scaled data");
      }
    }
  }
  return estimator.model();
}

/// Identifies the parameters of `structure` (its orders; its parameter values are not used) from
/// input u and measured output y.
/// - Method::Paper: the recursive estimator of eqs. (21)-(31), `passes` passes.
/// - Method::OutputError (the default) and Method::EquationError: that recursive estimator,
///   `passes` passes; then both its estimate and the paper method's are refined by
///   Levenberg-Marquardt on the free-run simulation error over this record, and the one that
///   simulates the record better is returned. ARX under Method::EquationError is least squares and
///   keeps that estimate (that is what an ARX model is).
template <class Model, typename U, typename Y>
Model identify(const Model& structure, const Eigen::MatrixBase<U>& u, const Eigen::MatrixBase<Y>& y,
               const IdentifyOptions& options = {}) {
  options.validate();
  detail::require(options.passes >= 1, "passes must be >= 1, got " + std::to_string(options.passes));
  detail::require(options.refine_iterations >= 0, "refine_iterations must be >= 0");
  detail::require_record(u, y, structure.num_params());

  const bool least_squares_arx = options.method == Method::EquationError && !Model::kHasInternalVariables;
  if (options.method == Method::Paper || least_squares_arx || options.refine_iterations == 0) {
    return estimate_recursively(structure, u, y, options);
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
  typename Model::VectorX buffer;
  for (const IdentifyOptions* start : starts) {
    try {
      const Model refined =
          refine_output_error(estimate_recursively(structure, u, y, *start), u, y, options.refine_iterations);
      const double cost = detail::simulation_cost(refined, u, y, buffer);
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

}  // namespace bonl
