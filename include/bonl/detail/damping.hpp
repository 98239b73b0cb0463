#pragma once
// Levenberg-Marquardt's damping, shared by the offline refinement (estimator/output_error.hpp) and
// the online estimator's window refinement (estimator/window_refinement.hpp): the system solved is
// (J'J + damping D) step = J'e. Each scales D its own way (damping_scale, levenberg_scale).

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

namespace bonl::detail {

/// The damping after a kept step whose gain ratio (actual over predicted decrease of the sum of
/// squares) is rho, as Nielsen (1999) proposes: it shrinks by max(1/3, 1 - (2 rho - 1)^3), so it falls
/// fast where the Gauss-Newton model is good; never below 1e-15.
inline double damping_after_kept_step(double damping, double rho) {
  return std::max(damping * std::max(1.0 / 3.0, 1.0 - std::pow(2.0 * rho - 1.0, 3)), 1e-15);
}

/// D, the scale of the damping term: the diagonal of J'J, floored at 1e-12 of its largest entry so
/// that a parameter the data barely reach is damped too. `scale` has J'J's size.
template <typename Normal, typename Scale>
void damping_scale(const Eigen::MatrixBase<Normal>& normal, Eigen::MatrixBase<Scale>& scale) {
  using Scalar = typename Normal::Scalar;
  scale = normal.diagonal().cwiseMax(Scalar(1e-12) * (normal.diagonal().maxCoeff() + Scalar(1e-300)));
}

/// D for the online window refinement: the mean of J'J's diagonal on every parameter (Levenberg's
/// damping toward the steepest descent, not Marquardt's per-parameter scale). Why: from the
/// recursion's estimate, at the bottom of the curved valley between a model's numerator and
/// denominator, the per-parameter scale lets a step move in the valley only a little per iteration.
/// Measured on the slowest known P-H-W under 10% noise: from the recursion's final estimate one
/// iteration with this scale reaches identify()'s accuracy, where the per-parameter scale takes 20;
/// the window refinement affords few iterations. The offline refinement keeps the per-parameter
/// scale: it has the iterations to spare, and its results are what the data-set figures record.
/// (On that system both reach about the same minimum offline, NRMSE 0.00439 and 0.00437; it was
/// not measured elsewhere.)
template <typename Normal, typename Scale>
void levenberg_scale(const Eigen::MatrixBase<Normal>& normal, Eigen::MatrixBase<Scale>& scale) {
  using Scalar = typename Normal::Scalar;
  scale.setConstant(std::max(normal.diagonal().mean(), Scalar(1e-300)));
}

}  // namespace bonl::detail
