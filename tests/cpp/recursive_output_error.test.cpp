// The output-error method (Method::OutputError, the models' OutputErrorTerms and Estimator's
// update), as property suites over every model:
// - each model's one-step simulation equals simulate(), and its sensitivities equal central finite
//   differences of simulate()'s output (for P-H-W through the backlash's driving and gap phases);
// - noise-free records are recovered exactly (the known systems of tests/data/online_systems.json);
// - under white output noise the error shrinks like 1 / sqrt(N) (consistency);
// - with constant forgetting a step in the parameters is tracked;
// - the update's contract: started at the truth it stays there, last_prediction() is the simulated
//   output, the stability projection keeps the linear block stable.
// The bounds are from measurement (docs/results/online_accuracy.md has the figures).

#include <bonl/io.hpp>

#include <nlohmann/json.hpp>

#include <fstream>
#include <string>
#include <vector>

#include "parameter_step.hpp"
#include "test_support.hpp"

using namespace bonl_test;

namespace {

template <class Model>
Model known() {
  return known_system<Model>();
}

template <class Model>
constexpr bool is_phw = has_backlash<Model>();

/// The model's output and d y / d theta over a record, from its OutputErrorTerms at fixed theta.
template <class Model>
Eigen::MatrixXd sensitivities(const Model& model, const Eigen::VectorXd& u, Eigen::VectorXd& y) {
  typename Model::OutputErrorTerms terms(model);
  Eigen::MatrixXd jacobian(u.size(), model.num_params());
  y.resize(u.size());
  for (Eigen::Index k = 0; k < u.size(); ++k) {
    const auto simulated = terms.step(model.theta(), u[k]);
    y[k] = simulated.output;
    jacobian.row(k) = simulated.sensitivity.transpose();
    terms.accept();
  }
  return jacobian;
}

/// The known systems of tests/data/online_systems.json.
/// A known online system: its name, its model, and the NRMSE one noise-free pass of the default
/// estimator stays within (the file's one_pass_nrmse where a system converges slower, else 1e-9).
struct OnlineSystem {
  std::string name;
  bonl::io::AnyModel model;
  double one_pass_nrmse;
};

std::vector<OnlineSystem> online_systems() {
  std::ifstream in(std::string(bonl_test::data_dir()) + "/online_systems.json");
  REQUIRE(in);
  const nlohmann::json document = nlohmann::json::parse(in);
  std::vector<OnlineSystem> out;
  for (const auto& entry : document.at("systems")) {
    out.push_back({entry.at("name").get<std::string>(), bonl::io::load_model(entry.at("model").dump()),
                   entry.value("one_pass_nrmse", 1e-9)});
  }
  return out;
}

template <class Model>
Model online_estimate(const Model& structure, const Eigen::VectorXd& u, const Eigen::VectorXd& y,
                      const bonl::EstimatorOptions& options = {}) {
  bonl::Estimator<Model> estimator(structure, options);
  for (Eigen::Index k = 0; k < u.size(); ++k) estimator.update(u[k], y[k]);
  return estimator.model();
}

}  // namespace

/// The output-error terms simulate like simulate() and their sensitivities are its derivatives.
template <class Model>
void check_sensitivities() {
  const Model model = known<Model>();
  const Eigen::VectorXd u = bonl::signals::random_levels(1500, 5, 1.0, 31);
  Eigen::VectorXd y;
  const Eigen::MatrixXd jacobian = sensitivities(model, u, y);
  const Eigen::VectorXd simulated = model.simulate(u);
  CHECK((y - simulated).cwiseAbs().maxCoeff() <= 1e-12 * simulated.cwiseAbs().maxCoeff());

  // Central differences of simulate(). A backlash output is piecewise smooth: a sample whose regime
  // the +-step flips (and the gap samples holding its value) differ, so P-H-W allows a few such samples.
  const Eigen::Index matching = matching_samples(jacobian, simulation_differences(model, u));
  INFO(Model::kName << ": " << matching << " of " << u.size() << " samples match the finite differences");
  if constexpr (is_phw<Model>) {
    CHECK(matching >= u.size() * 99 / 100);
    // The record goes through both phases: samples held in the gap and samples driven.
    Eigen::Index held = 0;
    for (Eigen::Index k = 1; k < u.size(); ++k) held += simulated[k] == simulated[k - 1];
    CHECK(held > u.size() / 10);
    CHECK(held < u.size() * 9 / 10);
  } else {
    CHECK(matching == u.size());
  }
}

TEMPLATE_LIST_TEST_CASE("the output-error terms simulate like simulate() and their sensitivities are its derivatives",
                        "[output_error]", bonl::Models) {
  check_sensitivities<TestType>();
}

TEMPLATE_LIST_TEST_CASE("fixed orders: the output-error sensitivities are the simulation's derivatives",
                        "[output_error]", bonl::PaperOrderModels) {
  check_sensitivities<TestType>();
}

TEST_CASE("noise-free records of the known online systems are recovered exactly", "[output_error]") {
  // One pass of 4000 samples of random levels (held 5 samples), default settings. Measured: 21 of the
  // 23 systems at 1e-13 or below and c within 1e-13; the Wiener-Hammerstein model and the integrating
  // friction drive converge slower (their one_pass_nrmse; docs/results/online_accuracy.md).
  const Eigen::VectorXd u = bonl::signals::random_levels(4000, 5, 1.0, 101);
  const Eigen::VectorXd u_validation = bonl::signals::random_levels(4000, 5, 1.0, 202);
  for (const OnlineSystem& system : online_systems()) {
    std::visit(
        [&](const auto& truth) {
          using Model = std::decay_t<decltype(truth)>;
          const Model estimate = online_estimate(truth, u, truth.simulate(u));
          const double error = bonl::metrics::nrmse(truth.simulate(u_validation), estimate.simulate(u_validation));
          INFO(system.name << ": validation NRMSE " << error);
          CHECK(error <= system.one_pass_nrmse);
          if constexpr (std::is_same_v<Model, bonl::PseudoHammersteinWienerd>) {
            CHECK(std::abs(estimate.c() - truth.c()) <= 1e-9 * truth.c());
          }
        },
        system.model);
  }
}

TEMPLATE_LIST_TEST_CASE("under white output noise the online error shrinks like 1 / sqrt(N)", "[output_error]",
                        bonl::Models) {
  // A consistent estimator's simulation error keeps falling as the record grows. By sqrt(4) = 2 when
  // it grows four-fold offline; online by less: at 4000 samples the window refinement's estimate is
  // already near identify()'s, and the adaptive memory keeps about half the samples seen, so from
  // 4000 to 16000 the error falls by about sqrt(8000 / 4000). Median over 5 seeds of 2% white noise;
  // measured ratios 0.40 (Wiener-Hammerstein, not yet converged at 4000) to 0.90 (Wiener), bound
  // 0.95. (With the window capping the memory at its 4000 samples, the error at 16000 was above the
  // one at 4000: 1.1 to 2.0.)
  const TestType truth = known<TestType>();
  const Eigen::VectorXd u_validation = bonl::signals::random_levels(4000, 5, 1.0, 77);
  const Eigen::VectorXd y_validation = truth.simulate(u_validation);
  const auto median_error = [&](Eigen::Index samples) {
    std::vector<double> errors;
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
      const Eigen::VectorXd u = bonl::signals::random_levels(samples, 5, 1.0, 500 + seed);
      const Eigen::VectorXd clean = truth.simulate(u);
      const Eigen::VectorXd y =
          clean + bonl::signals::white_noise(samples, 0.02 * standard_deviation(clean), 600 + seed);
      errors.push_back(bonl::metrics::nrmse(y_validation, online_estimate(truth, u, y).simulate(u_validation)));
    }
    std::sort(errors.begin(), errors.end());
    return errors[2];
  };
  const double short_record = median_error(4000), long_record = median_error(16000);
  INFO(TestType::kName << ": median NRMSE " << short_record << " at 4000 samples, " << long_record << " at 16000");
  CHECK(long_record <= 0.95 * short_record);
  CHECK(long_record >= 0.3 * short_record);  // not faster either: that would be an error, not noise
}

TEMPLATE_LIST_TEST_CASE("with constant forgetting a step in the parameters is tracked", "[output_error]",
                        bonl::Models) {
  // Noise-free, forgetting 0.995; at sample 4000 the input gain grows by 30% (and c doubles).
  // Measured: on the suite's known systems here 1150 (ARX), 2000 (Hammerstein), 2500 (H-W) and
  // 1950 (P-H-W) samples to get back under 1% NRMSE; on the online systems 700 to 2800
  // (docs/results/online_accuracy.md). Issue 16 asked for 1500: not met for the third-order fronts,
  // whose slow valley between numerator and denominator the estimator crawls along
  // (docs/explanation/algorithm.md). The bound holds what is measured.
  const TestType before = known<TestType>();
  const TestType after = with_parameter_step(before);

  const Eigen::VectorXd u = bonl::signals::random_levels(8000, 5, 1.0, 41);
  typename TestType::OutputErrorTerms plant(before);  // one free run, the parameters switched at 4000
  bonl::EstimatorOptions options;
  options.forgetting = bonl::ForgettingSchedule::constant(0.995);
  bonl::Estimator<TestType> estimator(before, options);
  const Eigen::VectorXd u_validation = bonl::signals::random_levels(4000, 5, 1.0, 42);
  const Eigen::VectorXd y_validation = after.simulate(u_validation);
  Eigen::Index recovered = -1;
  Eigen::VectorXd simulated;
  for (Eigen::Index k = 0; k < u.size(); ++k) {
    const double y = plant.step(k < 4000 ? before.theta() : after.theta(), u[k]).output;
    plant.accept();
    estimator.update(u[k], y);
    // An estimate whose free run leaves the finite numbers (the Bouc-Wen feedback model's, just after
    // the step, runs off once its hysteresis takes more stiffness than A holds) is not back.
    if (k >= 4000 && (k + 1 - 4000) % 50 == 0 && recovered < 0 &&
        estimator.model().try_simulate(u_validation, simulated) &&
        bonl::metrics::nrmse(y_validation, simulated) < 0.01) {
      recovered = k + 1 - 4000;
    }
  }
  INFO(TestType::kName << ": back under 1% after " << recovered << " samples");
  CHECK(recovered > 0);
  CHECK(recovered <= 3000);
}

TEMPLATE_LIST_TEST_CASE("started at the truth, the output-error update predicts by simulation and stays there",
                        "[output_error]", bonl::Models) {
  const TestType truth = known<TestType>();
  const Eigen::VectorXd u = bonl::signals::random_levels(2000, 5, 1.0, 51);
  const Eigen::VectorXd y = truth.simulate(u);
  bonl::EstimatorOptions options;
  options.normalise = false;  // one sample per update: its prediction is this sample's
  bonl::Estimator<TestType> estimator(truth, options);
  estimator.reset(truth.theta());
  double largest_difference = 0.0;
  for (Eigen::Index k = 0; k < u.size(); ++k) {
    REQUIRE(estimator.update(u[k], y[k]) == bonl::UpdateStatus::Updated);
    largest_difference = std::max(largest_difference, std::abs(estimator.last_prediction() - y[k]));
  }
  CHECK(largest_difference <= 1e-12 * y.cwiseAbs().maxCoeff());  // last_prediction(): the simulated output
  CHECK(near(estimator.theta(), truth.theta(), 1e-12));
  CHECK(estimator.health().projections == 0);
}

TEST_CASE("the stability projection keeps the estimated denominator stable", "[output_error]") {
  // A large initial covariance makes the first steps wild; every accepted estimate must still have
  // its poles inside the stability radius, and some steps must have been shortened for it.
  const bonl::Hammersteind truth = known<bonl::Hammersteind>();
  const Eigen::VectorXd u = bonl::signals::random_levels(3000, 5, 1.0, 61);
  const Eigen::VectorXd y = truth.simulate(u) + bonl::signals::white_noise(u.size(), 0.05, 62);
  bonl::EstimatorOptions options;
  options.p0 = 1e4;
  bonl::Estimator<bonl::Hammersteind> estimator(truth, options);
  Eigen::VectorXd work(3);
  for (Eigen::Index k = 0; k < u.size(); ++k) {
    estimator.update(u[k], y[k]);
    const Eigen::VectorXd a = estimator.model().a();
    REQUIRE(bonl::detail::roots_inside(a, 0.999, work));
  }
  CHECK(estimator.health().projections > 0);
}
