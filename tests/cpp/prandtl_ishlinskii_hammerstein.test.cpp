// The Prandtl-Ishlinskii Hammerstein model (models/prandtl_ishlinskii_hammerstein.hpp; its plays are
// tested in blocks.test.cpp). The property suites run over it with the other models (bonl::Models);
// here what is its own:
// - The free run equals the plays and the difference equation written out by hand (the oracle keeps
//   its own plays and past).
// - The output-error sensitivities equal central finite differences of the free run.
// - At the truth the key terms give the noise-free output exactly, for both key-term methods.
// - identify() recovers the known systems (tests/data/known_systems.json and one with an integrator),
//   noise-free, to NRMSE <= 1e-6 on a fresh input of a larger amplitude than the identification input.
// - identify()'s data rule places the thresholds at i / (np + 1) of the inputs' half-range.
// - The online output_error estimator converges on the known system.
// - A simulation after a measured past sets the plays' memory from the past input.
// - Bad orders and bad thresholds are refused with a message and leave the model as it was; the
//   model file keeps the thresholds. Its inverse for control is tested in control_inverse_model and
//   control_block_inverses.

#include "test_support.hpp"

#include <bonl/io.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

using namespace bonl_test;

namespace {

using Model = bonl::PrandtlIshlinskiiHammersteind;

/// The free run written out: plays from 0, w = f(u) + g . plays, then the difference equation
/// x(k) = sum_i b_i w(k-nk-i) - sum_j a_j z(k-j) (+ x(k-1) with ni = 1, z = x(k) - x(k-1)).
Eigen::VectorXd by_hand(const Model& m, const Eigen::VectorXd& u) {
  const Eigen::VectorXd b = m.b(), a = m.a(), f = m.f(), g = m.g(), r = m.thresholds();
  Eigen::VectorXd plays = Eigen::VectorXd::Zero(r.size());
  Eigen::VectorXd w(u.size()), x = Eigen::VectorXd::Zero(u.size());
  for (Eigen::Index k = 0; k < u.size(); ++k) {
    double value = 0.0;
    for (Eigen::Index l = 0; l < f.size(); ++l) value += f[l] * std::pow(u[k], double(l));
    for (Eigen::Index i = 0; i < r.size(); ++i) {
      plays[i] = std::min(std::max(plays[i], u[k] - r[i]), u[k] + r[i]);
      value += g[i] * plays[i];
    }
    w[k] = value;
  }
  const auto x_at = [&x](Eigen::Index k) { return k >= 0 ? x[k] : 0.0; };
  for (Eigen::Index k = 0; k < u.size(); ++k) {
    double out = 0.0;
    for (Eigen::Index i = 0; i < b.size(); ++i) {
      if (k - m.nk() - i >= 0) out += b[i] * w[k - m.nk() - i];
    }
    for (Eigen::Index j = 1; j <= a.size(); ++j) {
      out -= a[j - 1] * (m.ni() == 0 ? x_at(k - j) : x_at(k - j) - x_at(k - j - 1));
    }
    if (m.ni() == 1) out += x_at(k - 1);
    x[k] = out;
  }
  return x;
}

/// The known system with an integrator: its input hysteresis drives a velocity whose position is measured.
Model integrating() {
  const Model velocity = known_system<Model>("small");
  Model model(2, 1, 2, 2, 2, 1);
  model.set_theta(velocity.theta());
  model.set_thresholds(velocity.thresholds());
  model.set_g(vec({0.03, -0.015}));  // a small drift: the position stays within about +-30
  model.set_f(vec({0.0, 0.05, 0.01}));
  return model;
}

Eigen::VectorXd identification_input() { return levels(1.0, 3); }
/// A fresh input half as large again as the identification input: the plays turn further out.
Eigen::VectorXd fresh_input() { return levels(1.5, 77); }

}  // namespace

TEST_CASE("the Prandtl-Ishlinskii Hammerstein free run is the plays and the difference equation written out",
          "[prandtl_ishlinskii]") {
  for (const Model& m : {known_system<Model>(), known_system<Model>("small"), integrating()}) {
    INFO("np = " << m.np() << ", ni = " << m.ni());
    const Eigen::VectorXd u = bonl::signals::random_levels(500, 5, 1.5, 5);
    const Eigen::VectorXd expected = by_hand(m, u);
    CHECK((m.simulate(u) - expected).cwiseAbs().maxCoeff() <= 1e-12 * (1.0 + expected.cwiseAbs().maxCoeff()));
  }
  // The plays matter: without them (g = 0) the run is another.
  Model no_plays = known_system<Model>();
  no_plays.set_g(Eigen::VectorXd::Zero(no_plays.np()));
  const Eigen::VectorXd u = bonl::signals::random_levels(500, 5, 1.0, 5);
  CHECK((no_plays.simulate(u) - known_system<Model>().simulate(u)).cwiseAbs().maxCoeff() > 0.01);
}

TEST_CASE("the Prandtl-Ishlinskii Hammerstein output-error sensitivities are the free run's derivatives",
          "[prandtl_ishlinskii][output_error]") {
  for (const Model& truth : {known_system<Model>(), integrating()}) {
    INFO("ni = " << truth.ni());
    const Eigen::VectorXd u = bonl::signals::random_levels(300, 5, 1.0, 7);
    Model::OutputErrorTerms terms(truth);
    Eigen::MatrixXd psi(u.size(), truth.num_params());
    for (Eigen::Index k = 0; k < u.size(); ++k) {
      psi.row(k) = terms.step(truth.theta(), u[k]).sensitivity.transpose();
      terms.accept();
    }
    // w is linear in theta's f and g and the plays do not depend on theta: every sample matches.
    CHECK(matching_samples(psi, simulation_differences(truth, u)) == u.size());
  }
}

TEST_CASE("at the truth the Prandtl-Ishlinskii Hammerstein key terms give the output", "[prandtl_ishlinskii]") {
  for (const Model& truth : {known_system<Model>(), integrating()}) {
    const Eigen::VectorXd u = identification_input();
    const Eigen::VectorXd y = truth.simulate(u);
    for (const auto method : {bonl::KeyTermMethod::EquationError, bonl::KeyTermMethod::Paper}) {
      CHECK(worst_key_term_error(truth, u, y, method) <= 1e-12 * (1.0 + y.cwiseAbs().maxCoeff()));
    }
  }
}

TEST_CASE("identify recovers the Prandtl-Ishlinskii Hammerstein known systems, also at a larger amplitude",
          "[prandtl_ishlinskii][identify]") {
  for (const Model& truth : {known_system<Model>(), known_system<Model>("small"), integrating()}) {
    INFO("na = " << truth.na() << ", ni = " << truth.ni());
    const Eigen::VectorXd u = identification_input();
    const Eigen::VectorXd y = truth.simulate(u);
    const Eigen::VectorXd fresh = fresh_input();
    for (bonl::Method method : {bonl::Method::OutputError, bonl::Method::EquationError}) {
      bonl::IdentifyOptions options;
      options.method = method;
      const Model model = bonl::identify(structure_of(truth), u, y, options);
      // Beyond the identification input's range the model continues its polynomial linearly: the
      // truth, given the same range, does the same.
      Model continued = truth;
      continued.set_input_range(u.minCoeff(), u.maxCoeff());
      const double nrmse = bonl::metrics::nrmse(continued.simulate(fresh), model.simulate(fresh));
      std::printf("PrandtlIshlinskiiHammerstein na %d ni %d %-14s fresh NRMSE at amplitude 1.5: %.3e\n",
                  int(truth.na()), int(truth.ni()), bonl::to_string(method), nrmse);
      CHECK(nrmse <= 1e-6);
      CHECK(model.thresholds() == truth.thresholds());
    }
  }
}

TEST_CASE("identify places the thresholds by the data rule where the structure's are not the data's",
          "[prandtl_ishlinskii][identify]") {
  const Model truth = known_system<Model>("small");
  const Eigen::VectorXd u = (identification_input().array() * 0.8 + 0.1).matrix();
  const Eigen::VectorXd y = truth.simulate(u);
  const bonl::CheckedRecords<double> records(u, y, truth.num_params());
  const auto starts = bonl::prandtl_ishlinskii_starts(structure_of(truth), records);
  REQUIRE(starts.size() == 1);
  const double half_range = (u.maxCoeff() - u.minCoeff()) / 2.0;
  CHECK(starts.front().thresholds().isApprox(vec({half_range / 3.0, 2.0 * half_range / 3.0}), 1e-15));
  // A structure that already has the data's thresholds adds no start: its recursive estimates are that one.
  Model ruled = structure_of(truth);
  ruled.set_thresholds(starts.front().thresholds());
  CHECK(bonl::prandtl_ishlinskii_starts(ruled, records).empty());
  // With the structure's thresholds far off (beyond the input's half-range of 0.8, where the plays
  // never turn after the first sweep) the refinement keeps the data rule's start, which simulates better.
  Model off = structure_of(truth);
  off.set_thresholds(vec({1.0, 2.0}));
  const Model from_off = bonl::identify(off, u, y);
  const Eigen::VectorXd fresh = fresh_input();
  const double nrmse = bonl::metrics::nrmse(truth.simulate(fresh), from_off.simulate(fresh));
  std::printf("PrandtlIshlinskiiHammerstein thresholds by the data rule: fresh NRMSE %.3e\n", nrmse);
  CHECK(from_off.thresholds().isApprox(starts.front().thresholds(), 1e-12));
  CHECK(nrmse <= 0.1);
}

TEST_CASE("the online output_error estimator converges on the Prandtl-Ishlinskii Hammerstein known system",
          "[prandtl_ishlinskii][output_error]") {
  const Model truth = known_system<Model>();
  const Eigen::VectorXd u = identification_input();
  const Eigen::VectorXd y = truth.simulate(u);
  bonl::Estimator<Model> estimator(structure_of(truth));
  const Eigen::VectorXd fresh = fresh_input();
  const Eigen::VectorXd y_fresh = truth.simulate(fresh);
  // The fresh NRMSE after 500 samples, after the pass (4000) and after five passes.
  double early = 0.0, after_one = 0.0;
  for (int pass = 0; pass < 5; ++pass) {
    estimator.start_pass();
    for (Eigen::Index k = 0; k < u.size(); ++k) {
      estimator.update(u[k], y[k]);
      if (pass == 0 && k == 499) early = bonl::metrics::nrmse(y_fresh, estimator.model().simulate(fresh));
    }
    if (pass == 0) after_one = bonl::metrics::nrmse(y_fresh, estimator.model().simulate(fresh));
  }
  CHECK_FALSE(estimator.diverged());
  const double after_five = bonl::metrics::nrmse(y_fresh, estimator.model().simulate(fresh));
  std::printf(
      "PrandtlIshlinskiiHammerstein online output_error: fresh NRMSE %.3e after 500 samples, %.3e after "
      "one pass, %.3e after five\n",
      early, after_one, after_five);
  CHECK(after_one <= 1e-8);
  CHECK(after_five <= 1e-8);
  CHECK(near(estimator.theta(), truth.theta(), 1e-8));
}

TEST_CASE("after a measured past the plays' memory is the past input's", "[prandtl_ishlinskii][operating_point]") {
  const Model model = known_system<Model>("small");
  const Eigen::VectorXd u = bonl::signals::random_levels(1500, 5, 1.0, 34);
  const Eigen::VectorXd y = model.simulate(u);
  // The record starts mid-way, at sample 1000, with the plays turned away from rest.
  const Eigen::VectorXd u_record = u.tail(500), y_record = y.tail(500);
  const Eigen::Index window = 100;  // sweeps each play's width 2 r_i, so its memory is the past's
  const Eigen::VectorXd from_rest = model.simulate(u_record.tail(500 - window));
  const Eigen::VectorXd initialised =
      model.simulate(u_record.tail(500 - window), u_record.head(window), y_record.head(window));
  const double rest_error = (from_rest - y_record.tail(500 - window)).norm();
  const double initialised_error = (initialised - y_record.tail(500 - window)).norm();
  INFO("from rest " << rest_error << ", after the past " << initialised_error);
  CHECK(rest_error > 1e-3);
  CHECK(initialised_error <= 1e-10 * rest_error);
}

TEST_CASE("the Prandtl-Ishlinskii Hammerstein model refuses bad orders and thresholds and keeps its own",
          "[prandtl_ishlinskii][bad_input]") {
  CHECK_THROWS_WITH(Model(3, 2, 0, 3, 33), "bonl: np (play operators) must be <= 32");
  CHECK_THROWS_WITH(Model(3, 2, 0, 3, 0), "bonl: np (play operators) must be >= 1, got 0");
  CHECK_THROWS_WITH(Model(3, 2, 0, 0, 2), Catch::Matchers::Contains("r"));

  Model model = known_system<Model>("small");
  const Model before = model;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH(model.set_thresholds(vec({0.6, 0.25})),
                    "bonl: thresholds must be strictly increasing, got 0.6 before 0.25 at index 1");
  CHECK_THROWS_WITH(model.set_thresholds(vec({0.25, 0.25})), Catch::Matchers::Contains("strictly increasing"));
  CHECK_THROWS_WITH(model.set_thresholds(vec({0.0, 0.25})), Catch::Matchers::Contains("must be > 0"));
  CHECK_THROWS_WITH(model.set_thresholds(vec({-0.1, 0.25})), Catch::Matchers::Contains("got -0.1 at index 0"));
  CHECK_THROWS_WITH(model.set_thresholds(vec({0.25, nan})), Catch::Matchers::Contains("thresholds"));
  CHECK_THROWS_WITH(model.set_thresholds(vec({0.25})), Catch::Matchers::Contains("thresholds"));
  CHECK_THROWS_WITH(model.set_b(vec({2.0, 0.4})), Catch::Matchers::Contains("b[0] (b_0) must be 1"));
  CHECK(model.thresholds() == before.thresholds());
  CHECK(model.theta() == before.theta());
}

TEST_CASE("a Prandtl-Ishlinskii Hammerstein model file keeps the thresholds and refuses bad ones",
          "[prandtl_ishlinskii][io]") {
  Model model = known_system<Model>("small");
  model.set_thresholds(vec({0.1, 0.7}));
  const std::string text = bonl::io::to_json(model);
  const Model read = bonl::io::model_from_json<Model>(text);
  CHECK(read.thresholds() == model.thresholds());
  CHECK(read.theta() == model.theta());
  const Eigen::VectorXd u = bonl::signals::random_levels(300, 5, 1.0, 8);
  CHECK(read.simulate(u) == model.simulate(u));
  std::string bad = text;
  const std::size_t first = bad.find("0.1", bad.find("\"thresholds\""));  // thresholds [0.1, 0.7]
  REQUIRE(first != std::string::npos);
  bad.replace(first, 3, "-0.1");
  CHECK_THROWS_WITH(bonl::io::model_from_json<Model>(bad), Catch::Matchers::Contains("thresholds"));
}
