// Where a model sits: its operating point (u0, y0), the initial state from a measured past, and the
// input range it was identified on (models/detail/model_runs.hpp).
// Oracles:
// - a model with an operating point is the same model on the deviations: simulate(u) = y0 + the
//   zero-point model's simulate(u - u0), bit for bit; so for predict, the estimator and identify;
// - with a measured past at least as long as the model's memory, the simulation after it continues
//   the noise-free record the model itself produced: equal to its free run from rest over the whole
//   record (to round-off); an empty past is rest;
// - the input range: the records' own minimum and maximum; a count of samples outside by hand.

#include "test_support.hpp"

#include <bonl/io.hpp>

#include <limits>

using namespace bonl_test;

TEMPLATE_LIST_TEST_CASE("a model with an operating point is the same model on the deviations", "[operating_point]",
                        bonl::Models) {
  const TestType at_zero = known_system<TestType>("small");
  TestType model = at_zero;
  model.set_operating_point(2.5, -1.25);
  const Eigen::VectorXd u = (bonl::signals::random_levels(400, 5, 1.0, 31).array() + 2.5).matrix();
  const Eigen::VectorXd deviations = (u.array() - 2.5).matrix();
  CHECK(model.simulate(u) == (at_zero.simulate(deviations).array() - 1.25).matrix());
  const Eigen::VectorXd y = model.simulate(u) + bonl::signals::white_noise(u.size(), 0.01, 32);
  const Eigen::VectorXd y_deviations = (y.array() + 1.25).matrix();
  CHECK(model.predict(u, y) == (at_zero.predict(deviations, y_deviations).array() - 1.25).matrix());

  // The estimator sees the deviations; its model keeps the operating point.
  bonl::Estimator<TestType> with_point(model), without(at_zero);
  for (Eigen::Index k = 0; k < u.size(); ++k) {
    with_point.update(u[k], y[k]);
    without.update(deviations[k], y_deviations[k]);
  }
  CHECK(with_point.theta() == without.theta());
  CHECK(with_point.last_prediction() == without.last_prediction() - 1.25);
  CHECK(with_point.model().u0() == 2.5);
  CHECK(with_point.model().y0() == -1.25);

  // identify: the same as identifying the deviations, with the structure's operating point.
  const TestType identified = bonl::identify(model, u, y);
  const TestType identified_at_zero = bonl::identify(at_zero, deviations, y_deviations);
  CHECK(identified.theta() == identified_at_zero.theta());
  CHECK(identified.u0() == 2.5);
  CHECK(identified.y0() == -1.25);

  CHECK_THROWS_WITH(model.set_operating_point(std::nan(""), 0.0), Catch::Matchers::Contains("u0"));
  CHECK(model.u0() == 2.5);  // unchanged
}

TEMPLATE_LIST_TEST_CASE("identify takes the operating point from the records when asked", "[operating_point]",
                        bonl::Models) {
  const TestType truth = known_system<TestType>("small");
  const Eigen::VectorXd u1 = (bonl::signals::random_levels(300, 5, 1.0, 34).array() + 1.5).matrix();
  const Eigen::VectorXd u2 = (bonl::signals::random_levels(200, 5, 1.0, 35).array() - 0.5).matrix();
  const Eigen::VectorXd y1 = truth.simulate(u1), y2 = truth.simulate(u2);
  const bonl::Records<double> records{{u1, y1}, {u2, y2}};
  const double u_mean = (u1.sum() + u2.sum()) / 500.0, y_mean = (y1.sum() + y2.sum()) / 500.0;

  // Each source is the same as setting that point on the structure by hand.
  const std::pair<bonl::OperatingPointSource, std::pair<double, double>> cases[] = {
      {bonl::OperatingPointSource::Mean, {u_mean, y_mean}},
      {bonl::OperatingPointSource::Initial, {u1[0], y1[0]}},
      {bonl::OperatingPointSource::Structure, {0.0, 0.0}}};
  for (const auto& [source, point] : cases) {
    CAPTURE(bonl::to_string(source));
    bonl::IdentifyOptions options;
    options.operating_point = source;
    options.refine_iterations = 5;
    TestType by_hand = truth;
    by_hand.set_operating_point(point.first, point.second);
    const TestType identified = bonl::identify(truth, records, options);
    options.operating_point = bonl::OperatingPointSource::Structure;
    const TestType expected = bonl::identify(by_hand, records, options);
    CHECK(identified.u0() == point.first);
    CHECK(identified.y0() == point.second);
    CHECK(identified.theta() == expected.theta());
  }
}

TEMPLATE_LIST_TEST_CASE("after a measured past the simulation continues the record", "[operating_point]",
                        bonl::Models) {
  TestType model = known_system<TestType>("small");
  model.set_operating_point(0.5, 3.0);
  const Eigen::VectorXd u = (bonl::signals::random_levels(600, 5, 1.0, 33).array() + 0.5).matrix();
  const Eigen::VectorXd y = model.simulate(u);
  const Eigen::Index window = 20;  // longer than the model's memory (na = 2, nb + nk = 3)
  const Eigen::VectorXd continued = model.simulate(u.tail(u.size() - window), u.head(window), y.head(window));
  const Eigen::VectorXd expected = y.tail(u.size() - window);
  if constexpr (has_backlash<TestType>()) {
    // Inside the backlash's gap the measured output does not say where x is: the past sets the
    // output's memory exactly and x to within the gap, so the continuation stays within c of the record.
    CHECK((continued - expected).cwiseAbs().maxCoeff() <= model.c() + 1e-12);
  } else {
    CHECK((continued - expected).cwiseAbs().maxCoeff() <= 1e-10 * expected.cwiseAbs().maxCoeff());
  }
  // An empty past is rest.
  const Eigen::VectorXd none(0);
  CHECK((model.simulate(u, none, none) - y).cwiseAbs().maxCoeff() <= 1e-10 * y.cwiseAbs().maxCoeff());
  // predict after a past is predict over the whole record, from the window on.
  const Eigen::VectorXd predicted = model.predict(u, y);
  const Eigen::VectorXd predicted_after =
      model.predict(u.tail(u.size() - window), y.tail(u.size() - window), u.head(window), y.head(window));
  CHECK((predicted_after - predicted.tail(u.size() - window)).cwiseAbs().maxCoeff() <= 1e-12);
}

TEST_CASE("a record that does not start at rest simulates far better after its first samples", "[operating_point]") {
  const bonl::Hammersteind model = known_system<bonl::Hammersteind>("small");
  const Eigen::VectorXd u = bonl::signals::random_levels(1500, 5, 1.0, 34);
  const Eigen::VectorXd y = model.simulate(u);
  // The record starts at sample 1000, mid-way: the system is not at rest there.
  const Eigen::VectorXd u_record = u.tail(500), y_record = y.tail(500);
  const Eigen::Index window = 10;
  const Eigen::VectorXd from_rest = model.simulate(u_record);
  const Eigen::VectorXd initialised = model.simulate(u_record.tail(490), u_record.head(window), y_record.head(window));
  const double rest_error = (from_rest.tail(490) - y_record.tail(490)).norm();
  const double initialised_error = (initialised - y_record.tail(490)).norm();
  CHECK(rest_error > 1e-3);
  CHECK(initialised_error <= 1e-10 * rest_error);
}

TEST_CASE("a bad past is refused with a message naming it", "[operating_point][bad_input]") {
  const bonl::ARXd model = known_system<bonl::ARXd>("small");
  const Eigen::VectorXd u = bonl::signals::random_levels(50, 5, 1.0, 35);
  Eigen::VectorXd y_past = Eigen::VectorXd::Zero(4);
  CHECK_THROWS_WITH(model.simulate(u, Eigen::VectorXd(Eigen::VectorXd::Zero(5)), y_past),
                    Catch::Matchers::Contains("u_past and y_past must have the same length, got 5 and 4"));
  y_past[2] = std::nan("");
  CHECK_THROWS_WITH(model.simulate(u, Eigen::VectorXd(Eigen::VectorXd::Zero(4)), y_past),
                    Catch::Matchers::Contains("y_past has a non-finite value at index 2"));
  CHECK_THROWS_WITH(model.predict(u, Eigen::VectorXd(u.head(10)), Eigen::VectorXd(Eigen::VectorXd::Zero(4)),
                                  Eigen::VectorXd(Eigen::VectorXd::Zero(4))),
                    Catch::Matchers::Contains("u and y must have the same length"));
}

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
  std::string reversed = bonl::io::to_json(model);
  reversed.replace(reversed.find("[-1.0,1.0]"), 10, "[1.0,-1.0]");
  CHECK_THROWS_WITH(bonl::io::model_from_json<bonl::ARXd>(reversed),
                    Catch::Matchers::Contains("input_range must have min <= max"));
}
