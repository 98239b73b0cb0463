#pragma once
// What every model's simulate() and predict() share. One-step-ahead prediction runs the model's
// key-term tracker with the equation-error method's internal-variable estimates (those that use the
// measured output) and fixed parameters, so a prediction and the estimator's regressor come from
// the same code.

#include <Eigen/Core>

#include <string>

#include "../error.hpp"
#include "../estimator/method.hpp"
#include "validate.hpp"

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
  using Scalar = typename Model::Scalar;
  typename Model::KeyTerms terms(model);
  const typename Model::Params& theta = model.theta();
  typename Model::Params phi = Model::Params::Zero(model.num_params());
  typename Model::VectorX prediction(u.size());
  for (Eigen::Index k = 0; k < u.size(); ++k) {
    const Scalar x = terms.begin(theta, u[k], Method::EquationError, phi);
    prediction[k] = terms.predicted_output(theta, x);
    terms.end(theta, phi, u[k], y[k], Method::EquationError);
  }
  return prediction;
}

}  // namespace bonl::detail
