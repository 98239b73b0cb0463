#pragma once
// Recursive least squares with a forgetting factor (paper eqs. 21-23):
//   K = P phi / (lambda + phi' P phi),  theta += K (target - phi' theta),
//   P = (P - P phi phi' P / (lambda + phi' P phi)) / lambda.
// The downdate is written P -= h h' with h = P phi / sqrt(lambda + phi' P phi): entry (i, j) is
// P_ij - h_i h_j and (j, i) is P_ji - h_j h_i, equal because floating-point multiplication is
// commutative, so P stays exactly symmetric by construction without a triangular view (whose
// generic kernels cost 4x more at the paper's sizes). The paper's (I - K phi') P / lambda is the same
// matrix in exact arithmetic. An update that would make the denominator or a diagonal entry of P
// non-positive, or a number non-finite, is refused and leaves the state untouched.

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
    if constexpr (N_ == Eigen::Dynamic) {
      return update(phi, target, lambda, m_p_phi, m_next);  // preallocated: no allocation per update
    } else {
      Vector p_phi, next;  // on the stack; as locals they cannot alias phi, which keeps them in registers
      return update(phi, target, lambda, p_phi, next);
    }
  }

  const Vector& theta() const noexcept { return m_theta; }
  /// For projections after an update (e.g. a constraint on one parameter).
  Vector& mutable_theta() noexcept { return m_theta; }
  /// The covariance (exactly symmetric).
  const Matrix& covariance() const noexcept { return m_P; }
  Eigen::Index size() const noexcept { return m_theta.size(); }

 private:
  template <typename Phi>
  bool update(const Eigen::MatrixBase<Phi>& phi, Scalar target, Scalar lambda, Vector& p_phi, Vector& next) noexcept {
    // P phi as a sum of columns: vectorised axpys, no horizontal reductions (faster than Eigen's
    // small fixed-size matrix-vector product at these sizes).
    p_phi = m_P.col(0) * phi[0];
    for (Eigen::Index j = 1; j < phi.size(); ++j) p_phi += m_P.col(j) * phi[j];
    const Scalar denominator = lambda + phi.dot(p_phi);
    if (!(denominator > Scalar(0)) || !std::isfinite(denominator)) return false;
    const Scalar inverse = Scalar(1) / denominator;
    const Scalar error = target - phi.dot(m_theta);
    next = m_theta + (error * inverse) * p_phi;
    if (!next.allFinite()) return false;
    // The new diagonal, P_ii - (P phi)_i^2 / denominator, must stay positive.
    if (!((m_P.diagonal().array() - p_phi.array().square() * inverse) > Scalar(0)).all()) return false;
    m_theta = next;
    p_phi *= std::sqrt(inverse);
    m_P.noalias() -= p_phi * p_phi.transpose();
    if (lambda != Scalar(1)) m_P *= Scalar(1) / lambda;
    return true;
  }

  Vector m_theta;
  Matrix m_P;
  Vector m_next;   // scratch for run-time sizes
  Vector m_p_phi;  // scratch for run-time sizes
};

}  // namespace bonl
