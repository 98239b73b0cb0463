// The online estimator works in the data's own scale (EstimatorOptions::normalise,
// estimator/normalisation.hpp), over every model of bonl::Models:
// - the same machine recorded in other units (u and y multiplied by 1e-3 and 1e4, independently) gives
//   the same model, in those units: its estimate, rescaled back by the models' own units
//   (bonl::rescaled, the oracle), simulates a fresh input as the estimate in the original units does;
// - its scale is the RMS of the first kScaleSamples samples from the first moving input, computed
//   here directly, and the samples before that input moves are not counted;
// - the recursion catches up on the samples it waited for, two per update, or all at once
//   (catch_up(), start_pass()), and ends where the record's updates would have taken it;
// - covariance() is in the data's units: in other units it changes as the parameters' units say;
// - the paper's method and normalise = false are the algorithm in the data's units, as before.

#include "test_support.hpp"

using namespace bonl_test;

namespace {

/// One pass of the default estimator over (u, y); its model.
template <class Model>
Model online(const Model& structure, const Eigen::VectorXd& u, const Eigen::VectorXd& y,
             const bonl::EstimatorOptions& options = {}) {
  bonl::Estimator<Model> estimator(structure, options);
  for (Eigen::Index k = 0; k < u.size(); ++k) estimator.update(u[k], y[k]);
  return estimator.model();
}

/// NRMSE between what two models simulate on u.
template <class Model>
double difference(const Model& a, const Model& b, const Eigen::VectorXd& u) {
  Eigen::VectorXd sa, sb;
  if (!a.try_simulate(u, sa) || !b.try_simulate(u, sb)) return std::numeric_limits<double>::infinity();
  return bonl::metrics::nrmse(sa, sb);
}

}  // namespace

TEMPLATE_LIST_TEST_CASE("the online estimator gives the same model whatever the data's units", "[normalisation]",
                        bonl::Models) {
  const TestType truth = known_system<TestType>();
  const Eigen::VectorXd u = bonl::signals::random_levels(4000, 5, 1.0, 21);
  const Eigen::VectorXd y = truth.simulate(u);
  const Eigen::VectorXd fresh = bonl::signals::random_levels(4000, 5, 1.0, 22);
  const TestType original = online(structure_of(truth), u, y);
  for (const auto& [fu, fy] : {std::pair<double, double>{1e-3, 1e4}, {1e4, 1e-3}}) {
    INFO(TestType::kName << ": u times " << fu << ", y times " << fy);
    const TestType scaled =
        online(structure_of(bonl::rescaled(truth, fu, fy)), Eigen::VectorXd(u * fu), Eigen::VectorXd(y * fy));
    // Measured: 1e-15 to 8e-14 apart, where in the data's units the same factors took the P-H-W
    // estimate from exact to 0.51 (y) and diverged (u).
    CHECK(difference(bonl::rescaled(scaled, 1.0 / fu, 1.0 / fy), original, fresh) <= 1e-9);
  }
}

TEST_CASE("the data's scale is the RMS of the first samples from the first moving input", "[normalisation]") {
  const auto truth = known_phw();
  using Model = bonl::PaperPseudoHammersteinWiener;
  const Eigen::Index rest = 30, n = 600;
  Eigen::VectorXd u = bonl::signals::random_levels(n, 5, 1.0, 23);
  u.head(rest).setZero();  // the machine at rest first
  const Eigen::VectorXd y = truth.simulate(u) + bonl::signals::white_noise(n, 0.01, 24);
  bonl::Estimator<Model> estimator(structure_of(truth));
  const Eigen::Index measured = bonl::Estimator<Model>::kScaleSamples;
  for (Eigen::Index k = 0; k < rest + measured - 1; ++k) {
    CHECK(estimator.update(u[k], y[k]) == bonl::UpdateStatus::NoInformation);
  }
  CHECK(estimator.measuring_scale());
  CHECK(estimator.theta().isZero(0));
  estimator.update(u[rest + measured - 1], y[rest + measured - 1]);
  CHECK_FALSE(estimator.measuring_scale());
  // The oracle: the RMS of u and y over the samples from the first moving one, directly.
  const double su = std::sqrt(u.segment(rest, measured).squaredNorm() / static_cast<double>(measured));
  const double sy = std::sqrt(y.segment(rest, measured).squaredNorm() / static_cast<double>(measured));
  CHECK(estimator.data_scale().u == Approx(su).epsilon(1e-12));
  CHECK(estimator.data_scale().y == Approx(sy).epsilon(1e-12));
  // It took the first of the samples it kept; then two per update, the new one behind them.
  CHECK(estimator.pending_samples() == measured - 1);
  CHECK(estimator.samples() == 1);
  estimator.update(u[rest + measured], y[rest + measured]);
  CHECK(estimator.pending_samples() == measured - 2);
  CHECK(estimator.samples() == 3);
  for (Eigen::Index k = rest + measured + 1; k < n; ++k) estimator.update(u[k], y[k]);
  CHECK(estimator.pending_samples() == 0);
  CHECK(estimator.samples() == n - rest);
}

TEST_CASE("caught up at once or two samples an update, the recursion ends in the same place", "[normalisation]") {
  const auto truth = known_hammerstein();
  const Eigen::VectorXd u = bonl::signals::random_levels(2000, 5, 1.0, 25);
  const Eigen::VectorXd y = truth.simulate(u) + bonl::signals::white_noise(u.size(), 0.01, 26);
  bonl::EstimatorOptions options;
  options.window.enabled = false;  // the recursion itself: the window's slices follow the updates
  bonl::Estimator<bonl::PaperHammerstein> gradual(truth, options), at_once(truth, options);
  const Eigen::Index measured = bonl::Estimator<bonl::PaperHammerstein>::kScaleSamples;
  for (Eigen::Index k = 0; k < u.size(); ++k) {
    gradual.update(u[k], y[k]);
    at_once.update(u[k], y[k]);
    if (k == measured - 1) at_once.catch_up();
  }
  CHECK(at_once.pending_samples() == 0);
  CHECK(gradual.pending_samples() == 0);
  CHECK(gradual.theta() == at_once.theta());
  CHECK(gradual.covariance() == at_once.covariance());

  // A record shorter than the measurement: start_pass() and catch_up() end it with what it has.
  bonl::Estimator<bonl::PaperHammerstein> short_record(truth, options);
  for (Eigen::Index k = 0; k < 60; ++k) short_record.update(u[k], y[k]);
  CHECK(short_record.measuring_scale());
  short_record.catch_up();
  CHECK_FALSE(short_record.measuring_scale());
  CHECK(short_record.samples() == 60);
  CHECK_FALSE(short_record.theta().isZero(0));
}

TEST_CASE("the covariance is in the data's units", "[normalisation]") {
  // In other units the recursion's own P is the same; covariance(), the data's (the P of the
  // recursion on the data as they are, whose noise variance changes by fy^2), changes by the
  // parameters' units: entry (i, j) by d_i d_j / fy^2, d the parameters' factors (rescaled()).
  const auto truth = known_system<bonl::ARXd>();
  const Eigen::VectorXd u = bonl::signals::random_levels(3000, 5, 1.0, 27);
  const Eigen::VectorXd y = truth.simulate(u) + bonl::signals::white_noise(u.size(), 0.01, 28);
  const double fu = 1e-3, fy = 1e4;
  bonl::Estimator<bonl::ARXd> original(structure_of(truth)), scaled(structure_of(bonl::rescaled(truth, fu, fy)));
  for (Eigen::Index k = 0; k < u.size(); ++k) {
    original.update(u[k], y[k]);
    scaled.update(u[k] * fu, y[k] * fy);
  }
  CHECK(near(scaled.normalised_covariance(), original.normalised_covariance(), 1e-9));
  bonl::ARXd ones = structure_of(truth);
  ones.set_theta(Eigen::VectorXd::Ones(truth.num_params()));
  const Eigen::VectorXd d = bonl::rescaled(ones, fu, fy).theta();
  const Eigen::MatrixXd expected = (original.covariance().array() * (d * d.transpose()).array()).matrix() / (fy * fy);
  CHECK(((scaled.covariance() - expected).cwiseAbs().array() <= 1e-9 * expected.cwiseAbs().maxCoeff()).all());
}

TEST_CASE("the paper's method and normalise = false run in the data's units, from the first sample",
          "[normalisation]") {
  const auto truth = known_phw();
  const Eigen::VectorXd u = bonl::signals::random_levels(500, 5, 1.0, 29);
  const Eigen::VectorXd y = truth.simulate(u);
  for (const bool paper : {true, false}) {
    bonl::EstimatorOptions options;
    if (paper) {
      options.method = bonl::Method::Paper;
    } else {
      options.normalise = false;
    }
    bonl::Estimator<bonl::PaperPseudoHammersteinWiener> estimator(truth, options);
    estimator.update(u[0], y[0]);
    CHECK_FALSE(estimator.measuring_scale());
    CHECK(estimator.data_scale().u == 1.0);
    CHECK(estimator.data_scale().y == 1.0);
    CHECK(estimator.covariance() == estimator.normalised_covariance());
  }
}
