// The Wiener-Hammerstein model and its start from the best linear approximation
// (models/wiener_hammerstein.hpp, estimator/wiener_hammerstein_start.hpp). The property suites run
// over it with the other models (bonl::Models); here what is its own:
// - The free run equals the three blocks run one after the other by hand (LinearBlock, the polynomial
//   written out, LinearBlock).
// - identify() recovers both known systems (tests/data/known_systems.json, noise-free) to NRMSE <= 1e-6
//   on a fresh input (issue 21's acceptance).
// - Every scored split is a model whose own free run gives the split's cost: the normalisation
//   (f_1 = 1, b2_0 = 1, the gain into b1) changes nothing the data see.
// - The split scan keeps complex pairs together: the number of splits is what counting the groups gives.

#include "test_support.hpp"

#include <cmath>

using namespace bonl_test;

namespace {

Eigen::VectorXd fresh_input() { return bonl::signals::random_levels(6000, 5, 1.0, 77); }

}  // namespace

TEST_CASE("the free run is the first block, the polynomial and the second block in turn", "[wiener_hammerstein]") {
  const auto model = known_system<bonl::WienerHammersteind>();
  const Eigen::VectorXd u = fresh_input();
  bonl::LinearBlock<double> first(3, 2, kNk), second(3, 2, 0);
  first.set_a(model.a1());
  first.set_b(model.b1());
  second.set_a(model.a2());
  second.set_b(model.b2());
  const Eigen::VectorXd f = model.f();
  Eigen::VectorXd expected(u.size());
  for (Eigen::Index k = 0; k < u.size(); ++k) {
    const double x1 = first.step(u[k]);
    expected[k] = second.step(x1 + f[1] * x1 * x1 + f[2] * x1 * x1 * x1);
  }
  CHECK((model.simulate(u) - expected).cwiseAbs().maxCoeff() <= 1e-14 * expected.cwiseAbs().maxCoeff());
}

TEST_CASE("identify recovers the known Wiener-Hammerstein systems to NRMSE 1e-6 on a fresh input",
          "[wiener_hammerstein][identify]") {
  for (const char* set : {"paper_orders", "small"}) {
    INFO(set);
    const auto truth = known_system<bonl::WienerHammersteind>(set);
    const Eigen::VectorXd u = bonl::signals::random_levels(5000, 5, 1.0, 1);
    const auto identified = bonl::identify(truth, u, truth.simulate(u));
    const Eigen::VectorXd fresh = fresh_input();
    const double nrmse = bonl::metrics::nrmse(truth.simulate(fresh), identified.simulate(fresh));
    INFO("NRMSE " << nrmse);
    CHECK(nrmse <= 1e-6);
  }
}

TEST_CASE("each split of the best linear approximation is a model whose free run gives its cost",
          "[wiener_hammerstein][start]") {
  const auto truth = known_system<bonl::WienerHammersteind>();
  const Eigen::VectorXd u = bonl::signals::random_levels(5000, 5, 1.0, 3);
  const Eigen::VectorXd y = truth.simulate(u) + bonl::signals::white_noise(u.size(), 0.01, 4);
  const bonl::Records<double> records{{u, y}};
  const auto splits = bonl::wiener_hammerstein_splits(truth, records);
  REQUIRE_FALSE(splits.empty());
  for (std::size_t i = 0; i < splits.size(); ++i) {
    INFO("split " << i);
    const auto& model = splits[i].model;
    CHECK(model.f()[0] == 1.0);
    CHECK(model.b2()[0] == 1.0);
    const double cost = (y - model.simulate(u)).squaredNorm() / double(u.size());
    CHECK(cost == Approx(splits[i].cost).epsilon(1e-8));
    if (i > 0) CHECK(splits[i - 1].cost <= splits[i].cost);
  }
  // Six poles and four zeros, each block taking three poles and two zeros: the BLA's poles are
  // grouped as real roots and complex pairs, and so are its zeros; the scan takes every subset of
  // the groups of the right size (fewer splits where a pair cannot be split, never more than
  // C(6, 3) C(4, 2) = 120).
  CHECK(splits.size() <= 120);
  // The best split explains most of the output (the refinement does the rest).
  const double variance = (y.array() - y.mean()).square().mean();
  INFO("best split's cost " << splits.front().cost << ", output variance " << variance);
  CHECK(splits.front().cost <= 0.2 * variance);
}

TEST_CASE("an inverse is refused for the Wiener-Hammerstein model at compile time, not silently",
          "[wiener_hammerstein][control]") {
  STATIC_REQUIRE_FALSE(bonl::control::has_inverse<bonl::WienerHammersteind>::value);
  STATIC_REQUIRE(bonl::control::has_inverse<bonl::Wienerd>::value);
  STATIC_REQUIRE(bonl::control::InvertibleModels::size + 1 == bonl::Models::size);
}
