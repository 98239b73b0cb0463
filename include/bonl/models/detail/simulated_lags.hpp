#pragma once
// The output-error method's view of a linear block A(z^-1) x = z^-nk B(z^-1) w: the past simulated
// outputs x(k-1..k-na) and their sensitivities dx/dtheta, so that one simulation step also gives the
// sensitivity of x(k):
//   d x(k) / d theta = phi(k) - sum_j a_j d x(k-j) / d theta,
// where phi(k) is the regressor of the block's difference equation (its input-side entries filled by
// the caller, its a-entries -x(k-j) filled here). That recursion is the derivative of the difference
// equation with theta held fixed; Ljung and Soderstrom's recursive prediction-error method uses it
// with the estimate of each sample.
//
// correct(delta): after the estimate moved by delta, the stored lags are what the simulation with the
// old estimate gave; to first order the new estimate would have given x + (dx/dtheta)' delta, so
// they are moved there. Measured on the known systems: this recovers most of what re-simulating the
// whole record with the new estimate would (docs/algorithm.md), at na dot products per sample.

#include <Eigen/Core>

namespace bonl::detail {

/// Na: the order na (or Eigen::Dynamic); N: the number of parameters the sensitivities are taken to.
template <typename Scalar, int Na = Eigen::Dynamic, int N = Eigen::Dynamic>
class SimulatedLags {
 public:
  using Sensitivity = Eigen::Matrix<Scalar, N, 1>;

  SimulatedLags() = default;
  SimulatedLags(Eigen::Index na, Eigen::Index n)
      : m_x(Eigen::Matrix<Scalar, Na, 1>::Zero(na)), m_dx(Eigen::Matrix<Scalar, N, Na>::Zero(n, na)) {}

  /// Back to rest: every past x and its sensitivity zero.
  void reset() noexcept {
    m_x.setZero();
    m_dx.setZero();
  }

  /// With phi's input-side entries already in `dx` (everything but the a-entries at a_offset ..
  /// a_offset + na - 1): writes the a-entries -x(k-j), turns dx into d x(k) / d theta and returns
  /// -sum_j a_j x(k-j), the denominator's part of x(k).
  template <typename A, typename Dx>
  Scalar apply(const A& a, Dx& dx, Eigen::Index a_offset) const noexcept {
    Scalar part = Scalar(0);
    for (Eigen::Index j = 0; j < m_x.size(); ++j) {
      dx[a_offset + j] = -m_x[j];
      part -= a[j] * m_x[j];
    }
    for (Eigen::Index j = 0; j < m_x.size(); ++j) dx -= a[j] * m_dx.col(j);
    return part;
  }

  /// Stores x(k) and its sensitivity as the newest lag.
  template <typename Dx>
  void push(Scalar x, const Dx& dx) noexcept {
    for (Eigen::Index j = m_x.size() - 1; j > 0; --j) {
      m_x[j] = m_x[j - 1];
      m_dx.col(j) = m_dx.col(j - 1);
    }
    if (m_x.size() > 0) {
      m_x[0] = x;
      m_dx.col(0) = dx;
    }
  }

  /// Moves every stored x by its sensitivity times the change of the estimate (first order).
  template <typename Delta>
  void correct(const Delta& delta) noexcept {
    for (Eigen::Index j = 0; j < m_x.size(); ++j) m_x[j] += m_dx.col(j).dot(delta);
  }

  /// x(k-1-j).
  Scalar lag(Eigen::Index j) const noexcept { return m_x[j]; }

 private:
  Eigen::Matrix<Scalar, Na, 1> m_x;
  Eigen::Matrix<Scalar, N, Na> m_dx;  // column j: d x(k-1-j) / d theta
};

}  // namespace bonl::detail
