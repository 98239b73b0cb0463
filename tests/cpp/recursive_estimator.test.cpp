// The recursive estimator (paper eqs. 21-31) on tiny models, against an independent recomputation
// in plain Eigen: an explicit P, K = P phi / (lambda + phi' P phi), theta += K (target - phi' theta),
// P = (I - K phi') P / lambda exactly as eq. (23) is written (the library uses a symmetric rank-1
// downdate instead; both are the same matrix in exact arithmetic).
//
// The models have na = 1, nb = 1, nk = 0, r = 1, so that every regressor can be written out:
//   front phi(k) = [1, u(k), h, h u(k), w(k-1), -x(k-1)],  h = 1 if u(k) < 0,
//   theta = [f0, f1, p0, p1, b1, a1] (Hammerstein), plus c (P-H-W).
// The library's conventions for the paper's method (models/pseudo_hammerstein_wiener.hpp,
// models/detail/hammerstein_front.hpp): everything starts at rest (past u, w, x = 0, y(-1) = 0); the
// regressor is built with theta(k-1) and the STORED w, x; after the update x(k) and w(k) are stored
// a posteriori, with theta(k).

#include "test_support.hpp"

#include <algorithm>
#include <limits>
#include <vector>

namespace {

using bonl_test::near;

constexpr double kP0 = 100.0;
constexpr double kC0 = 0.01;
constexpr double kLambda = 0.98;  // the paper's forgetting factor for the first 200 samples

bonl::EstimatorOptions options_for(bonl::Method method) {
  bonl::EstimatorOptions options;
  options.method = method;
  options.p0 = kP0;
  options.forgetting = bonl::ForgettingSchedule::paper();  // 0.98 for 200 samples, then 1
  options.normalise = false;  // the algorithm in the data's units, from the first sample: the references'
  return options;
}

/// The P-H-W model's own settings: c(0) = kC0.
bonl::BacklashEstimatorSettings backlash_settings() {
  bonl::BacklashEstimatorSettings settings;
  settings.c0 = kC0;
  return settings;
}

double sign(double v) { return v > 0.0 ? 1.0 : (v < 0.0 ? -1.0 : 0.0); }
double h_of(double u) { return u < 0.0 ? 1.0 : 0.0; }

/// Eqs. (21)-(23) as written, with an explicit dense P.
struct ReferenceRls {
  Eigen::VectorXd theta;
  Eigen::MatrixXd P;

  ReferenceRls(const Eigen::VectorXd& theta0, double p0)
      : theta(theta0), P(p0 * Eigen::MatrixXd::Identity(theta0.size(), theta0.size())) {}

  void update(const Eigen::VectorXd& phi, double target, double lambda) {
    const Eigen::VectorXd P_phi = P * phi;
    const Eigen::VectorXd K = P_phi / (lambda + phi.dot(P_phi));  // eq. (22)
    theta += K * (target - phi.dot(theta));                       // eq. (21)
    const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(theta.size(), theta.size());
    P = (I - K * phi.transpose()) * P / lambda;  // eq. (23)
  }
};

/// Front regressor [1, u, h, h u, w_lag, -x_lag] for r = 1, nb = 1, na = 1, nk = 0.
Eigen::VectorXd front_regressor(double u, double w_lag, double x_lag) {
  const double h = h_of(u);
  return bonl_test::vec({1.0, u, h, h * u, w_lag, -x_lag});
}

/// w = f0 + f1 u + h(u) (p0 + p1 u) with the first four entries of theta.
double input_block(const Eigen::VectorXd& theta, double u) {
  return theta[0] + theta[1] * u + h_of(u) * (theta[2] + theta[3] * u);
}

/// Which branch of eqs. (26)-(27) a sample took, as seen by the reference.
struct Regime {
  double g3, g4, sgn;
};

/// Independent recomputation of the paper's MRLSA (eqs. 21-31) for the P-H-W model (1, 1, 0, 1).
struct PaperPhwReference {
  ReferenceRls rls{bonl_test::vec({0, 0, 0, 0, 0, 0, kC0}), kP0};
  double w_stored = 0.0;  // w_hat(k-1), a posteriori
  double x_stored = 0.0;  // x_hat(k-1), a posteriori
  double y_prev = 0.0;    // measured y(k-1)

  Regime step(double u, double y, double lambda) {
    const Eigen::VectorXd front = front_regressor(u, w_stored, x_stored);
    const double x = front.dot(rls.theta.head(6));  // a-priori x_hat(k), eq. (25)
    const double c = rls.theta[6];
    const double g3 = y_prev + c < x ? 1.0 : 0.0;  // eq. (30)
    const double g4 = y_prev - c > x ? 1.0 : 0.0;  // eq. (31)
    const double sgn = sign(x - x_stored);
    const double y1 = x - 0.5 * c * (sgn + 1.0) * g3 + 0.5 * c * (1.0 - sgn) * g4;  // eq. (26)
    const double yc = y - (y_prev - y1) * (g3 - 1.0) * (g4 - 1.0);                  // eq. (27)
    Eigen::VectorXd phi(7);
    phi << front, 0.5 * ((1.0 - sgn) * g4 - (1.0 + sgn) * g3);  // eq. (29)
    rls.update(phi, yc, lambda);
    x_stored = front.dot(rls.theta.head(6));  // a posteriori, with theta(k)
    w_stored = input_block(rls.theta, u);     // eq. (24) with theta(k)
    y_prev = y;
    return {g3, g4, sgn};
  }
};

/// Independent recomputation of the paper's method for the Hammerstein model (1, 1, 0, 1): the
/// target is y(k) itself, the stored x the a-posteriori front value.
struct PaperHammersteinReference {
  ReferenceRls rls{Eigen::VectorXd::Zero(6), kP0};
  double w_stored = 0.0;
  double x_stored = 0.0;

  void step(double u, double y, double lambda) {
    const Eigen::VectorXd phi = front_regressor(u, w_stored, x_stored);
    rls.update(phi, y, lambda);
    x_stored = phi.dot(rls.theta);
    w_stored = input_block(rls.theta, u);
  }
};

template <class Est, class Ref>
void require_matches(const Est& est, const Ref& reference, int k) {
  INFO("after sample k = " << k << "\nlibrary theta   = " << est.theta().transpose()
                           << "\nreference theta = " << reference.rls.theta.transpose());
  REQUIRE(est.theta().size() == reference.rls.theta.size());
  REQUIRE(near(est.theta(), reference.rls.theta, 1e-10));
  INFO("library P =\n" << est.covariance() << "\nreference P =\n" << reference.rls.P);
  REQUIRE(near(est.covariance(), reference.rls.P, 1e-10));
}

}  // namespace

// The paper's method on a P-H-W model reproduces eqs. (21)-(31) step by step. The samples were
// chosen so that every branch of the backlash switching occurs: the gap at rest (k = 0), the lower
// edge (g4) moving down, the upper edge (g3) moving up, the gap away from rest with a non-zero
// correction y(k-1) - y1 in eq. (27) (k = 5), and g4 while the model's x moves UP (k = 7), where
// eq. (26) gives y1 = x and the regressor's last entry is 0. Negative u (the h = 1 segment) occurs
// at k = 1, 3, 6, 7; the estimated c goes negative at k = 1, 2 (the paper's method does not
// constrain it).
TEST_CASE("Paper method, P-H-W: first steps reproduce eqs. (21)-(31)", "[estimator][paper][phw]") {
  bonl::PseudoHammersteinWiener<double> model(1, 1, 0, 1);
  REQUIRE(model.num_params() == 7);
  bonl::Estimator<decltype(model)> est(model, options_for(bonl::Method::Paper), backlash_settings());
  PaperPhwReference reference;

  // theta(0) = [0, ..., 0, c0], P(0) = p0 I.
  require_matches(est, reference, -1);
  REQUIRE(est.theta()[6] == kC0);

  const std::vector<double> u = {0.5, -0.4, 1.0, -0.8, 0.3, 0.2, -1.0, -0.9};
  const std::vector<double> y = {0.2, 0.1, 0.3, -0.2, 0.1, 0.12, 0.1, 0.0};
  // Expected branch of each sample (g3, g4, sgn(dx)), confirmed by the reference below.
  const std::vector<Regime> expected = {
      {0, 0, 0},   // at rest: x = 0 inside [-c, c], dx = 0
      {0, 1, -1},  // pushing the lower edge, moving down
      {1, 0, 1},   // pushing the upper edge, moving up
      {0, 1, -1},  // lower edge
      {1, 0, 1},   // upper edge
      {0, 0, -1},  // inside the gap
      {0, 1, -1},  // lower edge
      {0, 1, 1},   // lower edge, but x moving up: s = 0, y1 = x
  };

  for (int k = 0; k < static_cast<int>(u.size()); ++k) {
    const double lambda = bonl::ForgettingSchedule::paper().at(k);
    REQUIRE(lambda == kLambda);
    const Regime regime = reference.step(u[k], y[k], lambda);
    INFO("k = " << k);
    REQUIRE(regime.g3 == expected[k].g3);
    REQUIRE(regime.g4 == expected[k].g4);
    REQUIRE(regime.sgn == expected[k].sgn);
    REQUIRE(est.update(u[k], y[k]) == bonl::UpdateStatus::Updated);
    require_matches(est, reference, k);
    if (k == 1 || k == 2) REQUIRE(reference.rls.theta[6] < 0.0);  // c < 0, left alone by Paper

    if (k == 0) {
      // The first step in closed form: phi = [1, 0.5, 0, 0, 0, 0, 0], target y_c = y(0) = 0.2 (the
      // gap at rest: y1 = x = 0 and y(-1) = 0), prediction 0, so theta_front = p0 phi 0.2 / (lambda
      // + p0 |phi|^2) and c stays c0.
      const double denominator = kLambda + kP0 * (1.0 + 0.25);
      REQUIRE(near(est.theta()[0], kP0 * 0.2 / denominator, 1e-12));
      REQUIRE(near(est.theta()[1], kP0 * 0.5 * 0.2 / denominator, 1e-12));
      REQUIRE(est.theta()[2] == 0.0);
      REQUIRE(est.theta()[6] == kC0);
      REQUIRE(near(est.covariance()(0, 0), (kP0 - kP0 * kP0 / denominator) / kLambda, 1e-12));
      REQUIRE(near(est.covariance()(0, 1), -kP0 * kP0 * 0.5 / denominator / kLambda, 1e-12));
      REQUIRE(near(est.covariance()(6, 6), kP0 / kLambda, 1e-12));
    }
  }
  REQUIRE(est.samples() == static_cast<Eigen::Index>(u.size()));
  // No update was refused on numerical grounds.
  REQUIRE_FALSE(est.diverged());
}

// The paper's method on a Hammerstein model: plain RLS on y(k) = phi' theta, with the past w, x in
// the regressor taken from the model's own a-posteriori estimates.
TEST_CASE("Paper method, Hammerstein: first steps reproduce eqs. (21)-(25)", "[estimator][paper][hammerstein]") {
  bonl::Hammerstein<double> model(1, 1, 0, 1);
  REQUIRE(model.num_params() == 6);
  bonl::Estimator<decltype(model)> est(model, options_for(bonl::Method::Paper));
  PaperHammersteinReference reference;
  require_matches(est, reference, -1);

  const std::vector<double> u = {0.5, -0.4, 1.0, -0.8};
  const std::vector<double> y = {0.2, 0.1, 0.3, -0.2};
  for (int k = 0; k < static_cast<int>(u.size()); ++k) {
    reference.step(u[k], y[k], kLambda);
    REQUIRE(est.update(u[k], y[k]) == bonl::UpdateStatus::Updated);
    require_matches(est, reference, k);
  }
  // Sample 1's regressor used the stored a-posteriori values of sample 0, which are by hand
  // w(0) = f0 + 0.5 f1 = x(0) (b1 = a1 = 0 after the first step, and u(0) >= 0).
  // Check that convention directly on a fresh estimator after one sample.
  bonl::Estimator<decltype(model)> one(model, options_for(bonl::Method::Paper));
  one.update(u[0], y[0]);
  const double w0 = one.theta()[0] + 0.5 * one.theta()[1];
  ReferenceRls by_hand(Eigen::VectorXd::Zero(6), kP0);
  by_hand.update(bonl_test::vec({1.0, 0.5, 0.0, 0.0, 0.0, 0.0}), y[0], kLambda);
  by_hand.update(bonl_test::vec({1.0, -0.4, 1.0, -0.4, w0, -w0}), y[1], kLambda);
  one.update(u[1], y[1]);
  REQUIRE(near(one.theta(), by_hand.theta, 1e-10));
  REQUIRE(near(one.covariance(), by_hand.P, 1e-10));
}

// The default method on the same P-H-W, one sample at a time. Per the current header, Default
// builds its internal variables (past w, x lags, a-priori x, the regime's c) from a copy of theta
// refreshed every options.internal_refresh samples; with internal_refresh = 1 that copy is the
// current estimate theta(k-1), so:
//   - past w are recomputed from the stored u with theta(k-1);
//   - the stored x lag is x computed with that copy (i.e. the a-priori x), clipped to
//     [y(k) - c, y(k) + c] with c = max(c(k-1), 0);
//   - while the copy's front is all zero there is no model to decide a regime: the sample is used
//     as a Hammerstein sample (last regressor entry 0, target y);
//   - otherwise pushing the upper edge gives last entry -1, the lower edge +1 (target y(k)), and an
//     a-priori x strictly inside [y(k-1) - c, y(k-1) + c] is NoInformation.
// Samples:
//   k = 0: bootstrap: phi = [1, 0.5, 0, 0, 0, 0, 0], target y(0). x lag = 0 clipped to
//          [y(0) - c0, y(0) + c0], i.e. y(0) - c0.
//   k = 1: same input: x = f0 + 0.5 f1 lies strictly inside the gap around y(0): NoInformation,
//          theta and P exactly unchanged.
//   k = 2: x = f0 + f1 above y(1) + c: upper edge, last entry -1, regressor written out by hand.
//   k = 3: negative input; x below y(2) - c: lower edge, last entry +1.
TEST_CASE("Default method, P-H-W: gap samples are skipped, edges give s = -1 / +1", "[estimator][default][phw]") {
  bonl::PseudoHammersteinWiener<double> model(1, 1, 0, 1);
  bonl::EstimatorOptions options = options_for(bonl::Method::EquationError);
  options.internal_refresh = 1;  // internal variables from the current estimate
  bonl::Estimator<decltype(model)> est(model, options, backlash_settings());
  ReferenceRls reference(bonl_test::vec({0, 0, 0, 0, 0, 0, kC0}), kP0);
  const auto clip = [](double x, double y, double c) { return std::min(std::max(x, y - c), y + c); };

  // k = 0: no model yet, a Hammerstein sample.
  const double u0 = 0.5, y0 = 0.3;
  reference.update(bonl_test::vec({1.0, u0, 0.0, 0.0, 0.0, 0.0, 0.0}), y0, kLambda);
  REQUIRE(est.update(u0, y0) == bonl::UpdateStatus::Updated);
  REQUIRE(near(est.theta(), reference.theta, 1e-10));
  REQUIRE(near(est.covariance(), reference.P, 1e-10));
  REQUIRE(est.theta()[6] == kC0);  // the last entry was 0: c untouched
  const double x_lag0 = clip(0.0, y0, kC0);
  REQUIRE(x_lag0 == y0 - kC0);
  const Eigen::VectorXd theta_a = reference.theta;
  const double f0 = theta_a[0], f1 = theta_a[1];
  REQUIRE(theta_a[4] == 0.0);  // b1 and a1 are still 0, which keeps the next x simple
  REQUIRE(theta_a[5] == 0.0);

  // k = 1: x = f0 + 0.5 f1 (+ b1 w(0) - a1 x lag, both zero), inside (y(0) - c, y(0) + c).
  const double u1 = 0.5, y1 = 0.0;
  const double x1 = f0 + 0.5 * f1;
  INFO("x(1) = " << x1 << ", gap = [" << y0 - kC0 << ", " << y0 + kC0 << "]");
  REQUIRE(x1 > y0 - kC0 + 1e-3);  // strictly inside, with margin
  REQUIRE(x1 < y0 + kC0 - 1e-3);
  const Eigen::VectorXd theta_before = est.theta();
  const Eigen::MatrixXd P_before = est.covariance();
  REQUIRE(est.update(u1, y1) == bonl::UpdateStatus::NoInformation);
  REQUIRE(est.theta() == theta_before);
  REQUIRE(est.covariance() == P_before);
  const double x_lag1 = clip(x1, y1, kC0);
  REQUIRE(x_lag1 == y1 + kC0);  // the clip is active: x(1) is far above y(1)

  // k = 2: upper edge. phi = [1, 1, 0, 0, w(1), -x_lag(1), -1], w(1) = f0 + 0.5 f1 with theta_a.
  const double u2 = 1.0, y2 = 0.3;
  const double x2 = f0 + f1;
  REQUIRE(x2 > y1 + kC0 + 1e-3);
  reference.update(bonl_test::vec({1.0, u2, 0.0, 0.0, f0 + 0.5 * f1, -x_lag1, -1.0}), y2, kLambda);
  reference.theta[6] = std::max(reference.theta[6], 0.0);  // Default keeps c >= 0
  REQUIRE(est.update(u2, y2) == bonl::UpdateStatus::Updated);
  REQUIRE(near(est.theta(), reference.theta, 1e-10));
  REQUIRE(near(est.covariance(), reference.P, 1e-10));
  // y(2) lies below the predicted x - c, so the update widened the gap: c > c0, no projection.
  REQUIRE(reference.theta[6] > kC0);
  const double x_lag2 = clip(x2, y2, kC0);  // the copy still had c = c0 at the end of sample 2
  const Eigen::VectorXd theta_b = reference.theta;
  const double c_b = theta_b[6];

  // k = 3: w(2) recomputed from u(2) = 1 with theta_b; x from theta_b.
  const double u3 = -0.5, y3 = -0.3;
  const Eigen::VectorXd front3 = front_regressor(u3, input_block(theta_b, u2), x_lag2);
  REQUIRE(near(front3, bonl_test::vec({1.0, -0.5, 1.0, -0.5, theta_b[0] + theta_b[1], -x_lag2}), 1e-15));
  const double x3 = front3.dot(theta_b.head(6));
  INFO("x(3) = " << x3 << ", lower edge = " << y2 - c_b);
  REQUIRE(x3 < y2 - c_b - 1e-3);
  Eigen::VectorXd phi3(7);
  phi3 << front3, 1.0;
  reference.update(phi3, y3, kLambda);
  reference.theta[6] = std::max(reference.theta[6], 0.0);
  REQUIRE(est.update(u3, y3) == bonl::UpdateStatus::Updated);
  REQUIRE(near(est.theta(), reference.theta, 1e-10));
  REQUIRE(near(est.covariance(), reference.P, 1e-10));
}

// Compile-time orders take other code paths than run-time ones (unrolled key terms, a shift register
// for the x lags, padded fixed-size P): the recursion must be the same. The sizes only change the
// order of some floating-point sums, so the two agree to round-off, amplified by P(0) = 1e6 I
// (measured: predictions within 3e-10, SSE2 and AVX-512 builds).
template <class Fixed, class Dynamic>
void check_same_recursion(const Fixed& truth, Dynamic dynamic_truth, bonl::Method method) {
  INFO(Fixed::kName << (method == bonl::Method::Paper ? ", paper method" : ", default method"));
  dynamic_truth.set_theta(truth.theta());
  const Eigen::VectorXd u = bonl_test::identification_input(bonl_test::Input::RandomLevels).head(3000);
  const Eigen::VectorXd y = truth.simulate(u) + bonl::signals::white_noise(u.size(), 0.01, 11);
  bonl::EstimatorOptions options;
  options.method = method;
  bonl::Estimator<Fixed> fixed(truth, options);
  bonl::Estimator<Dynamic> dynamic(dynamic_truth, options);
  double worst_prediction = 0.0;
  for (Eigen::Index k = 0; k < u.size(); ++k) {
    const bonl::UpdateStatus status = fixed.update(u[k], y[k]);
    REQUIRE(dynamic.update(u[k], y[k]) == status);
    worst_prediction = std::max(worst_prediction, std::abs(fixed.last_prediction() - dynamic.last_prediction()));
  }
  CAPTURE(worst_prediction);
  CHECK(worst_prediction < 1e-8);
  CHECK(near(dynamic.theta(), fixed.theta(), 1e-7));
}

TEST_CASE("compile-time and run-time orders run the same recursion", "[estimator]") {
  using bonl::Method;
  using bonl_test::kNk;
  for (const Method method : {Method::OutputError, Method::EquationError, Method::Paper}) {
    check_same_recursion(bonl_test::known_arx(), bonl::ARXd(3, 2, kNk), method);
    check_same_recursion(bonl_test::known_hammerstein(), bonl::Hammersteind(3, 2, kNk, 3), method);
  }
  // Not the paper method for H-W and P-H-W: their internals, from the running estimate while P is
  // still large, amplify the round-off itself (fixed and run-time sizes measured 5e-3 and 98 apart
  // within the first 200 predictions of an SSE2 build).
  check_same_recursion(bonl_test::known_hammerstein_wiener(), bonl::HammersteinWienerd(3, 2, kNk, 3, 3),
                       Method::EquationError);
  check_same_recursion(bonl_test::known_phw(), bonl::PseudoHammersteinWienerd(3, 2, kNk, 3), Method::EquationError);
}

namespace {
/// The record in one call against the loop over its samples, from the same start: every status,
/// prediction and theta after each sample, and the final covariance and health, bit for bit.
template <class Model>
void check_record_equals_loop(const Model& structure, bonl::Method method) {
  INFO(Model::kName << ", method " << static_cast<int>(method));
  Eigen::VectorXd u = bonl::signals::random_levels(1500, 5, 1.0, 8);
  Eigen::VectorXd y = structure.simulate(u) + bonl::signals::white_noise(u.size(), 0.01, 9);
  u[300] = std::nan("");                             // rejected inside the record,
  y[700] = std::numeric_limits<double>::infinity();  // exactly as in the loop
  bonl::EstimatorOptions options;
  options.method = method;
  bonl::Estimator<Model> looped(structure, options);
  bonl::Estimator<Model> streamed(structure, options);
  std::vector<bonl::UpdateStatus> statuses;
  std::vector<double> predictions;
  Eigen::MatrixXd thetas(structure.num_params(), u.size());
  for (Eigen::Index k = 0; k < u.size(); ++k) {
    statuses.push_back(looped.update(u[k], y[k]));
    predictions.push_back(looped.last_prediction());
    thetas.col(k) = looped.theta();
  }
  Eigen::Index calls = 0;
  streamed.update(u, y, [&](Eigen::Index k, bonl::UpdateStatus status) {
    REQUIRE(k == calls++);
    REQUIRE(status == statuses[static_cast<std::size_t>(k)]);
    REQUIRE(streamed.last_prediction() == predictions[static_cast<std::size_t>(k)]);
    REQUIRE((streamed.theta().array() == thetas.col(k).array()).all());
  });
  CHECK(calls == u.size());
  CHECK(statuses[300] == bonl::UpdateStatus::RejectedNonFinite);
  CHECK(statuses[700] == bonl::UpdateStatus::RejectedNonFinite);
  CHECK((streamed.covariance().array() == looped.covariance().array()).all());
  CHECK(streamed.health().failures == looped.health().failures);
  CHECK(streamed.samples() == looped.samples());
}
}  // namespace

TEMPLATE_LIST_TEST_CASE("a record in one call equals the loop over its samples, bit for bit", "[estimator]",
                        bonl::Models) {
  for (const bonl::Method method : {bonl::Method::OutputError, bonl::Method::EquationError, bonl::Method::Paper}) {
    check_record_equals_loop(bonl_test::known_system<TestType>(), method);
  }
}

TEST_CASE("a record in one call with fixed sizes equals the loop too", "[estimator]") {
  check_record_equals_loop(bonl_test::known_phw(), bonl::Method::OutputError);
  check_record_equals_loop(bonl_test::known_hammerstein(), bonl::Method::EquationError);
}

TEST_CASE("a record whose u and y differ in length is refused before its first sample", "[estimator]") {
  bonl::Estimator<bonl::PseudoHammersteinWienerd> estimator(bonl_test::known_system<bonl::PseudoHammersteinWienerd>());
  const Eigen::VectorXd theta = estimator.theta();
  const Eigen::VectorXd u = Eigen::VectorXd::Ones(10);
  const Eigen::VectorXd y = Eigen::VectorXd::Ones(9);
  bool called = false;
  CHECK_THROWS_WITH(estimator.update(u, y, [&](Eigen::Index, bonl::UpdateStatus) { called = true; }),
                    "bonl: u and y must have the same length (u has 10 samples, y 9)");
  CHECK_FALSE(called);
  CHECK(estimator.samples() == 0);
  CHECK((estimator.theta().array() == theta.array()).all());
}
