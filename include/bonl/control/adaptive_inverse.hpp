#pragma once
// The online estimator and the inverse model together: a feedforward that follows the plant as it
// changes. Each sample, update(u, y) feeds the applied command and the measured output to the
// estimator; every `rederive_every` samples the inverse is derived again from the estimate, if the
// estimate is trusted, and goes on from where the old inverse was (InverseModel::continue_from). An
// estimate that is not trusted leaves the last good inverse in use and is counted by the reason:
//   - the estimator diverged (a refused update: diverged(); it stays so unless
//     options.estimator.recover_after lets it reset its covariance by itself);
//   - its covariance is large: trace(P) above max_covariance_trace * trace(P(0)) (the estimate has
//     lost what it knew, e.g. after a long stretch without excitation under forgetting);
//   - its linear block is not stable: a pole at or beyond stability_radius;
//   - it has no inverse: InverseModel's constructor refuses it (b_0 = 0, an input polynomial not
//     monotone through 0, ...).
// step() is the inverse's, noexcept and allocation-free; deriving an inverse allocates (the
// polynomial branches and B's zeros are computed anew), so it happens only every rederive_every
// samples, inside update().

#include <Eigen/Core>
#include <cmath>
#include <exception>
#include <string>

#include "../detail/validate.hpp"
#include "../estimator/recursive_estimator.hpp"
#include "../models/poles.hpp"
#include "inverse_model.hpp"

namespace bonl::control {

/// How AdaptiveInverse is built and when it trusts an estimate enough to derive a new inverse from it.
struct AdaptiveInverseOptions {
  InverseOptions inverse;             ///< how each inverse is built (command range, backlash band)
  EstimatorOptions estimator;         ///< the online estimator's (method, forgetting, p0, ...)
  Eigen::Index rederive_every = 100;  ///< samples between two derivations of the inverse, >= 1
  /// Trusted only while trace(P) <= max_covariance_trace * n * p0 (n parameters), >= 1.
  double max_covariance_trace = 10.0;
  /// Trusted only while every pole of the estimate's linear block is inside this radius, in (0, 1].
  double stability_radius = 0.999;

  /// Throws std::invalid_argument for a setting out of range: the estimator's options
  /// (EstimatorOptions::validate), rederive_every < 1, max_covariance_trace below 1 or not finite, or
  /// stability_radius outside (0, 1].
  void validate() const {
    estimator.validate();
    bonl::detail::require(rederive_every >= 1, "rederive_every must be >= 1, got " + std::to_string(rederive_every));
    bonl::detail::require(
        std::isfinite(max_covariance_trace) && max_covariance_trace >= 1.0,
        "max_covariance_trace must be finite and >= 1, got " + bonl::detail::format_number(max_covariance_trace));
    bonl::detail::require(stability_radius > 0.0 && stability_radius <= 1.0,
                          "stability_radius must be in (0, 1], got " + bonl::detail::format_number(stability_radius));
  }
};

/// What the guard did since the start: inverses derived, and estimates refused by reason.
struct AdaptiveInverseHealth {
  Eigen::Index rederivations = 0;       ///< new inverses put in use
  Eigen::Index refused_diverged = 0;    ///< the estimator had diverged
  Eigen::Index refused_covariance = 0;  ///< trace(P) above the limit
  Eigen::Index refused_unstable = 0;    ///< a pole of the estimate at or beyond stability_radius
  Eigen::Index refused_no_inverse = 0;  ///< InverseModel refused the estimate
  std::string last_refusal;             ///< why the last refused estimate was refused ("" if none)
};

/// The online estimator and the inverse model together: a feedforward that follows the plant as it
/// changes. update(u, y) feeds the applied command and the measured output to the estimator; every
/// rederive_every samples the inverse is derived again from the estimate, if the guard trusts it (not
/// diverged, covariance not too large, linear block stable, an inverse exists), and goes on from where
/// the old one was. An estimate not trusted leaves the last good inverse in use and is counted by its
/// reason in health(). step() is the inverse's, noexcept and allocation-free; deriving an inverse
/// allocates, so it happens only inside update() or rederive().
template <class Model>
class AdaptiveInverse {
 public:
  using Scalar = typename Model::Scalar;  ///< the model's arithmetic type

  /// Starts from `initial` (an identified model): the inverse is derived from it, and the estimator
  /// is warm-started from its parameters (P = p0 I). Throws std::invalid_argument for bad options or
  /// a model without an inverse.
  /// \param initial the identified model to start from
  /// \param options the inverse's, the estimator's and the guard's options
  /// \param settings the model's own estimator settings (Estimator)
  explicit AdaptiveInverse(const Model& initial, const AdaptiveInverseOptions& options = {},
                           const ModelSettings<Model>& settings = {})
      : m_options(validated(options)), m_model(initial), m_inverse(initial, options.inverse),
        m_estimator(initial, options.estimator, settings) {
    m_estimator.reset(initial.theta());
  }

  /// The command for the reference window, from the inverse in use (InverseModel::step).
  /// \param reference r(k+nk), ..., r(k+nk+window_size()-1), in the model's output units
  /// \return the command u(k) and its status
  template <typename W>
  InverseStep<Scalar> step(const Eigen::MatrixBase<W>& reference) noexcept {
    return m_inverse.step(reference);
  }
  /// The command for a window of one sample, r(k + nk), from the inverse in use (InverseModel::step):
  /// only where its window_size() is 1, else RejectedShortPreview.
  /// \param reference r(k + nk), in the model's output units
  /// \return the command u(k) and its status
  InverseStep<Scalar> step(Scalar reference) noexcept { return m_inverse.step(reference); }

  /// One sample of the plant: the command u applied (the whole command, feedback included) and the
  /// output y measured. Every rederive_every accepted samples the inverse is derived again from the
  /// estimate, where the guard trusts it (rederive()).
  /// \param u the command u(k) applied
  /// \param y the output y(k) measured
  /// \return what the estimator did with the sample
  UpdateStatus update(Scalar u, Scalar y) {
    const UpdateStatus status = m_estimator.update(u, y);
    if (status == UpdateStatus::RejectedNonFinite) return status;
    if (++m_since_derivation >= m_options.rederive_every) {
      m_since_derivation = 0;
      rederive();
    }
    return status;
  }

  /// Derives the inverse from the current estimate now, if the guard trusts it. Otherwise the last
  /// good one stays, and health() says why.
  /// \return true when the new inverse is in use
  bool rederive() {
    if (m_estimator.diverged()) return refuse(m_health.refused_diverged, "the estimator diverged");
    // The recursion's own P, in the coordinates p0 is in (EstimatorOptions::normalise).
    const double trace = static_cast<double>(m_estimator.normalised_covariance().trace());
    const double limit = m_options.max_covariance_trace * static_cast<double>(m_estimator.theta().size()) *
                         m_estimator.options().resolved_p0();
    if (!(trace <= limit))
      return refuse(m_health.refused_covariance, "trace(P) = " + bonl::detail::format_number(trace) +
                                                     " is above the limit " + bonl::detail::format_number(limit));
    Model estimate = m_estimator.model();
    const double radius = pole_radius(estimate);
    if (!(radius < m_options.stability_radius))
      return refuse(m_health.refused_unstable,
                    "a pole of the estimate has magnitude " + bonl::detail::format_number(radius));
    try {
      InverseModel<Model> inverse(estimate, m_options.inverse);
      inverse.continue_from(m_inverse);
      m_inverse = std::move(inverse);
    } catch (const std::invalid_argument& error) {
      return refuse(m_health.refused_no_inverse, error.what());
    }
    m_model = std::move(estimate);
    ++m_health.rederivations;
    return true;
  }

  /// The inverse in use, and the model it was derived from. \return the inverse, valid until the next
  /// update() or rederive()
  const InverseModel<Model>& inverse() const noexcept { return m_inverse; }
  /// The model the inverse in use was derived from
  /// \return the model, valid until the next update() or rederive()
  const Model& model() const noexcept { return m_model; }
  /// The online estimator, whose current estimate may be newer than model() (or refused by the guard).
  /// \return the estimator
  const Estimator<Model>& estimator() const noexcept { return m_estimator; }
  /// What the guard did since the start: inverses derived, estimates refused and why.
  /// \return the counters and the last refusal's reason
  const AdaptiveInverseHealth& health() const noexcept { return m_health; }
  /// The options, validated
  /// \return the options given
  const AdaptiveInverseOptions& options() const noexcept { return m_options; }

 private:
  static const AdaptiveInverseOptions& validated(const AdaptiveInverseOptions& options) {
    options.validate();
    return options;
  }
  bool refuse(Eigen::Index& counter, std::string why) {
    ++counter;
    m_health.last_refusal = std::move(why);
    return false;
  }

  AdaptiveInverseOptions m_options;
  Model m_model;
  InverseModel<Model> m_inverse;
  Estimator<Model> m_estimator;
  Eigen::Index m_since_derivation = 0;
  AdaptiveInverseHealth m_health;
};

}  // namespace bonl::control
