#pragma once
// How identified models are judged: mean squared error, its root, and the normalised fit of the
// System Identification Toolbox's `compare`, fit = 100 (1 - ||y - yhat|| / ||y - mean(y)||) %.
// simulation_scores runs the model free from rest (the criterion models are judged by);
// prediction_scores scores the one-step-ahead prediction, reported separately.

#include <Eigen/Core>
#include <cmath>

#include "detail/validate.hpp"

namespace bonl::metrics {

struct Scores {
  double mse = 0.0;
  double rmse = 0.0;
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
}  // namespace detail

template <typename A, typename B>
double mse(const Eigen::MatrixBase<A>& y, const Eigen::MatrixBase<B>& yhat) {
  detail::check_pair(y, yhat);
  return static_cast<double>((y - yhat).squaredNorm()) / static_cast<double>(y.size());
}

template <typename A, typename B>
double rmse(const Eigen::MatrixBase<A>& y, const Eigen::MatrixBase<B>& yhat) {
  return std::sqrt(mse(y, yhat));
}

/// ||y - yhat|| / ||y - mean(y)||. Throws if y is constant (the ratio is undefined).
template <typename A, typename B>
double nrmse(const Eigen::MatrixBase<A>& y, const Eigen::MatrixBase<B>& yhat) {
  detail::check_pair(y, yhat);
  const double spread = static_cast<double>((y.array() - y.mean()).matrix().norm());
  bonl::detail::require(spread > 0.0, "y is constant: the normalised error is undefined");
  return static_cast<double>((y - yhat).norm()) / spread;
}

template <typename A, typename B>
double fit_percent(const Eigen::MatrixBase<A>& y, const Eigen::MatrixBase<B>& yhat) {
  return 100.0 * (1.0 - nrmse(y, yhat));
}

template <typename A, typename B>
Scores scores(const Eigen::MatrixBase<A>& y, const Eigen::MatrixBase<B>& yhat) {
  Scores s;
  s.mse = mse(y, yhat);
  s.rmse = std::sqrt(s.mse);
  s.nrmse = nrmse(y, yhat);
  s.fit_percent = 100.0 * (1.0 - s.nrmse);
  return s;
}

/// Free-run simulation of `model` on u, scored against y.
template <class Model, typename U, typename Y>
Scores simulation_scores(const Model& model, const Eigen::MatrixBase<U>& u, const Eigen::MatrixBase<Y>& y) {
  return scores(y, model.simulate(u));
}

/// One-step-ahead prediction of `model` from u and the measured y, scored against y.
template <class Model, typename U, typename Y>
Scores prediction_scores(const Model& model, const Eigen::MatrixBase<U>& u, const Eigen::MatrixBase<Y>& y) {
  return scores(y, model.predict(u, y));
}

}  // namespace bonl::metrics
