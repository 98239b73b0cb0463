#pragma once
// Backlash (play) blocks of the P-H-W model (paper eqs. 10-12).
// - Backlash: the symmetric, unit-slope form used for identification, half-width c >= 0:
//     y(k) = x(k) - c if x(k) > y(k-1) + c;  x(k) + c if x(k) < y(k-1) - c;  else y(k-1).
// - GeneralBacklash: separate right/left thresholds and a slope m, for simulation (Fig. 9):
//     y(k) = m (x(k) - c_right) if m (x(k) - c_right) > y(k-1);
//            m (x(k) + c_left)  if m (x(k) + c_left)  < y(k-1);  else y(k-1).
// Both keep y(k-1) as their memory; they start engaged at a chosen output (default 0).

#include <cmath>
#include <string>

#include "../detail/validate.hpp"

namespace bonl {

/// Switching function g3 of the paper: 1 when the input pushes the upper edge, x > y_prev + c.
/// \param x the input x(k)
/// \param y_prev the previous output y(k-1)
/// \param c the half-width, >= 0
/// \return 1 or 0
template <typename Scalar>
constexpr Scalar backlash_g3(Scalar x, Scalar y_prev, Scalar c) noexcept {
  return y_prev + c < x ? Scalar(1) : Scalar(0);
}

/// Switching function g4 of the paper: 1 when the input pushes the lower edge, x < y_prev - c.
/// \param x the input x(k)
/// \param y_prev the previous output y(k-1)
/// \param c the half-width, >= 0
/// \return 1 or 0
template <typename Scalar>
constexpr Scalar backlash_g4(Scalar x, Scalar y_prev, Scalar c) noexcept {
  return y_prev - c > x ? Scalar(1) : Scalar(0);
}

/// The symmetric, unit-slope backlash of the P-H-W model (eqs. 10-12), half-width c >= 0: y(k) =
/// x(k) - c if x(k) > y(k-1) + c; x(k) + c if x(k) < y(k-1) - c; else y(k-1). Its memory is y(k-1);
/// it starts engaged at y0.
template <typename Scalar_ = double>
class Backlash {
 public:
  using Scalar = Scalar_;  ///< the arithmetic type

  /// A backlash of half-width c whose memory starts at y0; throws std::invalid_argument unless c is
  /// finite and >= 0.
  /// \param c the half-width, in the units of x
  /// \param y0 the memory y(-1)
  explicit Backlash(Scalar c = Scalar(0), Scalar y0 = Scalar(0)) : m_y(y0) { set_c(c); }

  Scalar c() const noexcept { return m_c; }  ///< the half-width c \return c, >= 0
  /// Sets the half-width; throws std::invalid_argument unless c is finite and >= 0.
  /// \param c the half-width, in the units of x
  void set_c(Scalar c) {
    detail::require(std::isfinite(c) && c >= Scalar(0),
                    "backlash half-width c must be finite and >= 0, got " + std::to_string(static_cast<double>(c)));
    m_c = c;
  }
  /// The memory y(k-1). \return the last output, or y0 before the first step
  Scalar output() const noexcept { return m_y; }
  /// Sets the memory y(k-1) to y0, as at the start.
  /// \param y0 the new memory
  void reset(Scalar y0 = Scalar(0)) noexcept { m_y = y0; }

  /// One sample: the output y(k) for the input x(k), which becomes the memory.
  /// \param x the input x(k)
  /// \return y(k)
  Scalar step(Scalar x) noexcept {
    m_y = map(x, m_y, m_c);
    return m_y;
  }

  /// One step of the play operator without state.
  /// \param x the input x(k)
  /// \param y_prev the previous output y(k-1)
  /// \param c the half-width, >= 0
  /// \return y(k)
  static Scalar map(Scalar x, Scalar y_prev, Scalar c) noexcept {
    if (x > y_prev + c) return x - c;
    if (x < y_prev - c) return x + c;
    return y_prev;
  }

 private:
  Scalar m_c = Scalar(0);
  Scalar m_y = Scalar(0);
};

/// The general backlash, for simulation (Fig. 9): separate left and right thresholds and a slope m:
/// y(k) = m (x(k) - c_right) if that is > y(k-1); m (x(k) + c_left) if that is < y(k-1); else y(k-1).
/// It starts engaged at y0.
template <typename Scalar_ = double>
class GeneralBacklash {
 public:
  using Scalar = Scalar_;  ///< the arithmetic type

  /// A backlash with the thresholds c_left, c_right (finite, >= 0), the slope m = slope (finite, > 0)
  /// and the memory y0; throws std::invalid_argument otherwise.
  /// \param c_left the left threshold, in the units of x
  /// \param c_right the right threshold, in the units of x
  /// \param slope the slope m
  /// \param y0 the memory y(-1)
  GeneralBacklash(Scalar c_left, Scalar c_right, Scalar slope = Scalar(1), Scalar y0 = Scalar(0))
      : m_c_left(c_left), m_c_right(c_right), m_slope(slope), m_y(y0) {
    detail::require(std::isfinite(c_left) && c_left >= Scalar(0), "c_left must be finite and >= 0");
    detail::require(std::isfinite(c_right) && c_right >= Scalar(0), "c_right must be finite and >= 0");
    detail::require(std::isfinite(slope) && slope > Scalar(0), "slope m must be finite and > 0");
    detail::require(std::isfinite(y0), "initial output y0 must be finite");
  }

  Scalar c_left() const noexcept { return m_c_left; }    ///< the left threshold c_left \return c_left, >= 0
  Scalar c_right() const noexcept { return m_c_right; }  ///< the right threshold c_right \return c_right, >= 0
  Scalar slope() const noexcept { return m_slope; }      ///< the slope m \return m, > 0
  /// The memory y(k-1)
  /// \return the last output, or y0 before the first step
  Scalar output() const noexcept { return m_y; }
  /// Sets the memory y(k-1) to y0, as at the start.
  /// \param y0 the new memory
  void reset(Scalar y0 = Scalar(0)) noexcept { m_y = y0; }

  /// One sample: the output y(k) for the input x(k), which becomes the memory.
  /// \param x the input x(k)
  /// \return y(k)
  Scalar step(Scalar x) noexcept {
    const Scalar up = m_slope * (x - m_c_right);
    const Scalar down = m_slope * (x + m_c_left);
    if (up > m_y) {
      m_y = up;
    } else if (down < m_y) {
      m_y = down;
    }
    return m_y;
  }

 private:
  Scalar m_c_left;
  Scalar m_c_right;
  Scalar m_slope;
  Scalar m_y;
};

}  // namespace bonl
