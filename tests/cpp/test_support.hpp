#pragma once
// Shared by the C++ tests: one tolerance helper, the known systems the identification tests
// recover, and the inputs they are excited with. Seeds are fixed.

#include <bonl/bonl.hpp>

#include <catch2/catch.hpp>
#include <cmath>
#include <initializer_list>

namespace bonl_test {

inline Eigen::VectorXd vec(std::initializer_list<double> values) {
  Eigen::VectorXd v(static_cast<Eigen::Index>(values.size()));
  Eigen::Index i = 0;
  for (double value : values) v[i++] = value;
  return v;
}

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

// The known systems, at the paper's orders (na = 3, nb = 2, nk = 8, r = r1 = 3). The linear block
// has poles 0.7 and 0.5 +- 0.3i (a damped, slow response like a hydraulic drive sampled fast); the
// input block is asymmetric (different slopes and curvature for u < 0), with small offsets; the
// output polynomial is monotone; the backlash half-width is about 10% of the output's spread.
inline constexpr Eigen::Index kNk = 8;

template <class Model>
void set_known_front(Model& model) {
  model.set_f(vec({0.002, 0.06, 0.02, -0.01}));
  model.set_p(vec({-0.003, -0.02, -0.03, 0.015}));
  model.set_b(vec({1.0, 0.5, 0.2}));
  model.set_a(vec({-1.7, 1.04, -0.238}));
}

inline bonl::PaperARX known_arx() {
  bonl::PaperARX model(3, 2, kNk);
  model.set_b(vec({0.05, 0.03, 0.02}));
  model.set_a(vec({-1.7, 1.04, -0.238}));
  return model;
}
inline bonl::PaperHammerstein known_hammerstein() {
  bonl::PaperHammerstein model(3, 2, kNk, 3);
  set_known_front(model);
  return model;
}
inline bonl::PaperHammersteinWiener known_hammerstein_wiener() {
  bonl::PaperHammersteinWiener model(3, 2, kNk, 3, 3);
  set_known_front(model);
  model.set_q(vec({1.0, 0.2, 0.05}));
  return model;
}
inline bonl::PaperPseudoHammersteinWiener known_phw() {
  bonl::PaperPseudoHammersteinWiener model(3, 2, kNk, 3);
  set_known_front(model);
  model.set_c(0.1);
  return model;
}

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
