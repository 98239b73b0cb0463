#pragma once
// Integrators in a linear block: ni poles fixed at z = 1 (0, 1 or 2), so that the block's denominator is
//   A(q^-1) (1 - q^-1)^ni,   A = 1 + a_1 q^-1 + ... + a_na q^-na the estimated part,
// the structure of a drive whose position integrates its velocity, or its velocity its acceleration.
// With z = (1 - q^-1)^ni x, the differenced output of the block, its difference equation is
//   z(k) = -sum_j a_j z(k-j) + (the block's input side),   x(k) = z(k) + carried(k),
//   carried(k) = -sum_{i=1..ni} d_i x(k-i),   (1 - q^-1)^ni = 1 + d_1 q^-1 + ... + d_ni q^-ni,
// which stays linear in a: a key-term regressor holds -z(k-j) where it held -x(k-j), and carried(k),
// known from the past, is taken off the target. The estimated A alone is kept stable and reported by
// pole_radius(): the integrators' poles are at 1 by structure. Where ni = 0, z = x and carried = 0,
// and every computation is the one of the block without integrators, bit for bit.

#include <Eigen/Core>

#include <string>

#include "validate.hpp"

namespace bonl::detail {

/// The largest number of integrators a linear block takes.
inline constexpr Eigen::Index kMaxIntegrators = 2;

/// Checks the order ni: 0, 1 or 2.
inline void require_integrators(Eigen::Index ni) {
  require(ni >= 0 && ni <= kMaxIntegrators,
          "ni (integrators, poles fixed at 1) must be 0, 1 or 2, got " + std::to_string(ni));
}

/// carried(k) = -sum_{i=1..ni} d_i x(k-i) from the past x, lags[0] = x(k-1), lags[1] = x(k-2):
/// x(k-1) for one integrator, 2 x(k-1) - x(k-2) for two.
template <typename Scalar, class Lags>
Scalar carried(Eigen::Index ni, const Lags& lags) noexcept {
  if (ni == 0) return Scalar(0);
  if (ni == 1) return lags[0];
  return Scalar(2) * lags[0] - lags[1];
}

/// out += sign * d carried(k) / d theta from the past sensitivities, columns[0] = dx(k-1) / d theta,
/// columns[1] = dx(k-2) / d theta: dx(k-1), or 2 dx(k-1) - dx(k-2). For ni > 0.
template <typename Scalar, class Columns, class Out>
void add_carried_sensitivity(Eigen::Index ni, const Columns& columns, Scalar sign, Out&& out) noexcept {
  if (ni == 1) {
    out += sign * columns.col(0);
  } else {
    out += (Scalar(2) * sign) * columns.col(0) - sign * columns.col(1);
  }
}

/// The whole denominator a_1..a_{na+ni} of A(q^-1) (1 - q^-1)^ni from the estimated a_1..a_na.
template <typename A>
Eigen::Matrix<typename A::Scalar, Eigen::Dynamic, 1> with_integrators(const Eigen::MatrixBase<A>& a, Eigen::Index ni) {
  using Scalar = typename A::Scalar;
  Eigen::Matrix<Scalar, Eigen::Dynamic, 1> full = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>::Zero(a.size() + ni);
  full.head(a.size()) = a;
  for (Eigen::Index n = 0; n < ni; ++n) {
    // Multiply by (1 - q^-1): full_j -= full_{j-1}, with full_0 = 1, from the highest power down.
    for (Eigen::Index j = a.size() + n; j >= 1; --j) full[j] -= full[j - 1];
    full[0] -= Scalar(1);
  }
  return full;
}

/// The past outputs x(k-1), x(k-2) of a block with integrators, newest first; what carried() reads.
/// Allocation-free; with ni = 0 it stores nothing.
template <typename Scalar>
class IntegratorLags {
 public:
  explicit IntegratorLags(Eigen::Index ni = 0) : m_ni(ni) {}

  Eigen::Index size() const noexcept { return m_ni; }
  void clear() noexcept { m_x[0] = m_x[1] = Scalar(0); }
  /// carried(k) of the step whose past these are.
  Scalar carried() const noexcept { return detail::carried<Scalar>(m_ni, m_x); }
  /// Stores x(k) and returns z(k) = x(k) - carried(k), the differenced output of the step.
  Scalar push(Scalar x) noexcept {
    if (m_ni == 0) return x;
    const Scalar z = x - carried();
    m_x[1] = m_x[0];
    m_x[0] = x;
    return z;
  }
  Scalar operator[](Eigen::Index lag) const noexcept { return m_x[lag]; }

 private:
  Eigen::Index m_ni;
  Scalar m_x[2] = {Scalar(0), Scalar(0)};
};

}  // namespace bonl::detail
