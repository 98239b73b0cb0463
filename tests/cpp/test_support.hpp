#pragma once
// Shared by the C++ tests: one tolerance helper, the known systems the identification tests
// recover (known_systems.hpp; with identify and friends compiled once, compiled_once.hpp), and the
// inputs they are excited with. Seeds are fixed.

#include <bonl/bonl.hpp>

#include <catch2/catch.hpp>
#include <cmath>
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

inline double standard_deviation(const Eigen::VectorXd& y) {
  return std::sqrt((y.array() - y.mean()).square().mean());
}

}  // namespace bonl_test
