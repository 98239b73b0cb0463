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

namespace {
/// The Prandtl-Ishlinskii input written out (the oracle): w = sum_l f_l u^l + sum_i g_i P_i with
/// P_i = min(max(P_i, u - r_i), u + r_i) stepped in `state`.
double hysteresis_by_hand(const Eigen::VectorXd& f, const Eigen::VectorXd& r, const Eigen::VectorXd& g,
                          Eigen::VectorXd& state, double u) {
  double w = 0.0;
  for (Eigen::Index l = 0; l < f.size(); ++l) w += f[l] * std::pow(u, static_cast<double>(l));
  for (Eigen::Index i = 0; i < r.size(); ++i) {
    state[i] = std::min(std::max(state[i], u - r[i]), u + r[i]);
    w += g[i] * state[i];
  }
  return w;
}
}  // namespace

TEST_CASE("the Prandtl-Ishlinskii input's inverse gives the w asked for through many reversals") {
  // w rises with u for every state (f' >= 0.15 on [-1, 1], the weights' negative sum -0.1 less).
  const Eigen::VectorXd f = vec({0.02, 0.5, 0.1, -0.05});
  const Eigen::VectorXd r = vec({0.1, 0.25, 0.5});
  for (const Eigen::VectorXd& g : {vec({0.3, 0.2, 0.1}), vec({0.3, -0.1, 0.2})}) {
    for (const double sign : {1.0, -1.0}) {  // -1: the whole block negated, w falls with u
      INFO("g = " << g.transpose() << ", sign " << sign);
      const bonl::PrandtlIshlinskiiInput<double> block(sign * f, r, sign * g);
      PrandtlIshlinskiiInverse<double> inverse(block, -1.0, 1.0);
      CHECK(inverse.direction() == static_cast<int>(sign));
      CHECK(inverse.lower() == -1.0);
      CHECK(inverse.upper() == 1.0);
      // Targets: the w a wandering command gives from the oracle's memory (so every target is
      // reachable); the inverse's command must give it from the same memory.
      Eigen::VectorXd oracle = Eigen::VectorXd::Zero(r.size());
      double worst_w = 0.0, worst_u = 0.0;
      for (Eigen::Index k = 0; k < 3000; ++k) {
        const double u_true = 0.85 * wavy(k) + 0.1 * std::sin(static_cast<double>(k) / 2.3);  // within +-0.96
        Eigen::VectorXd probe = oracle;
        const double w = hysteresis_by_hand(sign * f, r, sign * g, probe, u_true);
        const auto command = inverse(w);
        CHECK(command.status == InverseStatus::Exact);
        const double given = hysteresis_by_hand(sign * f, r, sign * g, oracle, command.value);
        CHECK(inverse.output(command.value) == Approx(given).margin(1e-14));
        inverse.advance(command.value);
        worst_w = std::max(worst_w, std::abs(given - w));
        worst_u = std::max(worst_u, std::abs(command.value - u_true));  // the map is strictly monotone
        CHECK(near(inverse.state(), oracle, 1e-14));
      }
      INFO("max |w(u) - w_d| = " << worst_w << ", max |u - u_true| = " << worst_u);
      CHECK(worst_w <= 1e-14);
      CHECK(worst_u <= 1e-12);
    }
  }
}

TEST_CASE("the Prandtl-Ishlinskii input's inverse saturates at the range's ends, reported") {
  const bonl::PrandtlIshlinskiiInput<double> block(vec({0.0, 0.5}), vec({0.2}), vec({0.3}));
  PrandtlIshlinskiiInverse<double> inverse(block, -1.0, 2.0);
  // From rest: u = 2 gives 0.5 * 2 + 0.3 * 1.8 = 1.54, u = -1 gives -0.5 - 0.3 * 0.8 = -0.74.
  CHECK(inverse(1.6).status == InverseStatus::Saturated);
  CHECK(inverse(1.6).value == 2.0);
  CHECK(inverse(1.5).status == InverseStatus::Exact);
  CHECK(inverse(-0.8).status == InverseStatus::Saturated);
  CHECK(inverse(-0.8).value == -1.0);
  // Inside the play's gap from rest (|u| <= 0.2) only the linear term moves w.
  CHECK(inverse(0.05).value == Approx(0.1).epsilon(1e-14));
  // The memory moves the map: after u = 2 the play is at 1.8, and u = 1.9 (inside its gap) gives
  // 0.95 + 0.3 * 1.8 = 1.49 (from rest it would give 1.46).
  inverse.advance(2.0);
  CHECK(inverse.state()[0] == Approx(1.8));
  CHECK(inverse(1.49).value == Approx(1.9).epsilon(1e-14));
  inverse.reset();
  CHECK(inverse.state()[0] == 0.0);
}

TEST_CASE("the Prandtl-Ishlinskii input's inverse keeps to where w is monotone for every state") {
  // f' = 0.04 + 0.02 u - 0.015 u^2 (the paper_orders known system) is negative beyond its roots
  // (0.02 -+ sqrt(0.0028)) / 0.03; the play's weight is positive, so f' is the least slope.
  const bonl::PrandtlIshlinskiiInput<double> block(vec({0.001, 0.04, 0.01, -0.005}), vec({0.4}), vec({0.03}));
  PrandtlIshlinskiiInverse<double> inverse(block, -3.0, 3.0);
  CHECK(inverse.upper() == Approx((0.02 + std::sqrt(0.0028)) / 0.03).epsilon(1e-9));
  CHECK(inverse.lower() == Approx((0.02 - std::sqrt(0.0028)) / 0.03).epsilon(1e-9));
  CHECK(inverse(1.0).status == InverseStatus::Saturated);
  CHECK(inverse(1.0).value == inverse.upper());
  // A negative weight larger than f' near 0 leaves a slope of either sign: no inverse.
  CHECK_THROWS_WITH(
      PrandtlIshlinskiiInverse<double>(
          bonl::PrandtlIshlinskiiInput<double>(vec({0.0, 0.1}), vec({0.2, 0.5}), vec({0.3, -0.2})), -1.0, 1.0),
      Catch::Contains("not monotone in u near the operating point for every state of the plays"));
  // w = u^2 + 0.1 play: rises on one side of 0 and falls on the other.
  CHECK_THROWS_WITH(PrandtlIshlinskiiInverse<double>(
                        bonl::PrandtlIshlinskiiInput<double>(vec({0.0, 0.0, 1.0}), vec({0.2}), vec({0.1})), -1.0, 1.0),
                    Catch::Contains("not monotone in u"));
  CHECK_THROWS_WITH(PrandtlIshlinskiiInverse<double>(
                        bonl::PrandtlIshlinskiiInput<double>(vec({0.5, 0.0}), vec({0.2}), vec({0.0})), -1.0, 1.0),
                    Catch::Contains("w does not change with u over the command range"));
  CHECK_THROWS_WITH(PrandtlIshlinskiiInverse<double>(block, 0.5, 1.0), Catch::Contains("contain the operating point"));
  // Only plays (f = 0) with positive weights: flat inside the gap, still an inverse (the classic PI operator).
  PrandtlIshlinskiiInverse<double> plays_only(
      bonl::PrandtlIshlinskiiInput<double>(vec({0.0, 0.0}), vec({0.1, 0.3}), vec({1.0, 0.5})), -1.0, 1.0);
  const auto up = plays_only(0.5);  // 1.0 (u - 0.1) + 0.5 (u - 0.3) = 0.5 at u = 0.5
  CHECK(up.status == InverseStatus::Exact);
  CHECK(up.value == Approx(0.5).epsilon(1e-14));
}
