#pragma once
// Inverse of the output polynomial of the H-W and Wiener models (paper eq. 9), y = sum_{m=1..r1} q_m x^m:
// the x on the monotone branch through the operating point x = 0 that gives y. The branch runs from 0
// to the first stationary point on each side (detail::branch_end; +-infinity where there is none);
// inside it, Newton's method safeguarded by bisection. A y beyond the branch's ends is OutOfRange and
// gets the end (the x where the model's output turns back). q_1 = q'(0) must not be 0.

#include <Eigen/Core>
#include <cmath>
#include <limits>

#include "../detail/validate.hpp"
#include "detail/polynomial_branch.hpp"
#include "inverse_status.hpp"

namespace bonl::control {

/// The inverse of the output polynomial of the H-W and Wiener models (paper eq. 9),
/// y = sum_{m=1..r1} q_m x^m: the x on the monotone branch through the operating point x = 0 that
/// gives y, by Newton's method safeguarded by bisection. The branch runs from 0 to the first stationary
/// point on each side; a y beyond its ends is OutOfRange and gets the end, where the model's output
/// turns back.
template <typename Scalar_ = double>
class OutputPolynomialInverse {
 public:
  using Scalar = Scalar_;                                    ///< the arithmetic type
  using VectorX = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;  ///< a vector of run-time size

  /// The inverse of the polynomial with coefficients q. Throws std::invalid_argument for an empty or
  /// non-finite q, or q_1 = 0 (no inverse through the operating point).
  /// \param q q_1..q_r1
  template <typename Q>
  explicit OutputPolynomialInverse(const Eigen::MatrixBase<Q>& q) {
    bonl::detail::require(q.size() >= 1, "the output polynomial needs q_1..q_r1 (at least one entry)");
    bonl::detail::require_finite(q, "q");
    bonl::detail::require(q[0] != Scalar(0),
                          "the output polynomial has no inverse through the operating point: q_1 = q'(0) is 0");
    m_c = VectorX::Zero(q.size() + 1);
    m_c.tail(q.size()) = q;
    const Scalar inf = std::numeric_limits<Scalar>::infinity();
    m_hi = detail::branch_end(m_c, 1, inf);
    m_lo = detail::branch_end(m_c, -1, inf);
    m_direction = q[0] > Scalar(0) ? Scalar(1) : Scalar(-1);
  }

  /// x with q(x) = y on the branch through 0, or the branch's end (OutOfRange).
  /// \param y the output to reach
  /// \return x and its status (Exact or OutOfRange)
  InverseStep<Scalar> operator()(Scalar y) const noexcept {
    if (m_direction * y >= Scalar(0)) return solve(y, m_hi);
    return solve(y, m_lo);
  }

  /// The branch: x in [lower(), upper()] (infinite where q is monotone to infinity).
  /// \return the branch's lower end, <= 0 (possibly -infinity)
  Scalar lower() const noexcept { return m_lo; }
  /// The branch's upper end (see lower())
  /// \return the branch's upper end, >= 0 (possibly infinity)
  Scalar upper() const noexcept { return m_hi; }

 private:
  /// Solves on [0, end] (end < 0: [end, 0]).
  InverseStep<Scalar> solve(Scalar y, Scalar end) const noexcept {
    // y is bracketed by q(0) = 0 and q(end) when they lie on either side of it.
    const auto outside = [&](Scalar v) { return (detail::polynomial(m_c, v) - y) * (Scalar(0) - y) > Scalar(0); };
    if (std::isfinite(end)) {
      if (outside(end)) return {end, InverseStatus::OutOfRange};
    } else {
      // Monotone to infinity: widen the bracket until it holds y (a polynomial that is monotone on a
      // half line grows without bound there).
      end = end > Scalar(0) ? Scalar(1) : Scalar(-1);
      for (int i = 0; i < 2100 && outside(end); ++i) end *= Scalar(2);
      if (!std::isfinite(detail::polynomial(m_c, end)) || outside(end)) return {end, InverseStatus::OutOfRange};
    }
    const Scalar lo = end < Scalar(0) ? end : Scalar(0);
    const Scalar hi = end < Scalar(0) ? Scalar(0) : end;
    return {detail::solve_on_branch(m_c, y, lo, hi), InverseStatus::Exact};
  }

  VectorX m_c;  // 0, q_1, ..., q_r1
  Scalar m_lo = Scalar(0), m_hi = Scalar(0);
  Scalar m_direction = Scalar(1);
};

}  // namespace bonl::control
