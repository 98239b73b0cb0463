#pragma once
// Input block of the Prandtl-Ishlinskii Hammerstein model: a polynomial and a Prandtl-Ishlinskii
// operator of the input,
//   w(k) = sum_{l=0..r} f_l u(k)^l + sum_{i=1..np} g_i play_{r_i}[u](k),
// with the plays of play_operators.hpp (their memory P_i(k-1) is this block's state, 0 at rest). The
// model's free run and its inverse both step this block, so the w the inverse computes for a command
// is the w the model makes of it. For fixed states, u -> w(k) is continuous: the polynomial plus, for
// each play, P_i between its breakpoints u = P_i - r_i and u = P_i + r_i and u -+ r_i beyond them.
// Beyond an input range (set_input_range: the range the model was identified on) the polynomial
// continues linearly (linear_continuation.hpp); the plays need no continuation (beyond their
// thresholds they follow u with slope 1).

#include <Eigen/Core>

#include <limits>
#include <string>

#include "../detail/validate.hpp"
#include "linear_continuation.hpp"
#include "play_operators.hpp"

namespace bonl {

/// The input block of the Prandtl-Ishlinskii Hammerstein model, w(k) = sum_{l=0..r} f_l u(k)^l +
/// sum_{i=1..np} g_i play_{r_i}[u](k): a polynomial and a Prandtl-Ishlinskii operator of the input,
/// the plays' memory its state (0 at rest). The model's free run and its inverse for control both step
/// this block, so the w the inverse computes for a command is the w the model makes of it. R_ and Np_
/// fix r and np at compile time (Eigen::Dynamic: from the coefficients given).
template <typename Scalar_ = double, int R_ = Eigen::Dynamic, int Np_ = Eigen::Dynamic>
class PrandtlIshlinskiiInput {
 public:
  using Scalar = Scalar_;                                          ///< the arithmetic type
  using Plays = PlayOperators<Scalar, Np_>;                        ///< the play operators' type
  using Coeffs = Eigen::Matrix<Scalar, detail::poly_size(R_), 1>;  ///< f_0..f_r (fixed size when R_ is)
  using Weights = Eigen::Matrix<Scalar, Np_, 1>;                   ///< g_1..g_np (fixed size when Np_ is)

  /// The block with the plays at rest. Throws std::invalid_argument for fewer than 2 entries of f, a
  /// degree that differs from R_, invalid thresholds, or a g of another length or not finite.
  /// \param f the polynomial's coefficients f_0..f_r, r >= 1
  /// \param thresholds the plays' thresholds r_1..r_np (PlayOperators::require_valid), in the units of u
  /// \param g the plays' weights g_1..g_np, as many as thresholds, finite
  template <typename F, typename T, typename G>
  PrandtlIshlinskiiInput(const Eigen::MatrixBase<F>& f, const Eigen::MatrixBase<T>& thresholds,
                         const Eigen::MatrixBase<G>& g)
      : m_plays(thresholds) {
    detail::require(f.size() >= 2,
                    "f must have at least 2 entries (f_0..f_r, degree r >= 1), got " + std::to_string(f.size()));
    detail::require_matches_template(f.size() - 1, R_, "r");
    m_f = Coeffs::Zero(f.size());
    m_g = Weights::Zero(thresholds.size());
    detail::assign_checked(m_f, f, "f");
    detail::assign_checked(m_g, g, "g");
  }

  const Coeffs& f() const noexcept { return m_f; }   ///< the polynomial's coefficients f_0..f_r \return r + 1 values
  const Weights& g() const noexcept { return m_g; }  ///< the plays' weights g_1..g_np \return np values
  /// The plays' thresholds. \return r_1..r_np, strictly increasing, > 0
  const typename Plays::Vector& thresholds() const noexcept { return m_plays.thresholds(); }
  /// The plays' outputs after the last step, P_i(k-1) for the next one. \return np values
  const typename Plays::Vector& state() const noexcept { return m_plays.state(); }
  Eigen::Index size() const noexcept { return m_plays.size(); }  ///< the number of plays, np \return np

  /// Back to rest: every play at 0.
  void reset() noexcept { m_plays.reset(); }
  /// Takes over `other`'s play memory (PlayOperators::continue_from).
  /// \param other the block whose play memory to take
  void continue_from(const PrandtlIshlinskiiInput& other) noexcept { m_plays.continue_from(other.m_plays); }

  /// One sample: steps the plays.
  /// \param u the input u(k)
  /// \return w(k)
  Scalar step(Scalar u) noexcept {
    m_plays.step(u);
    return polynomial(u) + m_plays.output(m_g);
  }
  /// The w that step(u) would give, the plays left as they are.
  /// \param u the input u(k)
  /// \return w(k)
  Scalar peek(Scalar u) const noexcept { return polynomial(u) + m_plays.output_for(u, m_g); }
  /// Where the polynomial continues linearly: beyond [low, high] (the file's header); (-inf, inf),
  /// the default, for none.
  /// \param low the range's low end
  /// \param high the range's high end
  void set_input_range(Scalar low, Scalar high) noexcept {
    m_low = low;
    m_high = high;
  }
  /// sum_l f_l u^l (Horner's scheme), continued linearly beyond the input range.
  /// \param u the input u(k)
  /// \return the polynomial part of w(k)
  Scalar polynomial(Scalar u) const noexcept {
    if (detail::beyond_range(u, m_low, m_high)) {
      const Scalar edge = u > m_high ? m_high : m_low;
      Scalar w = Scalar(0), slope = Scalar(0);
      for (Eigen::Index l = m_f.size() - 1; l >= 0; --l) {  // N and N' together
        slope = slope * edge + w;
        w = w * edge + m_f[l];
      }
      return w + slope * (u - edge);
    }
    Scalar w = Scalar(0);
    for (Eigen::Index l = m_f.size() - 1; l >= 0; --l) w = w * u + m_f[l];
    return w;
  }

 private:
  Coeffs m_f;
  Weights m_g;
  Plays m_plays;
  Scalar m_low = -std::numeric_limits<Scalar>::infinity();
  Scalar m_high = std::numeric_limits<Scalar>::infinity();
};

}  // namespace bonl
