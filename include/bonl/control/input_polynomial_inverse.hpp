#pragma once
// Inverse of the two-segment input polynomial N1 (paper eqs. 3-5), w = f(u) for u >= 0 and g(u) for
// u < 0 (g = f + p): given the w the linear block needs, the command u in [u_min, u_max] (u_min <= 0 <=
// u_max, deviations from the operating point) that gives it.
//
// Each side is inverted on its monotone branch from u = 0 (up to the first stationary point or the
// command's limit; detail::branch_end): w in [f(0), f(hi)] is solved for u >= 0, w in [g(lo), g(0)]
// for u < 0 (g(0) itself by the smallest negative command, -denorm_min; a w within 1e-9 |f_0 - g_0| of
// f_0 or g_0 counts as it), by Newton's method safeguarded by bisection. What no command reaches is reported, not
// hidden:
// - Saturated: w beyond the branch ends; the command is the end nearer to w (u = hi or lo);
// - DeadBand: w between the two segments' values at 0, g_0 = f_0 + p_0 and f_0 (the jump of w at
//   u = 0, the model's dead band): the command is 0, which gives f_0.
// Both sides must run in the same direction (w increasing with u, or decreasing), else there is no
// inverse (a polynomial symmetric about 0, u^2, is not invertible): the constructor throws.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "../blocks/two_segment_polynomial.hpp"
#include "../detail/validate.hpp"
#include "detail/polynomial_branch.hpp"
#include "inverse_status.hpp"

namespace bonl::control {

/// The inverse of the two-segment input polynomial N1 (paper eqs. 3-5; bonl::TwoSegmentPolynomial):
/// given the w the linear block needs, the command u in [u_min, u_max] (deviations from the operating
/// point) that gives it. Each side is inverted on its monotone branch from u = 0, by Newton's method
/// safeguarded by bisection; what no command reaches is reported, not hidden: Saturated beyond the
/// branches' ends (the nearer end is the command), DeadBand between the two segments' values at u = 0
/// (the command is 0).
template <typename Scalar_ = double>
class InputPolynomialInverse {
 public:
  using Scalar = Scalar_;                                    ///< the arithmetic type
  using VectorX = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;  ///< a vector of run-time size

  /// The inverse of the polynomial with f and p (as TwoSegmentPolynomial) on a command range. Throws
  /// std::invalid_argument for f and p of different lengths or fewer than 2 entries, non-finite
  /// coefficients, a range that is not finite or leaves out 0, or a polynomial with no inverse: w
  /// rising with u on one side of 0 and falling on the other, or constant over the range.
  /// \param f f_0..f_r, the polynomial for u >= 0
  /// \param p p_0..p_r, added for u < 0
  /// \param u_min the command range's lower end, finite, <= 0 (a deviation from the operating point)
  /// \param u_max the command range's upper end, finite, >= 0
  template <typename F, typename P>
  InputPolynomialInverse(const Eigen::MatrixBase<F>& f, const Eigen::MatrixBase<P>& p, Scalar u_min, Scalar u_max)
      : m_f(f), m_g(f + p), m_u_min(u_min), m_u_max(u_max) {
    bonl::detail::require(f.size() >= 2 && p.size() == f.size(),
                          "the input polynomial's f and p must have the same length >= 2, got " +
                              std::to_string(f.size()) + " and " + std::to_string(p.size()));
    bonl::detail::require_finite(f, "f");
    bonl::detail::require_finite(p, "p");
    bonl::detail::require(std::isfinite(u_min) && std::isfinite(u_max) && u_min <= Scalar(0) && Scalar(0) <= u_max,
                          "the command range of an input polynomial's inverse must be finite and contain the "
                          "operating point (u_min <= u0 <= u_max), got [" +
                              bonl::detail::format_number(static_cast<double>(u_min)) + ", " +
                              bonl::detail::format_number(static_cast<double>(u_max)) + "] about u0");
    m_hi = u_max > Scalar(0) ? detail::branch_end(m_f, 1, u_max) : Scalar(0);
    m_lo = u_min < Scalar(0) ? detail::branch_end(m_g, -1, u_min) : Scalar(0);
    const Scalar rise_positive = detail::polynomial(m_f, m_hi) - m_f[0];
    const Scalar rise_negative = m_g[0] - detail::polynomial(m_g, m_lo);
    bonl::detail::require(!(rise_positive * rise_negative < Scalar(0)),
                          "the input polynomial has no inverse: w rises with u on one side of 0 and falls on the "
                          "other");
    bonl::detail::require(rise_positive != Scalar(0) || rise_negative != Scalar(0),
                          "the input polynomial has no inverse: it is constant over the command range");
    m_direction = (rise_positive + rise_negative) > Scalar(0) ? Scalar(1) : Scalar(-1);
  }

  /// The block's f and p (TwoSegmentPolynomial) and the command range, as above.
  /// \param block the input polynomial to invert
  /// \param u_min the command range's lower end, finite, <= 0
  /// \param u_max the command range's upper end, finite, >= 0
  template <int R>
  InputPolynomialInverse(const TwoSegmentPolynomial<Scalar, R>& block, Scalar u_min, Scalar u_max)
      : InputPolynomialInverse(block.f(), block.p(), u_min, u_max) {}

  /// The command for w: {u, status}. Exact when f(u) (u >= 0) or g(u) (u < 0) equals w to rounding.
  /// \param w the block's output the linear block needs
  /// \return the command u and its status (Exact, Saturated or DeadBand)
  InverseStep<Scalar> operator()(Scalar w) const noexcept {
    const Scalar s = m_direction;
    const Scalar at_hi = detail::polynomial(m_f, m_hi);
    const Scalar at_lo = detail::polynomial(m_g, m_lo);
    // A w within 1e-9 of the dead band's width of a segment's end at 0 is that end: the linear
    // inverse's rounding (of a reference resting there, or offset by y0) is not the dead band.
    const Scalar snap = Scalar(1e-9) * std::abs(m_f[0] - m_g[0]);
    if (s * w >= s * m_f[0] - snap && s * w <= s * at_hi) {
      if (s * w <= s * m_f[0]) return {Scalar(0), InverseStatus::Exact};
      return {detail::solve_on_branch(m_f, w, Scalar(0), m_hi), InverseStatus::Exact};
    }
    // g(0) is reached by u -> 0 from below: the smallest negative command.
    if (m_lo < Scalar(0) && s * w >= s * at_lo && s * w <= s * m_g[0] + snap) {
      const Scalar u = s * w >= s * m_g[0] ? Scalar(0) : detail::solve_on_branch(m_g, w, m_lo, Scalar(0));
      return {std::min(u, -std::numeric_limits<Scalar>::denorm_min()), InverseStatus::Exact};
    }
    if (s * w > s * at_hi && s * w >= s * m_g[0]) return {m_hi, InverseStatus::Saturated};
    if (s * w < s * at_lo && s * w < s * m_f[0]) return {m_lo, InverseStatus::Saturated};
    return {Scalar(0), InverseStatus::DeadBand};
  }

  /// The w the command u gives (TwoSegmentPolynomial::evaluate's arithmetic).
  /// \param u the command, a deviation from the operating point
  /// \return w
  Scalar output(Scalar u) const noexcept { return detail::polynomial(u < Scalar(0) ? m_g : m_f, u); }
  /// The polynomial has no memory: nothing to advance, reset or take over (InverseModel calls these
  /// on every input block's inverse).
  void advance(Scalar /*u*/) noexcept {}
  void reset() noexcept {}                                                    ///< nothing to reset (see advance())
  void continue_from(const InputPolynomialInverse& /*previous*/) noexcept {}  ///< nothing to take over (see advance())

  /// The monotone branches the inverse uses: commands [lower(), upper()] (the command range, or
  /// nearer where a side stops being monotone).
  /// \return the lowest command used, <= 0
  Scalar lower() const noexcept { return m_lo; }
  /// The commands' upper end (see lower())
  /// \return the highest command used, >= 0
  Scalar upper() const noexcept { return m_hi; }
  /// The w no command reaches between the two segments at u = 0: [min, max] of g_0 and f_0.
  /// \return min(g_0, f_0)
  Scalar dead_band_lower() const noexcept { return std::min(m_f[0], m_g[0]); }
  /// See dead_band_lower()
  /// \return max(g_0, f_0)
  Scalar dead_band_upper() const noexcept { return std::max(m_f[0], m_g[0]); }

 private:
  VectorX m_f;  // f_0..f_r: u >= 0
  VectorX m_g;  // g_0..g_r = f + p: u < 0
  Scalar m_u_min, m_u_max;
  Scalar m_lo = Scalar(0), m_hi = Scalar(0);
  Scalar m_direction = Scalar(1);
};

}  // namespace bonl::control
