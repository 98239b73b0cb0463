#pragma once
// The monotone branch of a polynomial c_0 + c_1 v + ... + c_n v^n that starts at v = 0 and runs to one
// side, and its safeguarded Newton solve. The input and output polynomials' inverses use both. Users
// never name this header.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>

namespace bonl::control::detail {

template <typename C>
typename C::Scalar polynomial(const Eigen::MatrixBase<C>& c, typename C::Scalar v) noexcept {
  typename C::Scalar value(0);
  for (Eigen::Index i = c.size() - 1; i >= 0; --i) value = value * v + c[i];
  return value;
}
template <typename C>
typename C::Scalar polynomial_derivative(const Eigen::MatrixBase<C>& c, typename C::Scalar v) noexcept {
  using Scalar = typename C::Scalar;
  Scalar value(0);
  for (Eigen::Index i = c.size() - 1; i >= 1; --i) value = value * v + Scalar(i) * c[i];
  return value;
}

/// Where the branch from 0 towards `side` (+1 or -1) stops being monotone: the first zero of the
/// derivative that changes its sign, searched up to |v| = min(|limit|, the Cauchy bound of the
/// derivative's roots), on a grid of 4096 steps refined by bisection. +-infinity when the limit is
/// infinite and the derivative has no such zero on that side. A pair of zeros closer than one grid step
/// (a dip of the slope below 0 and back) is not seen; the inverse's Newton solve still converges there
/// (its bracket holds the solution) but the branch is then not strictly monotone.
template <typename C>
typename C::Scalar branch_end(const Eigen::MatrixBase<C>& c, int side, typename C::Scalar limit) {
  using Scalar = typename C::Scalar;
  Eigen::Index top = c.size() - 1;
  while (top >= 1 && c[top] == Scalar(0)) --top;
  Scalar bound = std::numeric_limits<Scalar>::infinity();
  if (top >= 2) {  // the derivative has degree top - 1 >= 1: its roots lie within the Cauchy bound
    Scalar largest(0);
    for (Eigen::Index i = 1; i < top; ++i)
      largest = std::max(largest, std::abs(Scalar(i) * c[i] / (Scalar(top) * c[top])));
    bound = Scalar(1) + largest;
  } else {
    return side * std::abs(limit);  // constant or linear: monotone everywhere
  }
  const Scalar reach = std::min(std::abs(limit), bound);
  const int steps = 4096;
  const Scalar h = reach / Scalar(steps);
  const auto slope = [&](Scalar v) { return polynomial_derivative(c, side * v); };
  // The branch's direction: the sign of the slope at the first grid point where it is not zero.
  int direction = 0;
  Scalar previous = Scalar(0);
  for (int j = 0; j <= steps; ++j) {
    const Scalar v = h * Scalar(j);
    const Scalar d = slope(v);
    if (direction == 0) {
      if (d != Scalar(0)) direction = d > Scalar(0) ? 1 : -1;
    } else if (direction * d < Scalar(0)) {
      Scalar lo = previous, hi = v;  // the slope changes sign in (lo, hi]
      for (int i = 0; i < 200 && hi - lo > Scalar(4) * std::numeric_limits<Scalar>::epsilon() * hi; ++i) {
        const Scalar mid = Scalar(0.5) * (lo + hi);
        (direction * slope(mid) > Scalar(0) ? lo : hi) = mid;
      }
      return side * lo;
    }
    previous = v;
  }
  return side * std::abs(limit);
}

/// Solves p(v) = target for v in [lo, hi], where p is monotone and p(lo), p(hi) bracket the target:
/// Newton's method, a step that leaves the bracket replaced by bisection; the bracket shrinks with
/// every step. Finite lo and hi.
template <typename C>
typename C::Scalar solve_on_branch(const Eigen::MatrixBase<C>& c, typename C::Scalar target, typename C::Scalar lo,
                                   typename C::Scalar hi) noexcept {
  using Scalar = typename C::Scalar;
  const Scalar p_lo = polynomial(c, lo) - target;
  if (p_lo == Scalar(0)) return lo;
  const Scalar p_hi = polynomial(c, hi) - target;
  if (p_hi == Scalar(0)) return hi;
  const bool rising = p_hi > p_lo;
  Scalar v = std::abs(p_lo) < std::abs(p_hi) ? lo : hi;
  const Scalar tolerance = Scalar(2) * std::numeric_limits<Scalar>::epsilon();
  for (int iteration = 0; iteration < 200; ++iteration) {
    const Scalar residual = polynomial(c, v) - target;
    if (residual == Scalar(0)) return v;
    // Keep the bracket [lo, hi] around the root.
    if ((residual > Scalar(0)) == rising)
      hi = v;
    else
      lo = v;
    const Scalar slope = polynomial_derivative(c, v);
    Scalar next = v - residual / slope;
    if (!(next > lo && next < hi)) next = Scalar(0.5) * (lo + hi);
    const Scalar scale = std::max(std::abs(next), std::abs(v)) + std::numeric_limits<Scalar>::min();
    const bool converged = std::abs(next - v) <= tolerance * scale || hi - lo <= tolerance * scale;
    v = next;
    if (converged) return v;
  }
  return v;
}

}  // namespace bonl::control::detail
