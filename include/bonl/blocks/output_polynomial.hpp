#pragma once
// Output block N2 of the Hammerstein-Wiener model (paper eq. 9): y = sum_{m=1..r1} q_m x^m.
// For identification q_1 = 1 (normalisation), but the block itself accepts any q_1.

#include <Eigen/Core>
#include <cmath>

#include "../detail/validate.hpp"

namespace bonl {

/// The output block N2 of the Hammerstein-Wiener model (eq. 9), a static polynomial without constant
/// term: y = sum_{m=1..r1} q_m x^m. Identification normalises q_1 = 1; the block accepts any q_1.
template <typename Scalar_ = double, int R1_ = Eigen::Dynamic>
class OutputPolynomial {
 public:
  using Scalar = Scalar_;                        ///< the arithmetic type
  using Coeffs = Eigen::Matrix<Scalar, R1_, 1>;  ///< q_1..q_r1 (fixed size when R1_ is)

  /// The identity, q = [1, 0, ..., 0]. Throws std::invalid_argument for a degree below 1 or one that
  /// differs from the compile-time degree.
  /// \param r1 the degree, >= 1
  explicit OutputPolynomial(Eigen::Index r1 = (R1_ == Eigen::Dynamic ? 1 : R1_)) {
    detail::require_order(r1, 1, "r1 (output polynomial degree)");
    detail::require_matches_template(r1, R1_, "r1");
    m_q = Coeffs::Zero(r1);
    m_q[0] = Scalar(1);
  }

  Eigen::Index degree() const noexcept { return m_q.size(); }  ///< the degree r1 \return r1, >= 1
  /// The coefficients. \return q_1..q_r1
  const Coeffs& q() const noexcept { return m_q; }
  /// Sets q_1..q_r1 (r1 finite values, else std::invalid_argument).
  /// \param q q_1..q_r1
  template <typename Q>
  void set_q(const Eigen::MatrixBase<Q>& q) {
    detail::assign_checked(m_q, q, "q");
  }

  /// The output y = q(x).
  /// \param x the block's input
  /// \return y
  Scalar operator()(Scalar x) const noexcept { return evaluate(m_q, x); }
  /// The slope dq/dx at x.
  /// \param x the block's input
  /// \return dq/dx at x
  Scalar derivative(Scalar x) const noexcept { return evaluate_derivative(m_q, x); }

  /// y = sum_m q_m x^m for q = q_1..q_r1.
  /// \param q q_1..q_r1
  /// \param x the block's input
  /// \return y
  template <typename Q>
  static Scalar evaluate(const Eigen::MatrixBase<Q>& q, Scalar x) noexcept {
    Scalar y = Scalar(0);
    for (Eigen::Index m = q.size() - 1; m >= 0; --m) y = (y + q[m]) * x;
    return y;
  }
  /// The slope dq/dx = sum_m m q_m x^(m-1) at x for q = q_1..q_r1.
  /// \param q q_1..q_r1
  /// \param x the block's input
  /// \return dq/dx at x
  template <typename Q>
  static Scalar evaluate_derivative(const Eigen::MatrixBase<Q>& q, Scalar x) noexcept {
    Scalar d = Scalar(0);
    for (Eigen::Index m = q.size() - 1; m >= 0; --m) d = d * x + Scalar(m + 1) * q[m];
    return d;
  }

  /// Solves q(x) = y by Newton's method from `guess`. Returns false (and leaves x alone) when the
  /// polynomial is not locally invertible there: a vanishing slope, or no convergence in 30 steps.
  /// \param q q_1..q_r1
  /// \param y the output to reach
  /// \param guess where Newton's method starts
  /// \param x set to the root on success
  /// \return true when x was found
  template <typename Q>
  static bool invert(const Eigen::MatrixBase<Q>& q, Scalar y, Scalar guess, Scalar& x) noexcept {
    Scalar z = guess;
    const Scalar scale = Scalar(1) + std::abs(y);
    for (int iteration = 0; iteration < 30; ++iteration) {
      const Scalar slope = evaluate_derivative(q, z);
      if (!(slope > Scalar(1e-6))) return false;
      const Scalar step = (evaluate(q, z) - y) / slope;
      z -= step;
      if (!std::isfinite(z)) return false;
      if (std::abs(step) <= Scalar(64) * Eigen::NumTraits<Scalar>::epsilon() * scale) {
        x = z;
        return true;
      }
    }
    return false;
  }

 private:
  Coeffs m_q;
};

}  // namespace bonl
