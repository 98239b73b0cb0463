#pragma once
// The play operators of a Prandtl-Ishlinskii (PI) operator, H[v](k) = sum_i g_i play_{r_i}[v](k):
//   play_r[v](k) = min(max(P_r(k-1), v(k) - r), v(k) + r),   P_r = 0 at rest,
// the backlash of half-width r (Backlash::map) started engaged at 0. The input v is a deviation from
// the operating point, so "at rest" is v = 0 with every play at 0. The thresholds r_1 < ... < r_np are
// structure: fixed, finite, > 0 (a threshold of 0 is the identity, which the model's linear term
// f_1 u already is). For fixed thresholds H is linear in the weights g, so the plays' values are
// regressors, as a polynomial's powers are. The plays are homogeneous of degree one,
// play_{s r}[s v] = s play_r[v] for s > 0, so in other units they are the same plays with their
// thresholds scaled as v.
// Np: the number of plays fixed at compile time (the state is then a fixed-size vector), or
// Eigen::Dynamic (sized at construction); a step never allocates.

#include <Eigen/Core>

#include <cmath>
#include <string>

#include "../detail/validate.hpp"
#include "backlash.hpp"

namespace bonl {

/// The play operators of a Prandtl-Ishlinskii operator, play_r[v](k) = min(max(P_r(k-1), v(k) - r),
/// v(k) + r) with P_r = 0 at rest: the backlash of half-width r started engaged at 0, one per threshold
/// r_1 < ... < r_np. Their outputs are the regressors of the weights g, as a polynomial's powers are;
/// the Prandtl-Ishlinskii Hammerstein model's input block and the nonlinear-feedback model's plays
/// step them. Np_ fixes the number of plays at compile time (Eigen::Dynamic: sized at construction);
/// a step never allocates.
template <typename Scalar_ = double, int Np_ = Eigen::Dynamic>
class PlayOperators {
 public:
  using Scalar = Scalar_;                        ///< the arithmetic type
  using Vector = Eigen::Matrix<Scalar, Np_, 1>;  ///< the thresholds or the plays' outputs (fixed size when Np_ is)

  /// The plays of `thresholds` (require_valid; Np of them where Np is fixed), at rest.
  /// \param thresholds r_1..r_np, in the units of the input
  template <typename T>
  explicit PlayOperators(const Eigen::MatrixBase<T>& thresholds) {
    require_valid(thresholds, Np_ == Eigen::Dynamic ? thresholds.size() : Eigen::Index(Np_));
    m_thresholds = thresholds;
    m_state = Vector::Zero(thresholds.size());
  }

  /// The rule that places np thresholds where none are given: r_i = i / (np + 1) of the half-range
  /// (max - min) / 2 of the input's deviations, evenly spread over the plays' reach (a play with
  /// r >= the half-range never leaves its rest value once the input has swept it, and only follows
  /// the input's mean). `half_range` <= 0 or not finite (a constant input) counts as 1.
  /// \param np the number of thresholds
  /// \param half_range (max - min) / 2 of the input's deviations
  /// \return r_1..r_np
  static Vector spread_thresholds(Eigen::Index np, Scalar half_range = Scalar(1)) {
    const Scalar scale = std::isfinite(half_range) && half_range > Scalar(0) ? half_range : Scalar(1);
    Vector thresholds(np);
    for (Eigen::Index i = 0; i < np; ++i) {
      thresholds[i] = scale * static_cast<Scalar>(i + 1) / static_cast<Scalar>(np + 1);
    }
    return thresholds;
  }

  /// What the plays accept: np finite thresholds, > 0, strictly increasing; otherwise
  /// std::invalid_argument saying which entry is wrong.
  /// \param thresholds the thresholds to check
  /// \param np how many there must be
  template <typename T>
  static void require_valid(const Eigen::MatrixBase<T>& thresholds, Eigen::Index np) {
    detail::require_size(thresholds, np, "thresholds");
    detail::require_finite(thresholds, "thresholds");
    for (Eigen::Index i = 0; i < thresholds.size(); ++i) {
      const double value = static_cast<double>(thresholds[i]);
      if (!(value > 0.0)) {
        detail::fail(
            "thresholds must be > 0 (a play of threshold 0 is the input itself, the linear term f_1 u), "
            "got " +
            detail::format_number(value) + " at index " + std::to_string(i));
      }
      if (i > 0 && !(thresholds[i - 1] < thresholds[i])) {
        detail::fail("thresholds must be strictly increasing, got " +
                     detail::format_number(static_cast<double>(thresholds[i - 1])) + " before " +
                     detail::format_number(value) + " at index " + std::to_string(i));
      }
    }
  }

  /// One play: its output for input v after the output `previous`.
  /// \param previous the play's output P(k-1)
  /// \param v the input v(k)
  /// \param threshold the play's threshold r
  /// \return P(k)
  static Scalar play(Scalar previous, Scalar v, Scalar threshold) noexcept {
    return Backlash<Scalar>::map(v, previous, threshold);
  }

  Eigen::Index size() const noexcept { return m_thresholds.size(); }  ///< the number of plays, np \return np
  /// The thresholds r_1..r_np
  /// \return r_1..r_np, strictly increasing, > 0
  const Vector& thresholds() const noexcept { return m_thresholds; }
  /// The plays' outputs P_i(k) after the last step (their memory): the PI part's regressors.
  /// \return P_1(k)..P_np(k), valid until the next step or reset
  const Vector& state() const noexcept { return m_state; }

  /// Back to rest: every play at 0.
  void reset() noexcept { m_state.setZero(); }
  /// Takes over `other`'s outputs (their memory) where it has as many plays; else back to rest.
  /// \param other the plays whose memory to take
  void continue_from(const PlayOperators& other) noexcept {
    if (other.m_state.size() == m_state.size()) {
      m_state = other.m_state;
    } else {
      m_state.setZero();
    }
  }

  /// Steps every play with the input v(k).
  /// \param v the input v(k)
  /// \return the plays' outputs P_1(k)..P_np(k), state(), valid until the next step or reset
  const Vector& step(Scalar v) noexcept {
    for (Eigen::Index i = 0; i < m_state.size(); ++i) m_state[i] = play(m_state[i], v, m_thresholds[i]);
    return m_state;
  }

  /// sum_i g_i play_{r_i}(P_i, v): the output step(v) would give for the weights g, the plays left
  /// as they are.
  /// \param v the input v(k)
  /// \param g the weights g_1..g_np
  /// \return the weighted sum
  template <typename G>
  Scalar output_for(Scalar v, const Eigen::MatrixBase<G>& g) const noexcept {
    Scalar sum = Scalar(0);
    for (Eigen::Index i = 0; i < m_state.size(); ++i) sum += g[i] * play(m_state[i], v, m_thresholds[i]);
    return sum;
  }

  /// sum_i g_i P_i(k) for the weights g (np of them).
  /// \param g the weights g_1..g_np
  /// \return the weighted sum
  template <typename G>
  Scalar output(const Eigen::MatrixBase<G>& g) const noexcept {
    Scalar sum = Scalar(0);
    for (Eigen::Index i = 0; i < m_state.size(); ++i) sum += g[i] * m_state[i];
    return sum;
  }

 private:
  Vector m_thresholds;
  Vector m_state;
};

}  // namespace bonl
