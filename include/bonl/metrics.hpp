#pragma once
// How identified models are judged: mean squared error, its root, and the normalised fit of the
// System Identification Toolbox's `compare`, fit = 100 (1 - ||y - yhat|| / ||y - mean(y)||) %.
// simulation_scores runs the model free from rest (the criterion models are judged by);
// prediction_scores scores the one-step-ahead prediction, reported separately.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

#include "detail/validate.hpp"

namespace bonl::metrics {

/// The scores of a prediction yhat of y, all at once (scores()).
struct Scores {
  double mse = 0.0;          ///< mean squared error
  double rmse = 0.0;         ///< root mean squared error, in y's units
  double nrmse = 0.0;        ///< ||y - yhat|| / ||y - mean(y)|| (0 is perfect)
  double fit_percent = 0.0;  ///< 100 (1 - nrmse)
};

namespace detail {
template <typename A, typename B>
void check_pair(const Eigen::MatrixBase<A>& y, const Eigen::MatrixBase<B>& yhat) {
  bonl::detail::require_same_length(y, "y", yhat, "yhat");
  bonl::detail::require(y.size() > 0, "y must not be empty");
  bonl::detail::require_finite(y, "y");
  bonl::detail::require_finite(yhat, "yhat");
}

/// v scaled by 2^-exponent, in double. Scaling by a power of two is exact (unless a value becomes
/// subnormal, which only happens to values negligible next to the largest one).
template <typename V>
auto scaled(const Eigen::MatrixBase<V>& v, int exponent) {
  return v.template cast<double>().unaryExpr([exponent](double x) { return std::ldexp(x, -exponent); });
}

/// The binary exponent of the largest magnitude in y and yhat (0 if all are zero): dividing by
/// 2^exponent brings every value into (-1, 1), where sums of squares neither overflow nor underflow.
template <typename A, typename B>
int common_exponent(const Eigen::MatrixBase<A>& y, const Eigen::MatrixBase<B>& yhat) {
  const double largest =
      std::max(static_cast<double>(y.cwiseAbs().maxCoeff()), static_cast<double>(yhat.cwiseAbs().maxCoeff()));
  int exponent = 0;
  if (largest > 0.0) std::frexp(largest, &exponent);
  return exponent;
}
}  // namespace detail

/// The mean squared error of yhat against y, mean((y - yhat)^2), computed on values scaled by a power
/// of two so that it neither overflows nor underflows needlessly. Throws std::invalid_argument for
/// different lengths, an empty y or a non-finite value.
/// \param y the measured output
/// \param yhat its prediction or simulation, as long as y
/// \return the MSE, in y's units squared, >= 0
template <typename A, typename B>
double mse(const Eigen::MatrixBase<A>& y, const Eigen::MatrixBase<B>& yhat) {
  detail::check_pair(y, yhat);
  return static_cast<double>((y - yhat).squaredNorm()) / static_cast<double>(y.size());
}

/// sqrt(mse). Where the mean square overflows (errors beyond 1e154) the root is computed from
/// scaled values, so that a representable RMSE is returned as a number, not infinity.
/// \param y the measured output
/// \param yhat its prediction or simulation, as long as y
/// \return the RMSE, in y's units, >= 0
template <typename A, typename B>
double rmse(const Eigen::MatrixBase<A>& y, const Eigen::MatrixBase<B>& yhat) {
  const double mean_square = mse(y, yhat);
  if (std::isfinite(mean_square)) return std::sqrt(mean_square);
  const int exponent = detail::common_exponent(y, yhat);
  const double norm = (detail::scaled(y, exponent) - detail::scaled(yhat, exponent)).norm();
  return std::ldexp(norm / std::sqrt(static_cast<double>(y.size())), exponent);
}

/// ||y - yhat|| / ||y - mean(y)||. Throws if y is constant (the ratio is undefined). Computed from
/// y and yhat scaled by a common power of two, so that data near the ends of double's range
/// (1e200, 1e-200) neither overflow nor underflow; elsewhere the scaling is exact and the result is
/// the plain formula's.
/// \param y the measured output
/// \param yhat its prediction or simulation, as long as y
/// \return the NRMSE, >= 0 (0 is perfect, 1 no better than y's mean)
template <typename A, typename B>
double nrmse(const Eigen::MatrixBase<A>& y, const Eigen::MatrixBase<B>& yhat) {
  detail::check_pair(y, yhat);
  bonl::detail::require(!(y.array() == y[0]).all(), "y is constant: the normalised error is undefined");
  const int exponent = detail::common_exponent(y, yhat);
  // Materialised, so that the norms and the mean are the same vectorised reductions as the plain
  // formula's on a VectorXd.
  const Eigen::VectorXd ys = detail::scaled(y, exponent);
  const Eigen::VectorXd yhats = detail::scaled(yhat, exponent);
  const double spread = (ys.array() - ys.mean()).matrix().norm();
  bonl::detail::require(spread > 0.0, "y is constant: the normalised error is undefined");
  return (ys - yhats).norm() / spread;
}

/// The fit in percent, 100 (1 - nrmse(y, yhat)): 100 is perfect, 0 no better than y's mean. Throws as
/// nrmse() does.
/// \param y the measured output
/// \param yhat its prediction or simulation, as long as y
/// \return the fit in percent, <= 100
template <typename A, typename B>
double fit_percent(const Eigen::MatrixBase<A>& y, const Eigen::MatrixBase<B>& yhat) {
  return 100.0 * (1.0 - nrmse(y, yhat));
}

/// mse(), rmse(), nrmse() and fit_percent() of yhat against y, in one Scores; throws as nrmse() does.
/// \param y the measured output
/// \param yhat its prediction or simulation, as long as y
/// \return the four scores
template <typename A, typename B>
Scores scores(const Eigen::MatrixBase<A>& y, const Eigen::MatrixBase<B>& yhat) {
  Scores s;
  s.mse = mse(y, yhat);
  s.rmse = rmse(y, yhat);
  s.nrmse = nrmse(y, yhat);
  s.fit_percent = 100.0 * (1.0 - s.nrmse);
  return s;
}

/// Free-run simulation of `model` on u, scored against y.
/// \param model the model
/// \param u the input
/// \param y the measured output, as long as u
/// \return the scores of the simulated output
template <class Model, typename U, typename Y>
Scores simulation_scores(const Model& model, const Eigen::MatrixBase<U>& u, const Eigen::MatrixBase<Y>& y) {
  bonl::detail::require_same_length(u, "u", y, "y");
  return scores(y, model.simulate(u));
}

/// One-step-ahead prediction of `model` from u and the measured y, scored against y.
/// \param model the model
/// \param u the input
/// \param y the measured output, as long as u
/// \return the scores of the one-step-ahead prediction
template <class Model, typename U, typename Y>
Scores prediction_scores(const Model& model, const Eigen::MatrixBase<U>& u, const Eigen::MatrixBase<Y>& y) {
  return scores(y, model.predict(u, y));
}

}  // namespace bonl::metrics
