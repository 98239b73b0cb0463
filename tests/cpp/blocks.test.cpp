// Tests of the building blocks in include/bonl/blocks: the backlash (paper eqs. 10-12) and its
// switching functions (eqs. 30-31), the general backlash of Fig. 9, the two-segment input
// polynomial (eqs. 3-5), the output polynomial (eq. 9), the linear block (eqs. 6-8) and the play
// operators of a Prandtl-Ishlinskii operator.
// Every expected value is computed here, by hand or from the defining formula.

#include "test_support.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace {

using bonl_test::near;
using bonl_test::vec;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

double sgn(double v) { return v > 0.0 ? 1.0 : (v < 0.0 ? -1.0 : 0.0); }

/// One sample of the triangle wave used to drive the backlash: x = i / 20 on a grid of 0.05, so
/// that the rising and falling branches visit exactly the same input values.
struct Sample {
  double x;
  double y;
};

/// Drives a backlash of half-width c with x: 0 -> 1 (rising), 1 -> -1 (falling), -1 -> 1 (rising).
/// Returns the three branches separately.
struct TriangleRun {
  std::vector<Sample> first_rise, fall, second_rise;
};
TriangleRun drive_triangle(double c) {
  bonl::Backlash<double> play(c);
  TriangleRun run;
  for (int i = 0; i <= 20; ++i) {
    const double x = i / 20.0;
    run.first_rise.push_back({x, play.step(x)});
  }
  for (int i = 19; i >= -20; --i) {
    const double x = i / 20.0;
    run.fall.push_back({x, play.step(x)});
  }
  for (int i = -19; i <= 20; ++i) {
    const double x = i / 20.0;
    run.second_rise.push_back({x, play.step(x)});
  }
  return run;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Backlash
// ---------------------------------------------------------------------------------------------

// The hysteresis loop of the play operator (eq. 10 with the symmetric, unit-slope form): after a
// reversal the output is held until the input has crossed the whole gap (2c), then it follows the
// input shifted by c (x - c rising, x + c falling). Checked sample by sample on a triangle wave.
TEST_CASE("Backlash: triangle wave traces the hysteresis loop", "[blocks][backlash]") {
  const double c = 0.2;
  const TriangleRun run = drive_triangle(c);

  // Starting engaged at y = 0 with x = 0, the first rise only has to cross c (half the gap).
  for (const Sample& s : run.first_rise) {
    INFO("first rise, x = " << s.x);
    if (s.x <= c) {
      REQUIRE(s.y == 0.0);
    } else {
      REQUIRE(near(s.y, s.x - c, 1e-12));
    }
  }
  const double top = run.first_rise.back().y;  // reached at x = 1
  REQUIRE(near(top, 1.0 - c, 1e-12));

  // Falling from the reversal at x = 1: held at 1 - c while x has moved less than 2c, then x + c.
  int held = 0;
  for (const Sample& s : run.fall) {
    INFO("fall, x = " << s.x);
    const double moved = 1.0 - s.x;
    if (moved < 2.0 * c - 1e-9) {
      REQUIRE(s.y == top);
      ++held;
    } else if (moved > 2.0 * c + 1e-9) {
      REQUIRE(near(s.y, s.x + c, 1e-12));
    } else {
      REQUIRE(near(s.y, top, 1e-12));  // exactly at the edge both branches meet
    }
  }
  REQUIRE(held == 7);                       // x = 0.95 .. 0.65: 2c / 0.05 - 1 samples strictly inside the gap
  const double bottom = run.fall.back().y;  // reached at x = -1
  REQUIRE(near(bottom, -1.0 + c, 1e-12));

  // Rising again from the reversal at x = -1: held at -1 + c for 2c, then x - c.
  held = 0;
  for (const Sample& s : run.second_rise) {
    INFO("second rise, x = " << s.x);
    const double moved = s.x - (-1.0);
    if (moved < 2.0 * c - 1e-9) {
      REQUIRE(s.y == bottom);
      ++held;
    } else if (moved > 2.0 * c + 1e-9) {
      REQUIRE(near(s.y, s.x - c, 1e-12));
    } else {
      REQUIRE(near(s.y, bottom, 1e-12));
    }
  }
  REQUIRE(held == 7);
}

// The backlash has memory: away from the turning points, the same input gives x + c on the falling
// branch and x - c on the rising branch, i.e. the two branches are 2c apart.
TEST_CASE("Backlash: same input, different output on the two branches", "[blocks][backlash]") {
  const double c = 0.2;
  const TriangleRun run = drive_triangle(c);
  int compared = 0;
  for (const Sample& down : run.fall) {
    if (std::abs(down.x) > 1.0 - 2.0 * c - 1e-9) continue;  // near the turning points: held part
    for (const Sample& up : run.second_rise) {
      if (up.x != down.x) continue;
      INFO("x = " << down.x);
      REQUIRE(near(down.y - up.y, 2.0 * c, 1e-12));
      ++compared;
    }
  }
  REQUIRE(compared == 23);  // x = -0.55 .. 0.55 on the 0.05 grid
  // And one value spelled out: x = 0.5 gives 0.7 falling, 0.3 rising.
  for (const Sample& s : run.fall)
    if (s.x == 0.5) REQUIRE(near(s.y, 0.7, 1e-12));
  for (const Sample& s : run.second_rise)
    if (s.x == 0.5) REQUIRE(near(s.y, 0.3, 1e-12));
}

// A reversal that does not cross the gap (smaller than 2c) does not move the output at all, and
// the output only resumes when the input exceeds the point where it last engaged.
TEST_CASE("Backlash: a reversal smaller than 2c leaves the output unchanged", "[blocks][backlash]") {
  const double c = 0.2;
  bonl::Backlash<double> play(c);
  for (int i = 0; i <= 10; ++i) play.step(i / 20.0);  // up to x = 0.5
  const double engaged = play.output();
  REQUIRE(near(engaged, 0.5 - c, 1e-12));
  for (int i = 9; i >= 3; --i) {  // down to x = 0.15: a reversal of 0.35 < 2c = 0.4
    REQUIRE(play.step(i / 20.0) == engaged);
  }
  for (int i = 4; i <= 9; ++i) {  // back up to x = 0.45: still inside the gap
    REQUIRE(play.step(i / 20.0) == engaged);
  }
  REQUIRE(near(play.step(0.6), 0.6 - c, 1e-12));  // beyond: follows x - c again
}

// map() is the stateless form of step(): the same recursion y(k) = map(x(k), y(k-1), c).
TEST_CASE("Backlash: map agrees with step", "[blocks][backlash]") {
  const double c = 0.15;
  bonl::Backlash<double> play(c, 0.05);
  double y_prev = 0.05;
  for (int k = 0; k < 200; ++k) {
    const double x = std::sin(0.13 * k) + 0.3 * std::sin(0.71 * k);
    const double expected = bonl::Backlash<double>::map(x, y_prev, c);
    REQUIRE(play.step(x) == expected);
    REQUIRE(play.output() == expected);
    y_prev = expected;
  }
  // reset() restores the chosen starting output.
  play.reset(-0.25);
  REQUIRE(play.output() == -0.25);
  REQUIRE(play.step(-0.3) == bonl::Backlash<double>::map(-0.3, -0.25, c));
}

// With c = 0 there is no gap: the backlash is the identity.
TEST_CASE("Backlash: c = 0 is the identity", "[blocks][backlash]") {
  bonl::Backlash<double> play(0.0);
  for (int k = 0; k < 100; ++k) {
    const double x = std::sin(0.37 * k) * (1.0 + 0.01 * k);
    REQUIRE(play.step(x) == x);
  }
}

// The half-width must be a finite, non-negative number; bad values are refused and the old value
// kept.
TEST_CASE("Backlash: invalid half-width throws", "[blocks][backlash]") {
  bonl::Backlash<double> play(0.1);
  REQUIRE_THROWS_AS(play.set_c(-0.01), std::invalid_argument);
  REQUIRE_THROWS_AS(play.set_c(kNaN), std::invalid_argument);
  REQUIRE_THROWS_AS(play.set_c(kInf), std::invalid_argument);
  REQUIRE(play.c() == 0.1);
  REQUIRE_THROWS_AS(bonl::Backlash<double>(-1.0), std::invalid_argument);
  REQUIRE_NOTHROW(play.set_c(0.0));
  REQUIRE(play.c() == 0.0);
}

// ---------------------------------------------------------------------------------------------
// Switching functions g3, g4 (eqs. 30-31) and the switched form of the backlash (eqs. 11-12)
// ---------------------------------------------------------------------------------------------

// g3 is 1 only strictly above the upper edge y_prev + c, g4 only strictly below the lower edge
// y_prev - c; exactly at an edge both are 0 (the paper's ">=" / "<=" cases).
TEST_CASE("backlash_g3 / backlash_g4: values around and at the thresholds", "[blocks][backlash]") {
  const double y_prev = 0.5;
  const double c = 0.25;  // edges 0.75 and 0.25, exact in binary
  const double upper = y_prev + c;
  const double lower = y_prev - c;
  REQUIRE(upper == 0.75);
  REQUIRE(lower == 0.25);

  REQUIRE(bonl::backlash_g3(upper, y_prev, c) == 0.0);
  REQUIRE(bonl::backlash_g3(std::nextafter(upper, kInf), y_prev, c) == 1.0);
  REQUIRE(bonl::backlash_g3(std::nextafter(upper, -kInf), y_prev, c) == 0.0);
  REQUIRE(bonl::backlash_g3(2.0, y_prev, c) == 1.0);
  REQUIRE(bonl::backlash_g3(0.5, y_prev, c) == 0.0);
  REQUIRE(bonl::backlash_g3(-2.0, y_prev, c) == 0.0);

  REQUIRE(bonl::backlash_g4(lower, y_prev, c) == 0.0);
  REQUIRE(bonl::backlash_g4(std::nextafter(lower, -kInf), y_prev, c) == 1.0);
  REQUIRE(bonl::backlash_g4(std::nextafter(lower, kInf), y_prev, c) == 0.0);
  REQUIRE(bonl::backlash_g4(-2.0, y_prev, c) == 1.0);
  REQUIRE(bonl::backlash_g4(0.5, y_prev, c) == 0.0);
  REQUIRE(bonl::backlash_g4(2.0, y_prev, c) == 0.0);

  // With c = 0 the edges coincide: exactly at y_prev neither switch is on.
  REQUIRE(bonl::backlash_g3(y_prev, y_prev, 0.0) == 0.0);
  REQUIRE(bonl::backlash_g4(y_prev, y_prev, 0.0) == 0.0);
}

// Eq. (12), y = y1 + (y_prev - y1)(g3 - 1)(g4 - 1) with y1 from eq. (11), is the same mapping as
// the case form of eq. (10) whenever sgn(dx) matches the motion: up past the upper edge, down past
// the lower edge, and (for any sgn) inside the gap, where the product term restores y_prev.
TEST_CASE("backlash_g3 / backlash_g4: eqs. (11)-(12) reproduce Backlash::map", "[blocks][backlash]") {
  const double c = 0.2;
  const auto eq12 = [c](double x, double y_prev, double sgn_dx) {
    const double g3 = bonl::backlash_g3(x, y_prev, c);
    const double g4 = bonl::backlash_g4(x, y_prev, c);
    const double y1 = x - 0.5 * c * (sgn_dx + 1.0) * g3 + 0.5 * c * (1.0 - sgn_dx) * g4;  // eq. (11)
    return y1 + (y_prev - y1) * (g3 - 1.0) * (g4 - 1.0);                                  // eq. (12)
  };
  int up = 0, down = 0, gap = 0;
  for (double y_prev : {-0.7, 0.0, 0.35}) {
    for (int i = -40; i <= 40; ++i) {
      const double x = y_prev + i / 40.0;  // from y_prev - 1 to y_prev + 1
      const double expected = bonl::Backlash<double>::map(x, y_prev, c);
      INFO("y_prev = " << y_prev << ", x = " << x);
      if (x > y_prev + c) {  // moving up
        REQUIRE(near(eq12(x, y_prev, +1.0), expected, 1e-14));
        REQUIRE(near(expected, x - c, 1e-14));
        ++up;
      } else if (x < y_prev - c) {  // moving down
        REQUIRE(near(eq12(x, y_prev, -1.0), expected, 1e-14));
        REQUIRE(near(expected, x + c, 1e-14));
        ++down;
      } else {  // inside the gap: any direction of motion
        for (double s : {-1.0, 0.0, 1.0}) REQUIRE(near(eq12(x, y_prev, s), expected, 1e-14));
        REQUIRE(expected == y_prev);
        ++gap;
      }
    }
  }
  REQUIRE(up > 0);
  REQUIRE(down > 0);
  REQUIRE(gap > 0);
  // Along an actual trajectory, with sgn taken from the real increment of x.
  bonl::Backlash<double> play(c);
  double x_prev = 0.0;
  for (int k = 0; k < 150; ++k) {
    const double x = std::sin(0.09 * k) + 0.2 * std::sin(0.5 * k);
    const double y_prev = play.output();
    REQUIRE(near(eq12(x, y_prev, sgn(x - x_prev)), play.step(x), 1e-14));
    x_prev = x;
  }
}

// ---------------------------------------------------------------------------------------------
// GeneralBacklash (Fig. 9: separate thresholds, slope m)
// ---------------------------------------------------------------------------------------------

// Hand-computed outputs for c_left = 0.1, c_right = 0.3, m = 2, starting at y = 0:
// up = 2 (x - 0.3) must exceed y, down = 2 (x + 0.1) must undercut y.
TEST_CASE("GeneralBacklash: hand-computed sequence", "[blocks][backlash]") {
  bonl::GeneralBacklash<double> play(0.1, 0.3, 2.0);
  REQUIRE(play.c_left() == 0.1);
  REQUIRE(play.c_right() == 0.3);
  REQUIRE(play.slope() == 2.0);
  const double x[] = {0.2, 0.5, 0.4, 0.2, 0.05, -0.2, 0.0, 0.45};
  const double expected[] = {
      0.0,   // up = -0.2, down = 0.6: inside the gap
      0.4,   // up = 0.4 > 0
      0.4,   // up = 0.2, down = 1.0: held
      0.4,   // up = -0.2, down = 0.6: held
      0.3,   // down = 0.3 < 0.4
      -0.2,  // down = -0.2 < 0.3
      -0.2,  // up = -0.6, down = 0.2: held
      0.3,   // up = 0.3 > -0.2
  };
  for (int k = 0; k < 8; ++k) {
    INFO("k = " << k << ", x = " << x[k]);
    REQUIRE(near(play.step(x[k]), expected[k], 1e-14));
  }
  play.reset(1.0);
  REQUIRE(play.output() == 1.0);
}

// With equal thresholds c and slope 1 the general backlash is the identification backlash.
TEST_CASE("GeneralBacklash: symmetric with unit slope equals Backlash", "[blocks][backlash]") {
  const double c = 0.12;
  bonl::GeneralBacklash<double> general(c, c, 1.0);
  bonl::Backlash<double> play(c);
  for (int k = 0; k < 300; ++k) {
    const double x = std::sin(0.07 * k) + 0.4 * std::sin(0.61 * k);
    INFO("k = " << k);
    REQUIRE(near(general.step(x), play.step(x), 1e-14));
  }
}

// Thresholds must be finite and >= 0, the slope finite and > 0, the initial output finite.
TEST_CASE("GeneralBacklash: invalid arguments throw", "[blocks][backlash]") {
  using GB = bonl::GeneralBacklash<double>;
  REQUIRE_THROWS_AS(GB(-0.1, 0.1), std::invalid_argument);
  REQUIRE_THROWS_AS(GB(0.1, -0.1), std::invalid_argument);
  REQUIRE_THROWS_AS(GB(kNaN, 0.1), std::invalid_argument);
  REQUIRE_THROWS_AS(GB(0.1, kInf), std::invalid_argument);
  REQUIRE_THROWS_AS(GB(0.1, 0.1, 0.0), std::invalid_argument);
  REQUIRE_THROWS_AS(GB(0.1, 0.1, -1.0), std::invalid_argument);
  REQUIRE_THROWS_AS(GB(0.1, 0.1, kNaN), std::invalid_argument);
  REQUIRE_THROWS_AS(GB(0.1, 0.1, 1.0, kInf), std::invalid_argument);
  REQUIRE_NOTHROW(GB(0.0, 0.0, 0.5, -1.0));
}

// ---------------------------------------------------------------------------------------------
// Two-segment input polynomial (eqs. 3-5)
// ---------------------------------------------------------------------------------------------

// h(u) of eq. (4): 1 strictly below zero, 0 from zero on (negative zero included, since -0.0 < 0
// is false).
TEST_CASE("input_switch: 1 for u < 0, 0 for u >= 0", "[blocks][input]") {
  REQUIRE(bonl::input_switch(-1.0) == 1.0);
  REQUIRE(bonl::input_switch(-1e-300) == 1.0);
  REQUIRE(bonl::input_switch(-std::numeric_limits<double>::denorm_min()) == 1.0);
  REQUIRE(bonl::input_switch(0.0) == 0.0);
  REQUIRE(bonl::input_switch(-0.0) == 0.0);
  REQUIRE(bonl::input_switch(1e-300) == 0.0);
  REQUIRE(bonl::input_switch(2.5) == 0.0);
  REQUIRE(bonl::input_switch(-2.5f) == 1.0f);
  REQUIRE(bonl::input_switch(0.0f) == 0.0f);
}

// w = sum f_l u^l for u >= 0 and sum (f_l + p_l) u^l for u < 0 (degree 3), checked against the
// hand-expanded polynomials and against literal values worked out by hand.
TEST_CASE("TwoSegmentPolynomial: values on both sides of zero", "[blocks][input]") {
  const Eigen::VectorXd f = vec({0.5, -1.0, 2.0, 0.25});
  const Eigen::VectorXd p = vec({-0.2, 0.3, -1.5, 0.75});
  const bonl::TwoSegmentPolynomial<double> n1(f, p);
  REQUIRE(n1.degree() == 3);
  REQUIRE(n1.f() == f);
  REQUIRE(n1.p() == p);
  // g = f + p = [0.3, -0.7, 0.5, 1.0]
  REQUIRE(near(n1.g(), vec({0.3, -0.7, 0.5, 1.0}), 1e-15));

  const auto positive = [&](double u) { return f[0] + f[1] * u + f[2] * u * u + f[3] * u * u * u; };
  const auto negative = [&](double u) {
    return (f[0] + p[0]) + (f[1] + p[1]) * u + (f[2] + p[2]) * u * u + (f[3] + p[3]) * u * u * u;
  };
  for (double u : {0.1, 0.5, 1.0, 2.0, 3.7}) {
    INFO("u = " << u);
    REQUIRE(near(n1(u), positive(u), 1e-13));
  }
  REQUIRE(n1(0.0) == 0.5);  // f_0: zero is on the u >= 0 side
  REQUIRE(n1(-0.0) == 0.5);
  for (double u : {-0.1, -0.5, -1.0, -2.0, -3.7}) {
    INFO("u = " << u);
    REQUIRE(near(n1(u), negative(u), 1e-13));
  }
  // By hand: 0.5 - 2 + 8 + 2 = 8.5; 0.5 - 0.5 + 0.5 + 0.03125; 0.3 + 0.7 + 0.5 - 1; 0.3 + 1.4 + 2 - 8.
  REQUIRE(near(n1(2.0), 8.5, 1e-14));
  REQUIRE(near(n1(0.5), 0.53125, 1e-14));
  REQUIRE(near(n1(-1.0), 0.5, 1e-14));
  REQUIRE(near(n1(-2.0), -4.3, 1e-14));
  // The static form agrees with the object.
  REQUIRE(bonl::TwoSegmentPolynomial<double>::evaluate(f, p, -1.3) == n1(-1.3));
}

// The key-term regressor: basis(u) = [1, u, u^2, u^3, h, h u, h u^2, h u^3], so that
// basis . [f; p] is the block's output on both sides of zero.
TEST_CASE("TwoSegmentPolynomial: basis dotted with [f; p] is the value", "[blocks][input]") {
  const Eigen::VectorXd f = vec({0.5, -1.0, 2.0, 0.25});
  const Eigen::VectorXd p = vec({-0.2, 0.3, -1.5, 0.75});
  const bonl::TwoSegmentPolynomial<double> n1(f, p);
  Eigen::VectorXd fp(8);
  fp << f, p;
  Eigen::VectorXd basis(8);
  for (double u : {-2.0, -0.7, -1e-3, 0.0, 1e-3, 0.7, 2.0}) {
    INFO("u = " << u);
    bonl::TwoSegmentPolynomial<double>::basis(u, 3, basis);
    const double h = u < 0.0 ? 1.0 : 0.0;
    REQUIRE(near(basis, vec({1.0, u, u * u, u * u * u, h, h * u, h * u * u, h * u * u * u}), 1e-15));
    REQUIRE(near(basis.dot(fp), n1(u), 1e-13));
    // The estimators' form: the same basis, and its dot with [f; p] returned.
    Eigen::VectorXd fused = Eigen::VectorXd::Constant(8, 99.0);
    const double w = bonl::TwoSegmentPolynomial<double>::basis(u, f, p, fused);
    REQUIRE(fused == basis);
    REQUIRE(near(w, n1(u), 1e-13));
  }
}

// Coefficient vectors must have r + 1 finite entries and the degree must be >= 1.
TEST_CASE("TwoSegmentPolynomial: invalid coefficients and degree throw", "[blocks][input]") {
  bonl::TwoSegmentPolynomial<double> n1(3);
  REQUIRE(n1.f() == Eigen::VectorXd::Zero(4));
  REQUIRE_THROWS_AS(n1.set_f(vec({1.0, 2.0, 3.0})), std::invalid_argument);
  REQUIRE_THROWS_AS(n1.set_f(vec({1.0, 2.0, 3.0, 4.0, 5.0})), std::invalid_argument);
  REQUIRE_THROWS_AS(n1.set_f(vec({1.0, kNaN, 3.0, 4.0})), std::invalid_argument);
  REQUIRE_THROWS_AS(n1.set_p(vec({1.0, 2.0})), std::invalid_argument);
  REQUIRE_THROWS_AS(n1.set_p(vec({1.0, 2.0, kInf, 4.0})), std::invalid_argument);
  REQUIRE(n1.f() == Eigen::VectorXd::Zero(4));  // nothing was stored
  REQUIRE_THROWS_AS(bonl::TwoSegmentPolynomial<double>(0), std::invalid_argument);
  REQUIRE_THROWS_AS(bonl::TwoSegmentPolynomial<double>(vec({1.0}), vec({1.0})), std::invalid_argument);
  REQUIRE_THROWS_AS(bonl::TwoSegmentPolynomial<double>(vec({1.0, 2.0}), vec({1.0, 2.0, 3.0})), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------
// Output polynomial (eq. 9)
// ---------------------------------------------------------------------------------------------

// y = x + 0.5 x^2 + 0.2 x^3 and y' = 1 + x + 0.6 x^2 (positive everywhere: 1 - 4 * 0.6 < 0).
TEST_CASE("OutputPolynomial: value and derivative", "[blocks][output]") {
  bonl::OutputPolynomial<double> n2(3);
  REQUIRE(n2.q() == vec({1.0, 0.0, 0.0}));  // starts as the identity
  REQUIRE(n2(0.3) == 0.3);
  n2.set_q(vec({1.0, 0.5, 0.2}));
  for (double x : {-2.0, -1.0, -0.3, 0.0, 0.4, 1.0, 2.0}) {
    INFO("x = " << x);
    REQUIRE(near(n2(x), x + 0.5 * x * x + 0.2 * x * x * x, 1e-14));
    REQUIRE(near(n2.derivative(x), 1.0 + x + 0.6 * x * x, 1e-14));
  }
  REQUIRE(near(n2(2.0), 5.6, 1e-14));              // 2 + 2 + 1.6
  REQUIRE(near(n2.derivative(2.0), 5.4, 1e-14));   // 1 + 2 + 2.4
  REQUIRE(near(n2(-1.0), -0.7, 1e-14));            // -1 + 0.5 - 0.2
  REQUIRE(near(n2.derivative(-1.0), 0.6, 1e-14));  // 1 - 1 + 0.6
  REQUIRE(n2(0.0) == 0.0);                         // no constant term
  REQUIRE_THROWS_AS(n2.set_q(vec({1.0, 0.5})), std::invalid_argument);
  REQUIRE_THROWS_AS(n2.set_q(vec({1.0, kNaN, 0.2})), std::invalid_argument);
  REQUIRE_THROWS_AS(bonl::OutputPolynomial<double>(0), std::invalid_argument);
}

// Newton inversion recovers x from y = q(x) for a monotone polynomial, and refuses (leaving x
// alone) where the slope vanishes or is negative.
TEST_CASE("OutputPolynomial: invert", "[blocks][output]") {
  using N2 = bonl::OutputPolynomial<double>;
  const Eigen::VectorXd q = vec({1.0, 0.5, 0.2});
  for (double x_true : {-3.0, -1.5, -0.4, 0.0, 0.2, 1.0, 2.5}) {
    const double y = N2::evaluate(q, x_true);
    for (double guess : {0.0, y, x_true + 0.5}) {
      double x = 1e300;
      INFO("x = " << x_true << ", guess = " << guess);
      REQUIRE(N2::invert(q, y, guess, x));
      REQUIRE(std::abs(x - x_true) <= 1e-12);
    }
  }
  // y = x - x^2: slope 1 - 2x is 0 at x = 0.5 and negative beyond.
  const Eigen::VectorXd hump = vec({1.0, -1.0});
  double x = 42.0;
  REQUIRE_FALSE(N2::invert(hump, 0.2, 0.5, x));
  REQUIRE_FALSE(N2::invert(hump, 0.2, 2.0, x));
  REQUIRE(x == 42.0);
  // y = x^2 (q_1 = 0): slope 0 at the guess 0.
  REQUIRE_FALSE(N2::invert(vec({0.0, 1.0}), 1.0, 0.0, x));
  REQUIRE(x == 42.0);
  // On the increasing side of the hump it still inverts: x - x^2 = 0.16 at x = 0.2.
  REQUIRE(N2::invert(hump, 0.16, 0.0, x));
  REQUIRE(std::abs(x - 0.2) <= 1e-12);
}

// ---------------------------------------------------------------------------------------------
// Linear block (eqs. 6-8)
// ---------------------------------------------------------------------------------------------

// na = 1, a = [-0.5], nb = 1, b = [1, 0.5], nk = 2: x(k) = 0.5 x(k-1) + w(k-2) + 0.5 w(k-3).
// For a unit impulse w(0) = 1: x = 0, 0, 1, 0.5 + 0.5 = 1, 0.5, 0.25, 0.125, 0.0625 (exact in binary).
TEST_CASE("PlayOperators: each play is min(max(P(k-1), v - r), v + r) from rest, and the data rule", "[blocks][play]") {
  bonl::PlayOperators<double> plays(vec({0.1, 0.4, 1.0}));
  const Eigen::VectorXd v = bonl::signals::random_levels(300, 3, 1.2, 21);
  Eigen::Vector3d expected = Eigen::Vector3d::Zero();
  for (Eigen::Index k = 0; k < v.size(); ++k) {
    const Eigen::VectorXd& state = plays.step(v[k]);
    for (int i = 0; i < 3; ++i) {
      const double r = plays.thresholds()[i];
      expected[i] = std::min(std::max(expected[i], v[k] - r), v[k] + r);
    }
    REQUIRE((state - expected).cwiseAbs().maxCoeff() == 0.0);
    CHECK(plays.output(vec({1.0, -2.0, 0.5})) == expected[0] - 2.0 * expected[1] + 0.5 * expected[2]);
  }
  plays.reset();
  CHECK(plays.state().isZero(0.0));
  // Fixed size: the same values.
  bonl::PlayOperators<double, 3> fixed(Eigen::Vector3d(0.1, 0.4, 1.0));
  bonl::PlayOperators<double> dynamic(vec({0.1, 0.4, 1.0}));
  for (Eigen::Index k = 0; k < v.size(); ++k) CHECK(fixed.step(v[k]) == Eigen::Vector3d(dynamic.step(v[k])));
  // The data rule: i / (np + 1) of the half-range.
  CHECK(bonl::PlayOperators<double>::spread_thresholds(3, 2.0).isApprox(vec({0.5, 1.0, 1.5}), 1e-15));
  CHECK(bonl::PlayOperators<double>::spread_thresholds(1, 0.0) == vec({0.5}));  // a constant input: half-range 1
}

TEST_CASE("PlayOperators: bad thresholds throw", "[blocks][play]") {
  CHECK_THROWS_WITH(bonl::PlayOperators<double>(vec({0.5, 0.1})),
                    "bonl: thresholds must be strictly increasing, got 0.5 before 0.1 at index 1");
  CHECK_THROWS_WITH(bonl::PlayOperators<double>(vec({0.0, 0.1})), Catch::Matchers::Contains("must be > 0"));
  CHECK_THROWS_WITH(bonl::PlayOperators<double>(vec({0.1, kNaN})), Catch::Matchers::Contains("thresholds"));
  CHECK_THROWS_WITH(bonl::PlayOperators<double>(vec({0.1, kInf})), Catch::Matchers::Contains("thresholds"));
  CHECK_THROWS_WITH((bonl::PlayOperators<double, 2>(vec({0.1, 0.2, 0.3}))), Catch::Matchers::Contains("thresholds"));
}

TEST_CASE("LinearBlock: hand-computed impulse response", "[blocks][linear]") {
  bonl::LinearBlock<double> block(1, 1, 2);
  REQUIRE(block.na() == 1);
  REQUIRE(block.nb() == 1);
  REQUIRE(block.nk() == 2);
  REQUIRE(block.b() == vec({1.0, 0.0}));  // default b = [1, 0...], a = 0
  block.set_a(vec({-0.5}));
  block.set_b(vec({1.0, 0.5}));
  const double expected[] = {0.0, 0.0, 1.0, 1.0, 0.5, 0.25, 0.125, 0.0625};
  for (int k = 0; k < 8; ++k) {
    INFO("k = " << k);
    REQUIRE(block.step(k == 0 ? 1.0 : 0.0) == expected[k]);
  }
}

// The pure delay nk only shifts the response: with the same a, b, the nk = 3 output is the nk = 0
// output delayed by exactly 3 samples (the first 3 samples are 0).
TEST_CASE("LinearBlock: pure delay shifts the response by nk samples", "[blocks][linear]") {
  const Eigen::VectorXd a = vec({-1.2, 0.35});
  const Eigen::VectorXd b = vec({1.0, -0.4, 0.25});
  bonl::LinearBlock<double> undelayed(2, 2, 0);
  bonl::LinearBlock<double> delayed(2, 2, 3);
  undelayed.set_a(a);
  undelayed.set_b(b);
  delayed.set_a(a);
  delayed.set_b(b);
  std::vector<double> x0, x3;
  for (int k = 0; k < 60; ++k) {
    const double w = std::sin(0.3 * k) + (k % 7 == 0 ? 1.0 : 0.0);
    x0.push_back(undelayed.step(w));
    x3.push_back(delayed.step(w));
  }
  for (int k = 0; k < 3; ++k) REQUIRE(x3[k] == 0.0);
  for (int k = 3; k < 60; ++k) {
    INFO("k = " << k);
    REQUIRE(x3[k] == x0[k - 3]);
  }
  // By hand for the undelayed block and w(0) = 1 (k % 7 == 0), w(1) = sin 0.3:
  // x(0) = 1, x(1) = 1.2 + sin 0.3 - 0.4.
  REQUIRE(near(x0[0], 1.0, 1e-15));
  REQUIRE(near(x0[1], 1.2 * 1.0 + std::sin(0.3) - 0.4 * 1.0, 1e-14));
}

// reset() puts the block back at rest: the response afterwards is that of a fresh block.
TEST_CASE("LinearBlock: reset returns to rest", "[blocks][linear]") {
  bonl::LinearBlock<double> block(1, 1, 2);
  block.set_a(vec({-0.5}));
  block.set_b(vec({1.0, 0.5}));
  for (int k = 0; k < 10; ++k) block.step(1.0 + k);
  block.reset();
  const double expected[] = {0.0, 0.0, 1.0, 1.0, 0.5, 0.25};
  for (int k = 0; k < 6; ++k) REQUIRE(block.step(k == 0 ? 1.0 : 0.0) == expected[k]);
  // At rest with zero input, the output stays zero.
  block.reset();
  for (int k = 0; k < 5; ++k) REQUIRE(block.step(0.0) == 0.0);
}

// Orders: na >= 1, nb >= 0, nk >= 0; fixed-size templates must match; coefficient vectors must
// have the right length and be finite.
TEST_CASE("LinearBlock: invalid orders and coefficients throw", "[blocks][linear]") {
  using LB = bonl::LinearBlock<double>;
  REQUIRE_THROWS_AS(LB(0, 1, 0), std::invalid_argument);
  REQUIRE_THROWS_AS(LB(1, -1, 0), std::invalid_argument);
  REQUIRE_THROWS_AS(LB(1, 1, -1), std::invalid_argument);
  REQUIRE_NOTHROW(LB(1, 0, 0));
  REQUIRE_THROWS_AS((bonl::LinearBlock<double, 2, 1>(1, 1, 0)), std::invalid_argument);
  REQUIRE_THROWS_AS((bonl::LinearBlock<double, 2, 1>(2, 2, 0)), std::invalid_argument);
  REQUIRE_NOTHROW((bonl::LinearBlock<double, 2, 1>(2, 1, 0)));
  LB block(2, 1, 0);
  REQUIRE_THROWS_AS(block.set_a(vec({0.1})), std::invalid_argument);
  REQUIRE_THROWS_AS(block.set_a(vec({0.1, kNaN})), std::invalid_argument);
  REQUIRE_THROWS_AS(block.set_b(vec({1.0, 0.5, 0.2})), std::invalid_argument);
  REQUIRE_THROWS_AS(block.set_b(vec({kInf, 0.5})), std::invalid_argument);
}
