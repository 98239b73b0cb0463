#pragma once
// What every model's simulate(), predict() and linear_block() share, written once (ModelRuns, a
// CRTP base). One-step-ahead prediction runs the model's key terms with the equation-error method's
// internal-variable estimates (those that use the measured output) and fixed parameters, so a
// prediction and the estimator's regressor come from the same code.

#include <Eigen/Core>

#include <cmath>
#include <string>

#include "../../detail/validate.hpp"
#include "../../error.hpp"
#include "../model_steps.hpp"

namespace bonl::detail {

/// The free run every model's try_simulate() is: y(k) = output(L(input(u(k)))) with `linear` the
/// model's linear block at rest, input and output its static maps (identity where it has none).
/// Returns false as soon as y leaves the finite numbers (an unstable or diverging model).
template <class Linear, typename U, typename VectorX, class InputMap, class OutputMap>
bool free_run(Linear linear, const Eigen::MatrixBase<U>& u, VectorX& y, InputMap&& input, OutputMap&& output) {
  y.resize(u.size());
  for (Eigen::Index k = 0; k < u.size(); ++k) {
    y[k] = output(linear.step(input(u[k])));
    if (!std::isfinite(y[k])) return false;
  }
  return true;
}

/// The identity map, for a model without an input or an output block.
struct Identity {
  template <typename Scalar>
  Scalar operator()(Scalar value) const noexcept {
    return value;
  }
};

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

/// simulate(), predict() and linear_block() for a model Derived with try_simulate(u, y), KeyTerms,
/// a(), b(), na(), nb(), nk() and the type Linear.
template <class Derived>
class ModelRuns {
 public:
  /// Free-run simulation from rest. Throws NumericalError if the output leaves the finite numbers.
  template <typename U>
  auto simulate(const Eigen::MatrixBase<U>& u) const {
    return simulate_checked(self(), u);
  }
  /// One-step-ahead prediction from the measured u and y: the internal variables are what the
  /// measured past says (the model's KeyTerms with KeyTermMethod::EquationError).
  template <typename U, typename Y>
  auto predict(const Eigen::MatrixBase<U>& u, const Eigen::MatrixBase<Y>& y) const {
    return predict_one_step(self(), u, y);
  }
  /// The linear block B / A with the model's delay.
  auto linear_block() const {
    typename Derived::Linear block(self().na(), self().nb(), self().nk());
    block.set_a(self().a());
    block.set_b(self().b());
    return block;
  }

 private:
  const Derived& self() const noexcept { return static_cast<const Derived&>(*this); }
};

}  // namespace bonl::detail
