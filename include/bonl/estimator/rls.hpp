#pragma once
// Recursive least squares with a forgetting factor (paper eqs. 21-23):
//   K = P phi / (lambda + phi' P phi),  theta += K (target - phi' theta),
//   P = (P - P phi phi' P / (lambda + phi' P phi)) / lambda.
// P is stored as its lower triangle and updated by a symmetric rank-1 downdate, so it stays exactly
// symmetric; the paper's (I - K phi') P / lambda is the same matrix in exact arithmetic. An update
// that would make the denominator or a diagonal entry of P non-positive, or a number non-finite,
// is refused and leaves the state untouched.

#include <Eigen/Core>
#include <cmath>

#include "../detail/validate.hpp"

namespace bonl {

template <typename Scalar_ = double, int N_ = Eigen::Dynamic>
class Rls {
 public:
  using Scalar = Scalar_;
  using Vector = Eigen::Matrix<Scalar, N_, 1>;
  using Matrix = Eigen::Matrix<Scalar, N_, N_>;

  /// n parameters, theta = 0, P = p0 I.
  explicit Rls(Eigen::Index n = (N_ == Eigen::Dynamic ? 1 : N_), Scalar p0 = Scalar(1e6)) {
    detail::require_order(n, 1, "number of parameters");
    detail::require_matches_template(n, N_, "number of parameters");
    m_theta = Vector::Zero(n);
    m_next = Vector::Zero(n);
    m_p_phi = Vector::Zero(n);
    reset(m_theta, p0);
  }

  /// theta = theta0, P = p0 I (p0 > 0 and finite).
  template <typename T>
  void reset(const Eigen::MatrixBase<T>& theta0, Scalar p0) {
    detail::require_size(theta0, m_theta.size(), "theta0");
    detail::require_finite(theta0, "theta0");
    detail::require(std::isfinite(p0) && p0 > Scalar(0), "p0 (initial covariance scale) must be finite and > 0");
    m_theta = theta0;
    m_P = Matrix::Identity(m_theta.size(), m_theta.size()) * p0;
  }

  /// One update with regressor phi, target y and forgetting factor lambda in (0, 1].
  /// Returns false, with theta and P untouched, when the update is numerically unsafe.
  template <typename Phi>
  bool update(const Eigen::MatrixBase<Phi>& phi, Scalar target, Scalar lambda) noexcept {
    m_p_phi.noalias() = m_P.template selfadjointView<Eigen::Lower>() * phi;
    const Scalar denominator = lambda + phi.dot(m_p_phi);
    if (!(denominator > Scalar(0)) || !std::isfinite(denominator)) return false;
    const Scalar error = target - phi.dot(m_theta);
    m_next = m_theta + (error / denominator) * m_p_phi;
    if (!m_next.allFinite()) return false;
    for (Eigen::Index i = 0; i < m_P.rows(); ++i) {
      if (!(m_P(i, i) - m_p_phi[i] * m_p_phi[i] / denominator > Scalar(0))) return false;
    }
    m_theta.swap(m_next);
    m_P.template selfadjointView<Eigen::Lower>().rankUpdate(m_p_phi, Scalar(-1) / denominator);
    if (lambda != Scalar(1)) m_P.template triangularView<Eigen::Lower>() *= Scalar(1) / lambda;
    return true;
  }

  const Vector& theta() const noexcept { return m_theta; }
  /// For projections after an update (e.g. a constraint on one parameter).
  Vector& mutable_theta() noexcept { return m_theta; }
  /// The full (symmetric) covariance.
  Matrix covariance() const { return m_P.template selfadjointView<Eigen::Lower>(); }
  Eigen::Index size() const noexcept { return m_theta.size(); }

 private:
  Vector m_theta;
  Matrix m_P;  // only the lower triangle is meaningful
  Vector m_next;
  Vector m_p_phi;
};

}  // namespace bonl
