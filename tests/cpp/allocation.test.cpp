// The fixed-size per-sample update performs no heap allocation, is noexcept, and keeps the
// covariance symmetric. Allocations are counted by replacing the global operator new in this test
// executable only.

#include "counting_allocator.hpp"
#include "test_support.hpp"

using namespace bonl_test;

TEMPLATE_TEST_CASE("fixed-size updates allocate nothing", "[allocation]", bonl::PaperARX, bonl::PaperHammerstein,
                   bonl::PaperHammersteinWiener, bonl::PaperPseudoHammersteinWiener) {
  static_assert(noexcept(std::declval<bonl::Estimator<TestType>&>().update(0.0, 0.0)));
  TestType structure = [] {
    if constexpr (std::is_same_v<TestType, bonl::PaperARX>) return known_arx();
    else if constexpr (std::is_same_v<TestType, bonl::PaperHammerstein>) return known_hammerstein();
    else if constexpr (std::is_same_v<TestType, bonl::PaperHammersteinWiener>) return known_hammerstein_wiener();
    else return known_phw();
  }();
  const Eigen::VectorXd u = bonl::signals::random_levels(3000, 5, 1.0, 3);
  const Eigen::VectorXd y = structure.simulate(u) + bonl::signals::white_noise(u.size(), 0.01, 4);
  for (bonl::Method method : {bonl::Method::Default, bonl::Method::Paper}) {
    bonl::EstimatorOptions options;
    options.method = method;
    bonl::Estimator<TestType> estimator(structure, options);
    const long before = bonl_test::allocations();
    for (Eigen::Index k = 0; k < u.size(); ++k) estimator.update(u[k], y[k]);
    estimator.update(std::nan(""), 0.0);
    const long after = bonl_test::allocations();
    CHECK(after - before == 0);
    const auto p = estimator.covariance();
    CHECK(p == p.transpose());
  }
}

TEST_CASE("updates with recording on, the trace ceiling acting and automatic recovery allocate nothing",
          "[allocation]") {
  const auto structure = known_phw();
  bonl::EstimatorOptions options;
  options.forgetting = bonl::ForgettingSchedule::constant(0.98);
  options.recover_after = 2;
  bonl::Estimator<bonl::PaperPseudoHammersteinWiener> estimator(structure, options);
  estimator.start_recording(64);
  const Eigen::VectorXd u = bonl::signals::random_levels(1000, 5, 1.0, 5);
  const Eigen::VectorXd y = structure.simulate(u);
  const long before = bonl_test::allocations();
  for (Eigen::Index k = 0; k < u.size(); ++k) estimator.update(u[k], y[k]);
  for (int k = 0; k < 500; ++k) estimator.update(0.0, 0.0);  // wind-up: the ceiling acts
  for (int k = 0; k < 20; ++k) estimator.update(1e150, 0.0);  // failures and automatic recoveries
  const long after = bonl_test::allocations();
  CHECK(after - before == 0);
  CHECK(estimator.health().forgetting_limited > 0);
  CHECK(estimator.health().failures > 0);
  CHECK(estimator.health().recoveries > 0);
}
