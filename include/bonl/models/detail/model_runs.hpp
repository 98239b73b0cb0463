#pragma once
// What every model's simulate() and predict() share. One-step-ahead prediction runs the model's
// key terms with the equation-error method's internal-variable estimates (those that use the
// measured output) and fixed parameters, so a prediction and the estimator's regressor come from
// the same code.

#include <Eigen/Core>

#include <string>

#include "../../detail/validate.hpp"
#include "../../error.hpp"
#include "../model_steps.hpp"

namespace bonl::detail {

/// Free run from rest through model.try_simulate(); divergence becomes a NumericalError.
template <class Model, typename U>
typename Model::VectorX simulate_checked(const Model& model, const Eigen::MatrixBase<U>& u) {
  require_finite(u, "u");
  typename Model::VectorX y;
  if (!model.try_simulate(u, y)) {
    throw NumericalError(std::string("bonl: ") + Model::kName +
                         " simulation left the finite numbers (an unstable model?)");
  }
  return y;
}

template <class Model, typename U, typename Y>
typename Model::VectorX predict_one_step(const Model& model, const Eigen::MatrixBase<U>& u, const Eigen::MatrixBase<Y>& y) {
  require_same_length(u, "u", y, "y");
  require_finite(u, "u");
  require_finite(y, "y");
  typename Model::KeyTerms terms(model, KeyTermMethod::EquationError);
  typename Model::VectorX prediction(u.size());
  for (Eigen::Index k = 0; k < u.size(); ++k) prediction[k] = terms.step(model.theta(), u[k], y[k]).prediction;
  return prediction;
}

}  // namespace bonl::detail
