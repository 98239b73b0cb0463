#pragma once
// Inverse of the P-H-W model's backlash (paper eqs. 10-12; bonl::Backlash, half-width c), after Tao
// and Kokotovic's backlash inverse: to make the output follow y_d, drive its input to
//   x = y_d + c  while y_d rises (the upper edge pushes the output),
//   x = y_d - c  while y_d falls (the lower edge),
// x = y_d + c s in general, s = +1 rising and -1 falling. The direction is the reference's: it turns
// when y_d has come back from its last extremum by the transition band `band` >= 0. Inside the band
// s moves from one side to the other along a smooth step, s = +-(1 - 2 S(t)), t = (distance from the
// extremum) / band, S(t) = t^2 (3 - 2 t), continuous with its slope: noise on the reference smaller than
// the band moves the command a little (quadratically in the noise) instead of throwing it by 2c at
// every reversal of the noise (the chatter of the exact switch).
//
// band = 0 is the exact switch: with the backlash's memory on the reference (y(k-1) = y_d(k-1), as
// when tracking from rest at the operating point), Backlash::step(x) == y_d for every sample. With a
// band, the output holds at the extremum while the reference comes back by less than the band after
// a reversal (an error of at most the band) and follows exactly after it. At the start the direction
// is not known (the model rests inside its gap): s = sign(y_d - y_0) S(|y_d - y_0| / band) until the
// reference first leaves y_0 by the band (band = 0: as soon as it moves), x = y_d while it rests.

#include <cmath>
#include <string>

#include "../detail/validate.hpp"

namespace bonl::control {

/// The inverse of the P-H-W model's backlash (bonl::Backlash, half-width c), after Tao and
/// Kokotovic: the backlash input x = y_d + c s that makes its output follow the reference y_d, s = +1
/// while y_d rises and -1 while it falls. The direction turns when y_d has come back from its last
/// extremum by the transition band; inside the band s moves between the sides along a smooth step, so
/// that noise smaller than the band does not throw the command by 2c at each of its reversals.
/// band = 0 is the exact switch.
template <typename Scalar_ = double>
class BacklashInverse {
 public:
  using Scalar = Scalar_;  ///< the arithmetic type

  /// The reference's direction and its last extremum: the whole state.
  struct State {
    int direction = 0;            ///< +1 rising, -1 falling, 0 not moved yet
    Scalar extremum = Scalar(0);  ///< the reference's last extremum (its start value before it moved)
  };

  /// The inverse at the start. Throws std::invalid_argument unless c and band are finite and >= 0 and
  /// y0 is finite.
  /// \param c the backlash's half-width, in the output's units, >= 0
  /// \param band the transition band, in the output's units, >= 0 (0: the exact switch)
  /// \param y0 the backlash's output at the start
  explicit BacklashInverse(Scalar c, Scalar band = Scalar(0), Scalar y0 = Scalar(0)) : m_c(c), m_band(band) {
    bonl::detail::require(std::isfinite(c) && c >= Scalar(0),
                          "the backlash half-width c must be finite and >= 0, got " +
                              bonl::detail::format_number(static_cast<double>(c)));
    bonl::detail::require(std::isfinite(band) && band >= Scalar(0),
                          "the backlash inverse's transition band must be finite and >= 0, got " +
                              bonl::detail::format_number(static_cast<double>(band)));
    bonl::detail::require_finite(static_cast<double>(y0), "the backlash's initial output y0");
    reset(y0);
  }

  Scalar c() const noexcept { return m_c; }        ///< the backlash's half-width c \return c, >= 0
  Scalar band() const noexcept { return m_band; }  ///< the transition band (0: the exact switch) \return the band, >= 0
  /// The reference's direction and last extremum, to carry over with continue_from().
  /// \return the state
  const State& state() const noexcept { return m_state; }
  /// Goes on from `state` (another inverse's, for one re-derived with a new c or band).
  /// \param state the state to go on from
  void continue_from(const State& state) noexcept { m_state = state; }
  /// Back to the start: the output at rest at y0, direction unknown.
  /// \param y0 the backlash's output at the start
  void reset(Scalar y0 = Scalar(0)) noexcept { m_state = State{0, y0}; }

  /// The backlash input for the reference y_d; advances the direction.
  /// \param y_d the reference output y_d(k)
  /// \return the backlash input x(k)
  Scalar step(Scalar y_d) noexcept { return map(y_d, m_state); }
  /// The same without advancing: the input for y_d from the current state.
  /// \param y_d the reference output y_d(k)
  /// \return the backlash input x(k)
  Scalar peek(Scalar y_d) const noexcept {
    State state = m_state;
    return map(y_d, state);
  }

  /// One step of the inverse on `state`.
  /// \param y_d the reference output y_d(k)
  /// \param state the direction and extremum, advanced
  /// \return the backlash input x(k)
  Scalar map(Scalar y_d, State& state) const noexcept {
    const Scalar away = y_d - state.extremum;  // > 0 above the extremum
    Scalar s;
    if (state.direction == 0) {
      const Scalar t = fraction(std::abs(away));
      s = (away > Scalar(0) ? Scalar(1) : Scalar(-1)) * smooth_step(t);
      if (t >= Scalar(1)) state = State{away > Scalar(0) ? 1 : -1, y_d};
      if (away == Scalar(0)) s = Scalar(0);
    } else {
      const Scalar d = Scalar(state.direction);
      if (d * away >= Scalar(0)) {  // further along the direction: a new extremum
        state.extremum = y_d;
        s = d;
      } else {
        const Scalar t = fraction(-d * away);
        s = d * (Scalar(1) - Scalar(2) * smooth_step(t));
        if (t >= Scalar(1)) state = State{-state.direction, y_d};
      }
    }
    return y_d + m_c * s;
  }

 private:
  /// distance / band, at least 1 beyond the band (band 0: any distance > 0 is beyond).
  Scalar fraction(Scalar distance) const noexcept {
    if (m_band == Scalar(0)) return distance > Scalar(0) ? Scalar(1) : Scalar(0);
    return distance >= m_band ? Scalar(1) : distance / m_band;
  }
  static Scalar smooth_step(Scalar t) noexcept { return t * t * (Scalar(3) - Scalar(2) * t); }

  Scalar m_c;
  Scalar m_band;
  State m_state;
};

}  // namespace bonl::control
