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
