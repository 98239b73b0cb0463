#pragma once
// The units the estimators work in. P(0), the trace ceiling, the process noise and the window
// refinement's damping are numbers; they mean the same on every machine only in units where the
// data and the parameters are of order one. Both estimators therefore work on the data divided by
// their scales (each signal's RMS about the operating point):
// - identify() divides the records by the powers of two nearest their scales and rescales the model
//   back (models/rescale.hpp), exactly;
// - the recursive estimator keeps the model in the data's units and runs its recursion in
//   normalised coordinates theta_n = theta / d, with d the size of each parameter for data of those
//   scales (its units in the model's description, ParameterUnitPowers), the regressor phi d / sy and the
//   error e / sy. That recursion is the one on the data divided by their scales, and it needs no
//   change of the model's state when the scales are set: they are measured over the first samples
//   (ScaleMeasurement), which the recursion then catches up on.
// With ni integrators the output's scale is that of its ni-th difference, the signal the estimated
// denominator and a fed-back velocity see: an integrated output's own RMS measures its drift.

#include <Eigen/Core>
#include <cmath>
#include <cstddef>
#include <vector>

#include "../models/rescale.hpp"
#include "record_view.hpp"

namespace bonl {
namespace detail {

/// Typical sizes of u - u0 and y - y0 (with integrators, of y's ni-th difference): the data's units.
struct DataScale {
  double u = 1.0;  ///< the input's
  double y = 1.0;  ///< the output's
};

/// The powers of two nearest the RMS of the records' deviations from (u0, y0), input and output
/// (1 for a signal that is all zero): identify()'s units. With ni integrators the output's is the RMS
/// of its ni-th difference (measured on the integrating friction system: in the output's own RMS the
/// velocity's curve came out too small for the refinement to move, NRMSE 0.035 against 2e-15).
template <typename Scalar>
DataScale data_scale(const CheckedRecords<Scalar>& records, double u0, double y0, Eigen::Index ni = 0) {
  double u_squares = 0.0, y_squares = 0.0, samples = 0.0;
  for (const auto& record : records) {
    u_squares += static_cast<double>((record.u.array() - static_cast<Scalar>(u0)).matrix().squaredNorm());
    const auto deviations = (record.y.array() - static_cast<Scalar>(y0)).matrix();
    if (ni == 0) {
      y_squares += static_cast<double>(deviations.squaredNorm());
    } else {  // the ni-th difference, its mean square counted over the record's length
      Eigen::Matrix<Scalar, Eigen::Dynamic, 1> y = deviations;
      for (Eigen::Index n = 0; n < ni && y.size() > 1; ++n) y = (y.tail(y.size() - 1) - y.head(y.size() - 1)).eval();
      double squares = static_cast<double>(y.squaredNorm());
      if (y.size() != record.y.size()) squares *= static_cast<double>(record.y.size()) / static_cast<double>(y.size());
      y_squares += squares;
    }
    samples += static_cast<double>(record.u.size());
  }
  const auto nearest_power_of_two = [samples](double squares) {
    const double rms = std::sqrt(squares / samples);
    return rms > 0.0 && std::isfinite(rms) ? std::exp2(std::round(std::log2(rms))) : 1.0;
  };
  return {nearest_power_of_two(u_squares), nearest_power_of_two(y_squares)};
}

/// The recursive estimator's scale measurement: the mean squares of u - u0 and of y - y0's ni-th
/// difference over the first `length` samples from the first one whose input moves (u != u0), and
/// those samples themselves, in order, for the recursion to catch up on once it has the scale: it
/// then runs from rest over them as if it had had the scale from the start. (Started on the sample
/// after them instead, from the zero estimate's free run, the first errors were the whole response,
/// and on 9 of 23 known systems the recursion settled in a wrong minimum.) The samples before the
/// input first moves are not kept: the model is at rest there whatever its parameters. Exact RMS,
/// not powers of two: the model is not rescaled, so nothing needs them, and data in other units then
/// give the same normalised recursion to rounding. Allocates at construction only.
template <typename Scalar>
class ScaleMeasurement {
 public:
  /// \param length the samples measured from the first moving input, >= 1
  /// \param ni the model's integrators, 0..2: the output's scale is its ni-th difference's
  ScaleMeasurement(Eigen::Index length, Eigen::Index ni)
      : m_length(length), m_ni(ni), m_u(static_cast<std::size_t>(length) + 1), m_y(m_u.size()) {}

  /// Back to no samples.
  void reset() noexcept {
    m_measured = m_first = m_pending = 0;
    m_u_squares = m_y_squares = 0.0;
    m_last[0] = m_last[1] = 0.0;
  }

  /// One sample's deviations from the operating point while measuring: kept (from the first moving
  /// input on) and measured; the differences start from rest.
  void push(Scalar u, Scalar y) noexcept {
    if (m_measured == 0 && u == Scalar(0)) return;  // at rest before the input first moves
    const double output = static_cast<double>(y);
    const double difference = m_ni == 0   ? output
                              : m_ni == 1 ? output - m_last[0]
                                          : output - 2.0 * m_last[0] + m_last[1];
    m_last[1] = m_last[0];
    m_last[0] = output;
    m_u_squares += static_cast<double>(u) * static_cast<double>(u);
    m_y_squares += difference * difference;
    ++m_measured;
    queue(u, y);
  }

  /// Whether the measurement is complete: `length` samples measured. If the output has not moved
  /// in them, they are dropped and it starts over (the output has not responded yet; a scale of it
  /// would be none).
  /// \return true once the scale can be taken
  bool complete() noexcept {
    if (m_measured < m_length) return false;
    if (!(m_y_squares > 0.0 && std::isfinite(m_y_squares) && std::isfinite(m_u_squares))) {
      reset();
      return false;
    }
    return true;
  }

  /// The RMS of each signal over the samples measured (1 for one that has not moved, or none)
  /// \return the scales
  DataScale scale() const noexcept {
    const auto rms = [this](double squares) {
      const double value = std::sqrt(squares / static_cast<double>(m_measured));
      return value > 0.0 && std::isfinite(value) ? value : 1.0;
    };
    return m_measured > 0 ? DataScale{rms(m_u_squares), rms(m_y_squares)} : DataScale{};
  }

  /// Samples kept and not yet taken by pop()
  /// \return the count, at most length + 1
  Eigen::Index pending() const noexcept { return m_pending; }
  /// Keeps a sample after the measurement, behind the ones kept (at most one more than were taken).
  void queue(Scalar u, Scalar y) noexcept {
    const auto slot = static_cast<std::size_t>((m_first + m_pending) % static_cast<Eigen::Index>(m_u.size()));
    m_u[slot] = u;
    m_y[slot] = y;
    ++m_pending;
  }
  /// The oldest sample kept (pending() > 0), taken out.
  void pop(Scalar& u, Scalar& y) noexcept {
    const auto slot = static_cast<std::size_t>(m_first);
    u = m_u[slot];
    y = m_y[slot];
    m_first = (m_first + 1) % static_cast<Eigen::Index>(m_u.size());
    --m_pending;
  }

 private:
  Eigen::Index m_length;
  Eigen::Index m_ni;
  std::vector<Scalar> m_u, m_y;  // a ring of length + 1 samples: the kept ones, oldest at m_first
  Eigen::Index m_measured = 0, m_first = 0, m_pending = 0;
  double m_u_squares = 0.0, m_y_squares = 0.0;
  double m_last[2] = {0.0, 0.0};  // y(k-1), y(k-2), from rest
};

/// How each parameter carries the units of u and y, in theta's order: its size for data of scales
/// (su, sy) is sy^y_power su^u_power (its block's units in the model's description).
template <class Model>
struct ParameterUnitPowers {
  typename Model::Params y_power;  ///< the power of sy in each parameter
  typename Model::Params u_power;  ///< the power of su in each parameter

  /// The powers of `structure`'s parameters, read off rescaled() of a model whose parameters are all
  /// 1 (exact: rescaled by powers of two). Allocates; once, at an estimator's construction.
  /// \param structure the model (its orders and structure; its parameter values are not used)
  explicit ParameterUnitPowers(const Model& structure) {
    Model ones = structure;
    ones.set_theta(Model::Params::Ones(structure.num_params()));
    const auto log2 = [](const typename Model::Params& scaled) {
      return typename Model::Params((scaled.array().log() / std::log(2.0)).round().matrix());
    };
    y_power = log2(rescaled(ones, 1.0, 2.0).theta());
    u_power = log2(rescaled(ones, 2.0, 1.0).theta());
  }

  /// Each parameter's size for data of the given scales, into `scales` (num_params() entries
  /// already, so that nothing allocates).
  /// \param scale the data's scales
  /// \param scales d: sy^y_power su^u_power per parameter
  void scales(DataScale scale, typename Model::Params& scales) const noexcept {
    using Scalar = typename Model::Scalar;
    for (Eigen::Index i = 0; i < scales.size(); ++i) {
      scales[i] = static_cast<Scalar>(std::pow(scale.y, static_cast<double>(y_power[i])) *
                                      std::pow(scale.u, static_cast<double>(u_power[i])));
    }
  }
};

}  // namespace detail
}  // namespace bonl
