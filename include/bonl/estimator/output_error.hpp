#pragma once
// Refinement of an identified model by minimising its free-run simulation error on the
// identification record or records (output-error / simulation-error criterion), by Levenberg-Marquardt.
// Under white output noise the key-term regressions are biased (their regressors carry the noise);
// the simulation error is not, and it is the criterion models are judged by.
// The Jacobian comes from central differences of the simulation: models with a backlash are only
// piecewise smooth in theta, where finite differences are as good as an analytic gradient and the
// code stays the same for every model.

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "../detail/validate.hpp"
#include "record_view.hpp"

namespace bonl {

struct RefinementReport {
  double initial_cost = std::numeric_limits<double>::infinity();  ///< mean squared simulation error
  double final_cost = std::numeric_limits<double>::infinity();
  int iterations = 0;
};

namespace detail {
/// Mean squared free-run simulation error over the records (each from rest); `y` is their outputs
/// one after another (stacked_outputs). Infinity where the simulation diverges.
template <class Model>
double simulation_cost(const Model& model, const Records<typename Model::Scalar>& records,
                       const typename Model::VectorX& y, typename Model::VectorX& simulated,
                       typename Model::VectorX& buffer) {
  if (!simulate_records(model, records, simulated, buffer)) return std::numeric_limits<double>::infinity();
  const double cost = static_cast<double>((y - simulated).squaredNorm()) / static_cast<double>(y.size());
  return std::isfinite(cost) ? cost : std::numeric_limits<double>::infinity();
}
}  // namespace detail

/// Levenberg-Marquardt on the mean squared free-run simulation error over the records, each
/// simulated from rest. Only steps that lower it are taken, so the result is never worse than `start`
/// on these records. Stops after `max_iterations`, or when a step improves the cost by less than a
/// relative 1e-10.
template <class Model>
Model refine_output_error(const Model& start, const Records<typename Model::Scalar>& records,
                          int max_iterations = 100, RefinementReport* report = nullptr) {
  using Scalar = typename Model::Scalar;
  using VectorX = typename Model::VectorX;
  using MatrixX = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>;
  const Eigen::Index n = start.num_params();
  const Eigen::Index samples = detail::require_records(records, n);
  detail::require(max_iterations >= 0, "max_iterations must be >= 0, got " + std::to_string(max_iterations));
  const VectorX y = detail::stacked_outputs(records);

  Model best = start;
  Model trial = start;
  VectorX simulated, scratch;
  double cost = detail::simulation_cost(best, records, y, simulated, scratch);
  RefinementReport local;
  local.initial_cost = cost;
  if (!std::isfinite(cost)) {
    if (report) *report = local;
    return best;
  }

  VectorX plus, minus;
  MatrixX jacobian(samples, n);
  double damping = 1e-3;
  int iteration = 0;
  for (; iteration < max_iterations; ++iteration) {
    const VectorX residual = y - simulated;
    typename Model::Params theta = best.theta();
    for (Eigen::Index i = 0; i < n; ++i) {
      const Scalar step = Scalar(1e-6) * std::max(Scalar(1), std::abs(theta[i]));
      typename Model::Params shifted = theta;
      // Projected like every candidate: at a bound (c = 0) the difference becomes one-sided, with
      // the same simulations as before (a model with c < 0 simulates as c = 0).
      shifted[i] = theta[i] + step;
      start.constrain(shifted);
      trial.set_theta(shifted);
      const bool ok_plus = detail::simulate_records(trial, records, plus, scratch);
      shifted[i] = theta[i] - step;
      start.constrain(shifted);
      trial.set_theta(shifted);
      const bool ok_minus = detail::simulate_records(trial, records, minus, scratch);
      if (ok_plus && ok_minus) {
        jacobian.col(i) = (plus - minus) / (Scalar(2) * step);
      } else {
        jacobian.col(i).setZero();  // this direction leaves the stable region: do not move along it
      }
    }
    const MatrixX normal = jacobian.transpose() * jacobian;
    const VectorX gradient = jacobian.transpose() * residual;
    const VectorX scale = normal.diagonal().cwiseMax(Scalar(1e-12) * (normal.diagonal().maxCoeff() + Scalar(1e-300)));

    bool accepted = false;
    double new_cost = cost;
    while (damping < 1e12) {
      MatrixX damped = normal;
      damped.diagonal() += Scalar(damping) * scale;
      const VectorX delta = damped.ldlt().solve(gradient);
      typename Model::Params candidate = theta + delta;
      start.constrain(candidate);
      if (candidate.allFinite()) {
        trial.set_theta(candidate);
        new_cost = detail::simulation_cost(trial, records, y, plus, scratch);
        if (new_cost < cost) {
          accepted = true;
          break;
        }
      }
      damping *= 4.0;
    }
    if (!accepted) break;
    const double improvement = (cost - new_cost) / cost;
    best = trial;
    simulated.swap(plus);
    cost = new_cost;
    damping = std::max(damping / 3.0, 1e-12);
    if (improvement < 1e-10 || cost == 0.0) {
      ++iteration;
      break;
    }
  }
  local.final_cost = cost;
  local.iterations = iteration;
  if (report) *report = local;
  return best;
}

/// The same on one record (u, y).
template <class Model, typename U, typename Y>
Model refine_output_error(const Model& start, const Eigen::MatrixBase<U>& u, const Eigen::MatrixBase<Y>& y,
                          int max_iterations = 100, RefinementReport* report = nullptr) {
  detail::require_record(u, y, start.num_params());
  const typename Model::VectorX input = u, output = y;
  return refine_output_error(start, Records<typename Model::Scalar>{{input, output}}, max_iterations, report);
}

}  // namespace bonl
