// Records that cannot excite a structure: the distinct input values counted, the levels a structure
// needs, and the sentence that says so. Oracles: inputs whose levels are known by construction; a
// polynomial of degree r is fixed by r + 1 points; a Hammerstein model identified from a constant
// input that misses the known system on an exciting one.

#include "test_support.hpp"

#include <string>

namespace {

using bonl_test::vec;

TEST_CASE("input_levels counts the distinct input values over all records", "[excitation]") {
  const Eigen::VectorXd u1 = vec({1.0, 1.0, 2.0, 2.0, 3.0}), u2 = vec({3.0, -1.0}), y1 = Eigen::VectorXd::Zero(5),
                        y2 = Eigen::VectorXd::Zero(2);
  CHECK(bonl::input_levels(bonl::CheckedRecords<double>(u1, y1, 0)) == 3);
  CHECK(bonl::input_levels(bonl::CheckedRecords<double>({{u1, y1}, {u2, y2}}, 0)) == 4);  // 3 is in both
  const Eigen::VectorXd constant = Eigen::VectorXd::Constant(50, 0.7), y = Eigen::VectorXd::Zero(50);
  CHECK(bonl::input_levels(bonl::CheckedRecords<double>(constant, y, 0)) == 1);
}

TEST_CASE("input_levels_needed is r + 1 per polynomial segment and two for every other structure", "[excitation]") {
  CHECK(bonl::input_levels_needed(bonl::ARXd(2, 1, 0)) == 2);
  CHECK(bonl::input_levels_needed(bonl::Wienerd(2, 1, 0, 3)) == 2);
  CHECK(bonl::input_levels_needed(bonl::Hammersteind(2, 1, 0, 2)) == 6);  // two segments of degree 2
  CHECK(bonl::input_levels_needed(bonl::HammersteinWienerd(2, 1, 0, 1, 2)) == 4);
  CHECK(bonl::input_levels_needed(bonl::PseudoHammersteinWienerd(2, 1, 0, 3)) == 8);
  CHECK(bonl::input_levels_needed(bonl::PrandtlIshlinskiiHammersteind(2, 1, 0, 3, 2)) == 4);
}

TEMPLATE_LIST_TEST_CASE("a constant input cannot excite any model, random levels excite every one", "[excitation]",
                        bonl::Models) {
  const TestType structure = bonl_test::known_system<TestType>("small");
  const Eigen::VectorXd constant = Eigen::VectorXd::Constant(400, 0.5),
                        levels = bonl::signals::random_levels(400, 5, 1.0, 7);
  const Eigen::VectorXd y = Eigen::VectorXd::Zero(400);
  const std::string shortfall = bonl::excitation_shortfall(structure, bonl::CheckedRecords<double>(constant, y, 0));
  CHECK(shortfall == std::string("the input takes 1 value (it is constant) but a ") + TestType::kName +
                         " model needs at least " + std::to_string(bonl::input_levels_needed(structure)) +
                         " to be determined: it cannot excite the structure, and the identified parameters are "
                         "not fixed by the data");
  CHECK(bonl::excitation_shortfall(structure, bonl::CheckedRecords<double>(levels, y, 0)).empty());
}

TEST_CASE("two input levels cannot fix a Hammerstein model's input polynomial", "[excitation]") {
  const auto truth = bonl_test::known_system<bonl::Hammersteind>("small");
  const Eigen::VectorXd binary = bonl::signals::random_levels(2000, 20, 1.0, 8).array().sign().matrix();
  const Eigen::VectorXd y = truth.simulate(binary);
  const bonl::CheckedRecords<double> records(binary, y, truth.num_params());
  REQUIRE(bonl::input_levels(records) == 2);
  CHECK(bonl::excitation_shortfall(truth, records) ==
        "the input takes 2 distinct values but a Hammerstein model needs at least 6 to be determined: it cannot "
        "excite the structure, and the identified parameters are not fixed by the data");
  // Why it matters: the model fits the binary record it was identified on, and misses the known
  // system on an input with other levels.
  const auto model = bonl::identify(bonl_test::structure_of(truth), records);
  const Eigen::VectorXd levels = bonl::signals::random_levels(2000, 20, 1.0, 9);
  CHECK(bonl::metrics::nrmse(y, model.simulate(binary)) < 0.01);
  CHECK(bonl::metrics::nrmse(truth.simulate(levels), model.simulate(levels)) > 0.05);
}

}  // namespace
