// The input blocks continue linearly beyond the input range a model was identified on
// (blocks/linear_continuation.hpp): the Hammerstein front's two-segment polynomial (Hammerstein,
// H-W, P-H-W) and the Prandtl-Ishlinskii model's polynomial.
// Oracles: N(e) + N'(e) (u - e) with N' differentiated by hand; the model's free run against its
// blocks composed by hand with that w; the simulation after a measured past and the free run agreeing
// on the model's own output; identify() unaffected by a structure's earlier range.

#include "test_support.hpp"

#include <limits>

using namespace bonl_test;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// N(e) + N'(e) (u - e) for the segment of N at e, f and p as the two-segment polynomial takes them,
/// differentiated term by term.
double continued_by_hand(const Eigen::VectorXd& f, const Eigen::VectorXd& p, double edge, double u) {
  const Eigen::VectorXd c = edge < 0 ? Eigen::VectorXd(f + p) : f;
  double value = 0.0, slope = 0.0;
  for (Eigen::Index l = 0; l < c.size(); ++l) {
    value += c[l] * std::pow(edge, static_cast<double>(l));
    if (l > 0) slope += static_cast<double>(l) * c[l] * std::pow(edge, static_cast<double>(l - 1));
  }
  return value + slope * (u - edge);
}

}  // namespace

TEST_CASE("the two-segment polynomial continues linearly beyond its range and is itself inside", "[blocks][input]") {
  const Eigen::Vector4d f(0.1, 1.0, 2.0, 3.0), p(-0.2, 0.5, -1.0, 0.25);
  using Block = bonl::TwoSegmentPolynomial<double>;
  // f at 1: 6.1, slope 1 + 4 + 9 = 14: at 2, 20.1.
  CHECK(Block::evaluate(f, p, 2.0, -0.5, 1.0) == Approx(20.1).epsilon(1e-14));
  for (const double u : {-3.0, -0.7, -0.5, -0.2, 0.0, 0.4, 1.0, 1.3, 5.0}) {
    const double low = -0.5, high = 1.0;
    const double expected = u > high  ? continued_by_hand(f, p, high, u)
                            : u < low ? continued_by_hand(f, p, low, u)
                                      : Block::evaluate(f, p, u);
    CHECK(Block::evaluate(f, p, u, low, high) == Approx(expected).epsilon(1e-13));
    // The regressor stays linear in [f; p]: basis . [f; p] is the value, and returned.
    Eigen::Matrix<double, 8, 1> phi;
    const double w = Block::basis(u, f, p, phi, low, high);
    Eigen::Matrix<double, 8, 1> coefficients;
    coefficients << f, p;
    CHECK(phi.dot(coefficients) == Approx(expected).epsilon(1e-13));
    CHECK(w == Approx(expected).epsilon(1e-13));
    // The infinite range is the polynomial.
    CHECK(Block::evaluate(f, p, u, -kInf, kInf) == Block::evaluate(f, p, u));
  }
  // An edge at 0 (a range that ends there) has the slope f_1.
  CHECK(Block::evaluate(f, p, 0.5, -1.0, 0.0) == Approx(0.1 + 0.5).epsilon(1e-14));
}

TEST_CASE("a Hammerstein model continues its input block linearly beyond its input range", "[models]") {
  bonl::Hammersteind model = known_system<bonl::Hammersteind>("small");  // r = 2, nk = 2
  model.set_operating_point(0.3, -0.1);
  const Eigen::VectorXd u = bonl::signals::random_levels(400, 4, 2.0, 31).array() + 0.3;  // inputs in 0.3 +- 2
  const Eigen::VectorXd inside = model.simulate(u);
  model.set_input_range(-0.7, 1.1);  // deviations -1 .. 0.8
  const Eigen::VectorXd y = model.simulate(u);
  // The oracle: w continued by hand, through the linear block.
  auto linear = model.linear_block();
  const Eigen::VectorXd f = model.f(), p = model.p();
  bool some_beyond = false;
  for (Eigen::Index k = 0; k < u.size(); ++k) {
    const double v = u[k] - 0.3;
    const double w = v > 0.8    ? continued_by_hand(f, p, 0.8, v)
                     : v < -1.0 ? continued_by_hand(f, p, -1.0, v)
                                : model.input_block()(v);
    some_beyond = some_beyond || v > 0.8 || v < -1.0;
    REQUIRE(y[k] == Approx(linear.step(w) - 0.1).margin(1e-12));
  }
  REQUIRE(some_beyond);
  CHECK((y - inside).cwiseAbs().maxCoeff() > 1e-3);  // the continuation changed something
  // After a measured past (its own output), the simulation continues the free run exactly, and the
  // one-step prediction of its own output is that output.
  const Eigen::Index past = 50;
  const Eigen::VectorXd after = model.simulate(u.tail(u.size() - past), u.head(past), y.head(past));
  CHECK(near(after, Eigen::VectorXd(y.tail(u.size() - past)), 1e-10));
  CHECK(near(model.predict(u, y), y, 1e-10));
}

TEST_CASE("H-W, P-H-W and Prandtl-Ishlinskii models continue linearly too, and the same after a past", "[models]") {
  const Eigen::VectorXd u = bonl::signals::random_levels(400, 4, 2.0, 33);
  const auto check = [&](auto model) {
    const Eigen::VectorXd inside = model.simulate(u);
    model.set_input_range(-0.9, 0.9);
    const Eigen::VectorXd y = model.simulate(u);
    CHECK((y - inside).cwiseAbs().maxCoeff() > 1e-3);
    // Inside the range the two agree until the first input beyond it reaches the output.
    Eigen::Index first = 0;
    while (std::abs(u[first]) <= 0.9) ++first;
    CHECK(near(Eigen::VectorXd(y.head(first)), Eigen::VectorXd(inside.head(first)), 1e-14));
    const Eigen::VectorXd after = model.simulate(u.tail(350), u.head(50), y.head(50));
    CHECK(near(after, Eigen::VectorXd(y.tail(350)), 1e-9));
  };
  check(known_system<bonl::HammersteinWienerd>("small"));
  check(known_system<bonl::PrandtlIshlinskiiHammersteind>("small"));
  // P-H-W: a past that ends outside the backlash's gap sets its state (the free run's own output).
  check(known_system<bonl::PseudoHammersteinWienerd>("small"));
}

TEST_CASE("identify fits the input block itself, whatever input range the structure had", "[identify]") {
  const bonl::Hammersteind truth = known_system<bonl::Hammersteind>("small");
  const Eigen::VectorXd u = bonl::signals::random_levels(1500, 5, 1.0, 35);
  const Eigen::VectorXd y = truth.simulate(u) + bonl::signals::white_noise(u.size(), 0.01, 36);
  bonl::Hammersteind narrow(2, 1, 2, 2);
  narrow.set_input_range(-0.2, 0.2);
  const bonl::Hammersteind a = bonl::identify(narrow, u, y);
  const bonl::Hammersteind b = bonl::identify(bonl::Hammersteind(2, 1, 2, 2), u, y);
  CHECK(a.theta() == b.theta());
  CHECK(a.input_min() == u.minCoeff());
  CHECK(a.input_max() == u.maxCoeff());
}
