#pragma once
// The output polynomial's part of a model's key-term form and of its output-error step, shared by the
// H-W and Wiener models: y = x + sum_{m=2..r1} q_m x^m, with q_1 = 1 outside theta and q_2..q_r1 the
// last r1 - 1 entries of theta (of n).

#include <Eigen/Core>

#include <algorithm>

#include "../../blocks/output_polynomial.hpp"

namespace bonl::detail {

template <typename Scalar>
class OutputPolynomialTerms {
 public:
  OutputPolynomialTerms(Eigen::Index r1, Eigen::Index n) : m_r1(r1), m_n(n) {}

  /// y for the internal variable x.
  template <typename Theta>
  Scalar output(const Theta& theta, Scalar x) const noexcept {
    Scalar y = x;
    Scalar power = x;
    for (Eigen::Index m = 2; m <= m_r1; ++m) {
      power *= x;
      y += theta[index(m)] * power;
    }
    return y;
  }

  /// The regressor's q entries: x^2..x^r1.
  template <typename Phi>
  void regress(Scalar x, Phi& phi) const noexcept {
    Scalar power = x;
    for (Eigen::Index m = 2; m <= m_r1; ++m) {
      power *= x;
      phi[index(m)] = power;
    }
  }

  /// The x that gives the measured y (Newton from x_model, the branch nearest the model's estimate);
  /// x_model where the polynomial cannot be inverted there.
  template <typename Theta>
  Scalar invert(const Theta& theta, Scalar y, Scalar x_model) const noexcept {
    Scalar q_buffer[32];
    const Eigen::Index r1 = std::min<Eigen::Index>(m_r1, 32);
    q_buffer[0] = Scalar(1);
    for (Eigen::Index m = 2; m <= r1; ++m) q_buffer[m - 1] = theta[index(m)];
    Eigen::Map<const Eigen::Matrix<Scalar, Eigen::Dynamic, 1>> q(q_buffer, r1);
    Scalar x = x_model;
    OutputPolynomial<Scalar>::invert(q, y, x_model, x);
    return x;
  }

  /// The output-error step: y, its sensitivity x^m to q_m written into psi, and the slope dy/dx
  /// (which scales the sensitivities of x).
  template <typename Theta, typename Psi>
  Scalar output_and_sensitivity(const Theta& theta, Scalar x, Psi& psi, Scalar& slope) const noexcept {
    Scalar y = x;
    slope = Scalar(1);
    Scalar power = x;  // x^(m-1), then x^m
    for (Eigen::Index m = 2; m <= m_r1; ++m) {
      slope += Scalar(m) * theta[index(m)] * power;
      power *= x;
      y += theta[index(m)] * power;
      psi[index(m)] = power;
    }
    return y;
  }

 private:
  Eigen::Index index(Eigen::Index m) const noexcept { return m_n - m_r1 + m - 1; }

  Eigen::Index m_r1, m_n;
};

}  // namespace bonl::detail
