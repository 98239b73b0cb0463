#pragma once
// The estimator fuzz target's harness (see fuzz_estimator_update.cpp for what it checks), in a header
// so that the model types compile in two translation units, one per core.

#include <bonl/estimator.hpp>
#include <bonl/models.hpp>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "fuzz_common.hpp"

namespace bonl_fuzz {

/// Everything model-specific comes from the model's description (bonl/models/model_description.hpp):
/// which orders it takes, their documented ranges and compile-time values, and whether it has a
/// backlash half-width c (the only constrained parameter, started at c0).
template <class Model>
constexpr std::size_t kNumOrders = Model::kDescription.orders.size();
template <class Model>
using Orders = std::array<Eigen::Index, kNumOrders<Model>>;

template <class Model>
constexpr bool uses_c0() {
  for (const auto& block : Model::kDescription.parameters) {
    if (block.non_negative) return true;
  }
  return false;
}

/// Orders for Model from the input: run-time orders small (a step below the minimum now and then),
/// compile-time ones at their value, now and then one more (a mismatch the constructor must refuse).
template <class Model>
Orders<Model> decode_orders(FuzzedDataProvider& in) {
  Orders<Model> orders{};
  for (std::size_t i = 0; i < orders.size(); ++i) {
    const bonl::OrderDescription& order = Model::kDescription.orders[i];
    if (order.fixed != Eigen::Dynamic) {
      orders[i] = order.fixed + (in.ConsumeIntegral<std::uint8_t>() < 8 ? 1 : 0);
    } else if (std::string(order.name) == "nk") {
      orders[i] = in.ConsumeIntegralInRange<Eigen::Index>(-1, 10);
    } else {
      orders[i] = in.ConsumeIntegralInRange<Eigen::Index>(order.minimum - 1, order.minimum + 3);
    }
  }
  return orders;
}

/// Whether the constructor must accept the orders: the description's ranges and compile-time values.
template <class Model>
bool orders_valid(const Orders<Model>& orders) {
  for (std::size_t i = 0; i < orders.size(); ++i) {
    const bonl::OrderDescription& order = Model::kDescription.orders[i];
    if (orders[i] < order.minimum || orders[i] > order.maximum) return false;
    if (order.fixed != Eigen::Dynamic && orders[i] != order.fixed) return false;
  }
  return true;
}

template <class Model>
void print_orders(const Orders<Model>& orders) {
  std::fprintf(stderr, "model %s, orders", Model::kName);
  for (std::size_t i = 0; i < orders.size(); ++i) {
    std::fprintf(stderr, " %s %ld", Model::kDescription.orders[i].name, long(orders[i]));
  }
  std::fprintf(stderr, "\n");
}

/// double -> Scalar, out-of-range magnitudes to +-inf explicitly (IEEE rounding, without relying on
/// the conversion of an out-of-range double to float).
template <typename Scalar>
Scalar to_scalar(double x) {
  if (std::isfinite(x) && std::abs(x) > static_cast<double>(std::numeric_limits<Scalar>::max())) {
    const auto rounded = static_cast<double>(std::nextafter(std::numeric_limits<Scalar>::max(), Scalar(0)));
    const double halfway = static_cast<double>(std::numeric_limits<Scalar>::max()) +
                           0.5 * (static_cast<double>(std::numeric_limits<Scalar>::max()) - rounded);
    if (std::abs(x) < halfway)
      return std::copysign(std::numeric_limits<Scalar>::max(), static_cast<Scalar>(x > 0 ? 1 : -1));
    return x > 0 ? std::numeric_limits<Scalar>::infinity() : -std::numeric_limits<Scalar>::infinity();
  }
  return static_cast<Scalar>(x);
}

/// One double for a setting: usually near a typical value, sometimes anything.
inline double setting(FuzzedDataProvider& in, double typical) {
  switch (in.ConsumeIntegralInRange<int>(0, 3)) {
    case 0: return typical;
    case 1: return typical * (1.0 + static_cast<double>(in.ConsumeIntegral<std::int8_t>()) / 256.0);
    case 2: return std::ldexp(typical, in.ConsumeIntegralInRange<int>(-1100, 1100));
    default: return any_double(in);
  }
}

/// The decoded settings: the estimator's options, and the c0 of the models with a backlash (their
/// EstimatorSettings), decoded for every model so that an input means the same settings for each.
struct FuzzedOptions {
  bonl::EstimatorOptions options;
  double c0 = 0.01;
};

/// The model's settings with the decoded c0 (models without settings have none).
template <class Model>
bonl::ModelSettings<Model> model_settings(double c0) {
  bonl::ModelSettings<Model> settings;
  if constexpr (uses_c0<Model>()) settings.c0 = c0;
  static_cast<void>(c0);
  return settings;
}

inline FuzzedOptions decode_options(FuzzedDataProvider& in) {
  FuzzedOptions decoded;
  bonl::EstimatorOptions& options = decoded.options;
  constexpr bonl::Method kMethods[] = {bonl::Method::OutputError, bonl::Method::EquationError, bonl::Method::Paper};
  options.method = kMethods[in.ConsumeIntegralInRange<int>(0, 2)];
  switch (in.ConsumeIntegralInRange<int>(0, 4)) {
    case 0: break;  // the method's schedule
    case 1: options.forgetting = bonl::ForgettingSchedule::constant(std::min(setting(in, 0.99), 1.0)); break;
    case 2: options.forgetting = bonl::ForgettingSchedule::constant(setting(in, 1.0)); break;
    case 3: {
      bonl::ForgettingSchedule schedule = bonl::ForgettingSchedule::adaptive_memory();
      schedule.initial_memory = setting(in, 50.0);
      schedule.changing_memory = setting(in, 100.0);
      schedule.memory_growth = setting(in, 0.5);
      options.forgetting = schedule;
      break;
    }
    default: {
      bonl::ForgettingSchedule schedule;
      schedule.initial = setting(in, 0.98);
      schedule.initial_samples = in.ConsumeIntegralInRange<Eigen::Index>(-2, 300);
      schedule.final = setting(in, 1.0);
      options.forgetting = schedule;
      break;
    }
  }
  if (in.ConsumeBool()) options.p0 = setting(in, 1e6);
  if (in.ConsumeBool()) decoded.c0 = setting(in, 0.01);
  if (in.ConsumeBool()) options.internal_refresh = in.ConsumeIntegralInRange<Eigen::Index>(-1, 300);
  switch (in.ConsumeIntegralInRange<int>(0, 4)) {
    case 0: break;  // the default ceiling
    case 1: options.trace_ceiling = 1.0; break;
    case 2: options.trace_ceiling = std::numeric_limits<double>::infinity(); break;  // off
    case 3: options.trace_ceiling = setting(in, 100.0); break;
    default: options.trace_ceiling = std::nextafter(1.0, 0.0); break;  // just below the minimum
  }
  if (in.ConsumeBool()) options.recover_after = in.ConsumeIntegralInRange<Eigen::Index>(-1, 4);
  return decoded;
}

/// BONL_FUZZ_VERBOSE set (when reproducing a finding): the decoded settings and every operation.
inline bool verbose() {
  static const bool on = std::getenv("BONL_FUZZ_VERBOSE") != nullptr;
  return on;
}

inline void print(const FuzzedOptions& decoded) {
  if (!verbose()) return;
  const bonl::EstimatorOptions& o = decoded.options;
  std::fprintf(
      stderr,
      "options: method %s, forgetting %s %.17g for %ld then %.17g (memory %.17g, %.17g, growth %.17g), p0 %.17g, "
      "c0 %.17g, internal_refresh %ld, trace_ceiling %.17g, recover_after %ld\n",
      bonl::to_string(o.method), o.resolved_forgetting().adaptive() ? "adaptive" : "steps",
      o.resolved_forgetting().initial, long(o.resolved_forgetting().initial_samples), o.resolved_forgetting().final,
      o.resolved_forgetting().initial_memory, o.resolved_forgetting().changing_memory,
      o.resolved_forgetting().memory_growth, o.resolved_p0(), decoded.c0, long(o.internal_refresh),
      o.resolved_trace_ceiling(), long(o.recover_after));
}

/// With BONL_FUZZ_STATS set: how the inputs and updates ended, printed at exit (docs/lab/fuzzing.md).
struct Outcomes {
  long bad_orders = 0, bad_options = 0, estimators = 0, status[4] = {0, 0, 0, 0};
  ~Outcomes() {
    if (std::getenv("BONL_FUZZ_STATS") == nullptr) return;
    std::fprintf(stderr,
                 "outcomes: orders rejected %ld, options rejected %ld, estimators run %ld; updates: Updated %ld, "
                 "NoInformation %ld, RejectedNonFinite %ld, NumericalFailure %ld\n",
                 bad_orders, bad_options, estimators, status[0], status[1], status[2], status[3]);
  }
};
inline Outcomes outcomes;

inline bool lambda_ok(double lambda) { return std::isfinite(lambda) && lambda > 0.0 && lambda <= 1.0; }

/// What EstimatorOptions::validate, the model's EstimatorSettings::validate and the estimator's
/// constructor accept, per their documentation.
template <class Model>
bool options_valid(const FuzzedOptions& decoded) {
  const bonl::EstimatorOptions& o = decoded.options;
  const double c0_value = decoded.c0;
  using Scalar = typename Model::Scalar;
  const bonl::ForgettingSchedule f = o.resolved_forgetting();
  const auto memory_ok = [](double value, double minimum) { return std::isfinite(value) && value >= minimum; };
  // Every field is validated, whichever kind is in force.
  const bool schedule = lambda_ok(f.initial) && lambda_ok(f.final) && f.initial_samples >= 0 &&
                        memory_ok(f.initial_memory, 1.0) && memory_ok(f.changing_memory, 1.0) &&
                        memory_ok(f.memory_growth, 0.0) && memory_ok(f.short_window, 1.0) &&
                        memory_ok(f.long_window, 1.0) && memory_ok(f.change_ratio, 1.0) && memory_ok(f.poor_fit, 0.0);
  const double p0_value = o.resolved_p0();
  const bool p0 = std::isfinite(p0_value) && p0_value > 0.0;
  const bool c0 = !uses_c0<Model>() || (std::isfinite(c0_value) && c0_value >= 0.0);
  // In Scalar: P(0) = p0 I must be finite and positive, and (P-H-W, where a recursion starts from it:
  // output_error's own starts at c = 0, but its window's equation-error start, on by default, at c0)
  // c(0) = c0 finite.
  const bool p0_scalar = p0 && std::isfinite(to_scalar<Scalar>(p0_value)) && to_scalar<Scalar>(p0_value) > Scalar(0);
  const bool equation_error_start = o.window.enabled && o.window.equation_error_start;
  const bool starts_from_c0 = uses_c0<Model>() && (o.method != bonl::Method::OutputError || equation_error_start);
  const bool c0_scalar = !starts_from_c0 || (c0 && std::isfinite(to_scalar<Scalar>(c0_value)));
  const bool safeguards = o.resolved_trace_ceiling() >= 1.0 && o.recover_after >= 0;  // the ceiling may be +inf
  return schedule && p0 && c0 && o.internal_refresh >= 1 && p0_scalar && c0_scalar && safeguards;
}

template <class Model>
class Harness {
 public:
  using Scalar = typename Model::Scalar;
  using Est = bonl::Estimator<Model>;
  using Params = typename Model::Params;
  using Covariance = typename Est::Covariance;
  using VectorX = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;

  Harness(const Model& structure, const bonl::EstimatorOptions& options, const bonl::ModelSettings<Model>& settings)
      : m_structure(structure), m_est(structure, options, settings), m_n(structure.num_params()) {
    // The documented ceiling: trace(P) <= trace_ceiling * trace(P(0)) = trace_ceiling * n * p0.
    m_max_trace = options.resolved_trace_ceiling() * static_cast<double>(to_scalar<Scalar>(options.resolved_p0())) *
                  static_cast<double>(m_n);
    check_fresh();
  }

  void run(FuzzedDataProvider& in) {
    int operations = 0;
    while (in.remaining_bytes() > 0 && operations++ < 4000) {
      const auto op = in.ConsumeIntegral<std::uint8_t>();
      if (verbose() && op >= 236) std::fprintf(stderr, "operation %d\n", int(op));
      if (op < 236) {
        update(in, op);
      } else if (op < 240) {
        m_est.reset();
        check_fresh();
      } else if (op < 243) {
        reset_to(in);
      } else if (op < 246) {
        m_est.catch_up();  // start_pass() takes the samples kept while the scale was measured first
        const Params theta = m_est.theta();
        const Covariance p = m_est.covariance();
        const bool diverged = m_est.diverged();
        m_est.start_pass();
        FUZZ_CHECK(m_est.samples() == 0 && m_est.diverged() == diverged);
        FUZZ_CHECK(same(theta, m_est.theta()) && same(p, m_est.covariance()));
      } else if (op < 249) {
        const Params theta = m_est.theta();
        m_est.recover();  // P = p0 I, theta kept, diverged() cleared
        FUZZ_CHECK(!m_est.diverged() && same(theta, m_est.theta()) && is_initial_covariance());
      } else if (op < 252) {
        m_capacity = in.ConsumeIntegralInRange<Eigen::Index>(1, 4);
        m_est.start_recording(m_capacity);
        m_recorded = 0;
        FUZZ_CHECK(m_est.recording() && m_est.trajectory().status.empty());
      } else {
        // theta is finite, so it is a valid model once projected (the P-H-W c < 0 of the paper
        // method becomes 0); nothing else changes.
        const Model model = m_est.model();
        Params expected = m_est.theta();
        if (uses_c0<Model>() && expected[m_n - 1] < Scalar(0)) expected[m_n - 1] = Scalar(0);
        FUZZ_CHECK(same(model.theta(), expected));
      }
      check_invariants();
    }
  }

 private:
  template <class A, class B>
  static bool same(const A& a, const B& b) {
    return a.size() == b.size() && same_bits(a.data(), b.data(), static_cast<long>(a.size()));
  }

  /// u and y: ordinary values in [-2, 2] (steps of 1/64), or any_double with its special values.
  Scalar sample(FuzzedDataProvider& in, std::uint8_t op) {
    if (op < 160) return static_cast<Scalar>(static_cast<double>(in.ConsumeIntegral<std::int8_t>()) / 64.0);
    return to_scalar<Scalar>(any_double(in));
  }

  /// P = p0 I in the recursion's coordinates (EstimatorOptions::normalise: covariance() is in the data's).
  bool is_initial_covariance() const {
    const Covariance expected = Covariance::Identity(m_n, m_n) * to_scalar<Scalar>(m_est.options().resolved_p0());
    return same(expected, m_est.normalised_covariance());
  }

  void update(FuzzedDataProvider& in, std::uint8_t op) {
    const Scalar u = sample(in, op);
    const Scalar y = sample(in, op);
    const Params theta = m_est.theta();
    const Covariance p = m_est.normalised_covariance();
    const Eigen::Index samples = m_est.samples();
    const bonl::EstimatorHealth health = m_est.health();
    const bool measuring = m_est.measuring_scale();
    const bonl::UpdateStatus status = m_est.update(u, y);
    // The samples the update took: one; none while the data's scale is measured; two while the
    // recursion catches up on the measured ones, when the status is the second's and the first may
    // have changed theta, P and the counts.
    const Eigen::Index taken = m_est.samples() - samples;
    const auto status_index = static_cast<std::size_t>(status);
    if (status_index < 4) ++outcomes.status[status_index];
    if (verbose()) {
      std::fprintf(stderr, "update(%.17g, %.17g) -> %d, trace %.17g\n", double(u), double(y), int(status),
                   double(m_est.covariance().trace()));
    }
    const bonl::EstimatorHealth& now = m_est.health();
    const bool finite = std::isfinite(u) && std::isfinite(y);
    FUZZ_CHECK(taken >= 0 && taken <= 2);
    // The update that ends the measurement sets the recursion's coordinates (and reads the method's
    // own start in them: P-H-W's c(0) = c0 sy) before it takes its first sample.
    if (taken == 2 || (measuring && !m_est.measuring_scale())) {
      FUZZ_CHECK(finite && status != bonl::UpdateStatus::RejectedNonFinite);
      FUZZ_CHECK(m_est.diverged() == m_est.health().diverged);
      record(status, taken);
      return;
    }
    const bool same_theta = same(theta, m_est.theta());
    // P is kept, or (recover_after) reset to p0 I by an automatic recovery in this update.
    const bool recovered = now.recoveries == health.recoveries + 1;
    FUZZ_CHECK(now.recoveries == health.recoveries || recovered);
    const bool kept_p = recovered ? is_initial_covariance() : same(p, m_est.normalised_covariance());
    switch (status) {
      case bonl::UpdateStatus::RejectedNonFinite:
        FUZZ_CHECK(!finite);
        FUZZ_CHECK(same_theta && same(p, m_est.normalised_covariance()) && taken == 0);
        FUZZ_CHECK(now.diverged == health.diverged && now.failures == health.failures && !recovered);
        return;  // not recorded either
      case bonl::UpdateStatus::NumericalFailure:
        FUZZ_CHECK(finite && same_theta && kept_p && m_est.diverged() && now.failures == health.failures + 1);
        break;
      case bonl::UpdateStatus::NoInformation:
        FUZZ_CHECK(finite && same_theta && kept_p && now.failures == health.failures);
        FUZZ_CHECK(m_est.diverged() == health.diverged);
        break;
      case bonl::UpdateStatus::Updated:
        FUZZ_CHECK(finite && !recovered && now.failures == health.failures && now.consecutive_failures == 0);
        FUZZ_CHECK(m_est.diverged() == health.diverged);
        break;
      default: FUZZ_CHECK(false);
    }
    // One sample taken, or none where the update was kept while the scale is measured (NoInformation).
    FUZZ_CHECK(taken == 1 || (taken == 0 && status == bonl::UpdateStatus::NoInformation));
    FUZZ_CHECK(m_est.diverged() == now.diverged);
    record(status, taken);
  }

  /// The recording after an update that took `taken` samples: its newest entry is the last of them.
  void record(bonl::UpdateStatus status, Eigen::Index taken) {
    if (m_est.recording() && taken > 0) {
      m_recorded += taken;
      const auto trajectory = m_est.trajectory();
      const auto count = static_cast<std::size_t>(std::min(m_recorded, m_capacity));
      FUZZ_CHECK(trajectory.status.size() == count && trajectory.sample.size() == count);
      FUZZ_CHECK(trajectory.theta.cols() == static_cast<Eigen::Index>(count) && trajectory.theta.rows() == m_n);
      FUZZ_CHECK(trajectory.status.back() == status);
      const Params newest = trajectory.theta.col(trajectory.theta.cols() - 1);
      FUZZ_CHECK(same(newest, m_est.theta()));
    }
  }

  void reset_to(FuzzedDataProvider& in) {
    const bool wrong_size = in.ConsumeIntegral<std::uint8_t>() < 32;
    const Eigen::Index size = wrong_size ? m_n + (in.ConsumeBool() ? 1 : -1) : m_n;
    VectorX theta0(size);
    bool finite = true;
    for (Eigen::Index i = 0; i < size; ++i) {
      theta0[i] = in.ConsumeBool() ? Scalar(0) : to_scalar<Scalar>(any_double(in));
      finite = finite && std::isfinite(theta0[i]);
    }
    try {
      m_est.reset(theta0);
      FUZZ_CHECK(size == m_n && finite);
      FUZZ_CHECK(same(theta0, m_est.theta()));
      check_fresh_covariance();
      m_recorded = 0;
    } catch (const std::invalid_argument&) {
      FUZZ_CHECK(size != m_n || !finite);
    }
  }

  void check_fresh() {
    // The output-error method starts from zero, the others at the model's initial estimate: zero
    // but c = c0 for a model with a backlash, or where a model's initial_estimate() says
    // (models/estimator_settings.hpp; the Bouc-Wen feedback model's alpha).
    Params expected = Params::Zero(m_n);
    if (m_est.options().method != bonl::Method::OutputError) {
      if constexpr (uses_c0<Model>()) {
        expected[m_n - 1] = to_scalar<Scalar>(m_est.settings().c0);
      } else if constexpr (bonl::detail::HasInitialEstimate<Model>::value) {
        expected = m_structure.initial_estimate(m_est.settings());
      }
    }
    FUZZ_CHECK(same(expected, m_est.theta()));
    check_fresh_covariance();
    m_recorded = 0;
  }

  void check_fresh_covariance() {
    FUZZ_CHECK(m_est.samples() == 0 && !m_est.diverged());
    FUZZ_CHECK(m_est.health().failures == 0 && m_est.health().recoveries == 0);
    FUZZ_CHECK(is_initial_covariance());
  }

  void check_invariants() {
    const Params& theta = m_est.theta();
    const Covariance p = m_est.normalised_covariance();  // the recursion's own P, which the safeguards keep
    FUZZ_CHECK(theta.size() == m_n && p.rows() == m_n && p.cols() == m_n);
    if (!theta.allFinite()) {
      std::fprintf(stderr, "theta is not finite\n");
      FUZZ_CHECK(false);
    }
    double trace = 0.0;
    for (Eigen::Index i = 0; i < m_n; ++i) {
      if (!(p(i, i) > Scalar(0))) std::fprintf(stderr, "P(%ld,%ld) = %g\n", long(i), long(i), double(p(i, i)));
      FUZZ_CHECK(p(i, i) > Scalar(0));
      trace += static_cast<double>(p(i, i));
      for (Eigen::Index j = 0; j < m_n; ++j) {
        if (!std::isfinite(p(i, j))) std::fprintf(stderr, "P(%ld,%ld) = %g\n", long(i), long(j), double(p(i, j)));
        FUZZ_CHECK(std::isfinite(p(i, j)));
        if (!same_bits(&p(i, j), &p(j, i), 1)) {
          std::fprintf(stderr, "P(%ld,%ld) = %.17g but P(%ld,%ld) = %.17g\n", long(i), long(j), double(p(i, j)),
                       long(j), long(i), double(p(j, i)));
          FUZZ_CHECK(false);
        }
      }
    }
    // The trace ceiling, up to the rounding of the n-term trace and of the scaling that enforces it:
    // relative, and absolute in Scalar's denormals (p0 may be denormal: it is finite and > 0).
    const double terms = 4.0 * static_cast<double>(m_n + 2);
    const double slack = m_max_trace * terms * static_cast<double>(std::numeric_limits<Scalar>::epsilon()) +
                         terms * static_cast<double>(std::numeric_limits<Scalar>::denorm_min());
    if (!(trace <= m_max_trace + slack)) {
      std::fprintf(stderr, "trace(P) = %.17g above the ceiling %.17g\n", trace, m_max_trace);
      FUZZ_CHECK(false);
    }
  }

  Model m_structure;
  Est m_est;
  Eigen::Index m_n;
  double m_max_trace = 0.0;
  Eigen::Index m_capacity = 0;
  Eigen::Index m_recorded = 0;
};

template <class Model>
void fuzz(FuzzedDataProvider& in) {
  const Orders<Model> orders = decode_orders<Model>(in);
  if (verbose()) print_orders<Model>(orders);
  std::optional<Model> structure;
  try {
    structure.emplace(bonl::make_model<Model>(orders));
  } catch (const std::invalid_argument&) {
    FUZZ_CHECK(!orders_valid<Model>(orders));
    ++outcomes.bad_orders;
    return;
  }
  FUZZ_CHECK(orders_valid<Model>(orders));

  const FuzzedOptions options = decode_options(in);
  print(options);
  std::optional<Harness<Model>> harness;
  try {
    harness.emplace(*structure, options.options, model_settings<Model>(options.c0));
  } catch (const std::invalid_argument& e) {
    if (options_valid<Model>(options)) std::fprintf(stderr, "valid options rejected: %s\n", e.what());
    FUZZ_CHECK(!options_valid<Model>(options));
    ++outcomes.bad_options;
    return;
  }
  FUZZ_CHECK(options_valid<Model>(options));
  ++outcomes.estimators;
  harness->run(in);
}

/// fuzz<Model>(in) for the model of the list at `index`.
template <class List>
void fuzz_model_at(List models, int index, FuzzedDataProvider& in) {
  int i = 0;
  bonl::for_each_model(models, [&](auto tag) {
    if (i++ == index) fuzz<typename decltype(tag)::type>(in);
  });
}

/// The kinds after the run-time models of bonl::Models: every model at the paper's fixed orders
/// (bonl::PaperOrders), in double, then in float (instantiated in fuzz_estimator_update_more.cpp
/// and fuzz_estimator_update_float.cpp: each is as long to compile as the run-time kinds, and the
/// three files compile side by side).
inline constexpr int kFixedKinds = 2 * static_cast<int>(bonl::Models::size);
void fuzz_fixed_kind(int kind, FuzzedDataProvider& in);
/// The float kinds of fuzz_fixed_kind: model `index` of bonl::PaperOrderModels in float.
void fuzz_fixed_float_kind(int index, FuzzedDataProvider& in);

}  // namespace bonl_fuzz
