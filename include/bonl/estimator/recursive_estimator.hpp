#pragma once
// The generic recursive estimator (the paper's MRLSA), templated on the model: the model's KeyTerms
// build the key-term regressor and estimate the internal variables, Rls does the update.

#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

#include "../detail/validate.hpp"
#include "forgetting_schedule.hpp"
#include "method.hpp"
#include "rls.hpp"

namespace bonl {

struct EstimatorOptions {
  Method method = Method::Default;
  ForgettingSchedule forgetting = ForgettingSchedule::paper();
  double p0 = 1e6;  ///< P(0) = p0 I
  double c0 = 0.01; ///< initial backlash half-width (P-H-W only)
  /// Method::Default only: the internal variables are computed from a copy of theta refreshed every
  /// `internal_refresh` samples, not from the running estimate (see Estimator::update).
  Eigen::Index internal_refresh = 100;

  // Numerical safeguards (see "Reliability" in the README and docs/reliability.md).
  /// trace(P) is kept at or below trace_ceiling * trace(P(0)) = trace_ceiling * n * p0 by reducing
  /// the forgetting where it would grow P beyond that (no covariance wind-up under poor excitation).
  /// Must be >= 1; infinity turns it off (the paper's algorithm exactly as written). The default,
  /// 1, means "never less certain than at the start"; larger ceilings let P's condition number
  /// grow with them (at 100 the paper method's P lost positive definiteness to round-off in the
  /// 1e8-sample soak test, docs/reliability.md).
  double trace_ceiling = 1.0;
  /// After this many consecutive refused updates (UpdateStatus::NumericalFailure) the estimator
  /// resets P to p0 I itself, keeping theta (counted in health().recoveries). 0: never; the caller
  /// sees diverged() and calls recover() or reset().
  Eigen::Index recover_after = 0;

  void validate() const {
    forgetting.validate();
    detail::require(std::isfinite(p0) && p0 > 0.0, "p0 (initial covariance scale) must be finite and > 0");
    detail::require(std::isfinite(c0) && c0 >= 0.0, "c0 (initial backlash half-width) must be finite and >= 0");
    detail::require(internal_refresh >= 1, "internal_refresh must be >= 1");
    detail::require(trace_ceiling >= 1.0, "trace_ceiling must be >= 1 (a multiple of trace(P(0))) or infinity, got " +
                                              detail::format_number(trace_ceiling));
    detail::require(recover_after >= 0, "recover_after must be >= 0 (0: never recover automatically)");
  }
};

/// What one online update did.
enum class UpdateStatus {
  Updated,            ///< theta and P were updated
  NoInformation,      ///< the sample says nothing about theta (inside the backlash gap); internals advanced
  RejectedNonFinite,  ///< u or y was NaN or infinite; the estimator's state is untouched
  NumericalFailure,   ///< the update would have broken P, or the internal variables left the finite
                      ///< numbers; theta and P kept, diverged() set
};

/// Counters since the last reset(): what the safeguards did.
struct EstimatorHealth {
  bool diverged = false;                   ///< a NumericalFailure happened (cleared by recover()/reset())
  Eigen::Index failures = 0;               ///< updates refused for numerical reasons
  Eigen::Index consecutive_failures = 0;   ///< refused in a row, up to the last update
  Eigen::Index forgetting_limited = 0;     ///< updates whose forgetting the trace ceiling reduced
  Eigen::Index recoveries = 0;             ///< automatic covariance resets (EstimatorOptions::recover_after)
  Eigen::Index internal_restarts = 0;      ///< internal variables restarted because they became non-finite
};

/// Recorded history of an estimator (Estimator::start_recording): one column / entry per update,
/// oldest first, at most `capacity` of the newest.
template <typename Scalar>
struct EstimatorTrajectory {
  std::vector<Eigen::Index> sample;  ///< running sample number since reset() (not since the pass)
  Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> theta;  ///< num_params x samples, after each update
  std::vector<Scalar> internal;       ///< the model's internal variable x(k) the update used (NaN for ARX)
  std::vector<UpdateStatus> status;
};

namespace detail {
template <class M, class = void>
struct is_model : std::false_type {};
template <class M>
struct is_model<M, std::void_t<typename M::Scalar, typename M::Params, typename M::KeyTerms, typename M::VectorX,
                               decltype(M::kNumParams), decltype(M::kHasInternalVariables),
                               decltype(std::declval<const M&>().theta()),
                               decltype(std::declval<const M&>().num_params())>> : std::true_type {};
}  // namespace detail

template <class Model>
class Estimator {
  static_assert(detail::is_model<Model>::value,
                "bonl::Estimator<Model>: Model must provide Scalar, Params, VectorX, KeyTerms, kNumParams, "
                "kHasInternalVariables, theta() and num_params() (see the model concept in bonl/models.hpp)");

 public:
  using Scalar = typename Model::Scalar;
  using Params = typename Model::Params;
  using Covariance = Eigen::Matrix<Scalar, Model::kNumParams, Model::kNumParams>;

  /// `structure` gives the orders; the estimate starts from the paper's initial values (zero, c = c0).
  explicit Estimator(const Model& structure, const EstimatorOptions& options = {})
      : m_model(structure), m_terms(structure), m_rls(structure.num_params(), Scalar(validated(options).p0)),
        m_phi(Params::Zero(structure.num_params())), m_theta_internal(m_phi), m_options(options) {
    reset();
  }

  /// Everything back to the start: initial theta, P = p0 I, internals at rest.
  void reset() {
    m_rls.reset(m_model.initial_estimate(Scalar(m_options.c0)), Scalar(m_options.p0));
    start_pass();
    clear_history();
  }

  /// Restarts from a given estimate (a warm start, e.g. a previously identified model's theta):
  /// P = p0 I, internals at rest.
  template <typename T>
  void reset(const Eigen::MatrixBase<T>& theta0) {
    m_rls.reset(theta0, Scalar(m_options.p0));
    start_pass();
    clear_history();
  }

  /// Leaves the diverged state: P = p0 I, theta kept (the standard covariance reset); the internal
  /// variables continue. The counters in health() are kept.
  void recover() {
    reset_covariance();
    m_health.diverged = false;
  }

  /// Records theta, the internal variable and the status of each of the next updates, keeping the
  /// newest `capacity` (a ring buffer, allocated here once: update() still never allocates).
  void start_recording(Eigen::Index capacity) {
    detail::require(capacity >= 1, "recording capacity must be >= 1");
    m_record_theta.resize(m_rls.size(), capacity);
    m_record_sample.assign(static_cast<std::size_t>(capacity), 0);
    m_record_internal.assign(static_cast<std::size_t>(capacity), Scalar(0));
    m_record_status.assign(static_cast<std::size_t>(capacity), UpdateStatus::Updated);
    m_record_next = 0;
    m_recorded = 0;
  }
  /// Stops recording and frees the buffer.
  void stop_recording() {
    m_record_theta.resize(m_rls.size(), 0);
    m_record_sample.clear();
    m_record_internal.clear();
    m_record_status.clear();
    m_record_next = 0;
    m_recorded = 0;
  }
  bool recording() const noexcept { return m_record_theta.cols() > 0; }
  /// What was recorded so far, oldest first.
  EstimatorTrajectory<Scalar> trajectory() const {
    EstimatorTrajectory<Scalar> out;
    const Eigen::Index capacity = m_record_theta.cols();
    const Eigen::Index count = std::min(m_recorded, capacity);
    out.theta.resize(m_rls.size(), count);
    const Eigen::Index first = m_recorded > capacity ? m_record_next : 0;
    for (Eigen::Index i = 0; i < count; ++i) {
      const Eigen::Index slot = (first + i) % capacity;
      const auto index = static_cast<std::size_t>(slot);
      out.theta.col(i) = m_record_theta.col(slot);
      out.sample.push_back(m_record_sample[index]);
      out.internal.push_back(m_record_internal[index]);
      out.status.push_back(m_record_status[index]);
    }
    return out;
  }

  /// A new pass over a record (the paper's step 5, "return to step 2"): theta and P carry on from
  /// where the last pass ended; the forgetting schedule and the internal variables restart from rest.
  /// (Resetting P instead made each pass a fresh start from a 100-sample estimate; for P-H-W that
  /// diverged over passes.)
  void start_pass() {
    restart_internals();
    m_sample = 0;
  }

  /// One sample. Never throws and, for fixed sizes, never allocates. A non-finite u or y is
  /// rejected and leaves the state untouched.
  UpdateStatus update(Scalar u, Scalar y) noexcept {
    if (!std::isfinite(u) || !std::isfinite(y)) return UpdateStatus::RejectedNonFinite;
    const Method method = m_options.method;
    // Paper: internal variables from the running estimate, as eqs. (24)-(27) write it. Default: from
    // a copy refreshed every internal_refresh samples. While P is large the running estimate swings,
    // and internal variables computed from it feed those swings back into the regressor, which
    // amplifies even round-off (seen from the true parameters with p0 = 1e6: the estimate left the
    // truth within 50 samples). With the copy, each block is a linear least-squares problem.
    const Params& theta = method == Method::Paper ? m_rls.theta() : m_theta_internal;
    const Scalar x = m_terms.begin(theta, u, method, m_phi);
    if (!std::isfinite(x)) return internal_divergence(x);
    m_prediction = m_terms.predicted_output(theta, x);
    Scalar target = Scalar(0);
    UpdateStatus status = UpdateStatus::NoInformation;
    if (m_terms.regress(theta, x, y, method, m_phi, target)) {
      if (m_rls.update(m_phi, target, Scalar(m_options.forgetting.at(m_sample)), m_max_trace)) {
        m_terms.constrain(m_rls.mutable_theta(), method);
        status = UpdateStatus::Updated;
        m_health.consecutive_failures = 0;
        if (m_rls.forgetting_limited()) ++m_health.forgetting_limited;
      } else {
        status = failure();
      }
    }
    if (method == Method::Paper) {
      m_terms.end(m_rls.theta(), m_phi, u, y, method);
    } else {
      m_terms.end(m_theta_internal, m_phi, u, y, method);
      if (++m_since_refresh >= m_options.internal_refresh) {
        m_theta_internal = m_rls.theta();
        m_since_refresh = 0;
      }
    }
    return finish(status, x);
  }

  const Params& theta() const noexcept { return m_rls.theta(); }
  Covariance covariance() const { return m_rls.covariance(); }
  /// The current estimate as a model, projected onto the model's valid set (the paper method's
  /// P-H-W estimate can have c < 0, which simulates as c = 0).
  Model model() const {
    Params theta = m_rls.theta();
    m_terms.constrain(theta, Method::Default);
    Model model = m_model;
    model.set_theta(theta);
    return model;
  }
  /// The one-step prediction of the last sample's y, made before the update with the parameters
  /// the update used: y - last_prediction() is the innovation (for monitoring and fault detection).
  Scalar last_prediction() const noexcept { return m_prediction; }
  /// Samples since the last pass started.
  Eigen::Index samples() const noexcept { return m_sample; }
  /// True once an update was refused for numerical reasons (cleared by recover() and reset()).
  bool diverged() const noexcept { return m_health.diverged; }
  /// What the safeguards did since the last reset().
  const EstimatorHealth& health() const noexcept { return m_health; }
  const EstimatorOptions& options() const noexcept { return m_options; }

 private:
  static const EstimatorOptions& validated(const EstimatorOptions& options) {
    options.validate();
    return options;
  }

  void clear_history() {
    m_health = EstimatorHealth{};
    m_max_trace = Scalar(m_options.trace_ceiling * m_options.p0 * double(m_rls.size()));
    m_record_next = 0;
    m_recorded = 0;
    m_total_samples = 0;
    m_prediction = Scalar(0);
  }

  void restart_internals() noexcept {
    m_terms.reset();
    m_theta_internal = m_rls.theta();
    m_since_refresh = 0;
  }

  /// recover() without clearing diverged(). The data histories are kept: they are fine unless
  /// non-finite, which update() handles itself. Cannot throw: p0 was validated, P keeps its size.
  void reset_covariance() noexcept {
    m_rls.reset_covariance(Scalar(m_options.p0));
    m_theta_internal = m_rls.theta();
    m_since_refresh = 0;
    m_health.consecutive_failures = 0;
  }

  UpdateStatus failure() noexcept {
    m_health.diverged = true;
    ++m_health.failures;
    ++m_health.consecutive_failures;
    return UpdateStatus::NumericalFailure;
  }

  /// The internal simulation left the finite numbers (possible with the paper's internals from an
  /// unstable running estimate): restart it from rest rather than feed NaN into every later regressor.
  UpdateStatus internal_divergence(Scalar x) noexcept {
    const UpdateStatus status = failure();
    ++m_health.internal_restarts;
    restart_internals();
    return finish(status, x);
  }

  UpdateStatus finish(UpdateStatus status, Scalar x) noexcept {
    if (m_options.recover_after > 0 && m_health.consecutive_failures >= m_options.recover_after) {
      reset_covariance();
      ++m_health.recoveries;
    }
    if (m_record_theta.cols() > 0) {
      const auto slot = static_cast<std::size_t>(m_record_next);
      m_record_theta.col(m_record_next) = m_rls.theta();
      m_record_sample[slot] = m_total_samples;
      m_record_internal[slot] = Model::kHasInternalVariables ? x : std::numeric_limits<Scalar>::quiet_NaN();
      m_record_status[slot] = status;
      m_record_next = (m_record_next + 1) % m_record_theta.cols();
      ++m_recorded;
    }
    ++m_sample;
    ++m_total_samples;
    return status;
  }

  Model m_model;
  typename Model::KeyTerms m_terms;
  Rls<Scalar, Model::kNumParams> m_rls;
  Params m_phi;
  Params m_theta_internal;
  EstimatorOptions m_options;
  Eigen::Index m_since_refresh = 0;
  Eigen::Index m_sample = 0;
  Eigen::Index m_total_samples = 0;
  Scalar m_max_trace = std::numeric_limits<Scalar>::infinity();
  Scalar m_prediction = Scalar(0);
  EstimatorHealth m_health;
  Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> m_record_theta;
  std::vector<Eigen::Index> m_record_sample;
  std::vector<Scalar> m_record_internal;
  std::vector<UpdateStatus> m_record_status;
  Eigen::Index m_record_next = 0;
  Eigen::Index m_recorded = 0;
};

}  // namespace bonl
