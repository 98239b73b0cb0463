#pragma once
// The recursive estimator run over whole records: identify()'s first step, and the best linear
// approximation's least squares (wiener_hammerstein_start.hpp).

#include <Eigen/Core>
#include <cstddef>
#include <string>

#include "../detail/validate.hpp"
#include "../error.hpp"
#include "identify_options.hpp"
#include "record_view.hpp"
#include "recursive_estimator.hpp"

namespace bonl {

/// The recursive estimator alone: `options.passes` passes over the records, each continuing from the
/// previous pass's theta and P; every record starts from rest, as a pass does (Estimator::start_pass).
/// Throws NumericalError if an update breaks down.
/// \param structure the model to identify: its orders and operating point (and knots, thresholds); its parameter values
/// are not used
/// \param records the records, checked (CheckedRecords)
/// \param options the method, passes and the estimator's options
/// \param settings the model's own estimator settings (Estimator)
/// \return structure with the last pass's estimate (projected onto the model's valid set)
template <class Model>
Model estimate_recursively(const Model& structure, const CheckedRecords<typename Model::Scalar>& records,
                           const IdentifyOptions& options, const ModelSettings<Model>& settings = {}) {
  detail::require(options.passes >= 1, "passes must be >= 1, got " + std::to_string(options.passes));
  // Without the checkpoint: a start for the refinement, which sees every record whole, from the
  // recursion as it runs (with it, the tanks' H-W start changed and refined to a worse model).
  EstimatorOptions recursion = options;
  recursion.checkpoint = false;
  Estimator<Model> estimator(structure, recursion, settings);
  for (int pass = 0; pass < options.passes; ++pass) {
    for (std::size_t r = 0; r < records.size(); ++r) {
      if (pass > 0 || r > 0) estimator.start_pass();
      const auto& u = records[r].u;
      const auto& y = records[r].y;
      for (Eigen::Index k = 0; k < u.size(); ++k) {
        estimator.update(u[k], y[k]);
        if (estimator.diverged()) {  // also where the refused sample was one of two an update caught up on
          const std::string record = records.size() > 1 ? " of record " + std::to_string(r) : "";
          throw NumericalError("bonl: the covariance lost positiveness at sample " + std::to_string(k) + record +
                               " of pass " + std::to_string(pass + 1) + " (method " + to_string(options.method) +
                               "); try a smaller p0 or better-scaled data");
        }
      }
    }
  }
  // A scale measurement's samples not yet taken (a record shorter than about two measurements).
  estimator.catch_up();
  if (estimator.diverged()) {
    throw NumericalError(std::string("bonl: the covariance lost positiveness at the end of the records (method ") +
                         to_string(options.method) + "); try a smaller p0 or better-scaled data");
  }
  return estimator.model();
}

/// The same on records checked here (std::invalid_argument naming the bad record).
/// \param structure the model to identify: its orders and operating point (and knots, thresholds); its parameter values
/// are not used
/// \param records the records, each an input u and measured output y of equal length
/// \param options the method, passes and the estimator's options
/// \param settings the model's own estimator settings (Estimator)
/// \return structure with the last pass's estimate (projected onto the model's valid set)
template <class Model>
Model estimate_recursively(const Model& structure, const Records<typename Model::Scalar>& records,
                           const IdentifyOptions& options, const ModelSettings<Model>& settings = {}) {
  return estimate_recursively(structure, CheckedRecords<typename Model::Scalar>(records, structure.num_params()),
                              options, settings);
}

/// The same on one record (u, y).
/// \param structure the model to identify: its orders and operating point (and knots, thresholds); its parameter values
/// are not used
/// \param u the input, one record
/// \param y the measured output, as long as u
/// \param options the method, passes and the estimator's options
/// \param settings the model's own estimator settings (Estimator)
/// \return structure with the last pass's estimate (projected onto the model's valid set)
template <class Model, typename U, typename Y>
Model estimate_recursively(const Model& structure, const Eigen::MatrixBase<U>& u, const Eigen::MatrixBase<Y>& y,
                           const IdentifyOptions& options, const ModelSettings<Model>& settings = {}) {
  const typename Model::VectorX input = u, output = y;
  return estimate_recursively(structure, CheckedRecords<typename Model::Scalar>(input, output, structure.num_params()),
                              options, settings);
}

}  // namespace bonl
