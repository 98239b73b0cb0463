// The recursive least-squares core (estimator/rls.hpp) against its batch oracle: with forgetting
// factor 1, N recursive updates from theta0 with P(0) = p0 I give exactly the regularised batch
// solution  theta = (Phi' Phi + I / p0)^-1 (Phi' y + theta0 / p0);  with a constant lambda < 1 the
// data and the prior are weighted by lambda^(N-k) and lambda^N.

#include "test_support.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <utility>

using namespace bonl_test;

namespace {

struct Problem {
  Eigen::MatrixXd phi;  // one regressor per row
  Eigen::VectorXd y;
};

Problem random_problem(Eigen::Index samples, Eigen::Index n, double noise, unsigned seed) {
  std::mt19937_64 generator(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  Problem problem{Eigen::MatrixXd(samples, n), Eigen::VectorXd(samples)};
  Eigen::VectorXd truth(n);
  for (Eigen::Index i = 0; i < n; ++i) truth[i] = normal(generator);
  for (Eigen::Index k = 0; k < samples; ++k) {
    for (Eigen::Index i = 0; i < n; ++i) problem.phi(k, i) = normal(generator);
    problem.y[k] = problem.phi.row(k).dot(truth) + noise * normal(generator);
  }
  return problem;
}

Eigen::VectorXd batch_solution(const Problem& problem, const Eigen::VectorXd& theta0, double p0, double lambda) {
  const Eigen::Index samples = problem.phi.rows();
  const Eigen::Index n = problem.phi.cols();
  Eigen::MatrixXd normal = std::pow(lambda, static_cast<double>(samples)) / p0 * Eigen::MatrixXd::Identity(n, n);
  Eigen::VectorXd rhs = std::pow(lambda, static_cast<double>(samples)) / p0 * theta0;
  for (Eigen::Index k = 0; k < samples; ++k) {
    const double weight = std::pow(lambda, static_cast<double>(samples - 1 - k));
    normal += weight * problem.phi.row(k).transpose() * problem.phi.row(k);
    rhs += weight * problem.phi.row(k).transpose() * problem.y[k];
  }
  return normal.ldlt().solve(rhs);
}

double relative_difference(const Eigen::VectorXd& a, const Eigen::VectorXd& b) { return (a - b).norm() / b.norm(); }

}  // namespace

TEST_CASE("RLS with forgetting factor 1 equals regularised batch least squares", "[rls]") {
  const double p0 = GENERATE(1e6, 10.0, 0.1);
  const Problem problem = random_problem(400, 12, 0.1, 42);
  const Eigen::VectorXd theta0 = Eigen::VectorXd::LinSpaced(12, -1.0, 1.0);
  bonl::Rls<double> rls(12, p0);
  rls.reset(theta0, p0);
  for (Eigen::Index k = 0; k < problem.phi.rows(); ++k) {
    REQUIRE(rls.update(problem.phi.row(k).transpose(), problem.y[k], 1.0));
  }
  INFO("p0 = " << p0);
  CHECK(relative_difference(rls.theta(), batch_solution(problem, theta0, p0, 1.0)) <= 1e-8);
}

TEST_CASE("run-time sizes equal weighted batch least squares at every size the update dispatches on", "[rls]") {
  // Run-time sizes run the kernel of their padded storage length up to 32 parameters (4, 8, 16, 24,
  // 32), the generic one above.
  const Eigen::Index n = GENERATE(range(1, 41));
  const Problem problem = random_problem(4 * n + 50, n, 0.1, static_cast<unsigned>(n));
  const Eigen::VectorXd theta0 = Eigen::VectorXd::LinSpaced(n, -1.0, 1.0);
  bonl::Rls<double> rls(n, 10.0);
  rls.reset(theta0, 10.0);
  for (Eigen::Index k = 0; k < problem.phi.rows(); ++k) {
    REQUIRE(rls.update(problem.phi.row(k).transpose(), problem.y[k], 0.99));
  }
  INFO("n = " << n);
  CHECK(relative_difference(rls.theta(), batch_solution(problem, theta0, 10.0, 0.99)) <= 1e-8);
  const Eigen::MatrixXd covariance = rls.covariance();
  CHECK(covariance.rows() == n);
  CHECK((covariance - covariance.transpose()).cwiseAbs().maxCoeff() == 0.0);
}

namespace {
/// Runs Rls<double> (run-time size) and Rls<double, N> side by side through the same updates (the
/// target and the given-error forms, a refused update, process noise, a trace ceiling, folds of the
/// scale) and requires every return value and the forgetting flag to be identical and theta and P
/// to agree to rounding: the run-time sizes' kernel works at the padded length (sums in another
/// order), the fixed sizes' at the exact one.
template <int N>
void require_run_time_size_equals_fixed() {
  INFO("n = " << N);
  const Problem problem = random_problem(600, N, 0.1, 1000 + N);
  bonl::Rls<double> run_time(N, 1e3);
  bonl::Rls<double, N> fixed(N, 1e3);
  run_time.set_process_noise(1e-9);
  fixed.set_process_noise(1e-9);
  for (Eigen::Index k = 0; k < problem.phi.rows(); ++k) {
    // The regressor as a vector (the copy-free path) and as a strided row (the copied one).
    const Eigen::VectorXd phi = problem.phi.row(k).transpose();
    const double lambda = k < 300 ? 0.9 : 0.999;  // 0.9 folds the scale every ~350 samples
    const double ceiling = k % 100 < 50 ? 5e3 : std::numeric_limits<double>::infinity();
    bool a = false, b = false;
    if (k % 3 == 0) {
      a = run_time.update_with_error(problem.phi.row(k).transpose(), problem.y[k], lambda, ceiling);
      b = fixed.update_with_error(Eigen::Matrix<double, N, 1>(phi), problem.y[k], lambda, ceiling);
    } else if (k == 200) {  // refused: a non-finite target
      a = run_time.update(phi, std::nan(""), lambda, ceiling);
      b = fixed.update(Eigen::Matrix<double, N, 1>(phi), std::nan(""), lambda, ceiling);
      CHECK(!a);
    } else {
      a = run_time.update(phi, problem.y[k], lambda, ceiling);
      b = fixed.update(Eigen::Matrix<double, N, 1>(phi), problem.y[k], lambda, ceiling);
    }
    REQUIRE(a == b);
    REQUIRE(run_time.forgetting_limited() == fixed.forgetting_limited());
    REQUIRE(relative_difference(run_time.theta(), fixed.theta()) <= 1e-10);
  }
  CHECK((run_time.covariance() - fixed.covariance()).norm() <= 1e-10 * fixed.covariance().norm());
}

}  // namespace

TEST_CASE("run-time sizes give the fixed sizes' results to rounding, at every padded length", "[rls]") {
  // Each padded length (4, 8, 16, 24, 32) once, and both ends of the first. Each fixed size
  // compiles two kernels, so a few sizes, not all 32.
  require_run_time_size_equals_fixed<1>();
  require_run_time_size_equals_fixed<4>();
  require_run_time_size_equals_fixed<6>();
  require_run_time_size_equals_fixed<14>();
  require_run_time_size_equals_fixed<17>();
  require_run_time_size_equals_fixed<32>();
}

TEST_CASE("RLS with a constant forgetting factor equals exponentially weighted least squares", "[rls]") {
  const Problem problem = random_problem(300, 8, 0.1, 7);
  const Eigen::VectorXd theta0 = Eigen::VectorXd::Zero(8);
  bonl::Rls<double, 8> rls(8, 100.0);
  for (Eigen::Index k = 0; k < problem.phi.rows(); ++k) {
    REQUIRE(rls.update(problem.phi.row(k).transpose(), problem.y[k], 0.98));
  }
  CHECK(relative_difference(rls.theta(), batch_solution(problem, theta0, 100.0, 0.98)) <= 1e-8);
}

TEST_CASE("forgetting kept as a scale on P matches the weighted least-squares covariance across folds", "[rls]") {
  // Rls stores P = scale * M and folds the scale into M when it passes 1 / epsilon: at lambda = 0.98
  // after ~1,780 samples and then every ~1,780. Oracle, advanced alongside: the information matrix
  // A = lambda A + phi phi' from A(0) = I / p0, and P = A^-1. Checked at every sample around the first
  // fold (an error there is forgotten only slowly: 0.98^k) and at the end.
  const double lambda = 0.98;
  const double p0 = 100.0;
  const Problem problem = random_problem(4000, 8, 0.1, 11);
  Eigen::MatrixXd information = Eigen::MatrixXd::Identity(8, 8) / p0;
  bonl::Rls<double, 8> fixed(8, p0);
  bonl::Rls<double> dynamic(8, p0);
  const auto relative = [](const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) { return (a - b).norm() / b.norm(); };
  double worst = 0.0;
  for (Eigen::Index k = 0; k < problem.phi.rows(); ++k) {
    const Eigen::VectorXd phi = problem.phi.row(k).transpose();
    REQUIRE(fixed.update(phi, problem.y[k], lambda));
    REQUIRE(dynamic.update(phi, problem.y[k], lambda));
    information = lambda * information + phi * phi.transpose();
    if ((k >= 1700 && k < 1900) || k + 1 == problem.phi.rows()) {
      const Eigen::MatrixXd expected = information.ldlt().solve(Eigen::MatrixXd::Identity(8, 8));
      worst = std::max({worst, relative(fixed.covariance(), expected), relative(dynamic.covariance(), expected)});
    }
  }
  CHECK(worst <= 1e-9);
  const Eigen::VectorXd expected_theta = batch_solution(problem, Eigen::VectorXd::Zero(8), p0, lambda);
  CHECK(relative_difference(fixed.theta(), expected_theta) <= 1e-8);
  CHECK(relative_difference(dynamic.theta(), expected_theta) <= 1e-8);
  const Eigen::MatrixXd covariance = fixed.covariance();
  CHECK((covariance - covariance.transpose()).cwiseAbs().maxCoeff() == 0.0);
}

TEST_CASE("the covariance stays exactly symmetric and positive definite", "[rls]") {
  const Problem problem = random_problem(2000, 18, 0.01, 3);
  bonl::Rls<double, 18> rls(18, 1e6);
  for (Eigen::Index k = 0; k < problem.phi.rows(); ++k) {
    REQUIRE(rls.update(problem.phi.row(k).transpose(), problem.y[k], k < 200 ? 0.98 : 1.0));
  }
  const Eigen::Matrix<double, 18, 18> p = rls.covariance();
  CHECK(p == p.transpose());
  CHECK(p.llt().info() == Eigen::Success);
}

TEST_CASE("the model estimator with lambda = 1 equals batch least squares on the ARX regressors", "[rls]") {
  // The whole path (model regressor + estimator) against the batch solution built by hand.
  const bonl::PaperARX truth = known_arx();
  const Eigen::VectorXd u = bonl::signals::random_levels(1500, 3, 1.0, 21);
  const Eigen::VectorXd y = truth.simulate(u) + bonl::signals::white_noise(u.size(), 0.01, 22);
  const double p0 = 1e3;
  bonl::EstimatorOptions options;
  options.method = bonl::Method::EquationError;  // for ARX: least squares on its regressor
  options.forgetting = bonl::ForgettingSchedule::constant(1.0);
  options.p0 = p0;
  options.normalise = false;  // P(0) = p0 I in the data's units, as the batch solution has it
  bonl::Estimator<bonl::PaperARX> estimator(truth, options);
  Problem problem{Eigen::MatrixXd::Zero(u.size(), 6), y};
  for (Eigen::Index k = 0; k < u.size(); ++k) {
    for (Eigen::Index i = 0; i <= 2; ++i) problem.phi(k, i) = k - kNk - i >= 0 ? u[k - kNk - i] : 0.0;
    for (Eigen::Index j = 1; j <= 3; ++j) problem.phi(k, 2 + j) = k - j >= 0 ? -y[k - j] : 0.0;
    REQUIRE(estimator.update(u[k], y[k]) == bonl::UpdateStatus::Updated);
  }
  CHECK(relative_difference(estimator.theta(), batch_solution(problem, Eigen::VectorXd::Zero(6), p0, 1.0)) <= 1e-8);
}

TEST_CASE("an unsafe update is refused and leaves the state untouched", "[rls]") {
  bonl::Rls<double, 2> rls(2, 1.0);
  const Eigen::Vector2d theta = rls.theta();
  const Eigen::Matrix2d p = rls.covariance();
  const Eigen::Vector2d huge(1e200, 1e200);
  CHECK_FALSE(rls.update(huge, 1.0, 1.0));  // phi' P phi overflows
  CHECK(rls.theta() == theta);
  CHECK(rls.covariance() == p);
}

TEMPLATE_TEST_CASE("an update whose new theta would overflow is refused", "[rls]", (bonl::Rls<double, 14>),
                   (bonl::Rls<double>)) {
  // A small regressor with a large P gives a gain of 500 (K = P phi / (1 + phi' P phi)), so a finite
  // error of 1e308 would take theta to infinity.
  TestType rls(14, 1e6);
  Eigen::VectorXd phi = Eigen::VectorXd::Zero(14);
  phi[3] = 1e-3;
  const Eigen::VectorXd theta = rls.theta();
  const Eigen::MatrixXd p = rls.covariance();
  CHECK_FALSE(rls.update(phi, 1e308, 1.0));
  CHECK(rls.theta() == theta);
  CHECK(rls.covariance() == p);
  CHECK(rls.update(phi, 1.0, 1.0));                       // and a sane update still goes through
  CHECK(rls.theta()[3] == Approx(500.0).epsilon(1e-12));  // 1e6 * 1e-3 / (1 + 1e6 * 1e-6) * error 1
}

TEST_CASE("process noise adds q I to P after each update, within the trace ceiling", "[rls]") {
  // Oracle: the textbook update with an explicit P, then P + q I, then the forgetting.
  const Problem problem = random_problem(200, 6, 0.1, 7);
  const double q = 1e-3, lambda = 0.98, p0 = 10.0;
  bonl::Rls<double> rls(6, p0);
  rls.set_process_noise(q);
  Eigen::VectorXd theta = Eigen::VectorXd::Zero(6);
  Eigen::MatrixXd p = p0 * Eigen::MatrixXd::Identity(6, 6);
  for (Eigen::Index k = 0; k < problem.phi.rows(); ++k) {
    const Eigen::VectorXd phi = problem.phi.row(k).transpose();
    REQUIRE(rls.update(phi, problem.y[k], lambda));
    const Eigen::VectorXd g = p * phi;
    const double denominator = lambda + phi.dot(g);
    theta += g * (problem.y[k] - phi.dot(theta)) / denominator;
    p = ((p - g * g.transpose() / denominator) + q * Eigen::MatrixXd::Identity(6, 6)) / lambda;
  }
  CHECK(relative_difference(rls.theta(), theta) <= 1e-12);
  CHECK((rls.covariance() - p).cwiseAbs().maxCoeff() <= 1e-12 * p.cwiseAbs().maxCoeff());

  // Without excitation P grows by forgetting and by q until the ceiling, which then holds both.
  const double ceiling = 2.0 * 6 * p0;
  for (int k = 0; k < 2000; ++k) REQUIRE(rls.update(Eigen::VectorXd::Zero(6), 0.0, lambda, ceiling));
  CHECK(rls.covariance().trace() <= ceiling * (1.0 + 1e-12));
  CHECK(rls.forgetting_limited());
  CHECK_THROWS_WITH(rls.set_process_noise(-1.0), Catch::Contains("process noise must be finite and >= 0"));
}
