#pragma once
// The output polynomial of the H-W and Wiener models, y = x + sum_{m=2..r1} q_m x^m, with q_1 = 1
// outside theta and q_2..q_r1 the last r1 - 1 entries of theta (of n): its parameters (a CRTP base)
// and its part of the key-term form and of the output-error step. The Wiener-Hammerstein model's
// middle polynomial uses the same terms with its coefficients inside theta.

#include <Eigen/Core>

#include <algorithm>

#include <string>

#include "../../blocks/output_polynomial.hpp"
#include "../../detail/validate.hpp"

namespace bonl::detail {

/// q(), set_q() and output_block() for a model Derived with r1(), theta(), set_theta(), the type
/// OutputBlock and a parameter block "q" in its description (whose normalisation set_q() enforces).
template <class Derived>
class OutputPolynomialParameters {
 public:
  /// q_1..q_r1 with q_1 = 1.
  auto q() const {
    const Derived& model = self();
    typename Derived::VectorX q(model.r1());
    q[0] = 1;
    q.tail(model.r1() - 1) = model.theta().tail(model.r1() - 1);
    return q;
  }
  /// q_1..q_r1 with q_1 = 1.
  template <typename T>
  void set_q(const Eigen::MatrixBase<T>& q) {
    Derived& model = static_cast<Derived&>(*this);
    require_size(q, model.r1(), "q");
    require_finite(q, "q");
    require(q[0] == 1, std::string("q[0] (q_1) must be 1: ") + normalisation());
    typename Derived::Params theta = model.theta();
    theta.tail(model.r1() - 1) = q.tail(model.r1() - 1);
    model.set_theta(theta);
  }
  auto output_block() const {
    typename Derived::OutputBlock block(self().r1());
    block.set_q(q());
    return block;
  }

 private:
  const Derived& self() const noexcept { return static_cast<const Derived&>(*this); }
  static const char* normalisation() noexcept {
    for (const auto& parameter : Derived::kDescription.parameters) {
      if (std::string(parameter.name) == "q" && parameter.normalised) return parameter.normalised;
    }
    return "q_1 = 1";
  }
};

/// A polynomial x + sum_{m=2..r1} q_m x^m whose q_2..q_r1 sit in theta: its last r1 - 1 entries (of n;
/// the H-W and Wiener models' output polynomial), or from index `first` on (starting_at; the
/// Wiener-Hammerstein model's middle polynomial, whose f_2..f_r lie between its two blocks).
template <typename Scalar>
class OutputPolynomialTerms {
 public:
  OutputPolynomialTerms(Eigen::Index r1, Eigen::Index n) : m_r1(r1), m_first(n - r1 + 1) {}
  static OutputPolynomialTerms starting_at(Eigen::Index r1, Eigen::Index first) {
    return OutputPolynomialTerms(r1, first + r1 - 1);
  }

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

  /// dy/dx at x.
  template <typename Theta>
  Scalar slope(const Theta& theta, Scalar x) const noexcept {
    Scalar slope = Scalar(1);
    Scalar power = Scalar(1);  // x^(m-1)
    for (Eigen::Index m = 2; m <= m_r1; ++m) {
      power *= x;
      slope += Scalar(m) * theta[index(m)] * power;
    }
    return slope;
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
  Eigen::Index index(Eigen::Index m) const noexcept { return m_first + m - 2; }

  Eigen::Index m_r1, m_first;  // the degree; the index of q_2 in theta
};

}  // namespace bonl::detail
