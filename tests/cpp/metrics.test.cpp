// Metrics (metrics.hpp) on hand-computed numbers.

#include "test_support.hpp"

using namespace bonl_test;

TEST_CASE("mse, rmse, nrmse and fit on a hand-computed example", "[metrics]") {
  const Eigen::VectorXd y = vec({1.0, 2.0, 3.0, 4.0});     // mean 2.5, ||y - mean|| = sqrt(5)
  const Eigen::VectorXd yhat = vec({1.0, 2.5, 2.0, 4.0});  // errors 0, -0.5, 1, 0: sum sq 1.25
  CHECK(bonl::metrics::mse(y, yhat) == Approx(1.25 / 4.0));
  CHECK(bonl::metrics::rmse(y, yhat) == Approx(std::sqrt(1.25 / 4.0)));
  CHECK(bonl::metrics::nrmse(y, yhat) == Approx(std::sqrt(1.25) / std::sqrt(5.0)));
  CHECK(bonl::metrics::fit_percent(y, yhat) == Approx(100.0 * (1.0 - std::sqrt(0.25))));
  CHECK(bonl::metrics::fit_percent(y, y) == 100.0);
  const bonl::metrics::Scores s = bonl::metrics::scores(y, yhat);
  CHECK(s.mse == bonl::metrics::mse(y, yhat));
  CHECK(s.fit_percent == Approx(50.0));
}

TEST_CASE("simulation and prediction scores run the model", "[metrics]") {
  const bonl::PaperHammerstein m = known_hammerstein();
  const Eigen::VectorXd u = bonl::signals::random_levels(500, 5, 1.0, 3);
  const Eigen::VectorXd y = m.simulate(u) + bonl::signals::white_noise(500, 0.01, 4);
  CHECK(bonl::metrics::simulation_scores(m, u, y).mse == Approx(bonl::metrics::mse(y, m.simulate(u))));
  CHECK(bonl::metrics::prediction_scores(m, u, y).mse == Approx(bonl::metrics::mse(y, m.predict(u, y))));
}
