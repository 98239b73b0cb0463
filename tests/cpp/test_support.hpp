#pragma once
// Shared by the C++ tests: one tolerance helper, the known systems the identification tests
// recover (known_systems.hpp; with identify and friends compiled once, compiled_once.hpp), and the
// inputs they are excited with. Seeds are fixed.

#include <bonl/bonl.hpp>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <initializer_list>

#include "compiled_once.hpp"

namespace bonl_test {

/// |a - b| <= tol * max(1, |b|) elementwise: relative for large values, absolute near zero.
template <typename A, typename B>
bool near(const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<B>& b, double tol) {
  if (a.size() != b.size()) return false;
  for (Eigen::Index i = 0; i < a.size(); ++i) {
    const double scale = std::max(1.0, std::abs(static_cast<double>(b.derived().coeff(i))));
    if (!(std::abs(static_cast<double>(a.derived().coeff(i) - b.derived().coeff(i))) <= tol * scale)) return false;
  }
  return true;
}
inline bool near(double a, double b, double tol) { return std::abs(a - b) <= tol * std::max(1.0, std::abs(b)); }

/// Identification and validation inputs of 5000 samples (the paper's 50 s at 100 Hz).
enum class Input { RandomLevels, MultiSine };

inline Eigen::VectorXd identification_input(Input input) {
  return input == Input::RandomLevels ? bonl::signals::random_levels(5000, 5, 1.0, 1)
                                      : bonl::signals::paper_multisine(5000, 0.01, 0.4);
}
/// A fresh input of the same kind: other levels, or the paper's tones with other phases.
inline Eigen::VectorXd validation_input(Input input) {
  if (input == Input::RandomLevels) return bonl::signals::random_levels(5000, 5, 1.0, 2);
  const Eigen::VectorXd phases = bonl::signals::random_levels(5, 1, 3.14159, 3);
  return bonl::signals::multisine(5000, 0.01, bonl::signals::paper_tones(), 0.4, phases);
}

/// Random levels held 5 samples, 4000 of them, of the given amplitude: the identification input of
/// the extrapolation tests (amplitude 1) and their fresh input of a larger amplitude (1.5).
inline Eigen::VectorXd levels(double amplitude, std::uint64_t seed) {
  return bonl::signals::random_levels(4000, 5, amplitude, seed);
}

/// The structure of a known system: its orders and structure parameters (knots, thresholds), theta zero.
template <class Model>
Model structure_of(const Model& truth) {
  Model structure = truth;
  structure.set_theta(Model::Params::Zero(truth.num_params()));
  return structure;
}

/// The largest error of a model's key terms run with `method` over (u, y) at the model's own theta:
/// regressor . theta against the target, and the prediction against y. Zero up to round-off where y
/// is the model's own noise-free output.
template <class Model>
double worst_key_term_error(const Model& model, const Eigen::VectorXd& u, const Eigen::VectorXd& y,
                            bonl::KeyTermMethod method) {
  typename Model::KeyTerms terms(model, method);
  double worst = 0.0;
  for (Eigen::Index k = 0; k < u.size(); ++k) {
    const auto step = terms.step(model.theta(), u[k], y[k]);
    worst = std::max(worst, std::abs(step.regressor.dot(model.theta()) - step.target));
    worst = std::max(worst, std::abs(step.prediction - y[k]));
  }
  return worst;
}

inline double standard_deviation(const Eigen::VectorXd& y) { return std::sqrt((y.array() - y.mean()).square().mean()); }

/// Central differences of run(model), one parameter at a time (step 1e-6 max(1, |theta_i|)): row k is
/// d run(model)(k) / d theta, the oracle of the output-error sensitivities and the refinement's Jacobians.
template <class Model, class Run>
Eigen::MatrixXd run_differences(const Model& model, Run&& run) {
  Eigen::MatrixXd differences;
  for (Eigen::Index i = 0; i < model.num_params(); ++i) {
    const double step = 1e-6 * std::max(1.0, std::abs(model.theta()[i]));
    Model plus = model, minus = model;
    typename Model::Params theta = model.theta();
    theta[i] += step;
    plus.set_theta(theta);
    theta[i] -= 2 * step;
    minus.set_theta(theta);
    const Eigen::VectorXd column = (run(plus) - run(minus)) / (2 * step);
    if (i == 0) differences.resize(column.size(), model.num_params());
    differences.col(i) = column;
  }
  return differences;
}

/// The same of model.simulate(u), the free run from rest.
template <class Model>
Eigen::MatrixXd simulation_differences(const Model& model, const Eigen::VectorXd& u) {
  return run_differences(model, [&u](const Model& m) -> Eigen::VectorXd { return m.simulate(u); });
}

/// How many samples (rows) of `jacobian` equal `differences` to 1e-6 of its largest entry. A backlash
/// output is piecewise smooth: a sample whose regime the +-step flips differs, so the tests count.
inline Eigen::Index matching_samples(const Eigen::MatrixXd& jacobian, const Eigen::MatrixXd& differences) {
  const double scale = differences.cwiseAbs().maxCoeff();
  Eigen::Index matching = 0;
  for (Eigen::Index k = 0; k < jacobian.rows(); ++k) {
    if ((jacobian.row(k) - differences.row(k)).cwiseAbs().maxCoeff() <= 1e-6 * scale) ++matching;
  }
  return matching;
}

}  // namespace bonl_test
