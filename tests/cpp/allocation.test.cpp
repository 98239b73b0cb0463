// The per-sample update performs no heap allocation (fixed sizes never, run-time sizes once the
// estimator is built), is noexcept, and keeps the covariance symmetric. Allocations are counted at
// the C allocator, in this test executable only (counting_allocator.hpp).

#include <optional>
#include <string>
#include <vector>

#include "counting_allocator.hpp"
#include "test_support.hpp"

using namespace bonl_test;

namespace {
/// Runs `body` and returns the heap allocations it made (counting_allocator.hpp).
template <typename Body>
long heap_allocations_in(Body&& body) {
  const long before = bonl_test::allocations();
  body();
  return bonl_test::allocations() - before;
}

/// Updates `structure` on a noisy record, with every method (the output-error one also with its
/// window refinement), and checks that they allocate nothing,
/// refuse nothing and leave the covariance exactly symmetric.
template <class Model>
void check_updates_allocate_nothing(const Model& structure, const std::optional<bonl::ForgettingSchedule>& forgetting) {
  INFO(Model::kName);
  const Eigen::VectorXd u = bonl::signals::random_levels(3000, 5, 1.0, 3);
  const Eigen::VectorXd y = structure.simulate(u) + bonl::signals::white_noise(u.size(), 0.01, 4);
  // The output-error method twice: the recursion alone and with the window refinement.
  for (int run = 0; run < 4; ++run) {
    const bonl::Method method = run < 2    ? bonl::Method::OutputError
                                : run == 2 ? bonl::Method::EquationError
                                           : bonl::Method::Paper;
    bonl::EstimatorOptions options;
    options.method = method;
    options.forgetting = forgetting;
    options.window.enabled = run == 1;
    INFO("method " << bonl::to_string(method) << (run == 1 ? " with the window refinement" : ""));
    bonl::Estimator<Model> estimator(structure, options);
    CHECK(heap_allocations_in([&] {
            for (Eigen::Index k = 0; k < u.size(); ++k) estimator.update(u[k], y[k]);
            estimator.update(std::nan(""), 0.0);
          }) == 0);
    // The same record again in one call (Estimator::update over arrays), its outputs preallocated.
    std::vector<bonl::UpdateStatus> statuses(static_cast<std::size_t>(u.size()));
    Eigen::VectorXd predictions(u.size());
    CHECK(heap_allocations_in([&] {
            estimator.update(u, y, [&](Eigen::Index k, bonl::UpdateStatus status) {
              statuses[static_cast<std::size_t>(k)] = status;
              predictions[k] = estimator.last_prediction();
            });
          }) == 0);
    // The Wiener-Hammerstein model's equation-error recursion wanders under forgetting 0.98 (its two
    // blocks' poles are told apart only through the polynomial) into f = 0, b2 = 0, where P loses
    // positiveness: those updates are refused and reported (docs/explanation/algorithm.md); allocation-free still.
    // The nonlinear-feedback model's output-error recursion refuses two early updates in the data's
    // scale (its cubic's coefficient, of order 1 / sy^2 there, moves far while P is P(0), and the
    // simulation it steps along leaves P's range once): the simulation restarts, and it converges.
    const bool refusals_expected = std::string(Model::kName) == "WienerHammerstein" &&
                                   method == bonl::Method::EquationError && forgetting.has_value();
    if (!refusals_expected) CHECK(estimator.health().failures <= 2);
    const auto p = estimator.covariance();
    CHECK(p == p.transpose());
  }
}
}  // namespace

TEMPLATE_LIST_TEST_CASE("fixed-size updates allocate nothing", "[allocation]", bonl::PaperOrderModels) {
  static_assert(noexcept(std::declval<bonl::Estimator<TestType>&>().update(0.0, 0.0)));
  check_updates_allocate_nothing(known_system<TestType>(), bonl::EstimatorOptions{}.forgetting);
}

// Run-time (Eigen::Dynamic) sizes allocate once, when the estimator is built; the updates reuse that.
// Forgetting 0.98 throughout, so that the trace ceiling and the scale fold run too.
TEMPLATE_LIST_TEST_CASE("run-time-size updates allocate nothing after construction", "[allocation]", bonl::Models) {
  check_updates_allocate_nothing(known_system<TestType>(), bonl::ForgettingSchedule::constant(0.98));
}

TEST_CASE("the Wiener-Hammerstein model's hinges update allocation-free too", "[allocation]") {
  check_updates_allocate_nothing(saturating_wiener_hammerstein(2), bonl::ForgettingSchedule::constant(0.98));
}

TEST_CASE("updates with recording on, the trace ceiling acting and automatic recovery allocate nothing",
          "[allocation]") {
  const auto structure = known_phw();
  bonl::EstimatorOptions options;
  // Equation error: its huge inputs stay in the regressor and fail updates in a row. (The
  // output-error method restarts its simulation when it leaves the finite numbers, so the failures
  // do not come in a row; check_updates_allocate_nothing covers its updates.)
  options.method = bonl::Method::EquationError;
  options.forgetting = bonl::ForgettingSchedule::constant(0.98);
  options.recover_after = 2;
  bonl::Estimator<bonl::PaperPseudoHammersteinWiener> estimator(structure, options);
  estimator.start_recording(64);
  const Eigen::VectorXd u = bonl::signals::random_levels(1000, 5, 1.0, 5);
  const Eigen::VectorXd y = structure.simulate(u);
  CHECK(heap_allocations_in([&] {
          for (Eigen::Index k = 0; k < u.size(); ++k) estimator.update(u[k], y[k]);
          for (int k = 0; k < 500; ++k) estimator.update(0.0, 0.0);   // wind-up: the ceiling acts
          for (int k = 0; k < 20; ++k) estimator.update(1e150, 0.0);  // failures and automatic recoveries
        }) == 0);
  CHECK(estimator.health().forgetting_limited > 0);
  CHECK(estimator.health().failures > 0);
  CHECK(estimator.health().recoveries > 0);
}
