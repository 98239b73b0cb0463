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
#include <cstddef>
#include <limits>
#include <type_traits>

namespace bonl {

/// The roots of z^na + a_1 z^(na-1) + ... + a_na (the poles of 1 / A(z^-1)).
/// \param a a_1..a_na
/// \return the na poles, complex
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

namespace detail {

/// How many linear blocks a model has: Model::kLinearBlocks (the Wiener-Hammerstein model's two), or one.
template <class Model, class = void>
struct linear_block_count : std::integral_constant<std::size_t, 1> {};
template <class Model>
struct linear_block_count<Model, std::void_t<decltype(Model::kLinearBlocks)>>
    : std::integral_constant<std::size_t, Model::kLinearBlocks> {};

/// The denominator a_1..a_na of the model's linear block i: a() where it has one block.
template <class Model>
typename Model::VectorX denominator(const Model& model, std::size_t i) {
  if constexpr (linear_block_count<Model>::value > 1) {
    return model.denominator(i);
  } else {
    (void)i;
    return model.a();
  }
}

/// Sets the denominator of the model's linear block i: set_a() where it has one block.
template <class Model, typename A>
void set_denominator(Model& model, std::size_t i, const A& a) {
  if constexpr (linear_block_count<Model>::value > 1) {
    model.set_denominator(i, a);
  } else {
    (void)i;
    model.set_a(a);
  }
}

}  // namespace detail

/// The largest pole magnitude of `model`'s linear blocks: < 1 stable, >= 1 not; near 1 barely damped.
/// Infinity where the coefficients are not finite.
/// \param model any model of the list
/// \return the largest |pole| over the linear blocks' denominators (integrators' poles at 1 not included)
template <class Model>
double pole_radius(const Model& model) {
  double radius = 0.0;
  for (std::size_t block = 0; block < detail::linear_block_count<Model>::value; ++block) {
    const auto a = detail::denominator(model, block);
    if (!a.allFinite()) return std::numeric_limits<double>::infinity();
    const auto poles = denominator_poles(a);
    for (Eigen::Index i = 0; i < poles.size(); ++i) radius = std::max(radius, static_cast<double>(std::abs(poles[i])));
  }
  return radius;
}

namespace detail {

/// [1, c_1, ..., c_n]: the coefficients of prod_i (1 - roots_i z^-1), real where the complex roots
/// come in conjugate pairs (their imaginary parts, rounding, are dropped).
template <typename Scalar>
Eigen::Matrix<Scalar, Eigen::Dynamic, 1> monic_from_roots(
    const Eigen::Matrix<std::complex<Scalar>, Eigen::Dynamic, 1>& roots) {
  using Complex = std::complex<Scalar>;
  Eigen::Matrix<Complex, Eigen::Dynamic, 1> product = Eigen::Matrix<Complex, Eigen::Dynamic, 1>::Zero(roots.size() + 1);
  product[0] = Complex(1);
  for (Eigen::Index i = 0; i < roots.size(); ++i) {
    for (Eigen::Index j = i + 1; j >= 1; --j) product[j] -= roots[i] * product[j - 1];
  }
  return product.real();
}

/// The denominator a_1..a_na with every pole of magnitude >= 1 reflected to 1 / conj(z) and, if that
/// leaves it on the unit circle, moved to magnitude `limit`. Stable denominators come back as they were.
template <typename A>
Eigen::Matrix<typename A::Scalar, Eigen::Dynamic, 1> reflected_inside(const Eigen::MatrixBase<A>& a,
                                                                      typename A::Scalar limit) {
  using Scalar = typename A::Scalar;
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
  return monic_from_roots(poles).tail(a.size());
}

/// Every linear block of `model` with a finite denominator reflected inside (reflected_inside, poles
/// of magnitude >= 1 to 1 / conj(z), at most `limit`); true if one changed.
template <class Model>
bool reflect_poles_inside(Model& model, typename Model::Scalar limit) {
  bool changed = false;
  for (std::size_t block = 0; block < linear_block_count<Model>::value; ++block) {
    const typename Model::VectorX a = denominator(model, block);
    if (!a.allFinite()) continue;
    const typename Model::VectorX reflected = reflected_inside(a, limit);
    if (reflected == a) continue;
    set_denominator(model, block, reflected);
    changed = true;
  }
  return changed;
}

}  // namespace detail
}  // namespace bonl
