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
// whole record with the new estimate would (docs/explanation/algorithm.md), at na dot products per sample.
//
// With ni integrators (detail/integrators.hpp) the recursion above runs on z = (1 - q^-1)^ni x, and
//   x(k) = z(k) + carried(k),   d x(k) / d theta = d z(k) / d theta - sum_i d_i d x(k-i) / d theta,
// so the past z and x are kept with their sensitivities, na and ni of them.

#include <Eigen/Core>

#include "../../detail/integrators.hpp"

namespace bonl::detail {

/// Na: the order na (or Eigen::Dynamic); N: the number of parameters the sensitivities are taken to.
template <typename Scalar, int Na = Eigen::Dynamic, int N = Eigen::Dynamic>
class SimulatedLags {
 public:
  using Sensitivity = Eigen::Matrix<Scalar, N, 1>;

  SimulatedLags() = default;
  /// na poles, n parameters, ni integrators (0..2).
  SimulatedLags(Eigen::Index na, Eigen::Index n, Eigen::Index ni = 0)
      : m_x(Eigen::Matrix<Scalar, Na, 1>::Zero(na)), m_dx(Eigen::Matrix<Scalar, N, Na>::Zero(n, na)), m_ni(ni),
        m_integrated(IntegratedSensitivities::Zero(n, ni)) {}

  /// Back to rest: every past x and its sensitivity zero.
  void reset() noexcept {
    m_x.setZero();
    m_dx.setZero();
    m_integrated_x[0] = m_integrated_x[1] = Scalar(0);
    m_integrated.setZero();
  }

  /// With phi's input-side entries already in `dx` (everything but the a-entries at a_offset ..
  /// a_offset + na - 1): writes the a-entries -z(k-j), turns dx into d x(k) / d theta and returns
  /// -sum_j a_j z(k-j) + carried(k), the denominator's part of x(k).
  template <typename A, typename Dx>
  Scalar apply(const A& a, Dx& dx, Eigen::Index a_offset) const noexcept {
    Scalar part = Scalar(0);
    for (Eigen::Index j = 0; j < m_x.size(); ++j) {
      dx[a_offset + j] = -m_x[j];
      part -= a[j] * m_x[j];
    }
    for (Eigen::Index j = 0; j < m_x.size(); ++j) dx -= a[j] * m_dx.col(j);
    if (m_ni > 0) {
      part += carried<Scalar>(m_ni, m_integrated_x);
      add_carried_sensitivity(m_ni, m_integrated, Scalar(1), dx);
    }
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
      if (m_ni > 0) {  // z(k) = x(k) - carried(k), and its sensitivity
        m_x[0] -= carried<Scalar>(m_ni, m_integrated_x);
        add_carried_sensitivity(m_ni, m_integrated, Scalar(-1), m_dx.col(0));
      }
    }
    if (m_ni > 0) {
      m_integrated_x[1] = m_integrated_x[0];
      m_integrated_x[0] = x;
      if (m_ni == 2) m_integrated.col(1) = m_integrated.col(0);
      m_integrated.col(0) = dx;
    }
  }

  /// Moves every stored x by its sensitivity times the change of the estimate (first order).
  template <typename Delta>
  void correct(const Delta& delta) noexcept {
    for (Eigen::Index j = 0; j < m_x.size(); ++j) m_x[j] += m_dx.col(j).dot(delta);
    for (Eigen::Index i = 0; i < m_ni; ++i) m_integrated_x[i] += m_integrated.col(i).dot(delta);
  }

 private:
  using IntegratedSensitivities = Eigen::Matrix<Scalar, N, Eigen::Dynamic, Eigen::ColMajor, N, kMaxIntegrators>;

  Eigen::Matrix<Scalar, Na, 1> m_x;   // z(k-1-j): x(k-1-j) where there are no integrators
  Eigen::Matrix<Scalar, N, Na> m_dx;  // column j: d z(k-1-j) / d theta
  Eigen::Index m_ni = 0;
  Scalar m_integrated_x[2] = {Scalar(0), Scalar(0)};  // x(k-1), x(k-2) for the integrators
  IntegratedSensitivities m_integrated;               // column i: d x(k-1-i) / d theta
};

}  // namespace bonl::detail
