#pragma once
// The linear block's part of a model's key-term regressor and of its output-error step, shared by
// the models whose front is the linear block alone (ARX, Wiener), as hammerstein_front.hpp is for
// the models with an input polynomial:
//   x(k) = sum_{i=0..nb} b_i u(k-nk-i) - sum_{j=1..na} a_j x(k-j),   theta = [b_0..b_nb, a_1..a_na, ...],
// with ni integrators x(k) = [u lags] . b - [z lags] . a + carried(k) (detail/integrators.hpp).

#include <Eigen/Core>

#include "../../detail/history.hpp"
#include "../../detail/integrators.hpp"
#include "../../detail/stability.hpp"
#include "simulated_lags.hpp"

namespace bonl::detail {

/// Regressor [u(k-nk), ..., u(k-nk-nb), -z(k-1), ..., -z(k-na)] in phi's first nb + 1 + na entries,
/// with z the differenced lags end() stored (ARX: the measured y; Wiener: the internal x), z = x where
/// there are no integrators. x(k) = regressor . [b, a] + carried().
template <typename Scalar, int Na = Eigen::Dynamic>
class LinearKeyTerms {
 public:
  LinearKeyTerms(Eigen::Index na, Eigen::Index nb, Eigen::Index nk, Eigen::Index ni = 0)
      : m_na(na), m_nb(nb), m_nk(nk), m_u(nk + nb + 1), m_z(na), m_integrators(ni) {}

  void reset() noexcept {
    m_u.clear();
    m_z.clear();
    m_integrators.clear();
  }
  /// Pushes u(k) and writes the regressor.
  template <typename Phi>
  void begin(Scalar u, Phi& phi) noexcept {
    m_u.push(u);
    for (Eigen::Index i = 0; i <= m_nb; ++i) phi[i] = m_u[m_nk + i];
    for (Eigen::Index j = 1; j <= m_na; ++j) phi[m_nb + j] = -m_z[j - 1];
  }
  /// The integrators' part of x(k), known from the past (0 without integrators).
  Scalar carried() const noexcept { return m_integrators.carried(); }
  /// Stores x(k), the lag later regressors use.
  void end(Scalar x) noexcept { m_z.push(m_integrators.push(x)); }

 private:
  Eigen::Index m_na, m_nb, m_nk;
  History<Scalar> m_u;  // capacity nk + nb + 1: nk is a run-time order
  History<Scalar, Na> m_z;
  IntegratorLags<Scalar> m_integrators;
};

/// One step of the linear block's free run with the current estimate, and the sensitivity of x(k) to
/// [b, a]: dx/db_i = u(k-nk-i), dx/da_j = -x(k-j), filtered by 1 / A (SimulatedLags). N: the length
/// of the sensitivity vectors (nb + 1 + na, or the model's whole parameter count where [b, a] is all).
template <typename Scalar, int Na = Eigen::Dynamic, int N = Eigen::Dynamic>
class LinearOutputError {
 public:
  LinearOutputError(Eigen::Index na, Eigen::Index nb, Eigen::Index nk, Eigen::Index n, Eigen::Index ni = 0)
      : m_na(na), m_nb(nb), m_nk(nk), m_u(nk + nb + 1), m_lags(na, n, ni),
        m_work(Eigen::Matrix<Scalar, Na, 1>::Zero(na)) {}

  void reset() noexcept {
    m_u.clear();
    m_lags.reset();
    m_x = Scalar(0);
  }
  /// Pushes u(k), returns x(k) and writes d x(k) / d [b, a] into dx's first nb + 1 + na entries.
  template <typename Theta, typename Dx>
  Scalar step(const Theta& theta, Scalar u, Dx& dx) noexcept {
    m_u.push(u);
    Scalar x = Scalar(0);
    for (Eigen::Index i = 0; i <= m_nb; ++i) {
      dx[i] = m_u[m_nk + i];
      x += theta[i] * dx[i];
    }
    x += m_lags.apply(theta.template segment<Na>(m_nb + 1, m_na), dx, m_nb + 1);
    m_x = x;
    return x;
  }
  /// Stores the last step's x(k) and its sensitivity dx as the newest lag.
  template <typename Dx>
  void commit(const Dx& dx) noexcept {
    m_lags.push(m_x, dx);
  }
  /// After the estimate moved by `delta`: the stored lags to first order (SimulatedLags).
  template <typename Delta>
  void correct(const Delta& delta) noexcept {
    m_lags.correct(delta);
  }
  /// Is the denominator in `theta` stable, all poles inside |z| < radius?
  template <typename Theta>
  bool stable(const Theta& theta, Scalar radius) noexcept {
    return roots_inside(theta.template segment<Na>(m_nb + 1, m_na), radius, m_work);
  }
  /// x(k) of the last step().
  Scalar x() const noexcept { return m_x; }

 private:
  Eigen::Index m_na, m_nb, m_nk;
  History<Scalar> m_u;
  SimulatedLags<Scalar, Na, N> m_lags;
  Eigen::Matrix<Scalar, Na, 1> m_work;  // for the stability test
  Scalar m_x = Scalar(0);
};

}  // namespace bonl::detail
