// Command signals for the plant (plant/excitation.hpp): values against hand computation, the smooth
// random signal's RMS and band limit, the chirp's instantaneous frequency, the zero-order hold's
// edges, allocation-free calls and bad input. Allocations are counted by replacing the global
// operator new in this test executable only.

#include <bonl/plant/excitation.hpp>

#include "counting_allocator.hpp"
#include "test_support.hpp"

#include <array>
#include <limits>
#include <stdexcept>
#include <vector>

using namespace bonl_test;
namespace excitation = bonl::plant::excitation;
using Catch::Matchers::Contains;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// Samples command(k dt) - offset, k = 0..n-1.
Eigen::VectorXd sample(const bonl::plant::Command& command, Eigen::Index n, double dt, double offset) {
  Eigen::VectorXd v(n);
  for (Eigen::Index k = 0; k < n; ++k) v[k] = command(static_cast<double>(k) * dt) - offset;
  return v;
}

/// Amplitude of the component of v (sampled at k dt) at frequency f: 2 / n * |sum v e^{-i 2 pi f t}|.
double amplitude_at(const Eigen::VectorXd& v, double dt, double f) {
  double c = 0.0;
  double s = 0.0;
  for (Eigen::Index k = 0; k < v.size(); ++k) {
    const double phase = 2.0 * kPi * f * static_cast<double>(k) * dt;
    c += v[k] * std::cos(phase);
    s += v[k] * std::sin(phase);
  }
  return 2.0 / static_cast<double>(v.size()) * std::hypot(c, s);
}

/// The times in (a, b) where command(t) crosses `level`, found on a grid of step dt and refined by
/// bisection.
std::vector<double> crossings(const bonl::plant::Command& command, double level, double a, double b, double dt) {
  std::vector<double> times;
  double t_prev = a;
  double v_prev = command(a) - level;
  for (double t = a + dt; t <= b; t += dt) {
    const double v = command(t) - level;
    if ((v_prev < 0.0) != (v < 0.0)) {
      double lo = t_prev;
      double hi = t;
      for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (((command(mid) - level) < 0.0) == (v_prev < 0.0))
          lo = mid;
        else
          hi = mid;
      }
      times.push_back(0.5 * (lo + hi));
    }
    t_prev = t;
    v_prev = v;
  }
  return times;
}

}  // namespace

TEST_CASE("step holds `before` until t_step, then the level", "[plant][excitation]") {
  const auto v = excitation::step(3.1, 2.0, 2.4);
  CHECK(v(-5.0) == 2.4);
  CHECK(v(0.0) == 2.4);
  CHECK(v(std::nextafter(2.0, 0.0)) == 2.4);
  CHECK(v(2.0) == 3.1);
  CHECK(v(10.0) == 3.1);
  const auto from_zero = excitation::step(1.7);
  CHECK(from_zero(-1e-9) == 2.5);
  CHECK(from_zero(0.0) == 1.7);
  CHECK(from_zero(50.0) == 1.7);
}

TEST_CASE("multisine sums its tones around the offset, with Schroeder phases by default", "[plant][excitation]") {
  const std::vector<double> f = {0.3, 1.1, 2.0};
  const auto schroeder = excitation::multisine(f, 0.2, 2.6);
  const auto given = excitation::multisine(f, 0.2, 2.6, {0.1, -0.4, 1.5});
  for (double t : {0.0, 0.37, 4.2, 12.3}) {
    double expected_schroeder = 2.6;
    for (int k = 1; k <= 3; ++k) {
      expected_schroeder += 0.2 * std::sin(2 * kPi * f[k - 1] * t - kPi * k * (k + 1) / 3.0);
    }
    const double expected_given = 2.6 + 0.2 * (std::sin(2 * kPi * 0.3 * t + 0.1) + std::sin(2 * kPi * 1.1 * t - 0.4) +
                                               std::sin(2 * kPi * 2.0 * t + 1.5));
    CHECK(schroeder(t) == Approx(expected_schroeder).margin(1e-12));
    CHECK(given(t) == Approx(expected_given).margin(1e-12));
  }
  // A zero frequency is a constant term sin(phase).
  CHECK(excitation::multisine({0.0}, 0.5, 1.0, {0.3})(7.0) == Approx(1.0 + 0.5 * std::sin(0.3)).margin(1e-15));

  SECTION("the paper's multi-sine is signals::paper_multisine around 2.5 V") {
    const Eigen::VectorXd u = bonl::signals::paper_multisine(5000, 0.01, 0.4);
    const auto v = excitation::paper_multisine();
    for (Eigen::Index k : {0, 1, 123, 2500, 4999}) {
      CHECK(v(static_cast<double>(k) * 0.01) - 2.5 == Approx(u[k]).margin(1e-12));
    }
    const auto scaled = excitation::paper_multisine(0.2, 3.0);
    CHECK(scaled(1.23) - 3.0 == Approx(0.5 * u[123]).margin(1e-12));
  }
}

TEST_CASE("chirp sweeps linearly from f0 to f1, then continues at f1", "[plant][excitation]") {
  const double f0 = 0.5;
  const double f1 = 4.0;
  const double duration = 10.0;
  const auto v = excitation::chirp(f0, f1, duration, 0.3, 2.4);
  const auto phase = [&](double t) { return 2 * kPi * (f0 * t + (f1 - f0) * t * t / (2 * duration)); };
  for (double t : {0.0, 0.3, 3.7, 7.1, 10.0}) CHECK(v(t) == Approx(2.4 + 0.3 * std::sin(phase(t))).margin(1e-12));
  for (double t : {10.2, 13.9, 42.0}) {
    CHECK(v(t) == Approx(2.4 + 0.3 * std::sin(phase(duration) + 2 * kPi * f1 * (t - duration))).margin(1e-10));
  }
  // Before 0 it continues at f0.
  CHECK(v(-0.7) == Approx(2.4 + 0.3 * std::sin(-2 * kPi * f0 * 0.7)).margin(1e-12));
  // Continuous through the end of the sweep.
  CHECK(std::abs(v(duration + 1e-9) - v(duration - 1e-9)) < 1e-7);

  SECTION("instantaneous frequency from the half periods between zero crossings") {
    // Between consecutive crossings the phase advances by pi; for a frequency linear in t the mean
    // frequency over an interval is the frequency at its midpoint: f(mid) = 1 / (2 (b - a)).
    const std::vector<double> times = crossings(v, 2.4, 1e-3, 16.0, 1e-3);
    REQUIRE(times.size() > 40);
    std::vector<double> mids;
    std::vector<double> freqs;
    int after = 0;
    for (std::size_t i = 0; i + 1 < times.size(); ++i) {
      const double mid = 0.5 * (times[i] + times[i + 1]);
      const double f = 0.5 / (times[i + 1] - times[i]);
      if (times[i + 1] <= duration) {
        CHECK(f == Approx(f0 + (f1 - f0) * mid / duration).epsilon(1e-8));
        mids.push_back(mid);
        freqs.push_back(f);
      } else if (times[i] >= duration) {
        CHECK(f == Approx(f1).epsilon(1e-8));
        ++after;
      }
    }
    CHECK(after > 20);
    // A straight line through (mid, f) on the sweep starts at f0 and ends at f1.
    const double m = static_cast<double>(mids.size());
    double mean_t = 0.0;
    double mean_f = 0.0;
    for (std::size_t i = 0; i < mids.size(); ++i) {
      mean_t += mids[i] / m;
      mean_f += freqs[i] / m;
    }
    double stt = 0.0;
    double stf = 0.0;
    for (std::size_t i = 0; i < mids.size(); ++i) {
      stt += (mids[i] - mean_t) * (mids[i] - mean_t);
      stf += (mids[i] - mean_t) * (freqs[i] - mean_f);
    }
    const double slope = stf / stt;
    const double line[2] = {mean_f - slope * mean_t, slope};
    CHECK(line[0] == Approx(f0).epsilon(1e-7));
    CHECK(line[0] + line[1] * duration == Approx(f1).epsilon(1e-7));
  }
}

TEST_CASE("sampled holds values(k) on the interval from t0 + k ts to t0 + (k + 1) ts", "[plant][excitation]") {
  const auto v = excitation::sampled(vec({1.0, 2.0, 3.0, 4.0}), 0.1, 0.5);
  CHECK(v(-3.0) == 1.0);
  CHECK(v(0.4) == 1.0);
  CHECK(v(0.5) == 1.0);
  CHECK(v(0.6 - 1e-9) == 1.0);
  CHECK(v(0.6) == 2.0);  // (0.6 - 0.5) / 0.1 = 0.99999999999999978 in floating point: still on the edge
  CHECK(v(0.5 + 0.1) == 2.0);
  CHECK(v(0.7 - 1e-9) == 2.0);
  CHECK(v(0.5 + 2 * 0.1) == 3.0);
  CHECK(v(0.8 - 1e-9) == 3.0);
  CHECK(v(0.8) == 4.0);
  CHECK(v(0.9) == 4.0);
  CHECK(v(100.0) == 4.0);
  CHECK(v(std::numeric_limits<double>::infinity()) == 4.0);
  CHECK(v(-std::numeric_limits<double>::infinity()) == 1.0);
  CHECK(std::isnan(v(std::nan(""))));

  SECTION("on the simulator's 1 kHz grid a 10 ms sequence changes exactly at its edges") {
    Eigen::VectorXd values(100);
    for (Eigen::Index i = 0; i < values.size(); ++i) values[i] = static_cast<double>(i);
    const auto held = excitation::sampled(values, 0.01);
    const auto held_late = excitation::sampled(values, 0.01, 0.3);
    long mismatches = 0;
    for (long k = 0; k < 1500; ++k) {
      const double expected = static_cast<double>(std::min(k / 10, 99L));
      if (held(static_cast<double>(k) * 0.001) != expected) ++mismatches;
      if (held(static_cast<double>(k) / 1000.0) != expected) ++mismatches;
      const double late = static_cast<double>(std::min(std::max(k - 300, 0L) / 10, 99L));
      if (held_late(static_cast<double>(k) * 0.001) != late) ++mismatches;
    }
    CHECK(mismatches == 0);
  }
  SECTION("a single value is a constant") {
    const auto one = excitation::sampled(vec({2.7}), 0.5);
    CHECK(one(-1.0) == 2.7);
    CHECK(one(0.2) == 2.7);
    CHECK(one(9.0) == 2.7);
  }
}

TEST_CASE("smooth random signal: exact RMS, nothing above the bandwidth, reproducible from the seed",
          "[plant][excitation]") {
  const double bandwidth = 2.0;
  const double rms = 0.3;
  const double duration = 20.0;
  const double dt = 1e-3;
  const auto n = static_cast<Eigen::Index>(duration / dt + 0.5);
  const auto command = excitation::smooth_random(bandwidth, rms, duration, 7, 2.6);
  const Eigen::VectorXd v = sample(command, n, dt, 2.6);  // a fine grid over [0, duration)

  CHECK(std::sqrt(v.squaredNorm() / static_cast<double>(n)) == Approx(rms).epsilon(1e-6));
  CHECK(std::abs(v.mean()) < 1e-9);
  // Equal amplitudes on the 1 / duration grid up to the bandwidth (40 tones) ...
  const double tone = rms * std::sqrt(2.0 / 40.0);
  for (int k = 1; k <= 40; ++k) CHECK(amplitude_at(v, dt, k / duration) == Approx(tone).epsilon(1e-8));
  // ... and nothing above it.
  for (double f : {41 / duration, 2.5, 3.0, 5.0, 10.0, 100.0}) CHECK(amplitude_at(v, dt, f) < 1e-10);

  const auto same = excitation::smooth_random(bandwidth, rms, duration, 7, 2.6);
  const auto other = excitation::smooth_random(bandwidth, rms, duration, 8, 2.6);
  double largest_difference = 0.0;
  for (double t : {0.0, 1.3, 7.7, 19.9, 35.0}) {
    CHECK(same(t) == command(t));
    largest_difference = std::max(largest_difference, std::abs(other(t) - command(t)));
  }
  CHECK(largest_difference > 0.01);
  const Eigen::VectorXd w = sample(other, n, dt, 2.6);
  CHECK(std::sqrt(w.squaredNorm() / static_cast<double>(n)) == Approx(rms).epsilon(1e-6));

  SECTION("periodic with period `duration`") {
    for (double t : {0.4, 3.3, 11.0}) CHECK(command(t + duration) == Approx(command(t)).margin(1e-10));
  }
  SECTION("a single tone when bandwidth * duration is just 1, the tone at the bandwidth included") {
    const auto single = excitation::smooth_random(0.5, 1.0, 2.0, 3, 0.0);
    const Eigen::VectorXd s = sample(single, 2000, 1e-3, 0.0);
    CHECK(amplitude_at(s, 1e-3, 0.5) == Approx(std::sqrt(2.0)).epsilon(1e-9));
    // 0.29 * 100 is 28.999999999999996 in floating point; the 0.29 Hz tone still counts.
    const auto edge = excitation::smooth_random(0.29, 1.0, 100.0, 3, 0.0);
    const Eigen::VectorXd e = sample(edge, 10000, 0.01, 0.0);
    CHECK(amplitude_at(e, 0.01, 0.29) == Approx(std::sqrt(2.0 / 29.0)).epsilon(1e-8));
    CHECK(amplitude_at(e, 0.01, 0.30) < 1e-10);
  }
  SECTION("zero RMS is the offset") {
    const auto flat = excitation::smooth_random(1.0, 0.0, 10.0, 1, 2.5);
    CHECK(flat(3.7) == 2.5);
  }
}

TEST_CASE("calling a command allocates nothing", "[plant][excitation]") {
  const std::array<bonl::plant::Command, 6> commands = {
      excitation::step(3.0, 1.0),
      excitation::multisine({0.1, 0.3, 0.7, 1.3, 2.9, 3.1}, 0.1),
      excitation::paper_multisine(),
      excitation::smooth_random(3.0, 0.4, 50.0, 11),
      excitation::chirp(0.1, 5.0, 30.0, 0.5),
      excitation::sampled(Eigen::VectorXd::LinSpaced(5000, 0.0, 5.0), 0.01),
  };
  double sink = 0.0;
  const long before = bonl_test::allocations();
  for (const auto& command : commands) {
    for (int k = 0; k < 2000; ++k) sink += command(0.025 * k);
  }
  const long after = bonl_test::allocations();
  CHECK(after - before == 0);
  CHECK(std::isfinite(sink));
}

#define CHECK_INVALID(expression, fragment)             \
  do {                                                  \
    CHECK_THROWS_AS(expression, std::invalid_argument); \
    CHECK_THROWS_WITH(expression, Contains(fragment));  \
  } while (false)

TEST_CASE("bad arguments throw std::invalid_argument naming the argument", "[plant][excitation]") {
  const double nan = std::nan("");
  const double inf = std::numeric_limits<double>::infinity();

  CHECK_INVALID(excitation::step(nan), "level");
  CHECK_INVALID(excitation::step(1.0, inf), "t_step");
  CHECK_INVALID(excitation::step(1.0, 0.0, nan), "before");
  CHECK_THROWS_WITH(excitation::step(nan), Contains("bonl: excitation::step:"));

  CHECK_INVALID(excitation::multisine({}, 0.1), "frequencies_hz must not be empty");
  CHECK_INVALID(excitation::multisine({0.1, nan}, 0.1), "frequencies_hz");
  CHECK_INVALID(excitation::multisine({0.1, inf}, 0.1), "frequencies_hz");
  CHECK_INVALID(excitation::multisine({0.1, -0.2}, 0.1), "frequencies_hz");
  CHECK_INVALID(excitation::multisine({0.1, 0.2}, 0.1, 2.5, {0.0}), "phases");
  CHECK_INVALID(excitation::multisine({0.1, 0.2}, 0.1, 2.5, {0.0, 1.0, 2.0}), "phases");
  CHECK_INVALID(excitation::multisine({0.1, 0.2}, 0.1, 2.5, {0.0, nan}), "phases");
  CHECK_INVALID(excitation::multisine({0.1}, nan), "amplitude");
  CHECK_INVALID(excitation::multisine({0.1}, 0.1, inf), "offset");
  CHECK_THROWS_WITH(excitation::multisine({}, 0.1), Contains("bonl: excitation::multisine:"));

  CHECK_INVALID(excitation::paper_multisine(nan), "amplitude");
  CHECK_INVALID(excitation::paper_multisine(0.4, -inf), "offset");
  CHECK_THROWS_WITH(excitation::paper_multisine(nan), Contains("bonl: excitation::paper_multisine:"));

  CHECK_INVALID(excitation::smooth_random(0.0, 0.3, 10.0, 1), "bandwidth_hz");
  CHECK_INVALID(excitation::smooth_random(-1.0, 0.3, 10.0, 1), "bandwidth_hz");
  CHECK_INVALID(excitation::smooth_random(nan, 0.3, 10.0, 1), "bandwidth_hz");
  CHECK_INVALID(excitation::smooth_random(1.0, -0.1, 10.0, 1), "rms");
  CHECK_INVALID(excitation::smooth_random(1.0, inf, 10.0, 1), "rms");
  CHECK_INVALID(excitation::smooth_random(1.0, 0.3, 0.0, 1), "duration");
  CHECK_INVALID(excitation::smooth_random(1.0, 0.3, -5.0, 1), "duration");
  CHECK_INVALID(excitation::smooth_random(1.0, 0.3, inf, 1), "duration");
  CHECK_INVALID(excitation::smooth_random(1.0, 0.3, 10.0, 1, nan), "offset");
  // No tone k / duration, k >= 1, fits under the bandwidth.
  CHECK_INVALID(excitation::smooth_random(0.05, 0.3, 10.0, 1), "bandwidth_hz");
  CHECK_THROWS_WITH(excitation::smooth_random(0.05, 0.3, 10.0, 1), Contains("duration"));

  CHECK_INVALID(excitation::chirp(nan, 1.0, 10.0, 0.3), "f0_hz");
  CHECK_INVALID(excitation::chirp(-0.1, 1.0, 10.0, 0.3), "f0_hz");
  CHECK_INVALID(excitation::chirp(0.1, inf, 10.0, 0.3), "f1_hz");
  CHECK_INVALID(excitation::chirp(0.1, -1.0, 10.0, 0.3), "f1_hz");
  CHECK_INVALID(excitation::chirp(0.1, 1.0, 0.0, 0.3), "duration");
  CHECK_INVALID(excitation::chirp(0.1, 1.0, nan, 0.3), "duration");
  CHECK_INVALID(excitation::chirp(0.1, 1.0, 10.0, nan), "amplitude");
  CHECK_INVALID(excitation::chirp(0.1, 1.0, 10.0, 0.3, inf), "offset");

  CHECK_INVALID(excitation::sampled(Eigen::VectorXd(), 0.01), "values must not be empty");
  CHECK_INVALID(excitation::sampled(vec({1.0, nan}), 0.01), "values");
  CHECK_INVALID(excitation::sampled(vec({1.0, inf}), 0.01), "values");
  CHECK_INVALID(excitation::sampled(vec({1.0}), 0.0), "ts");
  CHECK_INVALID(excitation::sampled(vec({1.0}), -0.01), "ts");
  CHECK_INVALID(excitation::sampled(vec({1.0}), nan), "ts");
  CHECK_INVALID(excitation::sampled(vec({1.0}), 0.01, inf), "t0");
}
