#pragma once
// Linear dynamic block L of the models (paper eqs. 6-8), with the sign convention of eq. (7):
//   A(z^-1) x(k) = z^-nk B(z^-1) w(k),  A = 1 + a_1 z^-1 + ... + a_na z^-na,
//   B = b_0 + b_1 z^-1 + ... + b_nb z^-nb,
// i.e. x(k) = -sum_j a_j x(k-j) + sum_i b_i w(k-nk-i). With ni integrators (detail/integrators.hpp)
// the denominator is A(z^-1) (1 - z^-1)^ni: the recursion runs on z = (1 - z^-1)^ni x and x carries
// the integrators' past. The block starts at rest: every past w and x is zero.

#include <Eigen/Core>

#include "../detail/history.hpp"
#include "../detail/integrators.hpp"
#include "../detail/validate.hpp"

namespace bonl {

/// The linear dynamic block L of the models (eqs. 6-8): A(z^-1) x(k) = z^-nk B(z^-1) w(k), i.e.
/// x(k) = -sum_j a_j x(k-j) + sum_i b_i w(k-nk-i), with ni integrators in the denominator
/// A(z^-1) (1 - z^-1)^ni. Na_, Nb_ fix na, nb at compile time. It starts at rest.
template <typename Scalar_ = double, int Na_ = Eigen::Dynamic, int Nb_ = Eigen::Dynamic>
class LinearBlock {
 public:
  using Scalar = Scalar_;                                            ///< the arithmetic type
  using ACoeffs = Eigen::Matrix<Scalar, Na_, 1>;                     ///< a_1..a_na (fixed size when Na_ is)
  using BCoeffs = Eigen::Matrix<Scalar, detail::poly_size(Nb_), 1>;  ///< b_0..b_nb (fixed size when Nb_ is)

  /// A block at rest with a = 0, b = [1, 0...]. Throws std::invalid_argument for an order out of range
  /// or one that differs from the compile-time order.
  /// \param na estimated poles, >= 1
  /// \param nb b has nb + 1 coefficients, >= 0
  /// \param nk pure delay in samples, >= 0
  /// \param ni integrators (poles fixed at 1), 0..2
  LinearBlock(Eigen::Index na, Eigen::Index nb, Eigen::Index nk, Eigen::Index ni = 0) : m_nk(nk), m_integrators(ni) {
    detail::require_order(na, 1, "na");
    detail::require_order(nb, 0, "nb");
    detail::require_order(nk, 0, "nk");
    detail::require_integrators(ni);
    detail::require_matches_template(na, Na_, "na");
    detail::require_matches_template(nb, Nb_, "nb");
    m_a = ACoeffs::Zero(na);
    m_b = BCoeffs::Zero(nb + 1);
    m_b[0] = Scalar(1);
    m_w = detail::History<Scalar>(nk + nb + 1);
    m_z = detail::History<Scalar>(na);
  }

  Eigen::Index na() const noexcept { return m_a.size(); }  ///< the order na: estimated poles \return na, >= 1
  /// The order nb: b has nb + 1 coefficients
  /// \return nb, >= 0
  Eigen::Index nb() const noexcept { return m_b.size() - 1; }
  Eigen::Index nk() const noexcept { return m_nk; }  ///< the pure delay nk in samples \return nk, >= 0
  /// The integrators ni (poles fixed at 1)
  /// \return ni, 0..2
  Eigen::Index ni() const noexcept { return m_integrators.size(); }
  /// The estimated denominator a_1..a_na (without the integrators).
  /// \return na values
  const ACoeffs& a() const noexcept { return m_a; }
  /// The whole denominator a_1..a_{na+ni} of A(z^-1) (1 - z^-1)^ni.
  /// \return na + ni values
  Eigen::Matrix<Scalar, Eigen::Dynamic, 1> denominator() const { return detail::with_integrators(m_a, ni()); }
  const BCoeffs& b() const noexcept { return m_b; }  ///< the numerator b_0..b_nb \return nb + 1 values

  /// Sets a_1..a_na (na finite values, else std::invalid_argument).
  /// \param a a_1..a_na
  template <typename A>
  void set_a(const Eigen::MatrixBase<A>& a) {
    detail::assign_checked(m_a, a, "a");
  }
  /// Sets b_0..b_nb (nb + 1 finite values, else std::invalid_argument).
  /// \param b b_0..b_nb
  template <typename B>
  void set_b(const Eigen::MatrixBase<B>& b) {
    detail::assign_checked(m_b, b, "b");
  }

  /// Back to rest.
  void reset() noexcept {
    m_w.clear();
    m_z.clear();
    m_integrators.clear();
  }

  /// One sample of the block.
  /// \param w the input w(k)
  /// \return the output x(k)
  Scalar step(Scalar w) noexcept {
    m_w.push(w);
    Scalar x = Scalar(0);
    for (Eigen::Index i = 0; i < m_b.size(); ++i) x += m_b[i] * m_w[m_nk + i];
    for (Eigen::Index j = 0; j < m_a.size(); ++j) x -= m_a[j] * m_z[j];
    if (m_integrators.size() > 0) x += m_integrators.carried();
    m_z.push(m_integrators.push(x));
    return x;
  }

 private:
  ACoeffs m_a;
  BCoeffs m_b;
  Eigen::Index m_nk;
  detail::History<Scalar> m_w;
  detail::History<Scalar> m_z;  // z(k-1..k-na); x itself where there are no integrators
  detail::IntegratorLags<Scalar> m_integrators;
};

}  // namespace bonl
