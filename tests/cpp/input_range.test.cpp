// The input range a model was identified on, and the flag for inputs outside it.
// Oracles: the records' own minimum and maximum; a count of samples outside by hand.

#include "test_support.hpp"

#include <bonl/io.hpp>

#include <limits>

using namespace bonl_test;

TEMPLATE_LIST_TEST_CASE("identify records the inputs' range and simulation outside it is counted", "[input_range]",
                        bonl::Models) {
  const TestType truth = known_system<TestType>("small");
  CHECK(truth.input_min() == -std::numeric_limits<double>::infinity());  // unknown: the whole line
  CHECK(truth.extrapolated_samples(Eigen::VectorXd::Constant(3, 1e300)) == 0);

  const Eigen::VectorXd u1 = bonl::signals::random_levels(800, 5, 0.8, 51);
  const Eigen::VectorXd u2 = (bonl::signals::random_levels(800, 5, 0.5, 52).array() + 0.6).matrix();
  const Eigen::VectorXd y1 = truth.simulate(u1), y2 = truth.simulate(u2);
  const TestType model = bonl::identify(truth, bonl::Records<double>{{u1, y1}, {u2, y2}});
  CHECK(model.input_min() == std::min(u1.minCoeff(), u2.minCoeff()));
  CHECK(model.input_max() == std::max(u1.maxCoeff(), u2.maxCoeff()));

  Eigen::VectorXd u = bonl::signals::random_levels(100, 5, 0.5, 53);
  CHECK(model.extrapolated_samples(u) == 0);
  u[10] = model.input_max() + 0.1;
  u[20] = model.input_min() - 1e-9;
  CHECK(model.extrapolated_samples(u) == 2);

  // Kept by the model file and by rescaled().
  const TestType loaded = bonl::io::model_from_json<TestType>(bonl::io::to_json(model));
  CHECK(loaded.input_min() == model.input_min());
  CHECK(loaded.input_max() == model.input_max());
  const TestType scaled = bonl::rescaled(model, 4.0, 0.5);
  CHECK(scaled.input_max() == 4.0 * model.input_max());
}

TEST_CASE("a bad input range is refused and leaves the model unchanged", "[input_range][bad_input]") {
  bonl::ARXd model = known_system<bonl::ARXd>("small");
  model.set_input_range(-1.0, 1.0);
  CHECK_THROWS_WITH(model.set_input_range(2.0, 1.0), Catch::Matchers::Contains("the input range must be min <= max"));
  CHECK_THROWS_WITH(model.set_input_range(std::nan(""), 1.0), Catch::Matchers::Contains("the input range"));
  CHECK(model.input_min() == -1.0);
  CHECK(model.input_max() == 1.0);
  CHECK_THROWS_WITH(bonl::io::model_from_json<bonl::ARXd>(
                        std::string(bonl::io::to_json(model)).replace(bonl::io::to_json(model).find("[-1.0,1.0]"), 10, "[1.0,-1.0]")),
                    Catch::Matchers::Contains("input_range must have min <= max"));
}
