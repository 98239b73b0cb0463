#pragma once
// Input block N1 of the Hammerstein-type models (paper eqs. 3-5): a polynomial of degree r for
// u >= 0 and another for u < 0, written as w = sum_l f_l u^l + h(u) sum_l p_l u^l with the
// switching function h(u) = 1 for u < 0, else 0, and p_l = g_l - f_l.
// The overloads with a range [low, high] continue the block linearly beyond it (linear_continuation.hpp),
// from the segment at the edge passed.

#include <Eigen/Core>
#include <string>

#include "../detail/validate.hpp"
#include "linear_continuation.hpp"

namespace bonl {

/// Switching function h(u) of eq. (4): 1 on the negative side, 0 for u >= 0.
/// \param u the input
/// \return 1 for u < 0, else 0
template <typename Scalar>
constexpr Scalar input_switch(Scalar u) noexcept {
  return u < Scalar(0) ? Scalar(1) : Scalar(0);
}

/// The input block N1 of the Hammerstein-type models (eqs. 3-5): a polynomial of degree r for u >= 0
/// and another for u < 0, w = sum_l f_l u^l + h(u) sum_l p_l u^l with h(u) = 1 for u < 0, else 0.
template <typename Scalar_ = double, int R_ = Eigen::Dynamic>
class TwoSegmentPolynomial {
 public:
  using Scalar = Scalar_;                                ///< the arithmetic type
  static constexpr int kCoeffs = detail::poly_size(R_);  ///< r + 1 coefficients per segment (Eigen::Dynamic when R_ is)
  static constexpr int kBasisSize =
      kCoeffs == Eigen::Dynamic ? Eigen::Dynamic : 2 * kCoeffs;  ///< the regressor's length, f's and p's: 2 (r + 1)
  using Coeffs = Eigen::Matrix<Scalar, kCoeffs, 1>;              ///< f_0..f_r or p_0..p_r

  /// All coefficients zero. Throws std::invalid_argument for a degree below 1 or one that differs from
  /// R_.
  /// \param r the degree of each segment, >= 1
  explicit TwoSegmentPolynomial(Eigen::Index r = (R_ == Eigen::Dynamic ? 1 : R_)) {
    detail::require_order(r, 1, "r (input polynomial degree)");
    detail::require_matches_template(r, R_, "r");
    m_f = Coeffs::Zero(r + 1);
    m_p = Coeffs::Zero(r + 1);
  }

  /// The block with the given coefficients, of equal length r + 1 >= 2, finite (else
  /// std::invalid_argument).
  /// \param f f_0..f_r, the polynomial for u >= 0
  /// \param p p_0..p_r = g_l - f_l, added for u < 0
  template <typename F, typename P>
  TwoSegmentPolynomial(const Eigen::MatrixBase<F>& f, const Eigen::MatrixBase<P>& p)
      : TwoSegmentPolynomial(degree_of(f)) {
    set_f(f);
    set_p(p);
  }

  Eigen::Index degree() const noexcept { return m_f.size() - 1; }  ///< the degree r \return r, >= 1
  const Coeffs& f() const noexcept { return m_f; }  ///< f_0..f_r, the polynomial for u >= 0 \return r + 1 values
  const Coeffs& p() const noexcept { return m_p; }  ///< p_0..p_r = g_l - f_l, added for u < 0 \return r + 1 values
  /// Coefficients of the negative-side polynomial, g_l = f_l + p_l.
  /// \return g_0..g_r
  Coeffs g() const { return m_f + m_p; }

  /// Sets f_0..f_r (r + 1 finite values, else std::invalid_argument).
  /// \param f f_0..f_r
  template <typename F>
  void set_f(const Eigen::MatrixBase<F>& f) {
    detail::assign_checked(m_f, f, "f");
  }
  /// Sets p_0..p_r (r + 1 finite values, else std::invalid_argument).
  /// \param p p_0..p_r
  template <typename P>
  void set_p(const Eigen::MatrixBase<P>& p) {
    detail::assign_checked(m_p, p, "p");
  }

  /// The output w for the input u.
  /// \param u the input
  /// \return w
  Scalar operator()(Scalar u) const noexcept { return evaluate(m_f, m_p, u); }

  /// w for coefficient vectors f and p of equal length (Horner's scheme).
  /// \param f f_0..f_r
  /// \param p p_0..p_r
  /// \param u the input
  /// \return w
  template <typename F, typename P>
  static Scalar evaluate(const Eigen::MatrixBase<F>& f, const Eigen::MatrixBase<P>& p, Scalar u) noexcept {
    Scalar w = Scalar(0);
    if (u < Scalar(0)) {
      for (Eigen::Index l = f.size() - 1; l >= 0; --l) w = w * u + (f[l] + p[l]);
    } else {
      for (Eigen::Index l = f.size() - 1; l >= 0; --l) w = w * u + f[l];
    }
    return w;
  }

  /// w continued linearly beyond [low, high] (the file's header): evaluate(f, p, u) inside, and
  /// N(e) + N'(e) (u - e) beyond the edge e it passed, N the segment at e. An infinite range is
  /// evaluate(f, p, u) everywhere.
  /// \param f f_0..f_r
  /// \param p p_0..p_r
  /// \param u the input
  /// \param low the range's low end (-inf: none)
  /// \param high the range's high end (inf: none)
  /// \return w
  template <typename F, typename P>
  static Scalar evaluate(const Eigen::MatrixBase<F>& f, const Eigen::MatrixBase<P>& p, Scalar u, Scalar low,
                         Scalar high) noexcept {
    if (!detail::beyond_range(u, low, high)) return evaluate(f, p, u);
    const Scalar edge = u > high ? high : low;
    const bool negative = edge < Scalar(0);
    Scalar w = Scalar(0), slope = Scalar(0);
    for (Eigen::Index l = f.size() - 1; l >= 0; --l) {  // Horner's scheme for N and N' together
      slope = slope * edge + w;
      w = w * edge + (negative ? f[l] + p[l] : f[l]);
    }
    return w + slope * (u - edge);
  }

  /// The key-term regressor of the block: [1, u, ..., u^r, h, h u, ..., h u^r], so that
  /// w = basis . [f; p]. `out` must have 2 (r + 1) entries.
  /// \param u the input
  /// \param r the degree
  /// \param out set to the regressor
  template <typename Out>
  static void basis(Scalar u, Eigen::Index r, Eigen::MatrixBase<Out>& out) noexcept {
    const Scalar h = input_switch(u);
    Scalar power = Scalar(1);
    for (Eigen::Index l = 0; l <= r; ++l) {
      out[l] = power;
      out[r + 1 + l] = h * power;
      power *= u;
    }
  }

  /// The regressor of the block continued linearly beyond [low, high]: inside, basis(u, f, p, out);
  /// beyond the edge e, [c_0..c_r, h(e) c_0..h(e) c_r] with c_l = e^l + l e^(l-1) (u - e), so that
  /// basis . [f; p] = evaluate(f, p, u, low, high). Returns that w.
  /// \param u the input
  /// \param f f_0..f_r
  /// \param p p_0..p_r
  /// \param out set to the regressor, 2 (r + 1) entries
  /// \param low the range's low end (-inf: none)
  /// \param high the range's high end (inf: none)
  /// \return w
  template <typename Out, typename F, typename P>
  static Scalar basis(Scalar u, const Eigen::MatrixBase<F>& f, const Eigen::MatrixBase<P>& p,
                      Eigen::MatrixBase<Out>& out, Scalar low, Scalar high) noexcept {
    if (!detail::beyond_range(u, low, high)) return basis(u, f, p, out);
    const Eigen::Index r = f.size() - 1;
    const Scalar h = input_switch(u > high ? high : low);  // the segment at the edge
    detail::continued_powers(u, r, low, high, out);
    Scalar w = Scalar(0);
    for (Eigen::Index l = 0; l <= r; ++l) {
      out[r + 1 + l] = h * out[l];
      w += out[l] * (f[l] + h * p[l]);
    }
    return w;
  }

  /// basis() and, returned, w = basis . [f; p] summed as the entries are made (f, p of length
  /// r + 1): an estimator needs both, and reading `out` back would stall on store forwarding.
  /// \param u the input
  /// \param f f_0..f_r
  /// \param p p_0..p_r
  /// \param out set to the regressor, 2 (r + 1) entries
  /// \return w
  template <typename Out, typename F, typename P>
  static Scalar basis(Scalar u, const Eigen::MatrixBase<F>& f, const Eigen::MatrixBase<P>& p,
                      Eigen::MatrixBase<Out>& out) noexcept {
    const Eigen::Index r = f.size() - 1;
    const Scalar h = input_switch(u);
    Scalar power = Scalar(1);
    Scalar w = Scalar(0);
    for (Eigen::Index l = 0; l <= r; ++l) {
      out[l] = power;
      out[r + 1 + l] = h * power;
      w += power * (f[l] + h * p[l]);
      power *= u;
    }
    return w;
  }

 private:
  /// The degree that f's length implies, r = f.size() - 1, which must be >= 1.
  template <typename F>
  static Eigen::Index degree_of(const Eigen::MatrixBase<F>& f) {
    detail::require(f.size() >= 2,
                    "f must have at least 2 entries (f_0..f_r, degree r >= 1), got " + std::to_string(f.size()));
    return f.size() - 1;
  }

  Coeffs m_f;
  Coeffs m_p;
};

}  // namespace bonl
