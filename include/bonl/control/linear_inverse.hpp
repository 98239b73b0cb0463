#pragma once
// Inverse of the linear block A(q^-1) x(k) = q^-nk B(q^-1) w(k) (paper eqs. 6-8; bonl::LinearBlock):
// the w(k) that makes x(k + nk) follow a reference x_d. Two forms, chosen by B's zeros:
//
// - Minimum phase (every zero of B inside the unit circle, the Schur-Cohn test detail::roots_inside):
//   the exact inverse, one sample ahead of the delay,
//     w(k) = (x_d(k+nk) + sum_j a_j x(k+nk-j) - sum_{i>=1} b_i w(k-i)) / b_0,
//   with x the block's own x, run on the w it was actually given (commit()): when nothing limits w,
//   x(k+nk) = x_d(k+nk) exactly; after a limited w (a saturated command) it aims at the reference
//   again from where the block is, with no wind-up. Stable because 1/B is.
// - Not minimum phase (a zero on or outside the unit circle, where 1/B is unstable): the zero-phase
//   error tracking controller (ZPETC, Tomizuka 1987). B = B_a B_u with B_a's zeros inside (b_0 in B_a)
//   and B_u = prod (1 - z_i q^-1) over the others, of degree s; B_u* its coefficients reversed. Then
//     w(k) = A(q^-1) B_u*(q^-1) x_d(k+nk+s) / (B_a(q^-1) B_u(1)^2),
//   which needs s samples of preview beyond the delay, and gives
//     x(k) = B_u(q^-1) B_u(q) / B_u(1)^2 x_d(k):
//   a zero-phase filter of the reference with unit gain at frequency 0 (steps and ramps are tracked
//   without lag; the gain |B_u(e^jw)|^2 / B_u(1)^2 falls or rises with frequency). A zero at z = 1
//   (B_u(1) = 0) leaves no such inverse: the constructor throws.
//
// Per sample: input(window) gives w(k) from the window x_d(k+nk), ..., x_d(k+nk+s) (window_size() =
// s + 1 entries), then commit(x_d(k+nk), w) stores what was applied. Allocation-free after construction.

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include "../detail/history.hpp"
#include "../detail/stability.hpp"
#include "../detail/validate.hpp"

namespace bonl::control {

/// The inverse of the linear block A(q^-1) x(k) = q^-nk B(q^-1) w(k) (paper eqs. 6-8; bonl::LinearBlock):
/// the w(k) that makes x(k + nk) follow a reference x_d. Where B is minimum phase, the exact inverse,
/// run on the w actually applied so that a limited command does not wind up; otherwise the zero-phase
/// error tracking controller (ZPETC, Tomizuka 1987), which needs preview() samples of the reference
/// beyond the delay and tracks it through a zero-phase filter of unit gain at frequency 0. Per sample:
/// input() for the reference window, then commit() what was applied. Allocation-free after construction.
template <typename Scalar_ = double>
class LinearInverse {
 public:
  using Scalar = Scalar_;                                    ///< the arithmetic type
  using VectorX = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;  ///< a vector of run-time size

  /// The inverse of the block with the given coefficients and delay. Throws std::invalid_argument for an
  /// empty or non-finite a or b, nk < 0, b_0 = 0, or (not minimum phase) a zero of B at z = 1, which
  /// leaves no ZPETC, or zeros that cannot be computed.
  /// \param a a_1..a_na
  /// \param b b_0..b_nb, b_0 != 0
  /// \param nk the delay in samples, >= 0
  template <typename A, typename B>
  LinearInverse(const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<B>& b, Eigen::Index nk)
      : m_a(a), m_b(b), m_nk(nk) {
    bonl::detail::require(a.size() >= 1 && b.size() >= 1, "the linear block needs a_1..a_na and b_0..b_nb");
    bonl::detail::require_finite(a, "a");
    bonl::detail::require_finite(b, "b");
    bonl::detail::require_order(nk, 0, "nk");
    bonl::detail::require(b[0] != Scalar(0),
                          "the linear block has no inverse: b_0 (B's leading coefficient) is 0, so w(k) does not "
                          "reach x(k + nk); the delay is longer than nk");
    const Eigen::Index nb = b.size() - 1;
    VectorX work(nb);
    m_minimum_phase = bonl::detail::roots_inside(VectorX(b.tail(nb) / b[0]), Scalar(1), work);
    if (m_minimum_phase) {
      m_x = bonl::detail::History<Scalar>(a.size());
      m_w = bonl::detail::History<Scalar>(nb);
    } else {
      split_zeros();
      m_x = bonl::detail::History<Scalar>(m_numerator.size() - 1 - preview());
      m_w = bonl::detail::History<Scalar>(m_stable.size() - 1);
    }
  }

  /// Are all of B's zeros inside the unit circle (the exact inverse), or is this ZPETC?
  /// \return true for the exact inverse, false for ZPETC
  bool minimum_phase() const noexcept { return m_minimum_phase; }
  Eigen::Index nk() const noexcept { return m_nk; }  ///< the delay nk in samples \return nk, >= 0
  /// Samples of preview beyond the delay: 0 (exact), s = B_u's degree (ZPETC).
  /// \return the preview beyond nk in samples, >= 0
  Eigen::Index preview() const noexcept { return m_minimum_phase ? 0 : m_unstable.size() - 1; }
  /// The reference window's length: x_d(k+nk), ..., x_d(k+nk+preview()).
  /// \return preview() + 1
  Eigen::Index window_size() const noexcept { return preview() + 1; }
  /// ZPETC's factors: B_a (b_0 included) and B_u, ascending powers of q^-1 (B_u = [1] and B_a = B
  /// when minimum phase).
  /// \return B_a's coefficients
  VectorX stable_factor() const { return m_minimum_phase ? m_b : m_stable; }
  /// ZPETC's factor B_u, the zeros on or outside the unit circle (see stable_factor()).
  /// \return B_u's coefficients, B_u_0 = 1
  VectorX unstable_factor() const { return m_minimum_phase ? VectorX::Ones(1) : m_unstable; }

  /// Back to rest: every past x and w zero.
  void reset() noexcept {
    m_x.clear();
    m_w.clear();
  }

  /// Goes on from where `previous` is instead of from rest: its newest stored x and w, as many of
  /// each as both keep (an adaptive inverse re-derived from a new estimate; where one inverse is
  /// exact and the other ZPETC, the stored x are the block's in one and the reference's in the other,
  /// which differ by the tracking error).
  /// \param previous the inverse to go on from
  void continue_from(const LinearInverse& previous) noexcept {
    copy_newest(m_x, previous.m_x);
    copy_newest(m_w, previous.m_w);
  }

  /// w(k) for the reference window (at least window_size() entries; window[0] = x_d(k+nk)).
  /// \param window x_d(k+nk), ..., x_d(k+nk+preview())
  /// \return w(k)
  template <typename W>
  Scalar input(const Eigen::MatrixBase<W>& window) const noexcept {
    if (m_minimum_phase) {
      Scalar v = window[0];
      for (Eigen::Index j = 0; j < m_a.size(); ++j) v += m_a[j] * m_x[j];
      for (Eigen::Index i = 1; i < m_b.size(); ++i) v -= m_b[i] * m_w[i - 1];
      return v / m_b[0];
    }
    // v = (A B_u*)(q^-1) x_d(k+nk+s) / B_u(1)^2: window entries ahead, stored references behind.
    const Eigen::Index s = preview();
    Scalar v = Scalar(0);
    for (Eigen::Index m = 0; m < m_numerator.size(); ++m) {
      const Eigen::Index ahead = s - m;
      v += m_numerator[m] * (ahead >= 0 ? window[ahead] : m_x[-ahead - 1]);
    }
    for (Eigen::Index i = 1; i < m_stable.size(); ++i) v -= m_stable[i] * m_w[i - 1];
    return v / m_stable[0];
  }

  /// Stores the step: x_d(k+nk) (window[0]) and the w(k) actually applied.
  /// \param x_reference x_d(k+nk), the window's first entry
  /// \param w the w(k) actually applied
  /// \return false, storing nothing, where w or the x it gives is not finite (a reference beyond the
  /// arithmetic's range); else true
  bool commit(Scalar x_reference, Scalar w) noexcept {
    Scalar x = x_reference;
    if (m_minimum_phase) {
      x = m_b[0] * w;
      for (Eigen::Index i = 1; i < m_b.size(); ++i) x += m_b[i] * m_w[i - 1];
      for (Eigen::Index j = 0; j < m_a.size(); ++j) x -= m_a[j] * m_x[j];
    }
    if (!std::isfinite(x) || !std::isfinite(w)) return false;
    m_x.push(x);
    m_w.push(w);
    return true;
  }

 private:
  static void copy_newest(bonl::detail::History<Scalar>& to, const bonl::detail::History<Scalar>& from) noexcept {
    to.clear();
    for (Eigen::Index lag = std::min(to.capacity(), from.capacity()) - 1; lag >= 0; --lag) to.push(from[lag]);
  }

  /// B = B_a B_u by B's zeros (the eigenvalues of its companion matrix); the ZPETC numerator
  /// A B_u* / B_u(1)^2.
  void split_zeros() {
    using Complex = std::complex<Scalar>;
    const Eigen::Index nb = m_b.size() - 1;
    Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> companion =
        Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>::Zero(nb, nb);
    for (Eigen::Index i = 0; i < nb; ++i) companion(0, i) = -m_b[i + 1] / m_b[0];
    for (Eigen::Index i = 1; i < nb; ++i) companion(i, i - 1) = Scalar(1);
    Eigen::EigenSolver<decltype(companion)> solver(companion, false);
    bonl::detail::require(solver.info() == Eigen::Success, "the zeros of B could not be computed");
    std::vector<Complex> stable{Complex(m_b[0])};
    std::vector<Complex> unstable{Complex(1)};
    const auto multiply = [](std::vector<Complex>& poly, Complex zero) {  // poly *= (1 - zero q^-1)
      poly.push_back(Complex(0));
      for (std::size_t i = poly.size() - 1; i >= 1; --i) poly[i] -= zero * poly[i - 1];
    };
    for (Eigen::Index i = 0; i < nb; ++i) {
      const Complex zero = solver.eigenvalues()[i];
      multiply(std::abs(zero) < Scalar(1) ? stable : unstable, zero);
    }
    m_stable.resize(static_cast<Eigen::Index>(stable.size()));
    for (std::size_t i = 0; i < stable.size(); ++i) m_stable[static_cast<Eigen::Index>(i)] = stable[i].real();
    m_unstable.resize(static_cast<Eigen::Index>(unstable.size()));
    for (std::size_t i = 0; i < unstable.size(); ++i) m_unstable[static_cast<Eigen::Index>(i)] = unstable[i].real();
    const Scalar gain = m_unstable.sum();  // B_u(1)
    bonl::detail::require(std::abs(gain) > Scalar(1e-8) * m_unstable.cwiseAbs().sum(),
                          "the linear block has no stable inverse: B has a zero at z = 1 (no gain at frequency 0)");
    // A(q^-1) B_u*(q^-1), B_u* = B_u reversed; divided by B_u(1)^2.
    const Eigen::Index s = m_unstable.size() - 1;
    VectorX a_full(m_a.size() + 1);
    a_full << Scalar(1), m_a;
    m_numerator = VectorX::Zero(a_full.size() + s);
    for (Eigen::Index i = 0; i < a_full.size(); ++i) {
      for (Eigen::Index j = 0; j <= s; ++j) m_numerator[i + j] += a_full[i] * m_unstable[s - j];
    }
    m_numerator /= gain * gain;
  }

  VectorX m_a, m_b;
  Eigen::Index m_nk;
  bool m_minimum_phase = true;
  VectorX m_stable, m_unstable, m_numerator;  // ZPETC only
  bonl::detail::History<Scalar> m_x;          // exact: the block's x(k+nk-j); ZPETC: x_d(k+nk-j)
  bonl::detail::History<Scalar> m_w;          // w(k-i) applied
};

}  // namespace bonl::control
