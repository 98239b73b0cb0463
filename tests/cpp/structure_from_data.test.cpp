// structure_from_data (estimator/structure_from_data.hpp): a structure with what its model leaves to
// the data placed by identify()'s rule.
// - The Prandtl-Ishlinskii Hammerstein model: the thresholds are identify's extra start's (so identify
//   adds no other), the parameters and orders are kept, and the placement follows the input's units
//   and ignores its offset (identify's scaled units give the same thresholds in the data's units).
// - Every other model: the structure as it is.

#include "test_support.hpp"

#include <bonl/estimator/structure_from_data.hpp>

using namespace bonl_test;

TEST_CASE("structure_from_data places the plays' thresholds as identify's extra start does",
          "[structure_from_data][prandtl_ishlinskii]") {
  using Model = bonl::PrandtlIshlinskiiHammersteind;
  const Model truth = known_system<Model>("small");
  const Eigen::VectorXd u = (bonl::signals::random_levels(3000, 5, 0.8, 11).array() + 0.3).matrix();
  const Eigen::VectorXd y = truth.simulate(u);
  const bonl::CheckedRecords<double> records(u, y, truth.num_params());
  const Model placed = bonl::structure_from_data(truth, records.records());

  const auto starts = bonl::prandtl_ishlinskii_starts(truth, records);
  REQUIRE(starts.size() == 1);
  CHECK(placed.thresholds() == starts.front().thresholds());
  CHECK(placed.thresholds() != truth.thresholds());
  CHECK(placed.theta() == truth.theta());
  CHECK(placed.orders() == truth.orders());
  // Placed, the structure is the rule's: identify adds no start of its own.
  CHECK(bonl::prandtl_ishlinskii_starts(placed, records).empty());

  // Four times the input: four times the thresholds, exactly (powers of two are identify's units);
  // an offset moves nothing (the half-range is that of the deviations).
  const Eigen::VectorXd u4 = 4.0 * u, shifted = (u.array() - 2.5).matrix();
  CHECK(bonl::structure_from_data(truth, bonl::Records<double>{{u4, y}}).thresholds() == 4.0 * placed.thresholds());
  CHECK(bonl::structure_from_data(truth, bonl::Records<double>{{shifted, y}})
            .thresholds()
            .isApprox(placed.thresholds(), 1e-15));
}

TEST_CASE("structure_from_data returns any other model as it is", "[structure_from_data]") {
  const auto truth = known_system<bonl::PseudoHammersteinWienerd>();
  const Eigen::VectorXd u = identification_input(Input::MultiSine);
  const Eigen::VectorXd y = truth.simulate(u);
  const auto same = bonl::structure_from_data(truth, bonl::Records<double>{{u, y}});
  CHECK(same.theta() == truth.theta());
  CHECK(same.orders() == truth.orders());
}
