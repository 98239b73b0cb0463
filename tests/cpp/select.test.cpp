// Order selection in C++ (estimator/select.hpp), as Python's bonl.select.
// Oracles: data from a known structure, whose orders the selection must find among wrong ones;
// the same selection on one thread and on two (identical tables); a candidate that cannot be fitted
// reported in its row while the others are kept.

#include "test_support.hpp"

#include <vector>

using namespace bonl_test;

namespace {

std::vector<bonl::Hammersteind> delay_grid() {
  std::vector<bonl::Hammersteind> grid;
  for (Eigen::Index nk : {1, 2, 3}) grid.emplace_back(2, 1, nk, 2);
  return grid;
}

}  // namespace

TEST_CASE("select finds the delay of a known system and ranks the others behind it", "[select]") {
  const bonl::Hammersteind truth = known_system<bonl::Hammersteind>("small");  // nk = 2
  const Eigen::VectorXd u = bonl::signals::random_levels(2000, 5, 1.0, 71);
  const Eigen::VectorXd y = truth.simulate(u) + bonl::signals::white_noise(u.size(), 0.01, 72);
  const bonl::Records<double> records{{u, y}};
  for (auto criterion : {bonl::SelectionCriterion::Validation, bonl::SelectionCriterion::AIC,
                         bonl::SelectionCriterion::BIC}) {
    bonl::SelectOptions options;
    options.criterion = criterion;
    const auto selection = bonl::select(delay_grid(), records, options);
    REQUIRE(selection.table.size() == 3);
    CHECK(selection.table[0].structure.nk() == 2);
    CHECK(selection.best.nk() == 2);
    CHECK(selection.table[0].score <= selection.table[1].score);
    CHECK(selection.table[1].score <= selection.table[2].score);
    // The refitted best is the identification on all the data.
    CHECK(selection.best.theta() == bonl::identify(truth, records).theta());
  }
}

TEST_CASE("select gives the same table on one thread and on two", "[select]") {
  const bonl::Hammersteind truth = known_system<bonl::Hammersteind>("small");
  const Eigen::VectorXd u = bonl::signals::random_levels(1500, 5, 1.0, 73);
  const Eigen::VectorXd y = truth.simulate(u) + bonl::signals::white_noise(u.size(), 0.02, 74);
  const bonl::Records<double> records{{u, y}};
  bonl::SelectOptions one, two;
  one.threads = 1;
  two.threads = 2;
  const auto a = bonl::select(delay_grid(), records, one);
  const auto b = bonl::select(delay_grid(), records, two);
  for (std::size_t i = 0; i < a.table.size(); ++i) {
    CHECK(a.table[i].structure.nk() == b.table[i].structure.nk());
    CHECK(a.table[i].score == b.table[i].score);
  }
}

TEST_CASE("select reports a candidate that cannot be fitted in its row and keeps the rest", "[select][bad_input]") {
  const bonl::ARXd truth = known_system<bonl::ARXd>("small");
  const Eigen::VectorXd u = bonl::signals::random_levels(40, 2, 1.0, 75);
  const Eigen::VectorXd y = truth.simulate(u);
  const bonl::Records<double> records{{u, y}};
  // 30 samples to fit on; ARX(20, 20, 0) has 41 parameters.
  const std::vector<bonl::ARXd> grid{bonl::ARXd(20, 20, 0), bonl::ARXd(2, 1, 2)};
  const auto selection = bonl::select(grid, records);
  CHECK(selection.table[0].structure.na() == 2);
  CHECK(selection.table[0].error.empty());
  CHECK(selection.table[1].structure.na() == 20);
  CHECK_THAT(selection.table[1].error, Catch::Matchers::Contains("longer together than the number of parameters"));
  CHECK_FALSE(selection.table[1].model.has_value());

  CHECK_THROWS_WITH(bonl::select(std::vector<bonl::ARXd>{}, records), Catch::Matchers::Contains("candidates is empty"));
  bonl::SelectOptions options;
  options.validation_fraction = 1.0;
  CHECK_THROWS_WITH(bonl::select(grid, records, options),
                    Catch::Matchers::Contains("validation_fraction must be in (0, 1), got 1"));
  const Eigen::VectorXd short_y = y.head(30);
  CHECK_THROWS_WITH(bonl::select(grid, bonl::Records<double>{{u, short_y}}),
                    Catch::Matchers::Contains("records[0].u and records[0].y must have the same length"));
  CHECK_THROWS_AS(bonl::select(std::vector<bonl::ARXd>{bonl::ARXd(20, 20, 0)}, records), bonl::NumericalError);
}
