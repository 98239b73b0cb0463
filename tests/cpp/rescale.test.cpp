// A model in other units (models/rescale.hpp) and identify()'s own units (IdentifyOptions::normalise).
// Oracles:
// - rescaled(model, su, sy) simulates sy * model(u / su), for every model, from its description alone;
// - identify() on data multiplied by powers of two gives exactly (bit for bit) the rescaled model
//   identified on the original data: both are identified in the same internal units (c0, a width in
//   the output's units, scaled with the output);
// - data in awkward units (input ~200, output ~1e-3, as the Bouc-Wen benchmark's newtons and
//   metres) identify with the default settings, to the same relative accuracy as unit-sized data.

#include "test_support.hpp"

using namespace bonl_test;

TEMPLATE_LIST_TEST_CASE("a rescaled model simulates the scaled model", "[rescale]", bonl::Models) {
  const TestType model = known_system<TestType>("small");
  const Eigen::VectorXd u = bonl::signals::random_levels(500, 5, 1.0, 9);
  const double su = 200.0, sy = 1e-3;
  const TestType scaled = bonl::rescaled(model, su, sy);
  const Eigen::VectorXd expected = sy * model.simulate(u);
  const Eigen::VectorXd actual = scaled.simulate(su * u);
  CHECK((actual - expected).norm() <= 1e-12 * expected.norm());
  // And back.
  const TestType back = bonl::rescaled(scaled, 1.0 / su, 1.0 / sy);
  CHECK((back.theta() - model.theta()).norm() <= 1e-12 * model.theta().norm());

  CHECK_THROWS_WITH(bonl::rescaled(model, 0.0, 1.0), Catch::Matchers::Contains("input_scale must be finite and > 0"));
  CHECK_THROWS_WITH(bonl::rescaled(model, 1.0, -1.0), Catch::Matchers::Contains("output_scale must be finite and > 0"));
}

TEMPLATE_LIST_TEST_CASE("identify is exact under data scaled by powers of two", "[rescale][identify]", bonl::Models) {
  const TestType truth = known_system<TestType>("small");
  const Eigen::VectorXd u = bonl::signals::random_levels(1500, 5, 1.0, 10);
  const Eigen::VectorXd y = truth.simulate(u) + bonl::signals::white_noise(u.size(), 0.01, 11);
  const double su = 256.0, sy = 1.0 / 1024.0;
  const TestType original = bonl::identify(truth, u, y);
  // The model's own settings in the data's units (P-H-W: c0, the initial backlash width, is in the output's).
  const auto settings = bonl::ModelSettings<TestType>{}.rescaled(su, sy);
  // The structure in the data's units: its knots (hinges) are in the output's units too.
  const TestType scaled = bonl::identify(bonl::rescaled(truth, su, sy), Eigen::VectorXd(su * u),
                                         Eigen::VectorXd(sy * y), bonl::IdentifyOptions{}, settings);
  const TestType expected = bonl::rescaled(original, su, sy);
  CHECK(scaled.theta() == expected.theta());
}

TEMPLATE_LIST_TEST_CASE("data in awkward units identify with the default settings", "[rescale][identify]",
                        bonl::Models) {
  const TestType truth = known_system<TestType>("small");
  const Eigen::VectorXd u = bonl::signals::random_levels(3000, 5, 1.0, 12);
  const Eigen::VectorXd y = truth.simulate(u) + bonl::signals::white_noise(u.size(), 0.005, 13);
  const Eigen::VectorXd u_val = bonl::signals::random_levels(2000, 5, 1.0, 14);
  const double su = 200.0, sy = 1e-3;  // not powers of two
  const TestType plain = bonl::identify(truth, u, y);
  const TestType awkward =  // the structure (its knots) in the data's units
      bonl::identify(bonl::rescaled(truth, su, sy), Eigen::VectorXd(su * u), Eigen::VectorXd(sy * y));
  const Eigen::VectorXd reference = truth.simulate(u_val);
  const double plain_error = bonl::metrics::nrmse(reference, plain.simulate(u_val));
  const double awkward_error = bonl::metrics::nrmse(reference, Eigen::VectorXd(awkward.simulate(su * u_val) / sy));
  CHECK(awkward_error <= 0.02);
  CHECK(awkward_error <= 2.0 * plain_error + 1e-6);
}
