// identify()'s initialisation window (IdentifyOptions::initialisation_window): the refinement fits
// each record's free run after its first m samples, measured, as Model::simulate(u, u_past, y_past)
// runs it.
// - Its normal equations: the oracle is J from central differences of that simulation (step 1e-6
//   relative, test_support.hpp's run_differences); the refinement takes forward differences (step
//   sqrt(eps) relative).
// - A known integrating system (the friction drive, ni = 1) recorded in motion, noise-free: fitted
//   after a window it is recovered to NRMSE <= 1e-6 on a fresh record, scored the same way; fitted
//   from rest, the start's transient stays in the integrated output and it is not.
// - select() ranks by the free run as it was fitted: fit_mse is the windowed run's MSE, recomputed.
// - With the initial state estimated (InitialState::Estimated): the window outputs the run depends
//   on are an ARX model's na + ni lags (the oracle: its difference equation); their Jacobian columns
//   are the central differences of the run in those outputs, zero on the other records' rows; and
//   the integrating system recorded in motion, noise-free but for its windows' outputs, is recovered
//   to NRMSE <= 1e-6, where the fit from the measured windows follows their noise.
// - Bad windows are refused with the option's name.

#include "test_support.hpp"

#include <vector>

using namespace bonl_test;

namespace {

/// The free run of u's samples from `window` on, after its first `window` samples of (u, y).
template <class Model>
Eigen::VectorXd after_window(const Model& model, const Eigen::VectorXd& u, const Eigen::VectorXd& y,
                             Eigen::Index window) {
  const Eigen::Index n = u.size() - window;
  return model.simulate(u.tail(n), u.head(window), y.head(window));
}

/// A record of `samples` samples that starts in motion: the system run from rest on a longer input,
/// its first `lead` samples dropped.
struct MovingRecord {
  Eigen::VectorXd u, y;
};
template <class Model>
MovingRecord moving_record(const Model& truth, Eigen::Index samples, Eigen::Index lead, unsigned seed) {
  const Eigen::VectorXd u = bonl::signals::random_levels(lead + samples, 5, 1.0, seed);
  const Eigen::VectorXd y = truth.simulate(u);
  return {u.tail(samples), y.tail(samples)};
}

/// The normal equations J'J and J'e, to 1e-5 relative, against the oracle's J and the error e.
void check_normal_equations(const Eigen::MatrixXd& normal, const Eigen::VectorXd& gradient,
                            const Eigen::MatrixXd& jacobian, const Eigen::VectorXd& error) {
  const Eigen::MatrixXd expected_normal = jacobian.transpose() * jacobian;
  const Eigen::VectorXd expected_gradient = jacobian.transpose() * error;
  CHECK((normal - expected_normal).norm() <= 1e-5 * expected_normal.norm());
  CHECK((gradient - expected_gradient).norm() <= 1e-5 * expected_gradient.norm());
}

double nrmse(const Eigen::VectorXd& simulated, const Eigen::VectorXd& measured) {
  const double spread = std::sqrt((measured.array() - measured.mean()).square().mean());
  return std::sqrt((simulated - measured).squaredNorm() / static_cast<double>(measured.size())) / spread;
}

}  // namespace

TEMPLATE_LIST_TEST_CASE("with an initialisation window the refinement's normal equations are the windowed run's",
                        "[initialisation_window]", bonl::Models) {
  const TestType model = known_system<TestType>("small");
  const Eigen::Index window = 12;
  const Eigen::VectorXd u = bonl::signals::random_levels(1500, 5, 1.0, 21);
  const Eigen::VectorXd y = model.simulate(u) + bonl::signals::white_noise(u.size(), 0.01, 22);
  const bonl::Records<double> records{{u, y}};
  const Eigen::VectorXd scored = bonl::detail::stacked_outputs(records, window);
  REQUIRE(scored.size() == u.size() - window);
  Eigen::MatrixXd normal;
  Eigen::VectorXd gradient;
  REQUIRE(bonl::detail::window_normal_equations(model, records, window, scored, normal, gradient));

  const Eigen::MatrixXd jacobian =
      run_differences(model, [&](const TestType& m) -> Eigen::VectorXd { return after_window(m, u, y, window); });
  check_normal_equations(normal, gradient, jacobian, y.tail(scored.size()) - after_window(model, u, y, window));
}

TEST_CASE("an integrating system recorded in motion is recovered when fitted after its initialisation window",
          "[initialisation_window]") {
  const bonl::NonlinearFeedbackd truth = friction_drive_position();
  const Eigen::Index window = 10;
  const MovingRecord fit = moving_record(truth, 4000, 700, 23);
  const MovingRecord fresh = moving_record(truth, 3000, 900, 24);
  REQUIRE(std::abs(fit.y[1] - fit.y[0]) > 1e-3);  // in motion at the record's start

  bonl::IdentifyOptions options;
  options.initialisation_window = window;
  const bonl::NonlinearFeedbackd fitted = bonl::identify(truth, fit.u, fit.y, options);
  const double windowed = nrmse(after_window(fitted, fresh.u, fresh.y, window), fresh.y.tail(fresh.y.size() - window));
  CHECK(windowed <= 1e-6);

  const bonl::NonlinearFeedbackd from_rest = bonl::identify(truth, fit.u, fit.y);
  const double rest = nrmse(after_window(from_rest, fresh.u, fresh.y, window), fresh.y.tail(fresh.y.size() - window));
  CHECK(rest > 1e3 * windowed);
}

TEST_CASE("select ranks by the free run as it was fitted, after the initialisation window", "[initialisation_window]") {
  const bonl::NonlinearFeedbackd truth = friction_drive_position();
  const Eigen::Index window = 10;
  const MovingRecord record = moving_record(truth, 2000, 500, 25);
  bonl::SelectOptions options;
  options.criterion = bonl::SelectionCriterion::BIC;
  options.identify.initialisation_window = window;
  options.identify.refine_iterations = 20;
  const bonl::SelectionData<double> data(bonl::Records<double>{{record.u, record.y}}, options);
  const auto row = bonl::score_candidate(truth, data);
  REQUIRE(row.model);
  const Eigen::VectorXd simulated = after_window(*row.model, record.u, record.y, window);
  const double expected = (record.y.tail(simulated.size()) - simulated).squaredNorm() / double(simulated.size());
  CHECK(row.fit_mse == Approx(expected).epsilon(1e-12));
}

TEST_CASE("the initial state's estimated outputs are an ARX model's lags", "[initialisation_window]") {
  // y(k) depends on the na outputs before it; with ni integrators on the na + ni before it.
  const Eigen::VectorXd u = bonl::signals::random_levels(300, 5, 1.0, 27);
  for (const int ni : {0, 1, 2}) {
    bonl::ARXd model(3, 2, 1, ni);
    model.set_a(vec({-0.5, 0.2, -0.1}));
    model.set_b(vec({0.3, 0.1, 0.05}));
    const Eigen::VectorXd y = model.simulate(u);
    const bonl::Records<double> records{{u, y}};
    CHECK(bonl::detail::window_memory(model, records, 10) == std::vector<Eigen::Index>{3 + ni});
    CHECK(bonl::detail::window_memory(model, records, 2) == std::vector<Eigen::Index>{2});  // all of a short window
  }
}

TEMPLATE_LIST_TEST_CASE("with the initial state estimated the normal equations' last columns are its outputs' own",
                        "[initialisation_window]", bonl::Models) {
  const TestType model = known_system<TestType>("small");
  const Eigen::Index window = 12;
  const Eigen::VectorXd u0 = bonl::signals::random_levels(700, 5, 1.0, 28);
  const Eigen::VectorXd u1 = bonl::signals::random_levels(500, 5, 1.0, 29);
  const Eigen::VectorXd y0 = model.simulate(u0) + bonl::signals::white_noise(u0.size(), 0.01, 30);
  const Eigen::VectorXd y1 = model.simulate(u1) + bonl::signals::white_noise(u1.size(), 0.01, 31);
  const bonl::Records<double> records{{u0, y0}, {u1, y1}};
  const std::vector<Eigen::Index> free = bonl::detail::window_memory(model, records, window);
  REQUIRE(free.size() == 2);
  REQUIRE(free[0] >= 1);  // each record's own: a backlash inside its gap remembers further back
  REQUIRE(free[1] >= 1);
  // Moved from the measured outputs, so that the columns are taken somewhere else than there.
  std::vector<Eigen::VectorXd> past{y0.head(window), y1.head(window)};
  past[0][window - 1] += 0.01;
  past[1][window - 1] -= 0.02;
  const Eigen::VectorXd scored = bonl::detail::stacked_outputs(records, window);
  Eigen::MatrixXd normal;
  Eigen::VectorXd gradient;
  REQUIRE(bonl::detail::window_normal_equations(model, records, window, scored, normal, gradient, Eigen::VectorXd(),
                                                past, free));
  const Eigen::Index n = model.num_params();
  REQUIRE(normal.rows() == n + free[0] + free[1]);

  // The oracle: J from central differences of the two runs (step 1e-6), in theta and in each output.
  const auto run = [&](const TestType& m, const std::vector<Eigen::VectorXd>& outputs) -> Eigen::VectorXd {
    Eigen::VectorXd both(scored.size());
    both << m.simulate(u0.tail(u0.size() - window), u0.head(window), outputs[0]),
        m.simulate(u1.tail(u1.size() - window), u1.head(window), outputs[1]);
    return both;
  };
  Eigen::MatrixXd jacobian(scored.size(), normal.rows());
  jacobian.leftCols(n) = run_differences(model, [&](const TestType& m) { return run(m, past); });
  Eigen::Index column = n;
  for (std::size_t r = 0; r < 2; ++r) {
    for (Eigen::Index j = window - free[r]; j < window; ++j, ++column) {
      std::vector<Eigen::VectorXd> plus = past, minus = past;
      const double step = 1e-6 * std::max(1.0, std::abs(past[r][j]));
      plus[r][j] += step;
      minus[r][j] -= step;
      jacobian.col(column) = (run(model, plus) - run(model, minus)) / (2 * step);
    }
  }
  const Eigen::Index first = u0.size() - window;
  CHECK(jacobian.block(first, n, jacobian.rows() - first, free[0]).isZero(0.0));  // record 0's outputs, record 1's rows
  CHECK(jacobian.block(0, n + free[0], first, free[1]).isZero(0.0));
  check_normal_equations(normal, gradient, jacobian, scored - run(model, past));
}

TEST_CASE("an integrating system whose windows' outputs are noisy is recovered with its initial state estimated",
          "[initialisation_window]") {
  const bonl::NonlinearFeedbackd truth = friction_drive_position();
  const Eigen::Index window = 10;
  MovingRecord first = moving_record(truth, 2500, 700, 32), second = moving_record(truth, 2000, 400, 33);
  const MovingRecord fresh = moving_record(truth, 3000, 900, 34);
  // Output noise on the windows alone: the records after them are exact, so the truth with the
  // windows' true outputs fits them exactly, and from the measured windows it cannot.
  first.y.head(window) += bonl::signals::white_noise(window, 0.01, 35);
  second.y.head(window) += bonl::signals::white_noise(window, 0.01, 36);
  const bonl::Records<double> records{{first.u, first.y}, {second.u, second.y}};
  bonl::IdentifyOptions options;
  options.initialisation_window = window;
  const auto fresh_nrmse = [&](const bonl::NonlinearFeedbackd& model) {
    return nrmse(after_window(model, fresh.u, fresh.y, window), fresh.y.tail(fresh.y.size() - window));
  };
  const double measured = fresh_nrmse(bonl::identify(truth, records, options));
  options.initial_state = bonl::InitialState::Estimated;
  const double estimated = fresh_nrmse(bonl::identify(truth, records, options));
  CHECK(estimated <= 1e-6);
  CHECK(measured > 1e3 * estimated);
}

TEST_CASE("E24 a bad initialisation window is refused with its name", "[initialisation_window][bad_input]") {
  const bonl::NonlinearFeedbackd truth = friction_drive_position();
  const MovingRecord record = moving_record(truth, 200, 50, 26);
  bonl::IdentifyOptions options;
  options.initialisation_window = -1;
  CHECK_THROWS_WITH(bonl::identify(truth, record.u, record.y, options),
                    Catch::Matchers::Contains("initialisation_window must be >= 0, got -1"));
  options.initialisation_window = 200;
  CHECK_THROWS_WITH(bonl::identify(truth, record.u, record.y, options),
                    Catch::Matchers::Contains("initialisation_window (200) must be shorter than every record; "
                                              "records[0] has 200 samples"));
  options.initialisation_window = 195;
  CHECK_THROWS_WITH(bonl::identify(truth, record.u, record.y, options),
                    Catch::Matchers::Contains("the records after their initialisation_window must be longer together "
                                              "than the number of parameters (9), got 5 samples"));
  bonl::SelectOptions select_options;
  select_options.identify.initialisation_window = 150;  // the fit part is 150 of the 200 samples
  CHECK_THROWS_WITH(bonl::SelectionData<double>(bonl::Records<double>{{record.u, record.y}}, select_options),
                    Catch::Matchers::Contains("initialisation_window (150) must be shorter than every record"));
  CHECK_THROWS_WITH(bonl::refine_output_error(truth, bonl::Records<double>{{record.u, record.y}}, 10, nullptr, 300),
                    Catch::Matchers::Contains("initialisation_window (300) must be shorter than every record"));
  options.initialisation_window = 0;
  options.initial_state = bonl::InitialState::Estimated;
  CHECK_THROWS_WITH(bonl::identify(truth, record.u, record.y, options),
                    Catch::Matchers::Contains("initial_state 'estimated' needs an initialisation_window > 0"));
  const bonl::CheckedRecords<double> checked(record.u, record.y, truth.num_params());
  CHECK_THROWS_WITH(bonl::refine_output_error(std::vector<bonl::NonlinearFeedbackd>{truth}, checked, 10, nullptr, 0, {},
                                              bonl::InitialState::Estimated),
                    Catch::Matchers::Contains("initial_state 'estimated' needs an initialisation_window > 0"));
}
