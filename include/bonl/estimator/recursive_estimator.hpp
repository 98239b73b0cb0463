#pragma once
// The generic recursive estimator (the paper's MRLSA), templated on the model. Per sample the model
// gives one step of the view the method chooses (models/model_steps.hpp): its key-term regression
// (equation_error, paper) or one step of its free run with the output's sensitivities (output_error);
// Rls does the update.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "../detail/indirect.hpp"
#include "../detail/validate.hpp"
#include "../models/model_steps.hpp"
#include "forgetting_schedule.hpp"
#include "method.hpp"
#include "normalisation.hpp"
#include "rls.hpp"
#include "window_refinement.hpp"

namespace bonl {

/// The online estimator's options, chosen at construction: the method, the forgetting, P(0), the
/// numerical safeguards; unset optionals take the method's defaults (docs/reference/conventions.md).
struct EstimatorOptions {
  Method method = Method::OutputError;  ///< the estimation method (the output-error method by default)
  /// Unset, the method's default: ForgettingSchedule::adaptive_memory() for output_error, the
  /// paper's schedule (0.98 for 200 samples, then 1) for equation_error and paper.
  std::optional<ForgettingSchedule> forgetting;
  /// P(0) = p0 I, in the recursion's coordinates (normalised ones unless `normalise` is false or the
  /// method is the paper's: EstimatorOptions::normalise). Unset, the method's default: 10 for
  /// output_error (its regressor is a gradient of the simulated output, and larger first steps
  /// destabilise the simulation it is taken along), the paper's 1e6 for equation_error and paper
  /// (linear regressions: P(0) large says "no prior").
  std::optional<double> p0;
  /// Method::EquationError only: the internal variables are computed from a copy of theta refreshed
  /// every `internal_refresh` samples, not from the running estimate (see Estimator::update).
  Eigen::Index internal_refresh = 100;

  // Numerical safeguards (docs/reference/numerical_safeguards.md and docs/lab/reliability.md).
  /// trace(P) is kept at or below trace_ceiling * trace(P(0)) = trace_ceiling * n * p0 by reducing
  /// the forgetting where it would grow P beyond that (no covariance wind-up under poor excitation).
  /// Must be >= 1; infinity turns it off (the paper's algorithm exactly as written). Unset, the
  /// method's default: 1 for equation_error and paper, "never less certain than at the start" (larger
  /// ceilings let P's condition number grow with them: at 100 the paper method's P lost positive
  /// definiteness to round-off in the 1e8-sample soak test, docs/lab/reliability.md); 10 for output_error,
  /// whose P(0) is small and whose short memory while converging needs room in the weakly excited
  /// directions (docs/explanation/algorithm.md: 100 made P indefinite in the soak test).
  std::optional<double> trace_ceiling;
  /// After this many consecutive refused updates (UpdateStatus::NumericalFailure) the estimator
  /// resets P to p0 I itself, keeping theta (counted in health().recoveries). 0: never; the caller
  /// sees diverged() and calls recover() or reset().
  Eigen::Index recover_after = 0;

  // Method::OutputError only.
  /// The linear block's estimated poles are kept inside |z| < stability_radius: an update that would
  /// move one outside is shortened (halved up to 10 times, else not taken), counted in
  /// health().projections. In (0, 1]; 0.999 admits time constants up to about 1000 samples.
  double stability_radius = 0.999;
  /// Levenberg-Marquardt over windows of recent samples, in slices beside the recursion, whose
  /// estimate it replaces where it simulates newer data better (estimator/window_refinement.hpp).
  WindowRefinementOptions window;

  /// Work in the data's own scale, so that p0, the trace ceiling and the window's damping mean the
  /// same on volts, milliamperes, bar or pascals (estimator/normalisation.hpp). The estimator: the
  /// RMS of u - u0 and y - y0 (with integrators, of y's differences) is measured over the first
  /// Estimator::kScaleSamples samples from the first whose input moves (updates return
  /// NoInformation meanwhile); then the recursion runs over them from rest, two samples per update
  /// until it has caught up, in coordinates where every parameter is of order one for data of that
  /// scale, and the results come back in the data's units. identify(): where it
  /// refines, on the data divided by the power of two nearest each signal's RMS over all records,
  /// the model returned in the data's units (rescaled()). Method::Paper is the paper's algorithm as
  /// written, in the data's units: it is never normalised.
  bool normalise = true;
  /// The output-error method's checkpoint (Estimator::watch_checkpoint; docs/reference/numerical_safeguards.md):
  /// an earlier estimate it returns to where that predicts far better. On by default; identify()'s
  /// recursive starts run without it (estimate_recursively).
  bool checkpoint = true;

  /// The forgetting schedule, p0 and trace ceiling in force: the ones set, or the method's defaults.
  /// \return the forgetting schedule
  ForgettingSchedule resolved_forgetting() const {
    if (forgetting) return *forgetting;
    return method == Method::OutputError ? ForgettingSchedule::adaptive_memory() : ForgettingSchedule::paper();
  }
  /// P0 in force: the one set, or the method's default (10 output-error, 1e6 the others)
  /// \return p0, > 0
  double resolved_p0() const { return p0 ? *p0 : (method == Method::OutputError ? 10.0 : 1e6); }
  /// The trace ceiling in force: the one set, or the method's default (10 output-error, 1 the others).
  /// \return the trace ceiling, >= 1 (infinity: none)
  double resolved_trace_ceiling() const {
    return trace_ceiling ? *trace_ceiling : (method == Method::OutputError ? 10.0 : 1.0);
  }

  /// Throws std::invalid_argument for a setting out of range (docs/reference/bad_input.md lists them).
  void validate() const {
    resolved_forgetting().validate();
    const double p0_value = resolved_p0();
    detail::require(std::isfinite(p0_value) && p0_value > 0.0,
                    "p0 (initial covariance scale) must be finite and > 0, got " + detail::format_number(p0_value));
    detail::require(internal_refresh >= 1, "internal_refresh must be >= 1");
    const double ceiling = resolved_trace_ceiling();
    detail::require(ceiling >= 1.0, "trace_ceiling must be >= 1 (a multiple of trace(P(0))) or infinity, got " +
                                        detail::format_number(ceiling));
    detail::require(recover_after >= 0, "recover_after must be >= 0 (0: never recover automatically)");
    detail::require(stability_radius > 0.0 && stability_radius <= 1.0,
                    "stability_radius must be in (0, 1], got " + detail::format_number(stability_radius));
    window.validate();
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
  bool diverged = false;                  ///< a NumericalFailure happened (cleared by recover()/reset())
  Eigen::Index failures = 0;              ///< updates refused for numerical reasons
  Eigen::Index consecutive_failures = 0;  ///< refused in a row, up to the last update
  Eigen::Index forgetting_limited = 0;    ///< updates whose forgetting the trace ceiling reduced
  Eigen::Index recoveries = 0;            ///< automatic covariance resets (EstimatorOptions::recover_after)
  Eigen::Index internal_restarts = 0;     ///< internal variables restarted because they became non-finite
  Eigen::Index projections = 0;           ///< output_error updates shortened to keep the linear block stable
  Eigen::Index checkpoint_returns = 0;    ///< output_error: returns to the checkpoint, which predicted far better
  WindowRefinementCounts window;          ///< what the output-error method's window refinement did
};

/// Recorded history of an estimator (Estimator::start_recording): one column / entry per update,
/// oldest first, at most `capacity` of the newest.
template <typename Scalar>
struct EstimatorTrajectory {
  std::vector<Eigen::Index> sample;  ///< running sample number since reset() (not since the pass)
  Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> theta;  ///< num_params x samples, after each update
  std::vector<Scalar> internal;      ///< the model's internal variable x(k) the update used (NaN for ARX)
  std::vector<UpdateStatus> status;  ///< what each update did
};

namespace detail {
template <class M, class = void>
struct is_model : std::false_type {};
template <class M>
struct is_model<M,
                std::void_t<typename M::Scalar, typename M::Params, typename M::KeyTerms, typename M::OutputErrorTerms,
                            typename M::VectorX, decltype(M::kNumParams), decltype(M::kHasInternalVariables),
                            decltype(std::declval<const M&>().theta()), decltype(std::declval<const M&>().num_params()),
                            decltype(std::declval<const M&>().constrain(std::declval<typename M::Params&>()))>>
    : std::true_type {};
}  // namespace detail

/// The online estimator of a model's parameters, one sample per update() (the paper's recursive
/// identification, section 4, and the output-error method): Model is one of the models (the
/// concept's members are checked at compile time), the per-sample update allocation-free and
/// noexcept, with numerical safeguards (docs/reference/numerical_safeguards.md). By default it works
/// in the data's own scale (EstimatorOptions::normalise) and refines its estimate over windows of
/// recent samples from two starts (EstimatorOptions::window).
template <class Model>
class Estimator {
  static_assert(
      detail::is_model<Model>::value,
      "bonl::Estimator<Model>: Model must provide Scalar, Params, VectorX, KeyTerms, OutputErrorTerms, kNumParams, "
      "kHasInternalVariables, theta(), num_params() and constrain() (see the model concept in bonl/models.hpp)");

 public:
  using Scalar = typename Model::Scalar;  ///< the model's arithmetic type
  using Params = typename Model::Params;  ///< the model's parameter vector
  using Covariance = Eigen::Matrix<Scalar, Model::kNumParams,
                                   Model::kNumParams>;  ///< the covariance P (fixed size when the model's orders are)
  using Settings = ModelSettings<Model>;  ///< what the model adds to the options (NoEstimatorSettings if nothing)

  /// `structure` gives the orders; `settings` are the model's own (P-H-W: c0 and backlash_hold). The
  /// estimate starts from zero for the output-error method and from the model's initial_estimate
  /// (P-H-W: c = c0, a fraction of the output's scale where normalised) for the equation-error and
  /// paper methods. Allocates here (the window's buffers, the equation-error recursion beside), never
  /// in update().
  /// \param structure the model whose orders (and knots, thresholds) are estimated; its parameters are not used
  /// \param options the method, forgetting, P(0) and safeguards; checked here (std::invalid_argument)
  /// \param settings the model's own estimator settings; checked here (std::invalid_argument)
  explicit Estimator(const Model& structure, const EstimatorOptions& options = {}, const Settings& settings = {});

  /// Everything back to the start: initial theta, P = p0 I, internals at rest; where normalised, the
  /// data's scale measured anew.
  void reset();

  /// Restarts from a given estimate (a warm start, e.g. a previously identified model's theta):
  /// P = p0 I, internals at rest; where normalised, the data's scale measured anew, the estimate
  /// held at theta0 meanwhile.
  /// \param theta0 the estimate to start from, num_params() finite values in the model's parameter order
  template <typename T>
  void reset(const Eigen::MatrixBase<T>& theta0) {
    restart_from(theta0);
    m_default_start = false;
    if (m_equation_error) m_equation_error->reset(theta0);
  }

  /// Leaves the diverged state: P = p0 I, theta kept (the standard covariance reset); the internal
  /// variables continue. The counters in health() are kept.
  void recover() {
    reset_covariance();
    m_health.diverged = false;
  }

  /// Records theta, the internal variable and the status of each of the next updates, keeping the
  /// newest `capacity` (a ring buffer, allocated here once: update() still never allocates).
  /// \param capacity how many of the newest updates to keep, >= 1
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
  /// Whether start_recording() is recording the updates
  /// \return true between start_recording() and stop_recording()
  bool recording() const noexcept { return m_record_theta.cols() > 0; }
  /// What was recorded so far, oldest first.
  /// \return a copy of the recorded updates, at most the capacity's newest
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
  /// diverged over passes.) The samples of the last record the recursion has yet to take are taken
  /// first (catch_up()).
  void start_pass();

  /// Takes now what the recursion has yet to: a scale measurement under way ends with the samples
  /// measured so far, and every sample kept is processed (update() does it two samples per update).
  /// For a record's end offline; start_pass() calls it. Never throws; does not allocate.
  void catch_up() noexcept;

  /// Whether the estimator is still measuring the data's scale (EstimatorOptions::normalise): its
  /// updates return NoInformation and the estimate stays where it started.
  /// \return true until kScaleSamples samples have been measured from the first moving input
  bool measuring_scale() const noexcept { return m_measuring; }
  /// The samples the recursion has yet to take: kept while the scale was measured, taken two per
  /// update after it; theta() lags the data by them.
  /// \return the count, 0 once caught up (and always where not normalised)
  Eigen::Index pending_samples() const noexcept { return m_measurement.pending(); }
  /// The data's scale the recursion works in: the RMS of u - u0 and of y - y0 (with integrators, of
  /// its differences) over the samples measured; 1 and 1 where not normalised or still measuring.
  /// \return the input's and the output's scale
  detail::DataScale data_scale() const noexcept { return m_scale; }

  /// The samples, from the first whose input moves, that the data's scale is measured over before
  /// the recursion starts (EstimatorOptions::normalise). Why 100: a few level changes of a typical
  /// identification input and the output's response to them; the scale needs to be right to a
  /// factor of a few, not more, and the recursion lags the data by as many samples for as many
  /// updates after.
  static constexpr Eigen::Index kScaleSamples = 100;

  /// One sample. Never throws and, for fixed sizes, never allocates. A non-finite u or y is
  /// rejected and leaves the state untouched. Where normalised, the first samples are kept until
  /// the data's scale is measured and then taken two per update (measuring_scale(),
  /// pending_samples()): what the update returns is then about the last sample it took.
  /// \param u the input u(k), the command that drove the sample
  /// \param y the measured output y(k)
  /// \return what the update did with the sample (Updated, NoInformation, RejectedNonFinite,
  /// NumericalFailure)
  UpdateStatus update(Scalar u, Scalar y) noexcept;

 private:
  /// One sample (deviations from the operating point) through the recursion.
  UpdateStatus process(Scalar u, Scalar y) noexcept {
    const Method method = m_options.method;
    if (method == Method::OutputError) return update_output_error(u, y);
    // Paper: internal variables from the running estimate, as eqs. (24)-(27) write it. Default: from
    // a copy refreshed every internal_refresh samples. While P is large the running estimate swings,
    // and internal variables computed from it feed those swings back into the regressor, which
    // amplifies even round-off (seen from the true parameters with p0 = 1e6: the estimate left the
    // truth within 50 samples). With the copy, each block is a linear least-squares problem.
    // The paper's method stores the previous sample's internal variables a posteriori with this
    // theta, the estimate after the previous update (eq. 24).
    const Params& theta = method == Method::Paper ? m_theta : m_theta_internal;
    const auto regression = m_terms.step(theta, u, y);
    if (!std::isfinite(regression.internal)) return internal_divergence(regression.internal);
    m_prediction = regression.prediction;
    UpdateStatus status = UpdateStatus::NoInformation;
    if (regression.informative) {
      m_phi = regression.regressor.cwiseProduct(m_regressor_scale);
      if (m_rls.update(m_phi, regression.target * m_inverse_output_scale, forgetting_factor(y, y - m_prediction),
                       m_max_trace)) {
        m_theta = m_rls.theta().cwiseProduct(m_parameter_scale);
        // The paper's algorithm lets c go negative (it simulates as c = 0); the others keep theta valid.
        if (method != Method::Paper) {
          m_model.constrain(m_theta);
          store_theta();
        }
        status = UpdateStatus::Updated;
        m_health.consecutive_failures = 0;
        if (m_rls.forgetting_limited()) ++m_health.forgetting_limited;
      } else {
        status = failure();
      }
    }
    if (method != Method::Paper && ++m_since_refresh >= m_options.internal_refresh) {
      m_theta_internal = m_theta;
      m_since_refresh = 0;
    }
    return finish(status, regression.internal);
  }

  /// The oldest sample kept while measuring, through the recursion.
  UpdateStatus take_pending() noexcept {
    Scalar u, y;
    m_measurement.pop(u, y);
    return process(u, y);
  }

  /// The measurement is over (or cut short): the recursion starts in the coordinates of the scale
  /// measured, from the estimate it was given.
  void start_recursion() noexcept {
    m_measuring = false;
    set_scales(m_measurement.scale());
    // The method's own start (reset() without an estimate: P-H-W's c0, the Bouc-Wen feedback model's
    // alpha) is read in the recursion's coordinates, the same part of the data's scale in any units:
    // P-H-W's c(0) = c0 sy. (Read in the output's units, c0 = 0.01 moved the figures under noise by
    // 6% between units 1e3 apart on a P-H-W known system.)
    if (m_default_start) m_theta = m_theta.cwiseProduct(m_parameter_scale);
    m_rls.reset_covariance(Scalar(m_p0));
    store_theta();
    m_theta_internal = m_theta;
  }

 public:
  /// A record in one call: update(u[k], y[k]) for k = 0, 1, ... in order, and after each
  /// on_sample(k, status), where last_prediction() and theta() are that sample's. The same, bit for
  /// bit, as the loop; no allocation of its own. u and y: vectors of equal length, else
  /// std::invalid_argument before the first sample (nothing changed).
  /// \param u the inputs u(0), u(1), ...
  /// \param y the measured outputs, as many
  /// \param on_sample called as on_sample(k, status) after each sample's update
  template <typename U, typename Y, typename OnSample>
  void update(const Eigen::MatrixBase<U>& u, const Eigen::MatrixBase<Y>& y, OnSample&& on_sample) {
    if (u.cols() != 1 || y.cols() != 1) detail::fail("u and y must be vectors (one column each)");
    if (u.size() != y.size()) {
      detail::fail("u and y must have the same length (u has " + std::to_string(u.size()) + " samples, y " +
                   std::to_string(y.size()) + ")");
    }
    for (Eigen::Index k = 0; k < u.size(); ++k) on_sample(k, update(Scalar(u[k]), Scalar(y[k])));
  }

  /// The current estimate theta, in the model's parameter order: the recursion's, or with the window
  /// refinement, the window's estimate while it predicts the newest samples about as well
  /// (estimator/window_refinement.hpp).
  /// \return num_params() values, valid until the next update or reset
  const Params& theta() const noexcept {
    if (m_window && m_window->has_estimate()) return m_window->estimate();
    return m_second_window && m_second_window->has_estimate() ? m_second_window->estimate() : m_theta;
  }
  /// The current covariance P of the recursion (exactly symmetric), also where theta() is the window's,
  /// in the data's units: the P of the recursion on the data as they are (normalised, D P_n D / sy^2,
  /// with theta = D theta_n).
  /// \return a copy of P, num_params() x num_params()
  Covariance covariance() const {
    Covariance P = m_rls.covariance();
    return (P.array() * (m_regressor_scale * m_regressor_scale.transpose()).array()).matrix();
  }
  /// The recursion's own P, in its normalised coordinates (theta = d .* theta_n, estimator/normalisation.hpp):
  /// what the trace ceiling bounds and the safeguards keep positive definite; covariance() where not
  /// normalised.
  /// \return a copy of P_n, num_params() x num_params()
  Covariance normalised_covariance() const { return m_rls.covariance(); }
  /// The current estimate as a model, projected onto the model's valid set (the paper method's
  /// P-H-W estimate can have c < 0, which simulates as c = 0).
  /// \return a copy of the structure with the projected estimate
  Model model() const {
    Params theta = this->theta();
    m_model.constrain(theta);
    Model model = m_model;
    model.set_theta(theta);
    return model;
  }
  /// The prediction of the last sample's y, made before the update with the parameters the update
  /// used: y - last_prediction() is the innovation (for monitoring and fault detection). For the
  /// output-error method it is the model's free-run (simulated) output; for the others the key-term
  /// one-step prediction from the measured past.
  /// \return the prediction of y(k), in y's units; the operating point included
  Scalar last_prediction() const noexcept { return m_prediction + m_y0; }
  /// Samples since the last pass started.
  /// \return the number of samples, >= 0
  Eigen::Index samples() const noexcept { return m_sample; }
  /// True once an update was refused for numerical reasons (cleared by recover() and reset()).
  /// \return true after a NumericalFailure until recover() or reset()
  bool diverged() const noexcept { return m_health.diverged; }
  /// What the safeguards did since the last reset().
  /// \return the counters, valid while the estimator lives
  const EstimatorHealth& health() const noexcept { return m_health; }
  /// The options the estimator was constructed with
  /// \return the options, with their unset optionals still unset (resolved_*() gives the values in force)
  const EstimatorOptions& options() const noexcept { return m_options; }
  /// The model's own settings the estimator was constructed with
  /// \return the settings (P-H-W: c0 and backlash_hold; other models: none)
  const Settings& settings() const noexcept { return m_settings; }
  /// The forgetting factor's current memory length 1 / (1 - lambda) under an adaptive-memory
  /// schedule (NaN for a step schedule).
  /// \return 1 / (1 - lambda) in samples, or NaN
  double memory() const noexcept {
    return m_forgetting.adaptive() ? m_memory.memory() : std::numeric_limits<double>::quiet_NaN();
  }

 private:
  /// Checks the options and the parameter count before any storage is sized from them (the
  /// output-error terms keep na x n sensitivities).
  static const Model& validated(const Model& structure, const EstimatorOptions& options, const Settings& settings) {
    options.validate();
    settings.validate();
    detail::require_order(structure.num_params(), 1, "number of parameters");
    return structure;
  }

  /// reset(theta0) but for the equation-error recursion beside.
  template <typename T>
  void restart_from(const Eigen::MatrixBase<T>& theta0) {
    m_rls.reset(theta0, Scalar(m_p0));  // checks theta0
    m_theta = theta0;
    m_measuring = false;
    m_measurement.reset();
    set_scales(detail::DataScale{});
    start_pass();
    clear_history();
    m_measuring = m_normalised;
  }

  void clear_history() {
    m_health = EstimatorHealth{};
    m_max_trace = Scalar(m_options.resolved_trace_ceiling() * m_p0 * double(m_rls.size()));
    m_record_next = 0;
    m_recorded = 0;
    m_total_samples = 0;
    m_prediction = Scalar(0);
    each_window([this](WindowRefinement<Model>& window) { window.reset(m_theta, m_outputs); });
  }

  void restart_internals() noexcept {
    m_terms.reset();
    m_outputs.reset();
    m_memory.reset(m_forgetting);
    m_error_scale = Scalar(0);
    m_last_outlier = false;
    m_checkpoint = m_theta;
    m_checkpoint_run = m_outputs;
    m_checkpoint_wins = 0;
    start_checkpoint_period();
    m_theta_internal = m_theta;
    m_since_refresh = 0;
    each_window([this](WindowRefinement<Model>& window) { window.restart(m_theta, m_outputs); });
  }

  /// recover() without clearing diverged(). The data histories are kept: they are fine unless
  /// non-finite, which update() handles itself. Cannot throw: p0 was validated, P keeps its size.
  void reset_covariance() noexcept {
    m_rls.reset_covariance(Scalar(m_p0));
    m_theta_internal = m_theta;
    m_since_refresh = 0;
    m_health.consecutive_failures = 0;
  }

  /// Lambda for this sample: the schedule's value, or under an adaptive memory the factor that the
  /// output y and its a-priori prediction error lead to.
  Scalar forgetting_factor(Scalar y, Scalar error) noexcept {
    if (m_forgetting.adaptive()) {
      return Scalar(m_memory.next(m_forgetting, static_cast<double>(y), static_cast<double>(error)));
    }
    return Scalar(m_forgetting.at(m_sample));
  }

  /// The recursion's coordinates for data of the given scale: theta = d theta_n, phi_n = phi d / sy,
  /// e_n = e / sy (estimator/normalisation.hpp).
  void set_scales(detail::DataScale scale) noexcept {
    m_scale = scale;
    m_units.scales(scale, m_parameter_scale);
    m_inverse_parameter_scale = m_parameter_scale.cwiseInverse();
    m_inverse_output_scale = Scalar(1.0 / scale.y);
    m_regressor_scale = m_parameter_scale * m_inverse_output_scale;
    each_window(
        [this](WindowRefinement<Model>& window) { window.set_scales(m_parameter_scale, m_inverse_output_scale); });
  }

  /// theta_n = theta / d: the recursion's estimate from m_theta after a projection.
  void store_theta() noexcept { m_rls.mutable_theta() = m_theta.cwiseProduct(m_inverse_parameter_scale); }

  /// Method::OutputError (docs/explanation/algorithm.md): simulate the model one step with the current estimate,
  /// take one Gauss-Newton step on the simulation error with the output's sensitivities as the
  /// regressor, keep the estimate valid (c >= 0, the linear block stable), then store the step and
  /// move the stored simulation to first order along the change of the estimate.
  UpdateStatus update_output_error(Scalar u, Scalar y) noexcept {
    const auto simulated = m_outputs.step(m_theta, u);
    const Scalar prediction = simulated.output;
    if (!std::isfinite(prediction)) return internal_divergence(prediction);
    m_prediction = prediction;
    const Scalar error = y - prediction;
    const Scalar lambda = forgetting_factor(y, error);
    // An outlier bound: an error beyond kOutlierBound times the running mean absolute error, after
    // a sample that was within it, drives the step at that size (Huber-type). One output outlier of
    // 20 standard deviations would otherwise throw the estimate far into the non-convex criterion,
    // from where the simulation takes thousands of samples to come back (the soak's outliers did).
    // Only an isolated sample is bounded: a real change (the plant changed) gives a run of large
    // errors, which passes from its second sample on; bounding every sample of it, against a mean
    // that lags behind, shortened the steps until a tracking estimate settled in another basin.
    // The mean follows the unclipped error.
    const Scalar bound = Scalar(kOutlierBound) * m_error_scale;
    const bool outlier = m_error_scale > Scalar(0) && std::abs(error) > bound && !m_last_outlier;
    const Scalar used = outlier ? std::clamp(error, -bound, bound) : error;
    m_last_outlier = outlier;
    m_error_scale = m_error_scale > Scalar(0) ? m_error_scale + (std::abs(error) - m_error_scale) * Scalar(kErrorRate)
                                              : std::abs(error);
    m_step = m_theta;
    UpdateStatus status = UpdateStatus::Updated;
    m_phi = simulated.sensitivity.cwiseProduct(m_regressor_scale);
    if (m_rls.update_with_error(m_phi, used * m_inverse_output_scale, lambda, m_max_trace)) {
      m_theta = m_rls.theta().cwiseProduct(m_parameter_scale);
      m_model.constrain(m_theta);
      m_step = m_theta - m_step;  // the step taken; theta = previous + m_step from here on
      if (!m_outputs.stable(m_theta, Scalar(m_options.stability_radius))) shorten_step(m_theta);
      store_theta();
      m_health.consecutive_failures = 0;
      if (m_rls.forgetting_limited()) ++m_health.forgetting_limited;
    } else {
      // Refused: the sensitivities, and the simulated state they come from, have left the range P can
      // take (an absurd input inside the simulation decays only with the model's poles and would
      // refuse every update for thousands of samples). Restart the simulation from rest instead.
      ++m_health.internal_restarts;
      m_outputs.reset();
      status = failure();
    }
    if (status == UpdateStatus::Updated) {
      m_outputs.accept();
      m_outputs.correct(m_step);
    }
    if (m_options.checkpoint) watch_checkpoint(u, y, error);
    if (m_window) refine_window(u, y, error, lambda);
    return finish(status, simulated.internal);
  }

  /// The window refinement's slice for this sample, and its swap where it has one: its estimate,
  /// covariance (within the trace ceiling) and free run replace the recursion's.
  void refine_window(Scalar u, Scalar y, Scalar error, Scalar lambda) noexcept {
    const double memory =
        lambda < Scalar(1) ? 1.0 / (1.0 - static_cast<double>(lambda)) : std::numeric_limits<double>::infinity();
    each_window([&](WindowRefinement<Model>& window) { window.push(u, y, error); });
    if (m_skip_window_slice) return;
    if (m_window->advance(m_theta, m_outputs, memory)) adopt(*m_window);
    m_health.window = m_window->counts();
    if (m_second_window) {
      if (m_second_window->advance(m_theta, m_outputs, memory, &m_equation_error->theta())) adopt(*m_second_window);
      m_health.window += m_second_window->counts();
    }
  }

  /// The output-error method's checkpoint: an earlier estimate, simulated beside the recursion on
  /// the same input. Why: the criterion is not convex, and data that the model cannot explain (a
  /// sensor switched off: u = y = 0 while the model's backlash holds its output) throw the estimate
  /// far within a few samples; from there the recursion and the windows, once the data are rich
  /// again, could settle in another basin for good (bonl_soak: a P-H-W estimate with a zero near 1
  /// that cancels a pole and |theta| near 100, 5.7% NRMSE against the plant's 1% noise, held for
  /// 14 million samples). Every kCheckpointPeriod samples of a varying input the recursion's
  /// estimate becomes the checkpoint where it predicted them at least as well; a period of a
  /// constant input (a held command, the sensors off) determines too little to judge by. Where
  /// the checkpoint predicted them kCheckpointMargin times better, twice in a row, the recursion
  /// returns to it (its estimate and free run; the covariance stays) and the windows restart from
  /// there. A changed plant does not return: the checkpoint, fitted to the plant before, predicts
  /// it worse than the tracking recursion, and gives way to it.
  void watch_checkpoint(Scalar u, Scalar y, Scalar error) noexcept {
    const auto simulated = m_checkpoint_run.step(m_checkpoint, u);
    m_checkpoint_run.accept();
    const double checkpoint_error = static_cast<double>(y - simulated.output);
    m_checkpoint_sse += checkpoint_error * checkpoint_error;
    m_recursion_sse += static_cast<double>(error) * static_cast<double>(error);
    m_period_u += static_cast<double>(u);
    m_period_u_squares += static_cast<double>(u) * static_cast<double>(u);
    if (++m_period_samples < kCheckpointPeriod) return;
    const double n = static_cast<double>(m_period_samples);
    const double mean = m_period_u / n;
    const double u_spread = kCheckpointExcitation * m_scale.u;
    const bool varying = m_period_u_squares / n - mean * mean > u_spread * u_spread;
    // A return only where the recursion misses the output by more than kCheckpointFloor of its
    // scale: a converged estimate on noise-free data is a rounding error away from its checkpoint.
    const double y_floor = kCheckpointFloor * m_scale.y;
    const bool far_better = std::isfinite(m_checkpoint_sse) && m_recursion_sse > n * y_floor * y_floor &&
                            kCheckpointMargin * m_checkpoint_sse < m_recursion_sse;
    if (varying && far_better) {
      if (++m_checkpoint_wins >= 2) return_to_checkpoint();
    } else {
      m_checkpoint_wins = 0;
      if (varying && !(m_checkpoint_sse < m_recursion_sse)) {
        m_checkpoint = m_theta;
        m_checkpoint_run = m_outputs;
      }
    }
    start_checkpoint_period();
  }

  void return_to_checkpoint() noexcept {
    m_checkpoint_wins = 0;
    ++m_health.checkpoint_returns;
    m_theta = m_checkpoint;
    store_theta();
    m_outputs = m_checkpoint_run;
    each_window([this](WindowRefinement<Model>& window) { window.restart(m_theta, m_outputs); });
  }

  void start_checkpoint_period() noexcept {
    m_checkpoint_sse = 0.0;
    m_recursion_sse = 0.0;
    m_period_u = 0.0;
    m_period_u_squares = 0.0;
    m_period_samples = 0;
  }

  /// f(window) for each window refinement the estimator runs (none, one, or two).
  template <typename F>
  void each_window(F f) noexcept {
    if (m_window) f(*m_window);
    if (m_second_window) f(*m_second_window);
  }

  /// A window's swap: its estimate, covariance (within the trace ceiling) and free run replace the
  /// recursion's.
  void adopt(const WindowRefinement<Model>& window) noexcept {
    const auto& covariance = window.covariance();  // in the recursion's coordinates
    const Scalar trace = covariance.trace();
    const Scalar factor = trace > m_max_trace ? m_max_trace / trace : Scalar(1);
    m_theta = window.theta();
    m_rls.assign(m_theta.cwiseProduct(m_inverse_parameter_scale), factor * covariance);
    m_outputs = window.run();
  }

  /// theta = previous + m_step left the stability region: halve the step until it is back inside
  /// (the region is not convex in theta, but its interior is open, so short enough steps from a
  /// stable estimate stay in it), at most 10 times, else take no step.
  void shorten_step(Params& theta) noexcept {
    ++m_health.projections;
    const Scalar radius = Scalar(m_options.stability_radius);
    for (int halving = 0; halving < 10; ++halving) {
      m_step *= Scalar(0.5);
      theta -= m_step;
      if (m_outputs.stable(theta, radius)) return;
    }
    theta -= m_step;
    m_step.setZero();
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
      m_record_theta.col(m_record_next) = theta();
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

  /// The output-error method's process noise, relative to p0 (Rls::set_process_noise): far above
  /// the downdates' round-off (about 1e-16 of the largest entry of P, at most ceiling x p0 here),
  /// far below what moves an estimate (over 1e8 samples it lets a never-excited direction's
  /// variance grow by 1% of p0).
  static constexpr double kProcessNoise = 1e-10;
  /// The output-error method's outlier bound, in running mean absolute errors (5: about 4 standard
  /// deviations of Gaussian noise), and that mean's rate (a time constant of 50 samples).
  static constexpr double kOutlierBound = 5.0;
  static constexpr double kErrorRate = 1.0 / 50.0;
  /// The checkpoint's period (watch_checkpoint): long beside a memory of 50 samples (lambda = 0.98),
  /// short beside the soak's phases of 50,000, so that a return comes within a thousand samples.
  static constexpr Eigen::Index kCheckpointPeriod = 500;
  /// How much better (sum of squared errors over a period) the checkpoint predicts before a return:
  /// far beyond chance between two estimates that fit the data alike (over 500 samples of white
  /// noise their sums differ by about 9%, one standard deviation).
  static constexpr double kCheckpointMargin = 4.0;
  /// A period's input varies where its standard deviation is above this part of the data's input
  /// scale (estimator/normalisation.hpp; 1 where not normalised).
  static constexpr double kCheckpointExcitation = 0.05;
  /// The least error, relative to the data's output scale, that a return is worth.
  static constexpr double kCheckpointFloor = 1e-3;

  static KeyTermMethod key_term_method(Method method) noexcept {
    return method == Method::Paper ? KeyTermMethod::Paper : KeyTermMethod::EquationError;
  }

  Model m_model;
  Scalar m_u0 = Scalar(0), m_y0 = Scalar(0);          // the structure's operating point
  typename Model::KeyTerms m_terms;                   // equation_error and paper
  typename Model::OutputErrorTerms m_outputs;         // output_error
  Params m_checkpoint;                                // output_error: the checkpoint (watch_checkpoint) ...
  typename Model::OutputErrorTerms m_checkpoint_run;  // ... its free run
  double m_checkpoint_sse = 0.0;                      // this period's squared errors: the checkpoint's ...
  double m_recursion_sse = 0.0;                       // ... and the recursion's (a priori)
  double m_period_u = 0.0, m_period_u_squares = 0.0;  // this period's input sums
  Eigen::Index m_period_samples = 0;
  int m_checkpoint_wins = 0;                        // periods in a row the checkpoint predicted far better
  std::optional<WindowRefinement<Model>> m_window;  // output_error, unless options.window.enabled is false
  // With the window, unless options.window.equation_error_start is false: the equation-error
  // recursion beside and the window that starts from its estimate.
  detail::Indirect<Estimator> m_equation_error;
  std::optional<WindowRefinement<Model>> m_second_window;
  Rls<Scalar, Model::kNumParams> m_rls;
  Params m_theta;           // the estimate in the data's units; the recursion's is m_theta / m_parameter_scale
  Params m_theta_internal;  // equation_error: the copy of theta the internal variables use
  Params m_step;            // output_error: the change of theta in the current update
  Params m_phi;             // the regressor in the recursion's coordinates
  // Normalisation (estimator/normalisation.hpp): theta = m_parameter_scale .* theta_n, phi_n =
  // m_regressor_scale .* phi, e_n = e * m_inverse_output_scale; all 1 where not normalised.
  Params m_parameter_scale, m_regressor_scale, m_inverse_parameter_scale;
  Scalar m_inverse_output_scale = Scalar(1);
  EstimatorOptions m_options;
  Settings m_settings;
  ForgettingSchedule m_forgetting;  // resolved from the options
  double m_p0;                      // resolved from the options
  detail::ParameterUnitPowers<Model> m_units;
  detail::ScaleMeasurement<Scalar> m_measurement;
  detail::DataScale m_scale;
  bool m_normalised;                 // options.normalise, for a method it applies to
  bool m_measuring = false;          // the data's scale is being measured: samples kept, no updates
  bool m_skip_window_slice = false;  // catching up: this sample's window slices are skipped
  bool m_default_start = true;       // reset() without an estimate: the method's start
  detail::AdaptiveMemory m_memory;
  Scalar m_error_scale = Scalar(0);  // output_error: running mean absolute prediction error (0: none yet)
  bool m_last_outlier = false;       // output_error: the last sample's error was bounded
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

// The constructor and the members that reach the whole update (reset, start_pass, catch_up, update)
// are defined here, outside the class, so that they are not inline: a program that builds
// estimators of the same model in many files can compile them in one (`template class
// bonl::Estimator<M>;` there, `extern template class bonl::Estimator<M>;` in the others; the C++
// tests do, tests/cpp/compiled_once.hpp), which an in-class (inline) definition would not allow.
// Compiled where used, they are as fast.

template <class Model>
Estimator<Model>::Estimator(const Model& structure, const EstimatorOptions& options, const Settings& settings)
    : m_model(validated(structure, options, settings)), m_terms(structure, key_term_method(options.method)),
      m_outputs(detail::output_error_terms(structure, settings)), m_checkpoint(Params::Zero(structure.num_params())),
      m_checkpoint_run(m_outputs), m_rls(structure.num_params(), Scalar(options.resolved_p0())),
      m_theta(Params::Zero(structure.num_params())), m_theta_internal(m_theta), m_step(m_theta), m_phi(m_theta),
      m_parameter_scale(Params::Ones(m_theta.size())), m_regressor_scale(m_parameter_scale),
      m_inverse_parameter_scale(m_parameter_scale), m_options(options), m_settings(settings),
      m_forgetting(options.resolved_forgetting()), m_p0(options.resolved_p0()), m_units(structure),
      m_measurement(kScaleSamples, structure.ni()), m_normalised(options.normalise && options.method != Method::Paper) {
  m_u0 = static_cast<Scalar>(structure.u0());
  m_y0 = static_cast<Scalar>(structure.y0());
  if (options.method == Method::OutputError) {
    m_rls.set_process_noise(Scalar(kProcessNoise * m_p0));
    if (options.window.enabled) {
      // The window keeps to a forgetting the caller chose, not to the adaptive memory's.
      m_window.emplace(structure, options.window, settings, options.stability_radius, m_p0, !m_forgetting.adaptive());
      if (options.window.equation_error_start) {
        // identify()'s second start: an equation-error recursion beside, with the caller's
        // forgetting (else its method's) and its method's other defaults, and a second window
        // that starts from its estimate.
        EstimatorOptions second;
        second.method = Method::EquationError;
        second.forgetting = options.forgetting;
        second.normalise = options.normalise;
        second.window.enabled = false;
        m_equation_error.emplace(structure, second, settings);
        m_second_window.emplace(structure, options.window, settings, options.stability_radius, m_p0,
                                !m_forgetting.adaptive());
      }
    }
  }
  reset();
}

template <class Model>
void Estimator<Model>::reset() {
  restart_from(m_options.method == Method::OutputError ? Params::Zero(m_rls.size())
                                                       : detail::initial_estimate(m_model, m_settings));
  m_default_start = true;
  if (m_equation_error) m_equation_error->reset();
}

template <class Model>
void Estimator<Model>::start_pass() {
  catch_up();
  restart_internals();
  m_sample = 0;
  if (m_equation_error) m_equation_error->start_pass();
}

template <class Model>
void Estimator<Model>::catch_up() noexcept {
  if (m_measuring) start_recursion();
  while (m_measurement.pending() > 0) take_pending();
  if (m_equation_error) m_equation_error->catch_up();
}

template <class Model>
UpdateStatus Estimator<Model>::update(Scalar u, Scalar y) noexcept {
  if (!std::isfinite(u) || !std::isfinite(y)) return UpdateStatus::RejectedNonFinite;
  if (m_equation_error) m_equation_error->update(u, y);
  // The model's blocks see the deviations from its operating point (0, 0 unless set).
  u -= m_u0;
  y -= m_y0;
  if (m_measuring) {
    m_measurement.push(u, y);
    if (!m_measurement.complete()) return UpdateStatus::NoInformation;
    start_recursion();
    return take_pending();
  }
  if (m_measurement.pending() == 0) return process(u, y);
  // Catching up on the samples kept while measuring: this one behind them, two taken per update.
  m_measurement.queue(u, y);
  // The second one's window slice is skipped (its samples are pushed): an update does one slice's
  // work, as it does when caught up.
  const UpdateStatus status = take_pending();
  if (m_measurement.pending() == 0) return status;
  m_skip_window_slice = true;
  const UpdateStatus second = take_pending();
  m_skip_window_slice = false;
  return second;
}

}  // namespace bonl
