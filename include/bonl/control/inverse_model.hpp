#pragma once
// The inverse of an identified model: per sample, given the reference output preview() samples ahead
// (the delay nk, plus ZPETC's preview where B is not minimum phase), the command u(k) that makes the
// model follow it. The blocks' inverses in reverse order:
//   reference r(k+nk) - y0
//     -> the backlash inverse (P-H-W) or the output polynomial's inverse (H-W, Wiener): x_d(k+nk)
//     -> the linear block's inverse (exact, or ZPETC): w(k)
//     -> the input block's inverse: the input polynomial's (Hammerstein, H-W, P-H-W) or the
//        Prandtl-Ishlinskii input's (its plays' memory included); ARX and Wiener: w = u: u(k) - u0,
// each reporting what it could not do (InverseStatus). The input block's inverse is chosen by the type
// of the block the model's input_block() returns (detail::input_inverse_of). The linear block's
// inverse runs on the w the command actually gives, and the plays advance with that command, so after
// a saturated or dead-band command the inverse aims at the reference from where the model is.
// Allocation-free and noexcept per sample; all storage is made by the constructor.
//
// With everything reachable (Exact on every sample), a minimum-phase B and the model started from rest
// together with the inverse, model.simulate(commands(r)) reproduces r(k) for k >= nk to rounding (the
// P-H-W with band 0; with a band, except within the band after each reversal; the Prandtl-Ishlinskii
// Hammerstein model through any number of reversals, its plays' memory followed). r(0..nk-1) are the
// model's response to its rest, which no command can change.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "../blocks/prandtl_ishlinskii_input.hpp"
#include "../blocks/two_segment_polynomial.hpp"
#include "../detail/validate.hpp"
#include "../models.hpp"
#include "backlash_inverse.hpp"
#include "input_polynomial_inverse.hpp"
#include "inverse_status.hpp"
#include "linear_inverse.hpp"
#include "output_polynomial_inverse.hpp"
#include "prandtl_ishlinskii_inverse.hpp"

namespace bonl::control {

/// How the inverse is built.
struct InverseOptions {
  /// The command range [command_min, command_max], in the model's input units; it must contain the
  /// operating point's u0. NaN: the model's input range (input_min(), input_max(); identify()
  /// records it). Models with an input polynomial need it finite; for ARX and Wiener an infinite
  /// range does not limit the command.
  double command_min = std::numeric_limits<double>::quiet_NaN();
  double command_max = std::numeric_limits<double>::quiet_NaN();  ///< the command range's upper end (see command_min)
  /// P-H-W: the backlash inverse's transition band, in the output's units (0: the exact switch).
  double backlash_band = 0.0;
  /// P-H-W: added to backlash_band, times the model's backlash half-width c (1: a band of c, which
  /// scales with the model; what the tracking experiment uses, docs/how-to/control.md).
  double backlash_band_per_c = 0.0;
};

/// A whole reference's commands and the status of each.
template <typename Scalar>
struct InverseRun {
  Eigen::Matrix<Scalar, Eigen::Dynamic, 1> command;  ///< the commands u(0..N-1), in the model's input units
  std::vector<InverseStatus> status;                 ///< each command's status: Exact, or what it could not do
};

namespace detail {
template <class M, class = void>
struct has_input_block : std::false_type {};
template <class M>
struct has_input_block<M, std::void_t<decltype(std::declval<const M&>().input_block())>> : std::true_type {};
template <class M, class = void>
struct has_output_block : std::false_type {};
template <class M>
struct has_output_block<M, std::void_t<decltype(std::declval<const M&>().output_block())>> : std::true_type {};
template <class M, class = void>
struct has_backlash : std::false_type {};
template <class M>
struct has_backlash<M, std::void_t<decltype(std::declval<const M&>().backlash())>> : std::true_type {};
}  // namespace detail

namespace detail {
/// The inverse of an input block, by the block's type: what InverseModel uses for the block the
/// model's input_block() returns. Each inverse is built from (block, u_min, u_max) and has
/// operator()(w), output(u), advance(u), reset() and continue_from(previous).
template <class Block>
struct input_inverse_of {
  static_assert(sizeof(Block) == 0, "bonl::control: no inverse is written for this input block type");
};
template <typename Scalar, int R>
struct input_inverse_of<TwoSegmentPolynomial<Scalar, R>> {
  using type = InputPolynomialInverse<Scalar>;
};
template <typename Scalar, int R, int Np>
struct input_inverse_of<PrandtlIshlinskiiInput<Scalar, R, Np>> {
  using type = PrandtlIshlinskiiInverse<Scalar>;
};
/// The model's input block's inverse; int for a model without an input block.
template <class Model, bool HasInputBlock>
struct model_input_inverse {
  using type = int;
};
template <class Model>
struct model_input_inverse<Model, true> {
  using type = typename input_inverse_of<decltype(std::declval<const Model&>().input_block())>::type;
};
}  // namespace detail

namespace detail {
/// A model says it has no inverse (yet) with static constexpr bool kInvertible = false.
template <class M, class = void>
struct declared_invertible : std::true_type {};
template <class M>
struct declared_invertible<M, std::void_t<decltype(M::kInvertible)>> : std::bool_constant<M::kInvertible> {};
}  // namespace detail

/// The models InverseModel inverts: those with one linear block that do not declare otherwise. The
/// Wiener-Hammerstein model's inverse (B2/A2's, the polynomial's and B1/A1's in turn, with the two
/// delays' preview) and the nonlinear-feedback model's are not written yet.
template <class Model>
struct has_inverse : std::bool_constant<bonl::detail::linear_block_count<Model>::value == 1 &&
                                        detail::declared_invertible<Model>::value> {};

/// The models of bonl::Models that have an inverse (what the Python bindings and the fuzz harness loop over).
using InvertibleModels = FilterModels<Models, has_inverse>::type;

/// The inverse of an identified model (one of InvertibleModels): per sample, given the reference
/// output preview() samples ahead, the command u(k) that makes the model follow it. The blocks'
/// inverses in reverse order: the backlash's (BacklashInverse) or the output polynomial's
/// (OutputPolynomialInverse), the linear block's (LinearInverse: exact, or ZPETC where B is not minimum
/// phase), then the input block's (InputPolynomialInverse or PrandtlIshlinskiiInverse, by the type of
/// the model's input_block()), each reporting what it could not do (InverseStatus). The linear block's
/// inverse runs on the w the command actually gives, so after a saturated or dead-band command the
/// inverse aims at the reference from where the model is. Allocation-free and noexcept per sample.
template <class Model>
class InverseModel {
  static_assert(has_inverse<Model>::value, "bonl::control::InverseModel inverts models with one linear block");

 public:
  using Scalar = typename Model::Scalar;                     ///< the model's arithmetic type
  using VectorX = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;  ///< a vector of run-time size
  /// Whether the model has an input block (input_block()) whose inverse gives the command; without
  /// one (ARX, Wiener) w = u, clamped to the command range.
  static constexpr bool kHasInputBlock = detail::has_input_block<Model>::value;
  /// Whether the model has an output polynomial (output_block(): H-W, Wiener) to invert first.
  static constexpr bool kHasOutputPolynomial = detail::has_output_block<Model>::value;
  /// Whether the model has a backlash (backlash(): P-H-W) to invert first.
  static constexpr bool kHasBacklash = detail::has_backlash<Model>::value;

  /// Throws std::invalid_argument where the model has no inverse (b_0 = 0, a zero of B at z = 1,
  /// q_1 = 0, an input polynomial not monotone through 0 or constant, input hysteresis whose slope
  /// can take either sign near 0), for a command range that is not finite (with an input block) or
  /// does not contain u0, or a band < 0.
  /// \param model the identified model to invert
  /// \param options the command range and the backlash inverse's band
  explicit InverseModel(const Model& model, const InverseOptions& options = {})
      : m_linear(bonl::detail::with_integrators(model.a(), model.ni()), model.b(), model.nk()),
        m_u0(static_cast<Scalar>(model.u0())), m_y0(static_cast<Scalar>(model.y0())),
        m_command_min(static_cast<Scalar>(std::isnan(options.command_min) ? model.input_min() : options.command_min)),
        m_command_max(static_cast<Scalar>(std::isnan(options.command_max) ? model.input_max() : options.command_max)),
        m_input(make_input(model, m_command_min - m_u0, m_command_max - m_u0)), m_output(make_output(model)),
        m_backlash(make_backlash(model, options)), m_window(VectorX::Zero(m_linear.window_size())) {
    bonl::detail::require(
        !std::isnan(m_command_min) && !std::isnan(m_command_max) && m_command_min <= m_u0 && m_u0 <= m_command_max,
        "the command range must contain the operating point u0 = " +
            bonl::detail::format_number(static_cast<double>(m_u0)) + ", got [" +
            bonl::detail::format_number(static_cast<double>(m_command_min)) + ", " +
            bonl::detail::format_number(static_cast<double>(m_command_max)) + "]");
  }

  /// The reference the step at sample k takes: r(k + nk), ..., r(k + preview()).
  /// \return nk, the model's delay in samples
  Eigen::Index nk() const noexcept { return m_linear.nk(); }
  /// How far ahead the last reference sample a step takes is: nk plus ZPETC's preview
  /// (LinearInverse::preview(); 0 when B is minimum phase).
  /// \return the preview in samples, >= nk
  Eigen::Index preview() const noexcept { return m_linear.nk() + m_linear.preview(); }
  /// How many reference samples step() needs: preview() - nk() + 1 (1 when B is minimum phase).
  /// \return the window's length, >= 1
  Eigen::Index window_size() const noexcept { return m_linear.window_size(); }
  /// Are all of B's zeros inside the unit circle (the exact inverse), or is the linear block's
  /// inverse ZPETC?
  /// \return true for the exact inverse, false for ZPETC
  bool minimum_phase() const noexcept { return m_linear.minimum_phase(); }
  /// The command range's lower end, in the model's input units (InverseOptions::command_min, or the
  /// model's input_min()).
  /// \return the lowest command
  Scalar command_min() const noexcept { return m_command_min; }
  /// The command range's upper end (see command_min())
  /// \return the highest command
  Scalar command_max() const noexcept { return m_command_max; }
  /// The linear block's inverse, for its factors (LinearInverse::stable_factor(), unstable_factor()).
  /// \return the linear block's inverse
  const LinearInverse<Scalar>& linear_inverse() const noexcept { return m_linear; }

  /// Back to rest, as the model's free run starts.
  void reset() noexcept {
    m_linear.reset();
    if constexpr (kHasInputBlock) m_input.reset();
    if constexpr (kHasBacklash) m_backlash.reset();
  }

  /// Goes on from where `previous` (an inverse of another model of the same type, e.g. an earlier
  /// estimate) is, instead of from rest: its linear block's stored past (LinearInverse::continue_from),
  /// its plays' memory and its backlash's direction. What AdaptiveInverse does when it re-derives the
  /// inverse.
  /// \param previous the inverse to go on from
  void continue_from(const InverseModel& previous) noexcept {
    m_linear.continue_from(previous.m_linear);
    if constexpr (kHasInputBlock) m_input.continue_from(previous.m_input);
    if constexpr (kHasBacklash) m_backlash.continue_from(previous.m_backlash.state());
  }

  /// The command u(k) for the reference window r(k+nk), ..., r(k+nk+window_size()-1) (the model's
  /// output units; more entries are ignored). A window too short (RejectedShortPreview), with a
  /// non-finite entry (RejectedNonFinite), or so large that the arithmetic overflows
  /// (RejectedOverflow) leaves the inverse untouched and the command NaN.
  /// \param reference the window, at least window_size() entries
  /// \return the command u(k), in the model's input units, and its status
  template <typename W>
  InverseStep<Scalar> step(const Eigen::MatrixBase<W>& reference) noexcept {
    const Eigen::Index n = m_window.size();
    const Scalar nan = std::numeric_limits<Scalar>::quiet_NaN();
    if (reference.size() < n) return {nan, InverseStatus::RejectedShortPreview};
    for (Eigen::Index i = 0; i < n; ++i) {
      if (!std::isfinite(reference[i])) return {nan, InverseStatus::RejectedNonFinite};
    }
    InverseStatus status = InverseStatus::Exact;
    // The output block's inverse over the window; the backlash's direction advances with r(k+nk) only.
    if constexpr (kHasBacklash) {
      auto state = m_backlash.state();
      for (Eigen::Index i = 0; i < n; ++i) m_window[i] = m_backlash.map(reference[i] - m_y0, state);
    } else if constexpr (kHasOutputPolynomial) {
      for (Eigen::Index i = 0; i < n; ++i) {
        const InverseStep<Scalar> x = m_output(reference[i] - m_y0);
        m_window[i] = x.value;
        if (i == 0) status |= x.status;
      }
    } else {
      for (Eigen::Index i = 0; i < n; ++i) m_window[i] = reference[i] - m_y0;
    }
    const Scalar w_desired = m_linear.input(m_window);
    if (!std::isfinite(w_desired)) return {nan, InverseStatus::RejectedOverflow};
    Scalar u = Scalar(0);
    Scalar w = Scalar(0);
    if constexpr (kHasInputBlock) {
      const InverseStep<Scalar> command = m_input(w_desired);
      u = command.value;
      status |= command.status;
      w = m_input.output(u);
    } else {
      u = std::min(std::max(w_desired, m_command_min - m_u0), m_command_max - m_u0);
      if (u != w_desired) status |= InverseStatus::Saturated;
      w = u;
    }
    if (!m_linear.commit(m_window[0], w)) return {nan, InverseStatus::RejectedOverflow};
    if constexpr (kHasInputBlock) m_input.advance(u);  // the plays' memory, after the commit succeeded
    if constexpr (kHasBacklash) m_backlash.step(reference[0] - m_y0);
    return {u + m_u0, status};
  }

  /// step() for a window of one sample, r(k + nk): only where window_size() is 1 (else
  /// RejectedShortPreview).
  /// \param reference r(k + nk), in the model's output units
  /// \return the command u(k), in the model's input units, and its status
  InverseStep<Scalar> step(Scalar reference) noexcept { return step(Eigen::Matrix<Scalar, 1, 1>::Constant(reference)); }

  /// The commands for a whole reference r(0..N-1), from rest (this inverse's state is not used or
  /// changed): u(k) for k = 0..N-1 from r(k+nk), ..., r(k+preview()), the reference held at r(N-1)
  /// beyond its end. model.simulate(command) then follows r from k = nk on. Throws
  /// std::invalid_argument for a non-finite reference, or one of preview() samples or fewer.
  /// \param reference r(0..N-1), in the model's output units, more than preview() samples
  /// \return N commands and their statuses
  template <typename R>
  InverseRun<Scalar> commands(const Eigen::MatrixBase<R>& reference) const {
    bonl::detail::require_finite(reference, "reference");
    const Eigen::Index size = reference.size();
    bonl::detail::require(size > preview(), "the reference must be longer than the inverse's preview (nk + " +
                                                std::to_string(m_linear.preview()) + " = " + std::to_string(preview()) +
                                                " samples), got " + std::to_string(size));
    InverseModel run = *this;
    run.reset();
    InverseRun<Scalar> out{VectorX(size), std::vector<InverseStatus>(static_cast<std::size_t>(size))};
    VectorX window(window_size());
    for (Eigen::Index k = 0; k < size; ++k) {
      for (Eigen::Index i = 0; i < window.size(); ++i) window[i] = reference[std::min(k + nk() + i, size - 1)];
      const InverseStep<Scalar> step = run.step(window);
      out.command[k] = step.value;
      out.status[static_cast<std::size_t>(k)] = step.status;
    }
    return out;
  }

 private:
  using InputInverse = typename detail::model_input_inverse<Model, kHasInputBlock>::type;
  using OutputInverse = std::conditional_t<kHasOutputPolynomial, OutputPolynomialInverse<Scalar>, int>;
  using BacklashInverseType = std::conditional_t<kHasBacklash, BacklashInverse<Scalar>, int>;

  static InputInverse make_input(const Model& model, Scalar low, Scalar high) {
    if constexpr (kHasInputBlock) {
      bonl::detail::require(std::isfinite(low) && std::isfinite(high),
                            std::string("the inverse of a ") + Model::kName +
                                " model needs a finite command range: set InverseOptions::command_min and "
                                "command_max, or the model's input range (identify() records it)");
      return InputInverse(model.input_block(), low, high);
    } else {
      (void)model, (void)low, (void)high;
      return 0;
    }
  }
  static OutputInverse make_output(const Model& model) {
    if constexpr (kHasOutputPolynomial) {
      return OutputPolynomialInverse<Scalar>(model.q());
    } else {
      (void)model;
      return 0;
    }
  }
  static BacklashInverseType make_backlash(const Model& model, const InverseOptions& options) {
    bonl::detail::require(std::isfinite(options.backlash_band_per_c) && options.backlash_band_per_c >= 0.0,
                          "the backlash inverse's backlash_band_per_c must be finite and >= 0, got " +
                              bonl::detail::format_number(options.backlash_band_per_c));
    if constexpr (kHasBacklash) {
      const Scalar band =
          static_cast<Scalar>(options.backlash_band) + static_cast<Scalar>(options.backlash_band_per_c) * model.c();
      return BacklashInverse<Scalar>(model.c(), band);
    } else {
      (void)model;
      bonl::detail::require(std::isfinite(options.backlash_band) && options.backlash_band >= 0.0,
                            "the backlash inverse's transition band must be finite and >= 0");
      return 0;
    }
  }

  LinearInverse<Scalar> m_linear;
  Scalar m_u0, m_y0;
  Scalar m_command_min, m_command_max;
  InputInverse m_input;
  OutputInverse m_output;
  BacklashInverseType m_backlash;
  VectorX m_window;  // x_d(k+nk), ..., x_d(k+nk+s)
};

}  // namespace bonl::control
