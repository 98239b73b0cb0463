#pragma once
// The generic recursive estimator (the paper's MRLSA), templated on the model: the model's KeyTerms
// build the key-term regressor and estimate the internal variables, Rls does the update.

#include <Eigen/Core>
#include <cmath>
#include <type_traits>
#include <utility>

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

  void validate() const {
    forgetting.validate();
    detail::require(std::isfinite(p0) && p0 > 0.0, "p0 (initial covariance scale) must be finite and > 0");
    detail::require(std::isfinite(c0) && c0 >= 0.0, "c0 (initial backlash half-width) must be finite and >= 0");
    detail::require(internal_refresh >= 1, "internal_refresh must be >= 1");
  }
};

/// What one online update did.
enum class UpdateStatus {
  Updated,            ///< theta and P were updated
  NoInformation,      ///< the sample says nothing about theta (inside the backlash gap); internals advanced
  RejectedNonFinite,  ///< u or y was NaN or infinite; the estimator's state is untouched
  NumericalFailure,   ///< the update would have broken P; theta and P kept, internals advanced, diverged() set
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
    m_diverged = false;
  }

  /// Restarts from a given estimate (a warm start, e.g. a previously identified model's theta):
  /// P = p0 I, internals at rest.
  template <typename T>
  void reset(const Eigen::MatrixBase<T>& theta0) {
    m_rls.reset(theta0, Scalar(m_options.p0));
    start_pass();
    m_diverged = false;
  }

  /// A new pass over a record (the paper's step 5, "return to step 2"): theta and P carry on from
  /// where the last pass ended; the forgetting schedule and the internal variables restart from rest.
  /// (Resetting P instead made each pass a fresh start from a 100-sample estimate; for P-H-W that
  /// diverged over passes.)
  void start_pass() {
    m_terms.reset();
    m_theta_internal = m_rls.theta();
    m_since_refresh = 0;
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
    Scalar target = Scalar(0);
    UpdateStatus status = UpdateStatus::NoInformation;
    if (m_terms.regress(theta, x, y, method, m_phi, target)) {
      if (m_rls.update(m_phi, target, Scalar(m_options.forgetting.at(m_sample)))) {
        m_terms.constrain(m_rls.mutable_theta(), method);
        status = UpdateStatus::Updated;
      } else {
        m_diverged = true;
        status = UpdateStatus::NumericalFailure;
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
    ++m_sample;
    return status;
  }

  const Params& theta() const noexcept { return m_rls.theta(); }
  Covariance covariance() const { return m_rls.covariance(); }
  /// The current estimate as a model.
  Model model() const {
    Model model = m_model;
    model.set_theta(m_rls.theta());
    return model;
  }
  /// Samples since the last pass started.
  Eigen::Index samples() const noexcept { return m_sample; }
  /// True once an update was refused for numerical reasons (cleared by reset()).
  bool diverged() const noexcept { return m_diverged; }
  const EstimatorOptions& options() const noexcept { return m_options; }

 private:
  static const EstimatorOptions& validated(const EstimatorOptions& options) {
    options.validate();
    return options;
  }

  Model m_model;
  typename Model::KeyTerms m_terms;
  Rls<Scalar, Model::kNumParams> m_rls;
  Params m_phi;
  Params m_theta_internal;
  EstimatorOptions m_options;
  Eigen::Index m_since_refresh = 0;
  Eigen::Index m_sample = 0;
  bool m_diverged = false;
};

}  // namespace bonl
