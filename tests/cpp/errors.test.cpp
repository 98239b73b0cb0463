// Bad input everywhere gets an exception whose message names the problem (error.hpp,
// detail/validate.hpp); a non-finite sample in the online update is refused without a trace.

#include "test_support.hpp"

using namespace bonl_test;
using Catch::Matchers::Contains;

TEST_CASE("invalid orders are rejected with the order's name", "[errors]") {
  CHECK_THROWS_WITH(bonl::ARXd(0, 1, 1), Contains("na"));
  CHECK_THROWS_WITH(bonl::ARXd(1, -1, 1), Contains("nb"));
  CHECK_THROWS_WITH(bonl::ARXd(1, 1, -1), Contains("nk"));
  CHECK_THROWS_WITH(bonl::Hammersteind(1, 1, 1, 0), Contains("r"));
  CHECK_THROWS_WITH(bonl::HammersteinWienerd(1, 1, 1, 2, 1), Contains("r1"));
  CHECK_THROWS_WITH(bonl::PseudoHammersteinWienerd(-3, 1, 1, 2), Contains("na"));
  // A compile-time order must match the run-time one.
  CHECK_THROWS_WITH(bonl::PaperPseudoHammersteinWiener(2, 2, 8, 3), Contains("compile-time"));
  CHECK_THROWS_WITH(bonl::PaperHammersteinWiener(3, 2, 8, 3, 4), Contains("r1"));
  CHECK_THROWS_AS(bonl::ARXd(0, 1, 1), std::invalid_argument);
}

TEST_CASE("invalid parameters are rejected", "[errors]") {
  bonl::PaperPseudoHammersteinWiener phw(3, 2, 8, 3);
  // The wrong size comes from a volatile: with a size known at compile time, GCC 12's -Warray-bounds
  // flags the assignment that the size check makes unreachable (a known false positive at -O3).
  volatile int wrong_size = 2;
  CHECK_THROWS_WITH(phw.set_f(Eigen::VectorXd::Ones(wrong_size)), Contains("f"));
  CHECK_THROWS_WITH(phw.set_b(vec({0.5, 0.1, 0.1})), Contains("b_0"));
  CHECK_THROWS_WITH(phw.set_c(-0.1), Contains("c"));
  CHECK_THROWS_WITH(phw.set_a(vec({0.1, std::nan(""), 0.0})), Contains("non-finite"));
  CHECK_THROWS_WITH(phw.set_theta(Eigen::VectorXd::Zero(3)), Contains("theta"));
  bonl::PaperHammersteinWiener hw(3, 2, 8, 3, 3);
  CHECK_THROWS_WITH(hw.set_q(vec({2.0, 0.0, 0.0})), Contains("q_1"));
}

TEST_CASE("estimator settings out of range are rejected", "[errors]") {
  const bonl::PaperPseudoHammersteinWiener model(3, 2, 8, 3);
  for (double lambda : {0.0, -0.5, 1.5, std::nan("")}) {
    bonl::EstimatorOptions options;
    options.forgetting = bonl::ForgettingSchedule::constant(lambda);
    CHECK_THROWS_WITH(bonl::Estimator<bonl::PaperPseudoHammersteinWiener>(model, options),
                      Contains("forgetting factor"));
  }
  bonl::EstimatorOptions options;
  options.p0 = 0.0;
  CHECK_THROWS_WITH(bonl::Estimator<bonl::PaperPseudoHammersteinWiener>(model, options), Contains("p0"));
  options.p0 = 1e6;
  // The model's own settings (P-H-W: BacklashEstimatorSettings), checked with the options.
  bonl::PaperPseudoHammersteinWiener::EstimatorSettings settings;
  settings.c0 = -1.0;
  CHECK_THROWS_WITH(bonl::Estimator<bonl::PaperPseudoHammersteinWiener>(model, options, settings), Contains("c0"));
  settings.c0 = 0.01;
  settings.backlash_hold = -1;
  CHECK_THROWS_WITH(bonl::Estimator<bonl::PaperPseudoHammersteinWiener>(model, options, settings),
                    Contains("backlash_hold must be >= 0"));
}

TEST_CASE("identify rejects bad records", "[errors]") {
  const bonl::PaperHammerstein model(3, 2, 8, 3);
  const Eigen::VectorXd u = bonl::signals::random_levels(300, 3, 1.0, 1);
  const Eigen::VectorXd y = known_hammerstein().simulate(u);
  CHECK_THROWS_WITH(bonl::identify(model, u, y.head(299)), Contains("same length"));
  Eigen::VectorXd bad = y;
  bad[17] = std::nan("");
  CHECK_THROWS_WITH(bonl::identify(model, u, bad), Contains("y has a non-finite value at index 17"));
  bad = u;
  bad[3] = std::numeric_limits<double>::infinity();
  CHECK_THROWS_WITH(bonl::identify(model, bad, y), Contains("u has a non-finite value at index 3"));
  CHECK_THROWS_WITH(bonl::identify(model, u.head(10), y.head(10)), Contains("longer than the number of parameters"));
  bonl::IdentifyOptions options;
  options.passes = 0;
  CHECK_THROWS_WITH(bonl::identify(model, u, y, options), Contains("passes"));
  options.passes = 1;
  options.forgetting = bonl::ForgettingSchedule::paper();
  options.forgetting->final = 1.01;
  CHECK_THROWS_WITH(bonl::identify(model, u, y, options), Contains("forgetting factor"));
}

TEST_CASE("simulate, predict and metrics reject non-finite or mismatched data", "[errors]") {
  const bonl::PaperPseudoHammersteinWiener model = known_phw();
  Eigen::VectorXd u = Eigen::VectorXd::Zero(20);
  u[4] = std::nan("");
  CHECK_THROWS_WITH(model.simulate(u), Contains("u has a non-finite value at index 4"));
  CHECK_THROWS_WITH(model.predict(Eigen::VectorXd::Zero(20), Eigen::VectorXd::Zero(19)), Contains("same length"));
  CHECK_THROWS_WITH(bonl::metrics::mse(Eigen::VectorXd::Zero(3), Eigen::VectorXd::Zero(4)), Contains("same length"));
  CHECK_THROWS_WITH(bonl::metrics::nrmse(Eigen::VectorXd::Ones(3), Eigen::VectorXd::Zero(3)), Contains("constant"));
}

TEST_CASE("a non-finite sample in the online update leaves the estimator untouched", "[errors]") {
  const bonl::PaperPseudoHammersteinWiener truth = known_phw();
  const Eigen::VectorXd u = bonl::signals::random_levels(1000, 5, 1.0, 31);
  const Eigen::VectorXd y = truth.simulate(u);
  for (bonl::Method method : {bonl::Method::OutputError, bonl::Method::EquationError, bonl::Method::Paper}) {
    bonl::EstimatorOptions options;
    options.method = method;
    bonl::Estimator<bonl::PaperPseudoHammersteinWiener> clean(truth, options);
    bonl::Estimator<bonl::PaperPseudoHammersteinWiener> disturbed(truth, options);
    for (Eigen::Index k = 0; k < u.size(); ++k) {
      if (k % 97 == 50) {
        const Eigen::VectorXd theta = disturbed.theta();
        const Eigen::MatrixXd p = disturbed.covariance();
        const Eigen::Index samples = disturbed.samples();
        REQUIRE(disturbed.update(std::nan(""), y[k]) == bonl::UpdateStatus::RejectedNonFinite);
        REQUIRE(disturbed.update(u[k], std::numeric_limits<double>::infinity()) ==
                bonl::UpdateStatus::RejectedNonFinite);
        REQUIRE(disturbed.theta() == theta);
        REQUIRE(disturbed.covariance() == p);
        REQUIRE(disturbed.samples() == samples);
      }
      clean.update(u[k], y[k]);
      disturbed.update(u[k], y[k]);
    }
    // The rejected samples left no trace: the two estimators are bit-identical.
    CHECK(disturbed.theta() == clean.theta());
    CHECK(disturbed.covariance() == clean.covariance());
    CHECK_FALSE(disturbed.diverged());
  }
}
