// Bad input, tried everywhere: each TEST_CASE backs the rows of docs/reference/bad_input.md whose IDs start
// its name (M = models and blocks, E = estimator and identify, S = metrics and signals, J = JSON
// model files; the plant's rows are in plant_bad_input.test.cpp, which links bonl::plant). Every
// case checks the exception's type and that its message names what was wrong. The last cases check
// that the caller's arrays are never modified.

#include <bonl/bonl.hpp>
#include <bonl/io.hpp>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <initializer_list>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "bad_input_cases.hpp"
#include "compiled_once.hpp"

namespace {

using Catch::Matchers::Contains;

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();
constexpr Eigen::Index kHuge = std::numeric_limits<Eigen::Index>::max();

/// A step schedule: `initial` for `initial_samples` samples, then `final`.
bonl::ForgettingSchedule steps(double initial, Eigen::Index initial_samples, double final) {
  bonl::ForgettingSchedule schedule;
  schedule.initial = initial;
  schedule.initial_samples = initial_samples;
  schedule.final = final;
  return schedule;
}

using bonl_test::Case;
using bonl_test::check_cases;
using bonl_test::quoted_model_names;
using bonl_test::vec;

const Eigen::VectorXd kF = vec({0.01, 0.8, 0.1});  // an input polynomial for the block tests

/// The small known system of Model (tests/data/known_systems.json, set "small": na = 2, nb = 1,
/// nk = 2, r = 2, r1 = 3), as the Python bad-input tests have it too.
template <class Model>
Model known() {
  return bonl_test::known_system<Model>("small");
}

/// Calls f(model, name) for the small known system of each model of bonl::Models.
template <class F>
void for_each_model(F&& f) {
  bonl::for_each_model(bonl::Models{}, [&](auto tag) {
    using Model = typename decltype(tag)::type;
    f(known<Model>(), Model::kName);
  });
}

Eigen::VectorXd input(Eigen::Index n, std::uint64_t seed) { return bonl::signals::random_levels(n, 3, 1.0, seed); }

bool same_bytes(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return a.size() == b.size() &&
         std::memcmp(a.data(), b.data(), static_cast<std::size_t>(a.size()) * sizeof(double)) == 0;
}

}  // namespace

// --- Models and blocks ---------------------------------------------------------------------------

TEST_CASE("M1 an order below its minimum is rejected, naming the order", "[bad_input][models]") {
  check_cases<std::invalid_argument>({
      {"ARX na = 0", [] { bonl::ARXd(0, 1, 1); }, "na must be >= 1, got 0"},
      {"ARX na = -3", [] { bonl::ARXd(-3, 1, 1); }, "na must be >= 1, got -3"},
      {"ARX nb = -1", [] { bonl::ARXd(1, -1, 1); }, "nb must be >= 0, got -1"},
      {"ARX nk = -1", [] { bonl::ARXd(1, 1, -1); }, "nk must be >= 0, got -1"},
      {"Hammerstein na = 0", [] { bonl::Hammersteind(0, 1, 1, 1); }, "na must be >= 1, got 0"},
      {"Hammerstein nb = -2", [] { bonl::Hammersteind(1, -2, 1, 1); }, "nb must be >= 0, got -2"},
      {"Hammerstein nk = -1", [] { bonl::Hammersteind(1, 1, -1, 1); }, "nk must be >= 0, got -1"},
      {"Hammerstein r = 0", [] { bonl::Hammersteind(1, 1, 1, 0); }, "r must be >= 1, got 0"},
      {"H-W na = 0", [] { bonl::HammersteinWienerd(0, 1, 1, 2, 2); }, "na must be >= 1, got 0"},
      {"H-W r = -1", [] { bonl::HammersteinWienerd(1, 1, 1, -1, 2); }, "r must be >= 1, got -1"},
      {"H-W r1 = 1", [] { bonl::HammersteinWienerd(1, 1, 1, 2, 1); },
       "r1 (output polynomial degree) must be >= 2, got 1"},
      {"H-W r1 = 0", [] { bonl::HammersteinWienerd(1, 1, 1, 2, 0); },
       "r1 (output polynomial degree) must be >= 2, got 0"},
      {"P-H-W na = -1", [] { bonl::PseudoHammersteinWienerd(-1, 1, 1, 2); }, "na must be >= 1, got -1"},
      {"P-H-W nk = -5", [] { bonl::PseudoHammersteinWienerd(1, 1, -5, 2); }, "nk must be >= 0, got -5"},
      {"P-H-W r = 0", [] { bonl::PseudoHammersteinWienerd(1, 1, 1, 0); }, "r must be >= 1, got 0"},
  });
}

TEST_CASE("M2 an order above 10^6 is rejected before anything is allocated", "[bad_input][models]") {
  // Before: std::bad_alloc for 10^12, and sizes such as nk + nb + 1 overflowed for INT64_MAX.
  check_cases<std::invalid_argument>({
      {"ARX na = 10^6 + 1", [] { bonl::ARXd(1000001, 1, 1); }, "na must be <= 1000000, got 1000001"},
      {"ARX nk = INT64_MAX", [] { bonl::ARXd(1, 1, kHuge); }, "nk must be <= 1000000, got 9223372036854775807"},
      {"Hammerstein nb = INT64_MAX", [] { bonl::Hammersteind(1, kHuge, 1, 1); }, "nb must be <= 1000000"},
      {"Hammerstein na = 10^12", [] { bonl::Hammersteind(1000000000000, 1, 1, 1); }, "na must be <= 1000000"},
      {"H-W r = 10^12", [] { bonl::HammersteinWienerd(1, 1, 1, 1000000000000, 2); }, "r must be <= 1000000"},
      {"P-H-W nk = INT64_MAX", [] { bonl::PseudoHammersteinWienerd(1, 1, kHuge, 1); }, "nk must be <= 1000000"},
  });
  // The limit itself is accepted, and works: with a delay of 10^6 samples, the first outputs are 0.
  const bonl::ARXd delayed(1, 0, bonl::detail::kMaxOrder);
  CHECK(delayed.simulate(vec({1.0, 1.0, 1.0})) == Eigen::VectorXd::Zero(3));
}

TEST_CASE("M3 r1 above 32 is rejected", "[bad_input][models]") {
  check_cases<std::invalid_argument>({
      {"r1 = 33", [] { bonl::HammersteinWienerd(1, 1, 1, 2, 33); }, "r1 (output polynomial degree) must be <= 32"},
  });
  CHECK(bonl::HammersteinWienerd(1, 1, 1, 2, 32).num_params() == 2 * 3 + 1 + 1 + 31);
}

TEST_CASE("M4 a run-time order that differs from the compile-time one is rejected", "[bad_input][models]") {
  check_cases<std::invalid_argument>({
      {"P-H-W na", [] { bonl::PaperPseudoHammersteinWiener(2, 2, 8, 3); },
       "na = 2 does not match the compile-time order 3"},
      {"Hammerstein r", [] { bonl::Hammerstein<double, 3, 2, 3>(3, 2, 8, 2); },
       "r = 2 does not match the compile-time order 3"},
      {"ARX nb", [] { bonl::ARX<double, 3, 2>(3, 1, 8); }, "nb = 1 does not match the compile-time order 2"},
      {"H-W r1", [] { bonl::PaperHammersteinWiener(3, 2, 8, 3, 4); }, "r1 = 4 does not match the compile-time order 3"},
  });
}

TEST_CASE("M6 a parameter vector of the wrong length is rejected, naming it and both lengths", "[bad_input][models]") {
  bonl::ARXd a = known<bonl::ARXd>();
  bonl::Hammersteind h = known<bonl::Hammersteind>();
  bonl::HammersteinWienerd hw = known<bonl::HammersteinWienerd>();
  bonl::PseudoHammersteinWienerd p = known<bonl::PseudoHammersteinWienerd>();
  check_cases<std::invalid_argument>({
      {"ARX b", [&] { a.set_b(vec({1.0})); }, "b must have 2 entries, got 1"},
      {"ARX a",
       [&] {
         a.set_a(vec({0.1, 0.2, 0.3}));
       },
       "a must have 2 entries, got 3"},
      {"ARX theta", [&] { a.set_theta(Eigen::VectorXd::Zero(0)); }, "theta must have 4 entries, got 0"},
      {"Hammerstein f",
       [&] {
         h.set_f(vec({1.0, 2.0}));
       },
       "f must have 3 entries, got 2"},
      {"Hammerstein p", [&] { h.set_p(Eigen::VectorXd::Zero(4)); }, "p must have 3 entries, got 4"},
      {"Hammerstein b", [&] { h.set_b(vec({1.0})); }, "b must have 2 entries, got 1"},
      {"H-W q",
       [&] {
         hw.set_q(vec({1.0, 0.1}));
       },
       "q must have 3 entries, got 2"},
      {"H-W theta", [&] { hw.set_theta(Eigen::VectorXd::Zero(3)); }, "theta must have 11 entries, got 3"},
      {"P-H-W a", [&] { p.set_a(vec({0.1})); }, "a must have 2 entries, got 1"},
      {"P-H-W theta", [&] { p.set_theta(Eigen::VectorXd::Zero(11)); }, "theta must have 10 entries, got 11"},
  });
  // A rejected setter leaves the model as it was.
  CHECK(a.theta() == known<bonl::ARXd>().theta());
  CHECK(h.theta() == known<bonl::Hammersteind>().theta());
  CHECK(hw.theta() == known<bonl::HammersteinWienerd>().theta());
  CHECK(p.theta() == known<bonl::PseudoHammersteinWienerd>().theta());
}

TEST_CASE("M7 a NaN or infinite parameter is rejected with its index", "[bad_input][models]") {
  bonl::ARXd a = known<bonl::ARXd>();
  bonl::Hammersteind h = known<bonl::Hammersteind>();
  bonl::HammersteinWienerd hw = known<bonl::HammersteinWienerd>();
  bonl::PseudoHammersteinWienerd p = known<bonl::PseudoHammersteinWienerd>();
  Eigen::VectorXd theta = p.theta();
  theta[9] = kInf;
  check_cases<std::invalid_argument>({
      {"ARX a NaN",
       [&] {
         a.set_a(vec({0.1, kNaN}));
       },
       "a has a non-finite value at index 1"},
      {"ARX b inf",
       [&] {
         a.set_b(vec({-kInf, 0.0}));
       },
       "b has a non-finite value at index 0"},
      {"Hammerstein f NaN",
       [&] {
         h.set_f(vec({0.0, kNaN, 0.0}));
       },
       "f has a non-finite value at index 1"},
      {"Hammerstein p inf",
       [&] {
         h.set_p(vec({0.0, 0.0, kInf}));
       },
       "p has a non-finite value at index 2"},
      {"Hammerstein b NaN",
       [&] {
         h.set_b(vec({1.0, kNaN}));
       },
       "b has a non-finite value at index 1"},
      {"H-W q NaN",
       [&] {
         hw.set_q(vec({1.0, kNaN, 0.0}));
       },
       "q has a non-finite value at index 1"},
      {"P-H-W theta inf", [&] { p.set_theta(theta); }, "theta has a non-finite value at index 9"},
  });
  CHECK(p.theta() == known<bonl::PseudoHammersteinWienerd>().theta());
  CHECK(h.theta() == known<bonl::Hammersteind>().theta());
}

TEST_CASE("M8 b_0 and q_1 other than 1 are rejected (the normalisation)", "[bad_input][models]") {
  bonl::Hammersteind h = known<bonl::Hammersteind>();
  bonl::HammersteinWienerd hw = known<bonl::HammersteinWienerd>();
  bonl::PseudoHammersteinWienerd p = known<bonl::PseudoHammersteinWienerd>();
  check_cases<std::invalid_argument>({
      {"Hammerstein b_0 = 0.5",
       [&] {
         h.set_b(vec({0.5, 0.1}));
       },
       "b[0] (b_0) must be 1"},
      {"P-H-W b_0 = 0",
       [&] {
         p.set_b(vec({0.0, 0.1}));
       },
       "b[0] (b_0) must be 1"},
      {"H-W q_1 = 2",
       [&] {
         hw.set_q(vec({2.0, 0.0, 0.0}));
       },
       "q[0] (q_1) must be 1"},
  });
  // ARX keeps b_0 free.
  bonl::ARXd a = known<bonl::ARXd>();
  a.set_b(vec({0.5, 0.1}));
  CHECK(a.b() == vec({0.5, 0.1}));
}

TEST_CASE("M9 a negative or non-finite backlash half-width c is rejected", "[bad_input][models]") {
  bonl::PseudoHammersteinWienerd p = known<bonl::PseudoHammersteinWienerd>();
  std::vector<Case> cases;
  for (double c : {-0.1, -kInf, kNaN, kInf}) {
    cases.push_back(
        {"c = " + std::to_string(c), [&p, c] { p.set_c(c); }, "c (backlash half-width) must be finite and >= 0"});
  }
  check_cases<std::invalid_argument>(cases);
  CHECK(p.c() == 0.05);
  p.set_c(0.0);  // no backlash at all is a valid model
  CHECK(p.c() == 0.0);

  // The whole parameter vector: the same rule for its last entry (before: accepted, and the model
  // then wrote JSON that the reader rejects).
  Eigen::VectorXd theta = known<bonl::PseudoHammersteinWienerd>().theta();
  theta[theta.size() - 1] = -0.1;
  check_cases<std::invalid_argument>({{"set_theta with c = -0.1", [&p, &theta] { p.set_theta(theta); },
                                       "theta: c (the last entry, the backlash half-width) must be >= 0, got -0.1"}});
  CHECK(p.c() == 0.0);  // untouched
  // An estimate with c < 0 (the paper method's can have one) becomes a model with c = 0, which is
  // how it simulates.
  bonl::Estimator<bonl::PseudoHammersteinWienerd> estimator(known<bonl::PseudoHammersteinWienerd>());
  estimator.reset(theta);
  CHECK(estimator.theta()[theta.size() - 1] == -0.1);
  CHECK(estimator.model().c() == 0.0);
}

TEST_CASE("M11 blocks reject bad orders and parameters", "[bad_input][blocks]") {
  bonl::LinearBlock<double> linear(1, 0, 0);
  bonl::OutputPolynomial<double> output(2);
  bonl::Backlash<double> play(0.1);
  check_cases<std::invalid_argument>({
      {"Backlash c < 0", [] { bonl::Backlash<double>(-1.0); }, "backlash half-width c must be finite and >= 0, got -1"},
      {"Backlash set_c NaN", [&] { play.set_c(kNaN); }, "backlash half-width c must be finite and >= 0, got nan"},
      {"GeneralBacklash c_left < 0", [] { bonl::GeneralBacklash<double>(-1.0, 0.0); },
       "c_left must be finite and >= 0"},
      {"GeneralBacklash c_right NaN", [] { bonl::GeneralBacklash<double>(0.0, kNaN); },
       "c_right must be finite and >= 0"},
      {"GeneralBacklash slope 0", [] { bonl::GeneralBacklash<double>(0.1, 0.1, 0.0); },
       "slope m must be finite and > 0"},
      {"GeneralBacklash y0 inf", [] { bonl::GeneralBacklash<double>(0.1, 0.1, 1.0, kInf); },
       "initial output y0 must be finite"},
      {"TwoSegmentPolynomial r = 0", [] { bonl::TwoSegmentPolynomial<double>(0); },
       "r (input polynomial degree) must be >= 1, got 0"},
      // Before: "r (input polynomial degree) must be >= 1, got -1", for an r the caller never gave.
      {"TwoSegmentPolynomial empty f",
       [] { bonl::TwoSegmentPolynomial<double>(Eigen::VectorXd(0), Eigen::VectorXd(0)); },
       "f must have at least 2 entries (f_0..f_r, degree r >= 1), got 0"},
      {"TwoSegmentPolynomial f, p lengths",
       [] {
         bonl::TwoSegmentPolynomial<double>(kF, vec({0.0, 0.0}));
       },
       "p must have 3 entries, got 2"},
      {"OutputPolynomial r1 = 0", [] { bonl::OutputPolynomial<double>(0); },
       "r1 (output polynomial degree) must be >= 1, got 0"},
      {"OutputPolynomial q NaN",
       [&] {
         output.set_q(vec({1.0, kNaN}));
       },
       "q has a non-finite value at index 1"},
      {"LinearBlock na = 0", [] { bonl::LinearBlock<double>(0, 0, 0); }, "na must be >= 1, got 0"},
      {"LinearBlock nk = INT64_MAX", [] { bonl::LinearBlock<double>(1, 0, kHuge); }, "nk must be <= 1000000"},
      {"LinearBlock a length",
       [&] {
         linear.set_a(vec({0.1, 0.2}));
       },
       "a must have 1 entries, got 2"},
  });
  CHECK(play.c() == 0.1);
}

TEST_CASE("M12 simulate rejects a NaN or infinite input sample, naming its index", "[bad_input][models]") {
  for_each_model([](const auto& model, const char* name) {
    INFO(name);
    Eigen::VectorXd u = input(20, 3);
    u[4] = kNaN;
    CHECK_THROWS_AS(model.simulate(u), std::invalid_argument);
    CHECK_THROWS_WITH(model.simulate(u), Contains("u has a non-finite value at index 4"));
    u[4] = 0.0;
    u[19] = -kInf;
    CHECK_THROWS_WITH(model.simulate(u), Contains("u has a non-finite value at index 19"));
  });
}

TEST_CASE("M13 simulating an unstable model is a NumericalError, not infinities", "[bad_input][models]") {
  const Eigen::VectorXd u = Eigen::VectorXd::Ones(3000);  // 2^3000 overflows
  for_each_model([&u](auto model, const char* name) {
    INFO(name);
    bonl::detail::set_denominator(model, 0, vec({-2.0, 0.0}));  // a pole at 2
    CHECK_THROWS_AS(model.simulate(u), bonl::NumericalError);
    CHECK_THROWS_WITH(model.simulate(u), Contains("simulation left the finite numbers (an unstable model?)"));
    // The same model on a short record is fine: the error is the overflow, not the model. (Short: a
    // feedback of the output's square grows the output faster than the pole alone.)
    CHECK(model.simulate(u.head(10)).allFinite());
  });
}

TEST_CASE("M14 predict rejects u and y of different lengths, and non-finite samples", "[bad_input][models]") {
  for_each_model([](const auto& model, const char* name) {
    INFO(name);
    const Eigen::VectorXd u = input(20, 4);
    const Eigen::VectorXd y = model.simulate(u);
    Eigen::VectorXd bad_y = y;
    bad_y[3] = kNaN;
    Eigen::VectorXd bad_u = u;
    bad_u[7] = kInf;
    check_cases<std::invalid_argument>({
        {"y shorter", [&] { model.predict(u, y.head(19)); }, "u and y must have the same length, got 20 and 19"},
        {"u empty", [&] { model.predict(u.head(0), y); }, "u and y must have the same length, got 0 and 20"},
        {"y NaN", [&] { model.predict(u, bad_y); }, "y has a non-finite value at index 3"},
        {"u inf", [&] { model.predict(bad_u, y); }, "u has a non-finite value at index 7"},
    });
  });
}

TEST_CASE("M15 empty records are not an error: simulate and predict return empty outputs", "[bad_input][models]") {
  for_each_model([](const auto& model, const char* name) {
    INFO(name);
    const Eigen::VectorXd empty(0);
    CHECK(model.simulate(empty).size() == 0);
    CHECK(model.predict(empty, empty).size() == 0);
  });
}

// --- Estimator and identify ----------------------------------------------------------------------

TEST_CASE("E1-E3 identify rejects mismatched, too short and non-finite records", "[bad_input][estimator]") {
  for_each_model([](const auto& model, const char* name) {
    INFO(name);
    const Eigen::VectorXd u = input(200, 5);
    const Eigen::VectorXd y = model.simulate(u);
    const Eigen::Index n = model.num_params();
    const std::string too_short = "the record must be longer than the number of parameters (" + std::to_string(n) + ")";
    Eigen::VectorXd bad_u = u;
    bad_u[3] = kNaN;
    Eigen::VectorXd bad_y = y;
    bad_y[17] = kInf;
    check_cases<std::invalid_argument>({
        {"E1 y shorter", [&] { bonl::identify(model, u, y.head(199)); },
         "u and y must have the same length, got 200 and 199"},
        {"E1 u empty", [&] { bonl::identify(model, u.head(0), y); },
         "u and y must have the same length, got 0 and 200"},
        {"E2 n samples", [&] { bonl::identify(model, u.head(n), y.head(n)); },
         too_short + ", got " + std::to_string(n) + " samples"},
        {"E2 empty", [&] { bonl::identify(model, u.head(0), y.head(0)); }, too_short + ", got 0 samples"},
        {"E3 u NaN", [&] { bonl::identify(model, bad_u, y); }, "u has a non-finite value at index 3"},
        {"E3 y inf", [&] { bonl::identify(model, u, bad_y); }, "y has a non-finite value at index 17"},
    });
    // One sample more than the parameters is enough to run.
    CHECK(bonl::identify(model, u.head(n + 1), y.head(n + 1)).theta().allFinite());
  });
}

TEST_CASE("E4-E11 identify and Estimator reject settings out of range", "[bad_input][estimator]") {
  const bonl::PseudoHammersteinWienerd model = known<bonl::PseudoHammersteinWienerd>();
  const Eigen::VectorXd u = input(100, 6);
  const Eigen::VectorXd y = model.simulate(u);
  const auto with = [](auto change) {
    bonl::IdentifyOptions options;
    change(options);
    return options;
  };
  std::vector<Case> cases = {
      {"E4 passes 0", [&] { bonl::identify(model, u, y, with([](auto& o) { o.passes = 0; })); },
       "passes must be >= 1, got 0"},
      {"E4 passes -1", [&] { bonl::identify(model, u, y, with([](auto& o) { o.passes = -1; })); },
       "passes must be >= 1, got -1"},
      {"E5 refine_iterations -1", [&] { bonl::identify(model, u, y, with([](auto& o) { o.refine_iterations = -1; })); },
       "refine_iterations must be >= 0"},
      {"E7 initial_samples -1",
       [&] { bonl::identify(model, u, y, with([](auto& o) { o.forgetting = steps(0.98, -1, 1.0); })); },
       "initial_samples must be >= 0"},
      {"E11 internal_refresh 0", [&] { bonl::identify(model, u, y, with([](auto& o) { o.internal_refresh = 0; })); },
       "internal_refresh must be >= 1"},
  };
  for (double lambda : {0.0, -0.5, 1.01, kNaN, kInf}) {
    const std::string what = "E6 lambda " + std::to_string(lambda);
    cases.push_back({what + " constant",
                     [&, lambda] {
                       bonl::identify(model, u, y, with([lambda](auto& o) {
                                        o.forgetting = bonl::ForgettingSchedule::constant(lambda);
                                      }));
                     },
                     "forgetting factor must be in (0, 1]"});
    cases.push_back({what + " initial",
                     [&, lambda] {
                       bonl::identify(model, u, y, with([lambda](auto& o) { o.forgetting = steps(lambda, 200, 1.0); }));
                     },
                     "forgetting factor must be in (0, 1]"});
    cases.push_back({what + " final, Estimator",
                     [&, lambda] {
                       bonl::EstimatorOptions options;
                       options.forgetting = steps(0.98, 200, lambda);
                       bonl::Estimator<bonl::PseudoHammersteinWienerd> estimator(model, options);
                     },
                     "forgetting factor must be in (0, 1]"});
  }
  for (double p0 : {0.0, -1.0, kNaN, kInf}) {
    cases.push_back({"E9 p0 " + std::to_string(p0),
                     [&, p0] { bonl::identify(model, u, y, with([p0](auto& o) { o.p0 = p0; })); },
                     "p0 (initial covariance scale) must be finite and > 0"});
    cases.push_back({"E9 p0 " + std::to_string(p0) + ", Estimator",
                     [&, p0] {
                       bonl::EstimatorOptions options;
                       options.p0 = p0;
                       bonl::Estimator<bonl::PseudoHammersteinWienerd> estimator(model, options);
                     },
                     "p0 (initial covariance scale) must be finite and > 0"});
  }
  // c0 and backlash_hold are the P-H-W model's own settings (BacklashEstimatorSettings).
  const auto settings_with = [](double c0, Eigen::Index hold) {
    bonl::PseudoHammersteinWienerd::EstimatorSettings settings;
    settings.c0 = c0;
    settings.backlash_hold = hold;
    return settings;
  };
  for (double c0 : {-0.01, kNaN, kInf}) {
    cases.push_back({"E10 c0 " + std::to_string(c0),
                     [&, c0] { bonl::identify(model, u, y, bonl::IdentifyOptions{}, settings_with(c0, 200)); },
                     "c0 (initial backlash half-width) must be finite and >= 0"});
    cases.push_back(
        {"E10 c0 " + std::to_string(c0) + ", Estimator",
         [&, c0] { bonl::Estimator<bonl::PseudoHammersteinWienerd> estimator(model, {}, settings_with(c0, 200)); },
         "c0 (initial backlash half-width) must be finite and >= 0"});
  }
  cases.push_back({"E10 backlash_hold -1",
                   [&] { bonl::identify(model, u, y, bonl::IdentifyOptions{}, settings_with(0.01, -1)); },
                   "backlash_hold must be >= 0"});
  check_cases<std::invalid_argument>(cases);
  // The boundaries are accepted: lambda = 1, c0 = 0, backlash_hold = 0, initial_samples = 0.
  CHECK(bonl::identify(model, u, y, with([](auto& o) {
                         o.forgetting = bonl::ForgettingSchedule::constant(1.0);
                         o.refine_iterations = 0;
                       }),
                       settings_with(0.0, 0))
            .theta()
            .allFinite());
}

TEST_CASE("E17 estimate_recursively and refine_output_error check their record and settings",
          "[bad_input][estimator]") {
  const bonl::Hammersteind model = known<bonl::Hammersteind>();
  const Eigen::VectorXd u = bonl::signals::random_levels(200, 5, 1.0, 7);
  const Eigen::VectorXd y = model.simulate(u);
  Eigen::VectorXd with_nan = y;
  with_nan[17] = kNaN;
  bonl::IdentifyOptions options;
  bonl::IdentifyOptions no_passes;
  no_passes.passes = 0;
  // Before: y shorter than u was read past its end, a NaN was skipped silently (or made the
  // refinement return its start unchanged), and passes = 0 returned the all-zero start.
  check_cases<std::invalid_argument>({
      {"estimate_recursively, y shorter", [&] { bonl::estimate_recursively(model, u, y.head(150), options); },
       "u and y must have the same length, got 200 and 150"},
      {"estimate_recursively, NaN", [&] { bonl::estimate_recursively(model, u, with_nan, options); },
       "y has a non-finite value at index 17"},
      {"estimate_recursively, too short", [&] { bonl::estimate_recursively(model, u.head(5), y.head(5), options); },
       "the record must be longer than the number of parameters"},
      {"estimate_recursively, passes = 0", [&] { bonl::estimate_recursively(model, u, y, no_passes); },
       "passes must be >= 1, got 0"},
      {"refine_output_error, y shorter", [&] { bonl::refine_output_error(model, u, y.head(150)); },
       "u and y must have the same length, got 200 and 150"},
      {"refine_output_error, NaN", [&] { bonl::refine_output_error(model, u, with_nan); },
       "y has a non-finite value at index 17"},
      {"refine_output_error, max_iterations < 0", [&] { bonl::refine_output_error(model, u, y, -1); },
       "max_iterations must be >= 0, got -1"},
  });
}

TEST_CASE("E18 the safeguard options and the recording capacity are checked", "[bad_input][estimator]") {
  bonl::EstimatorOptions low_ceiling;
  low_ceiling.trace_ceiling = 0.5;
  bonl::EstimatorOptions nan_ceiling;
  nan_ceiling.trace_ceiling = kNaN;
  bonl::EstimatorOptions negative_recover;
  negative_recover.recover_after = -1;
  bonl::Estimator<bonl::ARXd> estimator(known<bonl::ARXd>());
  check_cases<std::invalid_argument>({
      {"trace_ceiling 0.5", [&] { bonl::Estimator<bonl::ARXd>(known<bonl::ARXd>(), low_ceiling); },
       "trace_ceiling must be >= 1 (a multiple of trace(P(0))) or infinity, got 0.5"},
      {"trace_ceiling NaN", [&] { bonl::Estimator<bonl::ARXd>(known<bonl::ARXd>(), nan_ceiling); },
       "trace_ceiling must be >= 1"},
      {"recover_after -1", [&] { bonl::Estimator<bonl::ARXd>(known<bonl::ARXd>(), negative_recover); },
       "recover_after must be >= 0"},
      {"start_recording(0)", [&] { estimator.start_recording(0); }, "recording capacity must be >= 1"},
  });
}

TEST_CASE("E12 a model with more than 10^6 parameters cannot get an estimator", "[bad_input][estimator]") {
  // na = 10^6 is a valid order, but its estimator would need a 10^6 x 10^6 covariance.
  const bonl::Hammersteind big(bonl::detail::kMaxOrder, 0, 0, 1);
  CHECK_THROWS_AS(bonl::Estimator<bonl::Hammersteind>(big), std::invalid_argument);
  CHECK_THROWS_WITH(bonl::Estimator<bonl::Hammersteind>(big),
                    Contains("number of parameters must be <= 1000000, got 1000004"));
}

TEST_CASE("E14 a non-finite sample in Estimator::update is refused and leaves no trace", "[bad_input][estimator]") {
  for_each_model([](const auto& model, const char* name) {
    using Model = std::decay_t<decltype(model)>;
    for (bonl::Method method : {bonl::Method::OutputError, bonl::Method::EquationError, bonl::Method::Paper}) {
      INFO(name << ", method " << bonl::to_string(method));
      const Eigen::VectorXd u = input(300, 7);
      const Eigen::VectorXd y = model.simulate(u);
      bonl::EstimatorOptions options;
      options.method = method;
      bonl::Estimator<Model> clean(model, options);
      bonl::Estimator<Model> disturbed(model, options);
      for (Eigen::Index k = 0; k < u.size(); ++k) {
        if (k % 50 == 25) {
          const Eigen::VectorXd theta = disturbed.theta();
          const Eigen::MatrixXd p = disturbed.covariance();
          for (const auto& [bad_u, bad_y] : {std::pair{kNaN, y[k]}, std::pair{u[k], kInf}, std::pair{-kInf, kNaN}}) {
            REQUIRE(disturbed.update(bad_u, bad_y) == bonl::UpdateStatus::RejectedNonFinite);
          }
          REQUIRE(disturbed.theta() == theta);
          REQUIRE(disturbed.covariance() == p);
          REQUIRE(disturbed.samples() == clean.samples());
          REQUIRE(disturbed.pending_samples() == clean.pending_samples());
        }
        clean.update(u[k], y[k]);
        disturbed.update(u[k], y[k]);
      }
      CHECK(disturbed.theta() == clean.theta());
      CHECK(disturbed.covariance() == clean.covariance());
    }
  });
}

TEST_CASE("E15 Estimator::reset with a wrong-length or non-finite start is rejected", "[bad_input][estimator]") {
  const bonl::HammersteinWienerd model = known<bonl::HammersteinWienerd>();
  bonl::Estimator<bonl::HammersteinWienerd> estimator(model);
  estimator.update(0.5, 0.1);
  const Eigen::VectorXd theta = estimator.theta();
  const Eigen::Index pending = estimator.pending_samples();
  Eigen::VectorXd start = Eigen::VectorXd::Zero(model.num_params());
  start[4] = kNaN;
  check_cases<std::invalid_argument>({
      {"one entry", [&] { estimator.reset(vec({1.0})); }, "theta0 must have 11 entries, got 1"},
      {"NaN", [&] { estimator.reset(start); }, "theta0 has a non-finite value at index 4"},
  });
  CHECK(estimator.theta() == theta);
  CHECK(estimator.pending_samples() == pending);
  CHECK(estimator.measuring_scale());
}

// --- Metrics and signals -------------------------------------------------------------------------

TEST_CASE("S1-S3 metrics reject mismatched, empty and non-finite data", "[bad_input][metrics]") {
  using Metric = double (*)(const Eigen::MatrixBase<Eigen::VectorXd>&, const Eigen::MatrixBase<Eigen::VectorXd>&);
  const std::vector<std::pair<const char*, Metric>> metrics = {
      {"mse", &bonl::metrics::mse<Eigen::VectorXd, Eigen::VectorXd>},
      {"rmse", &bonl::metrics::rmse<Eigen::VectorXd, Eigen::VectorXd>},
      {"nrmse", &bonl::metrics::nrmse<Eigen::VectorXd, Eigen::VectorXd>},
      {"fit_percent", &bonl::metrics::fit_percent<Eigen::VectorXd, Eigen::VectorXd>},
  };
  const Eigen::VectorXd y = vec({1.0, 2.0, 4.0});
  const Eigen::VectorXd empty(0);
  for (const auto& [name, metric] : metrics) {
    INFO(name);
    check_cases<std::invalid_argument>({
        {"S1 lengths",
         [&, metric = metric] {
           metric(y, vec({1.0, 2.0, 3.0, 4.0}));
         },
         "y and yhat must have the same length, got 3 and 4"},
        {"S2 empty", [&, metric = metric] { metric(empty, empty); }, "y must not be empty"},
        {"S3 yhat NaN",
         [&, metric = metric] {
           metric(y, vec({1.0, kNaN, 3.0}));
         },
         "yhat has a non-finite value at index 1"},
        {"S3 y inf",
         [&, metric = metric] {
           metric(vec({1.0, 2.0, kInf}), y);
         },
         "y has a non-finite value at index 2"},
    });
  }
  check_cases<std::invalid_argument>({
      {"S1 scores", [&] { bonl::metrics::scores(y, empty); }, "y and yhat must have the same length, got 3 and 0"},
  });
}

TEST_CASE("S4 the normalised error of a constant y is an error, even when its mean rounds", "[bad_input][metrics]") {
  // Before: for y = (0.1, 0.1, 0.1) the mean rounds to 0.10000000000000002, and nrmse returned 7.2e15.
  const Eigen::VectorXd yhat = Eigen::VectorXd::Zero(3);
  check_cases<std::invalid_argument>({
      {"ones", [&] { bonl::metrics::nrmse(Eigen::VectorXd::Ones(3), yhat); },
       "y is constant: the normalised error is undefined"},
      {"0.1", [&] { bonl::metrics::nrmse(Eigen::VectorXd::Constant(3, 0.1), yhat); }, "y is constant"},
      {"0.1 fit", [&] { bonl::metrics::fit_percent(Eigen::VectorXd::Constant(3, 0.1), yhat); }, "y is constant"},
      {"scores", [&] { bonl::metrics::scores(Eigen::VectorXd::Constant(7, -0.3), Eigen::VectorXd::Zero(7)); },
       "y is constant"},
  });
}

TEST_CASE("S5-S6 metrics of data near the ends of double's range are numbers, not NaN or inf", "[bad_input][metrics]") {
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(2);
  // Before: nrmse returned NaN (inf / inf) for 1e200 and called 1e-200 "constant" (its squares underflow).
  CHECK(bonl::metrics::nrmse(vec({1e200, -1e200}), zero) == 1.0);
  CHECK(bonl::metrics::nrmse(vec({1e-200, -1e-200}), zero) == 1.0);
  CHECK(bonl::metrics::fit_percent(vec({3e-300, -1e-300}), vec({1e-300, -1e-300})) ==
        Approx(100.0 * (1.0 - 1.0 / std::sqrt(2.0))).epsilon(1e-14));
  // Before: rmse returned inf for errors of 1e200; mse overflows (1e400 is not a double) and says so.
  CHECK(bonl::metrics::rmse(vec({1e200, -1e200}), zero) == Approx(1e200).epsilon(1e-15));
  CHECK(bonl::metrics::mse(vec({1e200, -1e200}), zero) == kInf);
  CHECK(bonl::metrics::scores(vec({1e200, -1e200}), zero).rmse == Approx(1e200).epsilon(1e-15));
  // On ordinary data the scaling is exact: the plain formula's value, bit for bit.
  const Eigen::VectorXd y = input(500, 8);
  const Eigen::VectorXd yhat = y + 0.01 * input(500, 9);
  const double plain = (y - yhat).norm() / (y.array() - y.mean()).matrix().norm();
  CHECK(bonl::metrics::nrmse(y, yhat) == plain);
  CHECK(bonl::metrics::rmse(y, yhat) == std::sqrt((y - yhat).squaredNorm() / 500.0));
}

TEST_CASE("S7 simulation and prediction scores name u and y when their lengths differ", "[bad_input][metrics]") {
  // Before: simulation_scores reported "y and yhat", yhat being its own simulation.
  const bonl::ARXd model = known<bonl::ARXd>();
  check_cases<std::invalid_argument>({
      {"simulation", [&] { bonl::metrics::simulation_scores(model, input(3, 1), input(4, 2)); },
       "u and y must have the same length, got 3 and 4"},
      {"prediction", [&] { bonl::metrics::prediction_scores(model, input(3, 1), input(4, 2)); },
       "u and y must have the same length, got 3 and 4"},
  });
}

TEST_CASE("S8-S11 signal generators reject bad arguments and overflowing signals", "[bad_input][signals]") {
  const Eigen::VectorXd tones = bonl::signals::paper_tones();
  const Eigen::VectorXd phases = bonl::signals::schroeder_phases(5);
  check_cases<std::invalid_argument>({
      {"S8 n < 0", [] { bonl::signals::random_levels(-1, 1, 1.0, 1); }, "n must be >= 0"},
      {"S8 hold 0", [] { bonl::signals::random_levels(10, 0, 1.0, 1); }, "hold must be >= 1"},
      {"S8 amplitude < 0", [] { bonl::signals::random_levels(10, 1, -1.0, 1); }, "amplitude must be finite and >= 0"},
      {"S8 amplitude NaN", [] { bonl::signals::random_levels(10, 1, kNaN, 1); }, "amplitude must be finite and >= 0"},
      // Before: every level was infinite (the range 2 amplitude overflows).
      {"S8 amplitude 1e308", [] { bonl::signals::random_levels(10, 1, 1e308, 1); }, "amplitude must be <= 8.9e307"},
      {"S9 n < 0", [&] { bonl::signals::multisine(-1, 0.01, tones, 1.0, phases); }, "n must be >= 0"},
      {"S9 ts 0", [&] { bonl::signals::multisine(10, 0.0, tones, 1.0, phases); },
       "ts (sample time) must be finite and > 0"},
      {"S9 ts NaN", [&] { bonl::signals::multisine(10, kNaN, tones, 1.0, phases); },
       "ts (sample time) must be finite and > 0"},
      {"S9 lengths", [&] { bonl::signals::multisine(10, 0.01, tones, 1.0, phases.head(3)); },
       "frequencies_hz and phases must have the same length, got 5 and 3"},
      {"S9 frequency NaN", [&] { bonl::signals::multisine(10, 0.01, vec({kNaN}), 1.0, vec({0.0})); },
       "frequencies_hz has a non-finite value at index 0"},
      {"S9 phase inf", [&] { bonl::signals::multisine(10, 0.01, vec({1.0}), 1.0, vec({kInf})); },
       "phases has a non-finite value at index 0"},
      {"S9 amplitude NaN", [&] { bonl::signals::multisine(10, 0.01, tones, kNaN, phases); },
       "amplitude must be finite"},
      // Before: infinite samples (amplitude times a sum of five tones overflows), or NaN (sin(inf)).
      {"S9 amplitude 1e308",
       [] {
         bonl::signals::multisine(3, 0.01, vec({0.0, 0.0}), 1e308, vec({1.5707963267948966, 1.5707963267948966}));
       },
       "the multi-sine is not finite"},
      {"S9 frequency 1e308", [] { bonl::signals::multisine(3, 1.0, vec({1e308}), 1.0, vec({0.0})); },
       "the multi-sine is not finite"},
      {"S10 n < 0", [] { bonl::signals::white_noise(-1, 1.0, 1); }, "n must be >= 0"},
      {"S10 sigma < 0", [] { bonl::signals::white_noise(10, -1.0, 1); }, "sigma must be finite and >= 0"},
      {"S10 sigma inf", [] { bonl::signals::white_noise(10, kInf, 1); }, "sigma must be finite and >= 0"},
      // Before: samples beyond 1.8e308 were silently infinite.
      {"S10 sigma 1e308", [] { bonl::signals::white_noise(1000, 1e308, 1); }, "sigma is too large"},
      {"S11 tones 0", [] { bonl::signals::schroeder_phases(0); }, "tones must be >= 1"},
  });
  // The limits themselves work.
  const Eigen::VectorXd wide = bonl::signals::random_levels(100, 1, 8.9e307, 1);
  CHECK(wide.allFinite());
  CHECK(wide.cwiseAbs().maxCoeff() <= 8.9e307);
  CHECK(wide.cwiseAbs().maxCoeff() > 1e307);
  CHECK(bonl::signals::white_noise(0, 1.0, 1).size() == 0);
}

// --- JSON model files ----------------------------------------------------------------------------

namespace {

using Json = nlohmann::ordered_json;

Json document(const std::string& text) { return Json::parse(text); }
std::string hw_text() { return bonl::io::to_json(known<bonl::HammersteinWienerd>()); }
std::string phw_text() { return bonl::io::to_json(known<bonl::PseudoHammersteinWienerd>()); }
std::string arx_text() { return bonl::io::to_json(known<bonl::ARXd>()); }

/// The P-H-W file with one change.
template <class F>
std::string phw_with(F&& change) {
  Json d = document(phw_text());
  change(d);
  return d.dump();
}

}  // namespace

TEST_CASE("J1-J5 the reader rejects what is not a bonl model file of this version", "[bad_input][io]") {
  const std::string text = phw_text();
  std::string bad_utf8 = text;
  bad_utf8.replace(bad_utf8.find("bonl-model"), 4, "\xff\xfe\xfd\xfc");
  std::string nan_literal = text;
  nan_literal.replace(nan_literal.find("0.05"), 4, "NaN");
  std::vector<Case> cases = {
      {"J1 empty", [] { bonl::io::load_model(""); }, "bonl: model JSON: not valid JSON"},
      {"J1 truncated", [&] { bonl::io::load_model(text.substr(0, text.size() / 2)); }, "not valid JSON"},
      {"J1 trailing garbage", [&] { bonl::io::load_model(text + "x"); }, "not valid JSON"},
      {"J1 comment", [&] { bonl::io::load_model("// a model\n" + text); }, "not valid JSON"},
      // Before: the message quoted the raw byte 0xff (Python could not decode it).
      {"J1 invalid UTF-8", [&] { bonl::io::load_model(bad_utf8); }, "ill-formed UTF-8 byte; last read: '\"\\xff'"},
      {"J1 NaN literal", [&] { bonl::io::load_model(nan_literal); }, "not valid JSON"},
      {"J1 deep nesting", [] { bonl::io::load_model(std::string(100000, '[')); }, "not valid JSON"},
      {"J2 array", [] { bonl::io::load_model("[]"); }, "the document must be a JSON object, got array"},
      {"J2 number", [] { bonl::io::load_model("3"); }, "the document must be a JSON object, got number"},
      {"J2 null", [] { bonl::io::load_model("null"); }, "the document must be a JSON object, got null"},
      {"J3 no format", [] { bonl::io::load_model(phw_with([](Json& d) { d.erase("format"); })); },
       "missing key format"},
      {"J3 other format", [] { bonl::io::load_model(phw_with([](Json& d) { d["format"] = "bonl-modl"; })); },
       "format must be \"bonl-model\", got \"bonl-modl\""},
      {"J3 format number", [] { bonl::io::load_model(phw_with([](Json& d) { d["format"] = 1; })); },
       "format must be \"bonl-model\", got 1"},
      {"J4 no version", [] { bonl::io::load_model(phw_with([](Json& d) { d.erase("version"); })); },
       "missing key version"},
      {"J4 version 1.0", [] { bonl::io::load_model(phw_with([](Json& d) { d["version"] = 1.0; })); },
       "version must be an integer, got 1.0"},
      {"J4 version \"1\"", [] { bonl::io::load_model(phw_with([](Json& d) { d["version"] = "1"; })); },
       "version must be an integer, got \"1\""},
      {"J4 version 3", [] { bonl::io::load_model(phw_with([](Json& d) { d["version"] = 3; })); },
       "version 3 is newer than this bonl reads: it reads version 2"},
      {"J4 version 2^64 - 1",
       [] {
         bonl::io::load_model(phw_with([](Json& d) { d["version"] = std::numeric_limits<std::uint64_t>::max(); }));
       },
       "version 18446744073709551615 is newer than this bonl reads"},
      {"J4 version 0", [] { bonl::io::load_model(phw_with([](Json& d) { d["version"] = 0; })); },
       "version must be between 1 and 2, got 0"},
      {"J4 version -1", [] { bonl::io::load_model(phw_with([](Json& d) { d["version"] = -1; })); },
       "version must be between 1 and 2, got -1"},
      {"J17 operating_point not an object",
       [] { bonl::io::load_model(phw_with([](Json& d) { d["operating_point"] = 1.5; })); },
       "operating_point must be an object, got 1.5"},
      {"J17 operating_point.u0 not a number",
       [] { bonl::io::load_model(phw_with([](Json& d) { d["operating_point"]["u0"] = "nan"; })); },
       "operating_point.u0 must be a number"},
      {"J5 unknown model", [] { bonl::io::load_model(phw_with([](Json& d) { d["model"] = "Volterra"; })); },
       "model must be one of " + quoted_model_names() + ", got \"Volterra\""},
      {"J5 model with a hyphen",
       [] { bonl::io::load_model(phw_with([](Json& d) { d["model"] = "Pseudo-Hammerstein-Wiener"; })); },
       "model must be one of"},
      {"J5 model null", [] { bonl::io::load_model(phw_with([](Json& d) { d["model"] = nullptr; })); },
       "model must be one of " + quoted_model_names() + ", got null"},
  };
  check_cases<std::invalid_argument>(cases);
  // Every message is printable ASCII, whatever bytes the file held.
  try {
    bonl::io::load_model(bad_utf8);
  } catch (const std::invalid_argument& e) {
    for (const char c : std::string(e.what())) CHECK((c >= 0x20 && c < 0x7f));
  }
}

TEST_CASE("J6 a file of another model kind than the type asked for is rejected", "[bad_input][io]") {
  check_cases<std::invalid_argument>({
      {"ARX as Hammerstein", [] { bonl::io::model_from_json<bonl::Hammersteind>(arx_text()); },
       "model is \"ARX\", but the model type asked for is \"Hammerstein\""},
      {"H-W as P-H-W", [] { bonl::io::model_from_json<bonl::PaperPseudoHammersteinWiener>(hw_text()); },
       "model is \"HammersteinWiener\", but the model type asked for is \"PseudoHammersteinWiener\""},
  });
}

TEST_CASE("J7-J15 the reader names the key at fault", "[bad_input][io]") {
  std::string duplicate = phw_text();
  duplicate.replace(duplicate.find("\"na\":2"), 6, "\"na\":2,\"na\":3");
  const auto orders = [](const char* key, Json value) {
    return phw_with([key, value](Json& d) { d["orders"][key] = value; });
  };
  const auto param = [](const char* key, Json value) {
    return phw_with([key, value](Json& d) { d["params"][key] = value; });
  };
  const auto entry = [](const char* key, std::size_t i, Json value) {
    return phw_with([key, i, value](Json& d) { d["params"][key][i] = value; });
  };
  Json arx_with_r = document(arx_text());
  arx_with_r["orders"]["r"] = 2;
  std::string beyond_double = phw_text();
  beyond_double.replace(beyond_double.find("0.05"), 4, "1e400");
  std::string beyond_float = arx_text();
  beyond_float.replace(beyond_float.find("0.5"), 3, "1e300");
  Json hw_q = document(hw_text());
  hw_q["params"]["q"][0] = 2.0;
  Json hw_r1 = document(hw_text());
  hw_r1["orders"]["r1"] = 33;
  check_cases<std::invalid_argument>({
      {"J7 no params.c", [] { bonl::io::load_model(phw_with([](Json& d) { d["params"].erase("c"); })); },
       "missing key params.c"},
      {"J7 no orders", [] { bonl::io::load_model(phw_with([](Json& d) { d.erase("orders"); })); },
       "missing key orders"},
      {"J7 no orders.nk", [] { bonl::io::load_model(phw_with([](Json& d) { d["orders"].erase("nk"); })); },
       "missing key orders.nk"},
      {"J7 unknown top-level key", [] { bonl::io::load_model(phw_with([](Json& d) { d["comment"] = "x"; })); },
       "unknown key comment"},
      {"J7 r in an ARX file", [&] { bonl::io::load_model(arx_with_r.dump()); },
       "unknown key orders.r (expected orders keys: na, nb, nk, ni)"},
      {"J7 q in a P-H-W file", [&] { bonl::io::load_model(param("q", Json::array({1.0}))); }, "unknown key params.q"},
      {"J8 duplicate key", [&] { bonl::io::load_model(duplicate); }, "key \"na\" appears more than once in an object"},
      {"J9 na 2.0", [&] { bonl::io::load_model(orders("na", 2.0)); }, "orders.na must be an integer, got 2.0"},
      {"J9 nb true", [&] { bonl::io::load_model(orders("nb", true)); }, "orders.nb must be an integer, got true"},
      {"J9 nk \"2\"", [&] { bonl::io::load_model(orders("nk", "2")); }, "orders.nk must be an integer, got \"2\""},
      {"J9 r null", [&] { bonl::io::load_model(orders("r", nullptr)); }, "orders.r must be an integer, got null"},
      {"J9 orders array",
       [] { bonl::io::load_model(phw_with([](Json& d) {
              d["orders"] = Json::array({2, 1, 2, 2});
            })); },
       "orders must be an object, got [2,1,2,2]"},
      {"J10 na 0", [&] { bonl::io::load_model(orders("na", 0)); }, "orders.na must be between 1 and 1000000, got 0"},
      {"J10 nb -1", [&] { bonl::io::load_model(orders("nb", -1)); }, "orders.nb must be between 0 and 1000000, got -1"},
      {"J10 nk 10^6 + 1", [&] { bonl::io::load_model(orders("nk", 1000001)); },
       "orders.nk must be between 0 and 1000000"},
      {"J10 r 2^64 - 1", [&] { bonl::io::load_model(orders("r", std::numeric_limits<std::uint64_t>::max())); },
       "orders.r must be between 1 and 1000000, got 18446744073709551615"},
      {"J10 r1 33", [&] { bonl::io::load_model(hw_r1.dump()); }, "orders.r1 must be between 2 and 32, got 33"},
      // Before: "must be an integer", for an integer literal too large for 64 bits (read as a double).
      {"J10 nb 2^64",
       [] { bonl::io::load_model(phw_with([](Json& d) { d["orders"]["nb"] = 18446744073709551616.0; })); },
       "orders.nb must be between 0 and 1000000, got 1.8446744073709552e+19"},
      {"J10 na 1e300", [] { bonl::io::load_model(phw_with([](Json& d) { d["orders"]["na"] = -1e300; })); },
       "orders.na must be between 1 and 1000000, got -1e+300"},
      {"J11 compile-time na", [] { bonl::io::model_from_json<bonl::PaperPseudoHammersteinWiener>(phw_text()); },
       "orders.na = 2 does not match the model type's compile-time order 3"},
      {"J12 params array", [] { bonl::io::load_model(phw_with([](Json& d) { d["params"] = Json::array(); })); },
       "params must be an object, got []"},
      {"J12 f a number", [&] { bonl::io::load_model(param("f", 1)); }, "params.f must be an array of numbers, got 1"},
      {"J12 f too short",
       [&] {
         bonl::io::load_model(param("f", Json::array({0.0, 1.0})));
       },
       "params.f must have 3 entries, got 2"},
      {"J12 a too long",
       [&] {
         bonl::io::load_model(param("a", Json::array({0.1, 0.2, 0.3})));
       },
       "params.a must have 2 entries, got 3"},
      {"J13 a[1] a string", [&] { bonl::io::load_model(entry("a", 1, "x")); },
       "params.a[1] must be a number, got \"x\""},
      {"J13 p[0] null", [&] { bonl::io::load_model(entry("p", 0, nullptr)); },
       "params.p[0] must be a number, got null"},
      {"J13 b[1] true", [&] { bonl::io::load_model(entry("b", 1, true)); }, "params.b[1] must be a number, got true"},
      {"J13 c a string", [&] { bonl::io::load_model(param("c", "0.1")); }, "params.c must be a number, got \"0.1\""},
      {"J14 1e400", [&] { bonl::io::load_model(beyond_double); }, "a number is out of double's range"},
      {"J14 1e300 for float", [&] { bonl::io::model_from_json<bonl::ARX<float>>(beyond_float); },
       "params.b[0] = 1e+300 is out of the model's Scalar range"},
      {"J15 b_0 = 0.5", [&] { bonl::io::load_model(entry("b", 0, 0.5)); },
       "params.b[0] must be 1 (block models are normalised"},
      {"J15 q_1 = 2", [&] { bonl::io::load_model(hw_q.dump()); }, "params.q[0] must be 1 (the H-W model is normalised"},
      {"J15 c < 0", [&] { bonl::io::load_model(param("c", -0.1)); },
       "params.c (backlash half-width) must be >= 0, got -0.1"},
  });
  // Controls: the unchanged files load, as the kind they name.
  CHECK(std::get<bonl::PseudoHammersteinWienerd>(bonl::io::load_model(phw_text())).theta() ==
        known<bonl::PseudoHammersteinWienerd>().theta());
  CHECK(std::get<bonl::ARXd>(bonl::io::load_model(arx_text())).theta() == known<bonl::ARXd>().theta());
}

// --- The caller's arrays are never modified ------------------------------------------------------

TEST_CASE("A1 no entry point modifies the caller's arrays, contiguous or strided", "[bad_input][arrays]") {
  // Every input lives interleaved with sentinel values in one buffer, viewed with a stride of 2; the
  // whole buffer must be byte-identical afterwards, and the results equal those of contiguous copies.
  using Strided = Eigen::Map<const Eigen::VectorXd, 0, Eigen::InnerStride<2>>;
  for_each_model([](const auto& model, const char* name) {
    INFO(name);
    using Model = std::decay_t<decltype(model)>;
    const Eigen::Index n = 120;
    const Eigen::VectorXd u_plain = input(n, 11);
    const Eigen::VectorXd y_plain = model.simulate(u_plain) + 1e-3 * input(n, 12);
    Eigen::VectorXd buffer(4 * n);
    for (Eigen::Index k = 0; k < n; ++k) {
      buffer[2 * k] = u_plain[k];
      buffer[2 * k + 1] = -7.0;  // sentinel between the samples of u
      buffer[2 * n + 2 * k] = y_plain[k];
      buffer[2 * n + 2 * k + 1] = -9.0;
    }
    const Eigen::VectorXd before = buffer;
    const Strided u(buffer.data(), n);
    const Strided y(buffer.data() + 2 * n, n);

    CHECK(model.simulate(u) == model.simulate(u_plain));
    CHECK(model.predict(u, y) == model.predict(u_plain, y_plain));
    bonl::IdentifyOptions options;
    options.refine_iterations = 2;
    CHECK(bonl::identify(model, u, y, options).theta() == bonl::identify(model, u_plain, y_plain, options).theta());
    CHECK(bonl::estimate_recursively(model, u, y, options).theta() ==
          bonl::estimate_recursively(model, u_plain, y_plain, options).theta());
    // (Reductions over a strided view are not vectorised: the same numbers up to rounding.)
    CHECK(bonl::metrics::mse(y, u) == Approx(bonl::metrics::mse(y_plain, u_plain)).epsilon(1e-14));
    CHECK(bonl::metrics::nrmse(y, u) == bonl::metrics::nrmse(y_plain, u_plain));
    CHECK(bonl::metrics::simulation_scores(model, u, y).nrmse ==
          bonl::metrics::simulation_scores(model, u_plain, y_plain).nrmse);
    CHECK(bonl::metrics::prediction_scores(model, u, y).mse ==
          Approx(bonl::metrics::prediction_scores(model, u_plain, y_plain).mse).epsilon(1e-14));
    bonl::Estimator<Model> estimator(model);
    estimator.reset(Strided(buffer.data(), model.num_params()));
    CHECK(estimator.theta() == u_plain.head(model.num_params()));
    Model copy = model;
    copy.set_theta(Strided(buffer.data(), model.num_params()));
    bonl::detail::set_denominator(copy, 0, Strided(buffer.data(), 2));
    CHECK(bonl::detail::denominator(copy, 0) == u_plain.head(2));
    CHECK(same_bytes(buffer, before));
  });
  // The signal generators take their tones and phases by const reference.
  Eigen::VectorXd tones = bonl::signals::paper_tones();
  Eigen::VectorXd phases = bonl::signals::schroeder_phases(5);
  const Eigen::VectorXd tones_before = tones, phases_before = phases;
  CHECK(bonl::signals::multisine(50, 0.01, tones, 0.4, phases) == bonl::signals::paper_multisine(50, 0.01, 0.4));
  CHECK(same_bytes(tones, tones_before));
  CHECK(same_bytes(phases, phases_before));
}
