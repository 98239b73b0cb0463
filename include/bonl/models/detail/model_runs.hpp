#pragma once
// What every model's simulate(), predict() and linear_block() share, written once (ModelRuns, a
// CRTP base). One-step-ahead prediction runs the model's key terms with the equation-error method's
// internal-variable estimates (those that use the measured output) and fixed parameters, so a
// prediction and the estimator's regressor come from the same code.

#include <Eigen/Core>

#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>

#include "../../detail/validate.hpp"
#include "../../error.hpp"
#include "../model_steps.hpp"

namespace bonl::detail {

/// The input range a model was identified on, as deviations from its operating point's u0: where its
/// input polynomial stops and continues linearly (blocks/two_segment_polynomial.hpp). (-inf, inf):
/// none, the polynomial everywhere.
struct InputDeviationRange {
  double low = -std::numeric_limits<double>::infinity();  ///< input_min() - u0
  double high = std::numeric_limits<double>::infinity();  ///< input_max() - u0
};

/// Does a model's KeyTerms take the input range (set_input_range): those whose input block continues
/// linearly beyond it?
template <class Terms, class = void>
struct TakesInputRange : std::false_type {};
template <class Terms>
struct TakesInputRange<Terms, std::void_t<decltype(std::declval<Terms&>().set_input_range(InputDeviationRange{}))>>
    : std::true_type {};

/// The free run every model's try_simulate_deviations() is: y(k) = output(L(input(u(k)))) with `linear` the
/// model's linear block at rest, input and output its static maps (identity where it has none).
/// Returns false as soon as y leaves the finite numbers (an unstable or diverging model).
template <class Linear, typename U, typename VectorX, class InputMap, class OutputMap>
bool free_run(Linear linear, const Eigen::MatrixBase<U>& u, VectorX& y, InputMap&& input, OutputMap&& output) {
  y.resize(u.size());
  for (Eigen::Index k = 0; k < u.size(); ++k) {
    y[k] = output(linear.step(input(u[k])));
    if (!std::isfinite(y[k])) return false;
  }
  return true;
}

/// The identity map, for a model without an input or an output block.
struct Identity {
  template <typename Scalar>
  Scalar operator()(Scalar value) const noexcept {
    return value;
  }
};

/// The NumericalError of a simulation that left the finite numbers.
template <class Model>
[[noreturn]] void simulation_diverged() {
  throw NumericalError(std::string("bonl: ") + Model::kName +
                       " simulation left the finite numbers (an unstable model?)");
}

/// Free run from rest through model.try_simulate(); divergence becomes a NumericalError.
template <class Model, typename U>
typename Model::VectorX simulate_checked(const Model& model, const Eigen::MatrixBase<U>& u) {
  require_finite(u, "u");
  typename Model::VectorX y;
  if (!model.try_simulate(u, y)) simulation_diverged<Model>();
  return y;
}

/// The recent past (u_past, y_past) checked: the same length, finite.
template <typename P, typename Q>
void require_past(const Eigen::MatrixBase<P>& u_past, const Eigen::MatrixBase<Q>& y_past) {
  require_same_length(u_past, "u_past", y_past, "y_past");
  require_finite(u_past, "u_past");
  require_finite(y_past, "y_past");
}

/// Runs the model's key terms with the equation-error method's internal-variable estimates over the
/// measured past, then over (u, y) where y may be NaN (not measured: the model's own output stands in,
/// a free-run step). Returns the outputs over (u, y) with the operating point added.
template <class Model, typename P, typename Q, typename U, typename Y>
typename Model::VectorX run_after_past(const Model& model, const Eigen::MatrixBase<P>& u_past,
                                       const Eigen::MatrixBase<Q>& y_past, const Eigen::MatrixBase<U>& u,
                                       const Y& y_at) {
  using Scalar = typename Model::Scalar;
  const Scalar u0 = static_cast<Scalar>(model.u0());
  const Scalar y0 = static_cast<Scalar>(model.y0());
  typename Model::KeyTerms terms(model, KeyTermMethod::EquationError);
  // A model's input block continues linearly beyond the range it was identified on, in its free run
  // and here alike (the estimator's key terms, which fit the block, leave it out).
  if constexpr (TakesInputRange<typename Model::KeyTerms>::value) terms.set_input_range(model.input_deviation_range());
  for (Eigen::Index k = 0; k < u_past.size(); ++k) terms.step(model.theta(), u_past[k] - u0, y_past[k] - y0);
  typename Model::VectorX out(u.size());
  for (Eigen::Index k = 0; k < u.size(); ++k) {
    out[k] = terms.step(model.theta(), u[k] - u0, y_at(k) - y0).prediction + y0;
    if (!std::isfinite(out[k])) simulation_diverged<Model>();
  }
  return out;
}

/// simulate(), predict() and linear_block() for a model Derived with try_simulate_deviations(u, y),
/// KeyTerms, a(), b(), na(), nb(), nk(), ni() and the type Linear; and the model's operating point.
template <class Derived>
class ModelRuns {
 public:
  /// The operating point: the input u0 and the output y0 at which the model rests. The model's
  /// blocks map the deviation u - u0 to the deviation y - y0; (0, 0) unless set.
  double u0() const noexcept { return m_u0; }
  double y0() const noexcept { return m_y0; }
  void set_operating_point(double u0, double y0) {
    require_finite(u0, "u0");
    require_finite(y0, "y0");
    m_u0 = u0;
    m_y0 = y0;
  }

  /// The inputs the model was identified on, [input_min(), input_max()] (identify() records them);
  /// outside them the model extrapolates. The whole line (-inf, inf) unless set.
  double input_min() const noexcept { return m_input_min; }
  double input_max() const noexcept { return m_input_max; }
  void set_input_range(double min, double max) {
    require(!std::isnan(min) && !std::isnan(max) && min <= max,
            "the input range must be min <= max, got [" + format_number(min) + ", " + format_number(max) + "]");
    m_input_min = min;
    m_input_max = max;
  }
  /// The input range as deviations from u0 (InputDeviationRange): where an input polynomial continues
  /// linearly.
  /// \return [input_min() - u0, input_max() - u0]
  InputDeviationRange input_deviation_range() const noexcept { return {m_input_min - m_u0, m_input_max - m_u0}; }
  /// How many samples of u lie outside the input range: 0 where the model is used on inputs like
  /// those it was identified on; otherwise its output there is an extrapolation.
  template <typename U>
  Eigen::Index extrapolated_samples(const Eigen::MatrixBase<U>& u) const {
    Eigen::Index outside = 0;
    for (Eigen::Index k = 0; k < u.size(); ++k) {
      const double value = static_cast<double>(u[k]);
      outside += (value < m_input_min || value > m_input_max) ? 1 : 0;
    }
    return outside;
  }

  /// Free run from rest at the operating point; false (instead of simulate()'s NumericalError) if it
  /// leaves the finite numbers.
  template <typename U, typename VectorX>
  bool try_simulate(const Eigen::MatrixBase<U>& u, VectorX& y) const {
    using Scalar = typename VectorX::Scalar;
    if (m_u0 == 0.0 && m_y0 == 0.0) return self().try_simulate_deviations(u, y);
    const VectorX deviations = u.array() - static_cast<Scalar>(m_u0);
    const bool ok = self().try_simulate_deviations(deviations, y);
    y.array() += static_cast<Scalar>(m_y0);
    return ok && y.allFinite();
  }
  /// Free-run simulation from rest (at the operating point). Throws NumericalError if the output
  /// leaves the finite numbers.
  template <typename U>
  auto simulate(const Eigen::MatrixBase<U>& u) const {
    return simulate_checked(self(), u);
  }
  /// Free-run simulation of u after the measured recent past (u_past, y_past), which sets the
  /// model's state: its internal variables are what the measured past says, as predict() takes them.
  /// With a past as long as the model's memory (its lags) the simulation continues the record exactly
  /// where the model can be inverted (not inside a backlash's gap). An empty past is rest.
  /// The benchmarks' state-initialisation window of n samples: simulate(u.tail(N - n), u.head(n), y.head(n)).
  template <typename U, typename P, typename Q>
  auto simulate(const Eigen::MatrixBase<U>& u, const Eigen::MatrixBase<P>& u_past,
                const Eigen::MatrixBase<Q>& y_past) const {
    require_finite(u, "u");
    require_past(u_past, y_past);
    using Scalar = typename Derived::Scalar;
    return run_after_past(self(), u_past, y_past, u,
                          [](Eigen::Index) { return std::numeric_limits<Scalar>::quiet_NaN(); });
  }
  /// One-step-ahead prediction from the measured u and y: the internal variables are what the
  /// measured past says (the model's KeyTerms with KeyTermMethod::EquationError); from rest.
  template <typename U, typename Y>
  auto predict(const Eigen::MatrixBase<U>& u, const Eigen::MatrixBase<Y>& y) const {
    return predict(u, y, u.head(0), y.head(0));
  }
  /// The same after the measured recent past (u_past, y_past).
  template <typename U, typename Y, typename P, typename Q>
  auto predict(const Eigen::MatrixBase<U>& u, const Eigen::MatrixBase<Y>& y, const Eigen::MatrixBase<P>& u_past,
               const Eigen::MatrixBase<Q>& y_past) const {
    require_same_length(u, "u", y, "y");
    require_finite(u, "u");
    require_finite(y, "y");
    require_past(u_past, y_past);
    return run_after_past(self(), u_past, y_past, u, [&y](Eigen::Index k) { return y[k]; });
  }
  /// The linear block B / (A (1 - z^-1)^ni) with the model's delay and integrators.
  auto linear_block() const {
    typename Derived::Linear block(self().na(), self().nb(), self().nk(), self().ni());
    block.set_a(self().a());
    block.set_b(self().b());
    return block;
  }

 private:
  const Derived& self() const noexcept { return static_cast<const Derived&>(*this); }

  double m_u0 = 0.0;
  double m_y0 = 0.0;
  double m_input_min = -std::numeric_limits<double>::infinity();
  double m_input_max = std::numeric_limits<double>::infinity();
};

}  // namespace bonl::detail
