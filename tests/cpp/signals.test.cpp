// Excitation signals (signals.hpp).

#include "test_support.hpp"

using namespace bonl_test;

TEST_CASE("random levels are held, bounded and reproducible from the seed", "[signals]") {
  const Eigen::VectorXd u = bonl::signals::random_levels(1000, 5, 0.7, 9);
  for (Eigen::Index k = 0; k < u.size(); ++k) {
    REQUIRE(std::abs(u[k]) <= 0.7);
    if (k % 5 != 0) REQUIRE(u[k] == u[k - 1]);
  }
  CHECK(u == bonl::signals::random_levels(1000, 5, 0.7, 9));
  CHECK(u != bonl::signals::random_levels(1000, 5, 0.7, 10));
  CHECK((u.array() < 0).count() > 300);
  CHECK((u.array() > 0).count() > 300);
}

TEST_CASE("Schroeder phases and the paper's multi-sine", "[signals]") {
  const double pi = 3.14159265358979323846;
  const Eigen::VectorXd phases = bonl::signals::schroeder_phases(5);
  CHECK(phases[0] == Approx(-pi * 2.0 / 5.0));
  CHECK(phases[4] == Approx(-pi * 30.0 / 5.0));
  const Eigen::VectorXd u = bonl::signals::paper_multisine(5000, 0.01, 0.4);
  const double t = 123 * 0.01;
  double expected = 0.0;
  const double tones[] = {0.1, 0.2, 0.4, 0.5, 1.0};
  for (int i = 0; i < 5; ++i) expected += 0.4 * std::sin(2 * pi * tones[i] * t + phases[i]);
  CHECK(u[123] == Approx(expected).margin(1e-12));
  // 50 s holds whole periods of every tone: the signal has zero mean.
  CHECK(std::abs(u.mean()) < 1e-9);
}

TEST_CASE("white noise has the requested spread", "[signals]") {
  const Eigen::VectorXd e = bonl::signals::white_noise(20000, 0.3, 1);
  CHECK(standard_deviation(e) == Approx(0.3).epsilon(0.02));
  CHECK(std::abs(e.mean()) < 0.01);
}
