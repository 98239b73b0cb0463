// The block inverses of bonl/control/ one by one, each against the block it inverts: backlash_inverse,
// output_polynomial_inverse, input_polynomial_inverse, linear_inverse.

#include <bonl/control.hpp>

#include <cmath>

#include "test_support.hpp"

using namespace bonl_test;
using namespace bonl::control;

namespace {
/// A reference that rises, holds, falls and turns, sample by sample.
double wavy(Eigen::Index k) {
  const double t = static_cast<double>(k);
  return 0.8 * std::sin(t / 30.0) + 0.2 * std::sin(t / 7.0) + (k % 90 < 10 ? 0.0 : 0.01 * std::sin(t));
}
}  // namespace

TEST_CASE("the backlash inverse with band 0 makes the backlash follow the reference exactly") {
  const double c = 0.1;
  BacklashInverse<double> inverse(c);
  bonl::Backlash<double> play(c);
  double worst = 0.0;
  for (Eigen::Index k = 0; k < 3000; ++k) {
    const double r = k < 5 ? 0.0 : wavy(k);
    worst = std::max(worst, std::abs(play.step(inverse.step(r)) - r));
  }
  CHECK(worst <= 1e-12);
  // At rest it stays inside the gap: x = y_d.
  BacklashInverse<double> fresh(c);
  CHECK(fresh.step(0.0) == 0.0);
  CHECK(fresh.state().direction == 0);
  CHECK(fresh.step(0.01) == Approx(0.11));
  CHECK(fresh.state().direction == 1);
  CHECK(fresh.peek(0.0) == Approx(-0.1));  // a reversal: the lower edge
  CHECK(fresh.state().direction == 1);     // peek does not advance
}

TEST_CASE("the backlash inverse's band: within the band of the reference after reversals, smooth inside") {
  const double c = 0.1;
  const double band = 0.2;  // wider than the reference's largest move in one sample (0.06)
  BacklashInverse<double> inverse(c, band);
  bonl::Backlash<double> play(c);
  double worst = 0.0;
  double previous = 0.0;
  double largest_jump = 0.0;
  for (Eigen::Index k = 0; k < 3000; ++k) {
    const double r = wavy(k);
    const double x = inverse.step(r);
    worst = std::max(worst, std::abs(play.step(x) - r));
    if (k > 0) largest_jump = std::max(largest_jump, std::abs((x - r) - previous));
    previous = x - r;  // c s
  }
  CHECK(worst <= band + 1e-12);
  // x - r = c s never jumps by the 2c of the exact switch.
  CHECK(largest_jump < c);
  CHECK_THROWS_WITH(BacklashInverse<double>(-0.1), Catch::Contains("bonl: the backlash half-width c must be finite"));
  CHECK_THROWS_WITH(BacklashInverse<double>(0.1, std::nan("")), Catch::Contains("transition band must be finite"));
}

TEST_CASE("the output polynomial's inverse on its monotone branch through 0") {
  const Eigen::VectorXd q = vec({1.0, 0.2, 0.05});  // q' > 0 everywhere: the whole line
  const OutputPolynomialInverse<double> inverse(q);
  CHECK(std::isinf(inverse.upper()));
  CHECK(std::isinf(inverse.lower()));
  for (double y = -50.0; y <= 50.0; y += 0.37) {
    const auto x = inverse(y);
    CHECK(x.status == InverseStatus::Exact);
    CHECK(std::abs(bonl::OutputPolynomial<double>::evaluate(q, x.value) - y) <= 1e-12 * std::max(1.0, std::abs(y)));
  }
  // y = x - 0.5 x^2 + 0 x^3 rises to 0.5 at x = 1 (and falls for x < 0 without end).
  const OutputPolynomialInverse<double> bounded(vec({1.0, -0.5, 0.0}));
  CHECK(bounded.upper() == Approx(1.0).epsilon(1e-12));
  CHECK(std::isinf(bounded.lower()));
  CHECK(bounded(0.4).status == InverseStatus::Exact);
  CHECK(bounded(0.4).value == Approx(1.0 - std::sqrt(0.2)).epsilon(1e-12));
  CHECK(bounded(0.6).status == InverseStatus::OutOfRange);
  CHECK(bounded(0.6).value == Approx(1.0).epsilon(1e-12));
  CHECK(bounded(-4.0).value == Approx(1.0 - 3.0).epsilon(1e-12));
  CHECK_THROWS_WITH(OutputPolynomialInverse<double>(vec({0.0, 1.0})), Catch::Contains("q_1 = q'(0) is 0"));
}

TEST_CASE("the input polynomial's inverse on each side of 0, with saturation and dead band") {
  const Eigen::VectorXd f = vec({0.01, 0.8, 0.1});     // u >= 0: 0.01 .. 0.91 on [0, 1]
  const Eigen::VectorXd p = vec({-0.01, -0.2, 0.05});  // g = 0.6 u + 0.15 u^2 for u < 0: -0.45 .. 0
  const InputPolynomialInverse<double> inverse(f, p, -1.0, 1.0);
  CHECK(inverse.dead_band_lower() == 0.0);
  CHECK(inverse.dead_band_upper() == 0.01);
  for (double w = -0.45; w <= 0.91; w += 0.0031) {
    const auto u = inverse(w);
    if (w > 0.0 && w < 0.01) {
      CHECK(u.status == InverseStatus::DeadBand);
      CHECK(u.value == 0.0);
    } else {
      CHECK(u.status == InverseStatus::Exact);
      CHECK(std::abs(bonl::TwoSegmentPolynomial<double>::evaluate(f, p, u.value) - w) <= 1e-14);
    }
  }
  CHECK(inverse(1.0).status == InverseStatus::Saturated);
  CHECK(inverse(1.0).value == 1.0);
  CHECK(inverse(-0.5).status == InverseStatus::Saturated);
  CHECK(inverse(-0.5).value == -1.0);
  // A branch that turns before the range ends: f = u - u^2 is monotone on [0, 0.5] only.
  const InputPolynomialInverse<double> turning(vec({0.0, 1.0, -1.0}), vec({0.0, 0.0, 1.0}), -1.0, 1.0);
  CHECK(turning.upper() == Approx(0.5).epsilon(1e-12));
  CHECK(turning(0.3).status == InverseStatus::Saturated);
  CHECK(turning(0.3).value == Approx(0.5).epsilon(1e-12));
  // A decreasing polynomial is inverted too.
  const InputPolynomialInverse<double> falling(vec({0.0, -2.0}), vec({0.0, 0.0}), -1.0, 1.0);
  CHECK(falling(-1.0).value == Approx(0.5));
  CHECK(falling(1.0).value == Approx(-0.5));
  CHECK_THROWS_WITH(InputPolynomialInverse<double>(f, p, 0.1, 1.0), Catch::Contains("contain the operating point"));
  CHECK_THROWS_WITH(InputPolynomialInverse<double>(vec({0.0, 0.0}), vec({0.0, 0.0}), -1.0, 1.0),
                    Catch::Contains("constant over the command range"));
}

TEST_CASE("the linear block's exact inverse makes the block follow x_d nk samples later") {
  bonl::LinearBlock<double> block(3, 2, 4);
  const Eigen::VectorXd a = vec({-1.7, 1.04, -0.238});
  const Eigen::VectorXd b = vec({0.05, 0.03, 0.02});
  block.set_a(a);
  block.set_b(b);
  LinearInverse<double> inverse(a, b, 4);
  CHECK(inverse.minimum_phase());
  CHECK(inverse.window_size() == 1);
  Eigen::VectorXd x(600);
  Eigen::VectorXd window(1);
  double worst = 0.0;
  for (Eigen::Index k = 0; k < x.size(); ++k) {
    window[0] = k + 4 < 10 ? 0.0 : wavy(k + 4);  // x_d(k + nk)
    const double w = inverse.input(window);
    inverse.commit(window[0], w);
    x[k] = block.step(w);
    if (k >= 4) worst = std::max(worst, std::abs(x[k] - (k < 10 ? 0.0 : wavy(k))));
  }
  CHECK(worst <= 1e-9);
  CHECK_THROWS_WITH(LinearInverse<double>(a, vec({std::nan(""), 1.0}), 1), Catch::Contains("b has a non-finite value"));
}

TEST_CASE("ZPETC splits B into its stable and unstable zeros") {
  // B = (1 - 0.5 q^-1)(1 + 1.5 q^-1)(1 - 2 q^-1) = 1 - 1.0 q^-1 - 2.75 q^-2 + 1.5 q^-3.
  const LinearInverse<double> inverse(vec({-0.5}), vec({1.0, -1.0, -2.75, 1.5}), 2);
  CHECK_FALSE(inverse.minimum_phase());
  CHECK(inverse.preview() == 2);
  CHECK(near(inverse.stable_factor(), vec({1.0, -0.5}), 1e-12));
  CHECK(near(inverse.unstable_factor(), vec({1.0, -0.5, -3.0}), 1e-12));
}
