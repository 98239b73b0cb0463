// The four models (models/*.hpp): parameters in eq. (19) order and by name, free-run simulation
// against the blocks composed by hand, one-step prediction, run-time sizes and float.

#include "test_support.hpp"

using namespace bonl_test;

TEST_CASE("theta follows eq. (19): f, p, b_1..b_nb, a, then q_2.. or c", "[models]") {
  const bonl::PaperPseudoHammersteinWiener phw = known_phw();
  const Eigen::VectorXd expected =
      vec({0.002, 0.06, 0.02, -0.01, -0.003, -0.02, -0.03, 0.015, 0.5, 0.2, -1.7, 1.04, -0.238, 0.1});
  CHECK(phw.theta() == expected);
  CHECK(phw.f() == expected.head(4));
  CHECK(phw.p() == expected.segment(4, 4));
  CHECK(phw.b() == vec({1.0, 0.5, 0.2}));
  CHECK(phw.a() == expected.segment(10, 3));
  CHECK(phw.c() == 0.1);

  const bonl::PaperHammersteinWiener hw = known_hammerstein_wiener();
  CHECK(hw.num_params() == 15);
  CHECK(hw.theta().tail(2) == vec({0.2, 0.05}));
  CHECK(hw.q() == vec({1.0, 0.2, 0.05}));

  const bonl::PaperARX arx = known_arx();
  CHECK(arx.theta() == vec({0.05, 0.03, 0.02, -1.7, 1.04, -0.238}));
  CHECK(known_hammerstein().num_params() == 13);
}

TEST_CASE("simulation equals the blocks composed by hand", "[models]") {
  const Eigen::VectorXd u = bonl::signals::random_levels(600, 4, 1.2, 17);
  const bonl::PaperPseudoHammersteinWiener phw = known_phw();
  const bonl::PaperHammersteinWiener hw = known_hammerstein_wiener();
  auto input = phw.input_block();
  auto linear = phw.linear_block();
  auto linear_hw = hw.linear_block();
  auto output = hw.output_block();
  bonl::Backlash<double> play(0.1);
  bonl::LinearBlock<double> arx_block(3, 2, kNk);
  arx_block.set_a(known_arx().a());
  arx_block.set_b(known_arx().b());

  const Eigen::VectorXd y_h = known_hammerstein().simulate(u);
  const Eigen::VectorXd y_hw = hw.simulate(u);
  const Eigen::VectorXd y_phw = phw.simulate(u);
  const Eigen::VectorXd y_arx = known_arx().simulate(u);
  for (Eigen::Index k = 0; k < u.size(); ++k) {
    const double w = input(u[k]);
    const double x = linear.step(w);
    REQUIRE(y_h[k] == Approx(x).margin(1e-14));
    REQUIRE(y_phw[k] == Approx(play.step(x)).margin(1e-14));
    REQUIRE(y_hw[k] == Approx(output(linear_hw.step(w))).margin(1e-14));
    REQUIRE(y_arx[k] == Approx(arx_block.step(u[k])).margin(1e-14));
  }
}

TEST_CASE("the delay nk holds the response back by nk samples", "[models]") {
  bonl::Hammersteind h(1, 0, 5, 1);
  h.set_f(vec({0.0, 1.0}));
  h.set_a(vec({-0.5}));
  Eigen::VectorXd u = Eigen::VectorXd::Zero(10);
  u[0] = 1.0;
  const Eigen::VectorXd y = h.simulate(u);
  CHECK(y.head(5).isZero());
  CHECK(y[5] == 1.0);
  CHECK(y[6] == 0.5);
}

TEST_CASE("one-step prediction of the true model reproduces noise-free data", "[models]") {
  const Eigen::VectorXd u = bonl::signals::random_levels(800, 5, 1.0, 4);
  SECTION("ARX") {
    const auto m = known_arx();
    CHECK(near(m.predict(u, m.simulate(u)), m.simulate(u), 1e-12));
  }
  SECTION("Hammerstein") {
    const auto m = known_hammerstein();
    CHECK(near(m.predict(u, m.simulate(u)), m.simulate(u), 1e-12));
  }
  SECTION("Hammerstein-Wiener") {
    const auto m = known_hammerstein_wiener();
    CHECK(near(m.predict(u, m.simulate(u)), m.simulate(u), 1e-12));
  }
  SECTION("P-H-W") {
    const auto m = known_phw();
    CHECK(near(m.predict(u, m.simulate(u)), m.simulate(u), 1e-12));
  }
}

TEST_CASE("one-step prediction uses the measured past", "[models]") {
  // ARX by hand: y_hat(k) = -sum a_j y(k-j) + sum b_i u(k-nk-i) with the measured y.
  const bonl::PaperARX m = known_arx();
  const Eigen::VectorXd u = bonl::signals::random_levels(300, 2, 1.0, 8);
  const Eigen::VectorXd y = m.simulate(u) + bonl::signals::white_noise(u.size(), 0.05, 9);
  const Eigen::VectorXd prediction = m.predict(u, y);
  for (Eigen::Index k = 0; k < u.size(); ++k) {
    double expected = 0.0;
    for (Eigen::Index i = 0; i <= 2; ++i) expected += k - kNk - i >= 0 ? m.b()[i] * u[k - kNk - i] : 0.0;
    for (Eigen::Index j = 1; j <= 3; ++j) expected -= k - j >= 0 ? m.a()[j - 1] * y[k - j] : 0.0;
    REQUIRE(prediction[k] == Approx(expected).margin(1e-12));
  }
  // P-H-W: the backlash's memory is the measured previous output, so wherever the prediction
  // stays inside the gap it repeats the measured y(k-1) exactly; random levels put it there often.
  const bonl::PaperPseudoHammersteinWiener phw = known_phw();
  const Eigen::VectorXd y_phw = phw.simulate(u) + bonl::signals::white_noise(u.size(), 0.01, 10);
  const Eigen::VectorXd p_phw = phw.predict(u, y_phw);
  Eigen::Index repeats = 0;
  for (Eigen::Index k = 1; k < u.size(); ++k) repeats += p_phw[k] == y_phw[k - 1] ? 1 : 0;
  CHECK(repeats > 30);
  CHECK(repeats < u.size() - 30);
}

TEST_CASE("run-time and compile-time orders simulate identically, and float works", "[models]") {
  const Eigen::VectorXd u = bonl::signals::random_levels(500, 3, 1.0, 12);
  const bonl::PaperHammersteinWiener fixed = known_hammerstein_wiener();
  bonl::HammersteinWienerd dynamic(3, 2, kNk, 3, 3);
  dynamic.set_theta(fixed.theta());
  CHECK(dynamic.simulate(u) == fixed.simulate(u));

  bonl::PseudoHammersteinWiener<float, 3, 2, 3> single(3, 2, kNk, 3);
  single.set_theta(known_phw().theta().cast<float>());
  const Eigen::VectorXf y_float = single.simulate(u.cast<float>());
  CHECK(near(y_float.cast<double>(), known_phw().simulate(u), 1e-4));
}

TEST_CASE("an unstable model's simulation is reported, not returned", "[models]") {
  bonl::Hammersteind h(1, 0, 0, 1);
  h.set_f(vec({0.0, 1.0}));
  h.set_a(vec({-1.5}));  // pole at 1.5
  const Eigen::VectorXd u = Eigen::VectorXd::Ones(5000);
  CHECK_THROWS_AS(h.simulate(u), bonl::NumericalError);
  Eigen::VectorXd y;
  CHECK_FALSE(h.try_simulate(u, y));
}
