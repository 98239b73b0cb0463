#pragma once
// The poles of a model's linear block, the roots of z^na A(z^-1) = z^na + a_1 z^(na-1) + ... + a_na,
// and what identification does with them: the largest pole magnitude says whether the model is
// stable (< 1) and how well damped, and a denominator with poles outside the unit circle can be
// replaced by the stable one whose magnitude response is the same up to a constant gain (each pole
// z outside reflected to 1 / conj(z), as MATLAB's polystab does).
// The roots are the eigenvalues of the companion matrix: O(na^3), allocates; for offline use.

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

namespace bonl {

/// The roots of z^na + a_1 z^(na-1) + ... + a_na (the poles of 1 / A(z^-1)).
template <typename A>
Eigen::Matrix<std::complex<typename A::Scalar>, Eigen::Dynamic, 1> denominator_poles(const Eigen::MatrixBase<A>& a) {
  using Scalar = typename A::Scalar;
  const Eigen::Index n = a.size();
  if (n == 0) return {};
  Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> companion =
      Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>::Zero(n, n);
  companion.row(0) = -a.transpose();
  if (n > 1) companion.bottomLeftCorner(n - 1, n - 1).setIdentity();
  return companion.eigenvalues();
}

/// The largest pole magnitude of `model`'s linear block: < 1 stable, >= 1 not; near 1 barely damped.
/// Infinity where the coefficients are not finite.
template <class Model>
double pole_radius(const Model& model) {
  const auto a = model.a();
  if (!a.allFinite()) return std::numeric_limits<double>::infinity();
  const auto poles = denominator_poles(a);
  double radius = 0.0;
  for (Eigen::Index i = 0; i < poles.size(); ++i) radius = std::max(radius, static_cast<double>(std::abs(poles[i])));
  return radius;
}

namespace detail {

/// The denominator a_1..a_na with every pole of magnitude >= 1 reflected to 1 / conj(z) and, if that
/// leaves it on the unit circle, moved to magnitude `limit`. Stable denominators come back as they were.
template <typename A>
Eigen::Matrix<typename A::Scalar, Eigen::Dynamic, 1> reflected_inside(const Eigen::MatrixBase<A>& a,
                                                                     typename A::Scalar limit) {
  using Scalar = typename A::Scalar;
  using Complex = std::complex<Scalar>;
  auto poles = denominator_poles(a);
  bool changed = false;
  for (Eigen::Index i = 0; i < poles.size(); ++i) {
    Scalar magnitude = std::abs(poles[i]);
    if (magnitude >= Scalar(1)) {
      poles[i] = Scalar(1) / std::conj(poles[i]);
      magnitude = std::abs(poles[i]);
      if (magnitude > limit) poles[i] *= limit / magnitude;
      changed = true;
    }
  }
  if (!changed) return a;
  // prod_i (1 - z_i z^-1): the coefficients of z^-1..z^-na; conjugate pairs make them real.
  Eigen::Matrix<Complex, Eigen::Dynamic, 1> product = Eigen::Matrix<Complex, Eigen::Dynamic, 1>::Zero(a.size() + 1);
  product[0] = Complex(1);
  for (Eigen::Index i = 0; i < poles.size(); ++i) {
    for (Eigen::Index j = i + 1; j >= 1; --j) product[j] -= poles[i] * product[j - 1];
  }
  return product.tail(a.size()).real();
}

}  // namespace detail
}  // namespace bonl
