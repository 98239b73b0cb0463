#pragma once
// Inverse of the Prandtl-Ishlinskii Hammerstein model's input block (blocks/prandtl_ishlinskii_input.hpp),
//   w(k) = sum_{l=0..r} f_l u(k)^l + sum_{i=1..np} g_i play_{r_i}[u](k):
// given the w the linear block needs and the plays' memory P(k-1), the command u in [u_min, u_max]
// (u_min <= 0 <= u_max, deviations from the operating point) that gives it; then the plays advance
// with the command actually given (advance()), so this inverse's play memory is the model's.
//
// For fixed P(k-1), u -> w(k) is continuous, and between the breakpoints u = P_i -+ r_i a polynomial
// (each play is either held at P_i or follows u -+ r_i with slope 1). Its slope is f'(u) plus the
// weights of the plays that move, so it lies between f'(u) + sum of the negative g_i and f'(u) + sum
// of the positive g_i for every state. The inverse uses the range where one of these bounds keeps
// its sign whatever the plays do: the monotone branch from u = 0 of f + (sum of the negative g_i) u
// (w rising with u) or of f + (sum of the positive g_i) u (w falling), up to its first stationary
// point or the command's limit (detail::branch_end, as the input polynomial's inverse). On that range
// w is monotone for every state, and a bracketing search gives the exact command: the bracket
// [lower(), upper()] is narrowed to the breakpoints around the solution, where w is one polynomial,
// and that polynomial is solved by Newton's method safeguarded by bisection (detail::solve_on_branch).
// What no command reaches is reported, not hidden:
// - Saturated: w beyond what the range's ends give with the current memory; the command is the end
//   nearer to w.
// Where neither bound keeps its sign near u = 0 (weights of either sign that outweigh f'(0), or a
// polynomial that rises on one side of 0 and falls on the other), or w cannot change with u, there is
// no inverse: the constructor throws.
//
// Why a search and not the closed-form inverse PI operator (Kuhnen 2003): that one inverts f = (0, f_1)
// with positive weights, by plays with transformed thresholds and weights. The model's polynomial
// terms (f_0, f_2, ...), weights of either sign and a command range with saturation are outside it;
// the search covers them all, costs O(np (np + r)) per sample, and reproduces the model's w to
// rounding because it evaluates the model's own block.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <string>

#include "../blocks/prandtl_ishlinskii_input.hpp"
#include "../detail/validate.hpp"
#include "detail/polynomial_branch.hpp"
#include "inverse_status.hpp"

namespace bonl::control {

/// The inverse of the Prandtl-Ishlinskii Hammerstein model's input block (bonl::PrandtlIshlinskiiInput):
/// given the w the linear block needs and the plays' memory, the command u in [u_min, u_max] (deviations
/// from the operating point) that gives it; advance() then steps the plays with the command actually
/// given, so the inverse's memory is the model's. It searches the range where w is monotone in u for
/// every state of the plays: the bracket is narrowed to the plays' breakpoints around the solution, where
/// w is one polynomial, solved by Newton's method safeguarded by bisection. A w beyond what the range's
/// ends give is Saturated (the nearer end is the command). A search rather than the closed-form inverse PI
/// operator (Kuhnen 2003), which covers only f = (0, f_1) with positive weights.
template <typename Scalar_ = double>
class PrandtlIshlinskiiInverse {
 public:
  using Scalar = Scalar_;                                    ///< the arithmetic type
  using VectorX = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;  ///< a vector of run-time size
  using Block = PrandtlIshlinskiiInput<Scalar>;              ///< the input block the inverse steps (run-time sizes)

  /// The block's f, thresholds and weights (its memory is not taken: the inverse starts at rest) and
  /// the command range [u_min, u_max], finite, with u_min <= 0 <= u_max. Throws std::invalid_argument
  /// for a range that is not finite or leaves out 0, or a block with no inverse: w not monotone in u
  /// near 0 for every state of the plays (weights of either sign that outweigh f'(0), or a polynomial
  /// that rises on one side of 0 and falls on the other), or w that does not change with u.
  /// \param block the input block to invert
  /// \param u_min the command range's lower end, finite, <= 0 (a deviation from the operating point)
  /// \param u_max the command range's upper end, finite, >= 0
  template <int R, int Np>
  PrandtlIshlinskiiInverse(const PrandtlIshlinskiiInput<Scalar, R, Np>& block, Scalar u_min, Scalar u_max)
      : m_block(block.f(), block.thresholds(), block.g()), m_piece(block.f()) {
    bonl::detail::require(std::isfinite(u_min) && std::isfinite(u_max) && u_min <= Scalar(0) && Scalar(0) <= u_max,
                          "the command range of the Prandtl-Ishlinskii input's inverse must be finite and contain "
                          "the operating point (u_min <= u0 <= u_max), got [" +
                              bonl::detail::format_number(static_cast<double>(u_min)) + ", " +
                              bonl::detail::format_number(static_cast<double>(u_max)) + "] about u0");
    const VectorX& f = m_piece;
    const VectorX g = block.g();
    // The least and the greatest slope over the plays' states: f' plus the negative, or the positive, weights.
    VectorX least = f, greatest = f;
    least[1] += g.cwiseMin(Scalar(0)).sum();
    greatest[1] += g.cwiseMax(Scalar(0)).sum();
    const Branch rising = branch(least, u_min, u_max);
    const Branch falling = branch(greatest, u_min, u_max);
    const bool rises = rising.rise_lower >= Scalar(0) && rising.rise_upper >= Scalar(0);
    const bool falls = falling.rise_lower <= Scalar(0) && falling.rise_upper <= Scalar(0);
    bonl::detail::require(
        rises || falls,
        "the Prandtl-Ishlinskii input has no inverse: w = f(u) + sum g_i play_i is not monotone in u near the "
        "operating point for every state of the plays (its slope lies between f'(u) + " +
            bonl::detail::format_number(static_cast<double>(least[1] - f[1])) + " and f'(u) + " +
            bonl::detail::format_number(static_cast<double>(greatest[1] - f[1])) +
            ", the sums of the negative and the positive weights g_i, and these take both signs there)");
    bonl::detail::require(!(rises && falls),
                          "the Prandtl-Ishlinskii input has no inverse: w does not change with u over the command "
                          "range (f' = 0 there and every weight g_i is 0)");
    const Branch& chosen = rises ? rising : falling;
    m_lo = chosen.lower;
    m_hi = chosen.upper;
    m_direction = rises ? Scalar(1) : Scalar(-1);
  }

  /// The command for w with the plays' current memory: {u, status}. Exact when the block gives w to
  /// rounding. The memory is not changed (advance() does that); not const because it solves in the
  /// inverse's own scratch polynomial (no allocation per sample), so one inverse serves one thread.
  /// \param w the block's output the linear block needs
  /// \return the command u and its status (Exact or Saturated)
  InverseStep<Scalar> operator()(Scalar w) noexcept {
    const Scalar s = m_direction;
    Scalar lo = m_lo, hi = m_hi;
    const Scalar at_lo = m_block.peek(lo);
    const Scalar at_hi = m_block.peek(hi);
    if (s * w > s * at_hi) return {hi, InverseStatus::Saturated};
    if (s * w < s * at_lo) return {lo, InverseStatus::Saturated};
    if (w == at_hi) return {hi, InverseStatus::Exact};
    if (w == at_lo) return {lo, InverseStatus::Exact};
    // Every breakpoint inside the bracket becomes one of its ends: then the bracket is one piece.
    const auto& state = m_block.state();
    const auto& thresholds = m_block.thresholds();
    for (Eigen::Index i = 0; i < state.size(); ++i) {
      for (const Scalar breakpoint : {state[i] - thresholds[i], state[i] + thresholds[i]}) {
        if (!(breakpoint > lo && breakpoint < hi)) continue;
        const Scalar value = m_block.peek(breakpoint);
        if (value == w) return {breakpoint, InverseStatus::Exact};
        (s * value < s * w ? lo : hi) = breakpoint;
      }
    }
    // The piece's polynomial: a held play adds g_i P_i, one that follows u adds g_i (u -+ r_i).
    const Scalar middle = Scalar(0.5) * (lo + hi);
    const auto& f = m_block.f();
    const auto& g = m_block.g();
    m_piece = f;
    for (Eigen::Index i = 0; i < state.size(); ++i) {
      if (middle > state[i] + thresholds[i]) {
        m_piece[0] -= g[i] * thresholds[i];
        m_piece[1] += g[i];
      } else if (middle < state[i] - thresholds[i]) {
        m_piece[0] += g[i] * thresholds[i];
        m_piece[1] += g[i];
      } else {
        m_piece[0] += g[i] * state[i];
      }
    }
    return {detail::solve_on_branch(m_piece, w, lo, hi), InverseStatus::Exact};
  }

  /// The w the command u gives with the plays' current memory (the model's arithmetic).
  /// \param u the command
  /// \return w
  Scalar output(Scalar u) const noexcept { return m_block.peek(u); }
  /// Steps the plays with the command given.
  /// \param u the command given
  void advance(Scalar u) noexcept { m_block.step(u); }
  /// Back to rest: every play at 0.
  void reset() noexcept { m_block.reset(); }
  /// Takes over `previous`'s play memory (an inverse of another estimate with as many plays).
  /// \param previous the inverse whose memory to take
  void continue_from(const PrandtlIshlinskiiInverse& previous) noexcept { m_block.continue_from(previous.m_block); }

  /// The commands the inverse uses, [lower(), upper()]: the command range, or nearer to 0 where the
  /// slope bound stops keeping its sign.
  /// \return the lowest command used, <= 0
  Scalar lower() const noexcept { return m_lo; }
  /// The commands' upper end (see lower())
  /// \return the highest command used, >= 0
  Scalar upper() const noexcept { return m_hi; }
  /// +1 where w rises with u, -1 where it falls.
  /// \return +1 or -1
  int direction() const noexcept { return m_direction > Scalar(0) ? 1 : -1; }
  /// The plays' memory P(k-1).
  /// \return P_1(k-1)..P_np(k-1)
  const VectorX& state() const noexcept { return m_block.state(); }

 private:
  struct Branch {
    Scalar lower, upper;            // the monotone branch from 0 on each side
    Scalar rise_lower, rise_upper;  // c(0) - c(lower), c(upper) - c(0)
  };
  /// The monotone branch from u = 0 of the polynomial c (a slope bound's antiderivative) within the range.
  static Branch branch(const VectorX& c, Scalar u_min, Scalar u_max) {
    const Scalar upper = u_max > Scalar(0) ? detail::branch_end(c, 1, u_max) : Scalar(0);
    const Scalar lower = u_min < Scalar(0) ? detail::branch_end(c, -1, u_min) : Scalar(0);
    return {lower, upper, c[0] - detail::polynomial(c, lower), detail::polynomial(c, upper) - c[0]};
  }

  Block m_block;
  VectorX m_piece;  // scratch: the polynomial of the piece being solved (sized once)
  Scalar m_lo = Scalar(0), m_hi = Scalar(0);
  Scalar m_direction = Scalar(1);
};

}  // namespace bonl::control
