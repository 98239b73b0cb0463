#pragma once
// Data shared by the benchmarks, all from fixed seeds:
// - the recorded noisy response of the known P-H-W system (the estimator and simulation benchmarks);
// - the paper-order models with those known parameters, in any scalar type and size;
// - random regressors for the RLS benchmarks, from splitmix64 so that bench/python_baselines.py
//   generates exactly the same numbers for padasip and numpy (see regressors()).

#include <Eigen/Core>
#include <array>
#include <bonl/bonl.hpp>
#include <cstdint>
#include <string>
#include <type_traits>

namespace bonl_bench {

/// Known parameters of the P-H-W system that generates the record (also used, in part, by the other
/// models for the free-run benchmarks).
inline Eigen::VectorXd true_f() { return (Eigen::VectorXd(4) << 0.002, 0.06, 0.02, -0.01).finished(); }
inline Eigen::VectorXd true_p() { return (Eigen::VectorXd(4) << -0.003, -0.02, -0.03, 0.015).finished(); }
inline Eigen::VectorXd true_b() { return (Eigen::VectorXd(3) << 1.0, 0.5, 0.2).finished(); }
inline Eigen::VectorXd true_a() { return (Eigen::VectorXd(3) << -1.7, 1.04, -0.238).finished(); }
inline Eigen::VectorXd true_q() { return (Eigen::VectorXd(3) << 1.0, 0.3, -0.1).finished(); }
constexpr double kTrueC = 0.1;

/// Input and measured output, 4096 samples, as Scalar.
template <typename Scalar>
struct Record {
  Eigen::Matrix<Scalar, Eigen::Dynamic, 1> u, y;
};

inline const Record<double>& record_double() {
  static const Record<double> data = [] {
    auto truth = bonl::make_model_at<bonl::PaperPseudoHammersteinWiener, bonl::PaperOrders>();
    truth.set_f(true_f());
    truth.set_p(true_p());
    truth.set_b(true_b());
    truth.set_a(true_a());
    truth.set_c(kTrueC);
    Record<double> r;
    r.u = bonl::signals::random_levels(4096, 5, 1.0, 1);
    r.y = truth.simulate(r.u) + bonl::signals::white_noise(r.u.size(), 0.01, 2);
    return r;
  }();
  return data;
}

template <typename Scalar>
const Record<Scalar>& record() {
  if constexpr (std::is_same_v<Scalar, double>) {
    return record_double();
  } else {
    static const Record<Scalar> data{record_double().u.template cast<Scalar>(),
                                     record_double().y.template cast<Scalar>()};
    return data;
  }
}

/// Records the P-H-W structure at the paper's orders (nk = 8) does not fit, on which the output-error
/// update's safeguards work on most samples (the estimator benchmarks' `/<data>` rows): the
/// benchmark record's input, and
/// - DelayedFir: a tenth of it through a pure delay of 12 samples, with the record's noise: the
///   small input excites the estimate weakly, the trace ceiling limits the forgetting on most samples;
/// - Integrator: its sum from sample 8 on (a pole at 1, which the stability radius 0.999 forbids),
///   with the record's noise: most updates are shortened by the stability projection.
enum class Mismatch { DelayedFir, Integrator };
constexpr Mismatch kMismatches[] = {Mismatch::DelayedFir, Mismatch::Integrator};
inline const char* name(Mismatch data) { return data == Mismatch::DelayedFir ? "delayed_fir" : "integrator"; }

template <typename Scalar>
const Record<Scalar>& mismatched_record(Mismatch data) {
  static const auto make = [](Mismatch which) {
    const Record<double>& known = record_double();
    const Eigen::Index n = known.u.size();
    const Eigen::VectorXd noise = bonl::signals::white_noise(n, 0.01, 2);
    Record<Scalar> r;
    Eigen::VectorXd u = known.u, y = Eigen::VectorXd::Zero(n);
    if (which == Mismatch::DelayedFir) {
      u *= 0.1;
      for (Eigen::Index k = 12; k < n; ++k) y[k] = u[k - 12];
    } else {
      for (Eigen::Index k = 8; k < n; ++k) y[k] = y[k - 1] + u[k - 8];
    }
    r.u = u.cast<Scalar>();
    r.y = (y + noise).cast<Scalar>();
    return r;
  };
  static const Record<Scalar> fir = make(Mismatch::DelayedFir), integrator = make(Mismatch::Integrator);
  return data == Mismatch::DelayedFir ? fir : integrator;
}

/// The benchmarked models at the paper's orders (bonl::PaperOrders), in scalar type S, with fixed
/// (template) or run-time sizes: every model of bonl::Models, each named by its kName.
template <typename S, bool Fixed>
using PaperOrderModels =
    typename bonl::ModelsWithScalar<std::conditional_t<Fixed, bonl::PaperOrderModels, bonl::Models>, S>::type;

/// The structure of a model at the paper's orders (na = 3, nb = 2, nk = 8, r = r1 = 3, ...:
/// bonl::PaperOrders); any other order (the feedback's signal nv, ...) at the smallest value the
/// model accepts.
template <class Model>
Model make_structure() {
  return bonl::make_model_at<Model, bonl::PaperOrders>();
}

/// What the safeguards did over passes of an estimator over a record: how many updates ran the RLS
/// step (UpdateStatus::Updated), had their forgetting limited by the trace ceiling, or were shortened
/// by the stability projection.
struct PassCounts {
  long updated = 0, forgetting_limited = 0, projections = 0;
};

/// Updates an estimator of `structure` over `data` `passes` times, each pass from the initial
/// estimate (reset()), and counts what the updates did.
template <class Model>
PassCounts count_updates(const Model& structure, const bonl::EstimatorOptions& options,
                         const Record<typename Model::Scalar>& data, long passes = 1) {
  bonl::Estimator<Model> estimator(structure, options);
  PassCounts counts;
  for (long pass = 0; pass < passes; ++pass) {
    estimator.reset();
    for (Eigen::Index k = 0; k < data.u.size(); ++k) {
      counts.updated += estimator.update(data.u[k], data.y[k]) == bonl::UpdateStatus::Updated ? 1 : 0;
    }
    counts.forgetting_limited += static_cast<long>(estimator.health().forgetting_limited);
    counts.projections += static_cast<long>(estimator.health().projections);
  }
  return counts;
}

/// A stable model with the known parameters, each block by its name (b, a, f, p, q, c).
template <class Model>
Model make_known_model() {
  using S = typename Model::Scalar;
  Model model = make_structure<Model>();
  for (std::size_t i = 0; i < Model::kDescription.parameters.size(); ++i) {
    const std::string name = Model::kDescription.parameters[i].name;
    // The Wiener-Hammerstein model: both blocks the known linear block's (b1 at a tenth, so that the
    // polynomial sees moderate x1), its normalised f the output polynomial's q.
    const bool normalised_f = name == "f" && Model::kDescription.parameters[i].normalised != nullptr;
    // Any other block (the W-H model's knots and g: none at nh = 0), and a known block whose size
    // differs here (the nonlinear-feedback model's f, f_2..f_r), keeps the structure's value, which
    // is valid by construction: a block this function does not know cannot make it throw.
    const Eigen::VectorXd value = name == "b" || name == "b2"                   ? true_b()
                                  : name == "b1"                                ? Eigen::VectorXd(0.1 * true_b())
                                  : name == "a" || name == "a1" || name == "a2" ? true_a()
                                  : normalised_f || name == "q"                 ? true_q()
                                  : name == "f"                                 ? true_f()
                                  : name == "p"                                 ? true_p()
                                  : name == "c"                                 ? Eigen::VectorXd::Constant(1, kTrueC)
                                                : model.parameter(i).template cast<double>();
    if (value.size() == model.parameter(i).size()) model.set_parameter(i, value.cast<S>());
  }
  return model;
}

/// splitmix64 (Steele, Lea, Flood 2014), the generator shared with bench/python_baselines.py.
class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : m_state(seed) {}
  std::uint64_t next() noexcept {
    std::uint64_t z = (m_state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }
  /// Uniform on [-1, 1): the top 53 bits.
  double uniform() noexcept { return static_cast<double>(next() >> 11) * 0x1.0p-52 - 1.0; }

 private:
  std::uint64_t m_state;
};

/// `samples` random regressors of n parameters (columns, uniform on [-1, 1)) and targets
/// y = phi' theta_true + 0.01 e: one generator, seeded with 12345 + n, draws theta_true (n values),
/// then per sample the n regressor entries and e (uniform on [-1, 1)). The RLS benchmarks cycle
/// through them.
struct Regressors {
  Eigen::MatrixXd phi;  // n x samples
  Eigen::VectorXd y;
};

inline Regressors regressors(Eigen::Index n, Eigen::Index samples = 1024) {
  SplitMix64 generator(12345u + static_cast<std::uint64_t>(n));
  Eigen::VectorXd theta(n);
  for (Eigen::Index i = 0; i < n; ++i) theta[i] = generator.uniform();
  Regressors r{Eigen::MatrixXd(n, samples), Eigen::VectorXd(samples)};
  for (Eigen::Index k = 0; k < samples; ++k) {
    for (Eigen::Index i = 0; i < n; ++i) r.phi(i, k) = generator.uniform();
    r.y[k] = r.phi.col(k).dot(theta) + 0.01 * generator.uniform();
  }
  return r;
}

/// Settings shared by every RLS benchmark and the Python baselines: forgetting factor and P(0).
constexpr double kLambda = 0.99;
constexpr double kP0 = 1e3;

}  // namespace bonl_bench
