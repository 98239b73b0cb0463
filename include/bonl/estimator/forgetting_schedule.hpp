#pragma once
// Forgetting factor over time. Two kinds:
// - steps: `initial` for the first `initial_samples` samples, `final` afterwards. The paper uses 0.98
//   for 200 samples (forget the poor start quickly) and 1 afterwards (least sensitive to noise);
//   constant(lambda) is the special case of one step.
// - adaptive memory (the output-error method's default): lambda = 1 - 1 / L with a memory length L
//   that grows with the record while the prediction error is stationary, and is cut back while the
//   error is still falling (the estimate is converging: the old samples were linearised at a worse
//   estimate), rising markedly (the plant changed), or as large as the output's own variation (the
//   model explains little yet). See AdaptiveMemory below and docs/explanation/algorithm.md.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <string>

#include "../detail/validate.hpp"

namespace bonl {

/// The forgetting factor lambda over time, of one of two kinds: steps (`initial` for the first
/// `initial_samples` samples, `final` afterwards: the paper's 0.98 for 200 samples, then 1) or an
/// adaptive memory (the output-error method's default: lambda = 1 - 1 / L with a memory L that grows
/// while the prediction error is stationary and is cut back while it changes). docs/explanation/algorithm.md.
struct ForgettingSchedule {
  /// The two kinds: steps, adaptive memory.
  enum class Kind { Steps, AdaptiveMemory };
  Kind kind = Kind::Steps;  ///< which kind this schedule is

  // Kind::Steps
  double initial = 0.98;               ///< lambda for samples 0 .. initial_samples - 1
  Eigen::Index initial_samples = 200;  ///< how long `initial` applies
  double final = 1.0;                  ///< lambda afterwards

  // Kind::AdaptiveMemory (memory lengths in samples; lambda = 1 - 1 / memory)
  double initial_memory = 50;    ///< memory at the first sample
  double changing_memory = 100;  ///< memory is cut back to this while the prediction error changes
  double memory_growth = 0.5;    ///< memory added per sample otherwise (0.5: memory ~ samples / 2)
  double short_window = 50;      ///< time constant of the recent mean squared prediction error
  double long_window = 200;      ///< time constant of the reference mean squared prediction error
  double change_ratio = 2.0;     ///< "changing": one mean square more than change_ratio times the other
  double poor_fit = 0.25;        ///< "explains little": recent mean square error > poor_fit x output variance

  /// The paper's steps: 0.98 for 200 samples, then 1
  /// \return the schedule
  static ForgettingSchedule paper() { return {}; }
  /// A constant forgetting factor lambda, in (0, 1] (checked by validate()).
  /// \param lambda the factor for every sample
  /// \return a Steps schedule with initial = final = lambda
  static ForgettingSchedule constant(double lambda) {
    ForgettingSchedule schedule;
    schedule.initial = schedule.final = lambda;
    schedule.initial_samples = 0;
    return schedule;
  }
  /// The adaptive memory with its default settings. \return the schedule
  static ForgettingSchedule adaptive_memory() {
    ForgettingSchedule schedule;
    schedule.kind = Kind::AdaptiveMemory;
    return schedule;
  }

  /// Whether this is the adaptive-memory kind
  /// \return true for Kind::AdaptiveMemory
  bool adaptive() const noexcept { return kind == Kind::AdaptiveMemory; }
  /// Kind::Steps only: lambda at a sample.
  /// \param sample the sample's number since the pass started
  /// \return lambda, initial or final
  double at(Eigen::Index sample) const noexcept { return sample < initial_samples ? initial : final; }

  /// Throws std::invalid_argument for a setting out of range (a lambda outside (0, 1], a negative
  /// length, a memory, window or ratio below its minimum or not finite).
  void validate() const {
    const auto in_range = [](double lambda) { return std::isfinite(lambda) && lambda > 0.0 && lambda <= 1.0; };
    detail::require(in_range(initial), "forgetting factor must be in (0, 1], got " + detail::format_number(initial));
    detail::require(in_range(final), "forgetting factor must be in (0, 1], got " + detail::format_number(final));
    detail::require(initial_samples >= 0, "forgetting schedule: initial_samples must be >= 0");
    const auto at_least = [](double value, double minimum, const char* name) {
      detail::require(std::isfinite(value) && value >= minimum,
                      std::string("adaptive memory: ") + name + " must be finite and >= " +
                          detail::format_number(minimum) + ", got " + detail::format_number(value));
    };
    at_least(initial_memory, 1.0, "initial_memory");
    at_least(changing_memory, 1.0, "changing_memory");
    at_least(memory_growth, 0.0, "memory_growth");
    at_least(short_window, 1.0, "short_window");
    at_least(long_window, 1.0, "long_window");
    at_least(change_ratio, 1.0, "change_ratio");
    at_least(poor_fit, 0.0, "poor_fit");
  }
};

namespace detail {

/// The running state of Kind::AdaptiveMemory: two exponentially weighted mean squares of the a-priori
/// prediction error (short and long windows) decide whether the error is changing, and one of the
/// output's variance (long window) whether the model explains much of it yet; the memory is cut back
/// to `changing_memory` while the error changes or the fit is poor, and grows by `memory_growth` per
/// sample otherwise.
/// Without noise the error keeps falling as the estimate converges, so old samples keep being
/// forgotten and the estimate converges geometrically; with noise the error levels off at the noise
/// and the memory grows with the record (near the efficiency of lambda = 1).
class AdaptiveMemory {
 public:
  void reset(const ForgettingSchedule& schedule) noexcept {
    m_memory = schedule.initial_memory;
    m_recent = m_reference = -1.0;  // set by the first sample
    // The windows as rates, once: per sample they would be divisions on the update's path.
    m_recent_rate = 1.0 / schedule.short_window;
    m_reference_rate = 1.0 / schedule.long_window;
  }

  /// The forgetting factor for a sample with output y and a-priori prediction error `error` (both finite).
  double next(const ForgettingSchedule& schedule, double y, double error) noexcept {
    const double square = error * error;
    if (m_recent < 0.0) {
      m_recent = m_reference = square;
      m_mean = y;
      m_variance = 0.0;
    }
    m_recent += (square - m_recent) * m_recent_rate;
    m_reference += (square - m_reference) * m_reference_rate;
    m_mean += (y - m_mean) * m_reference_rate;
    m_variance += ((y - m_mean) * (y - m_mean) - m_variance) * m_reference_rate;
    const double ratio = schedule.change_ratio;
    const bool changing =
        ratio * m_recent < m_reference || m_recent > ratio * m_reference || m_recent > schedule.poor_fit * m_variance;
    m_memory = changing ? std::min(m_memory + schedule.memory_growth, schedule.changing_memory)
                        : m_memory + schedule.memory_growth;
    return 1.0 - 1.0 / std::max(m_memory, 1.0);
  }

  double memory() const noexcept { return m_memory; }

 private:
  double m_memory = 1.0;
  double m_recent = -1.0;
  double m_reference = -1.0;
  double m_mean = 0.0;
  double m_variance = 0.0;
  double m_recent_rate = 1.0;
  double m_reference_rate = 1.0;
};

}  // namespace detail
}  // namespace bonl
