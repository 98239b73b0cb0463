// Order selection in C++ (estimator/select.hpp), which Python's bonl.select runs candidate by candidate
// (tests/python/test_select.py compares the two tables).
// Oracles: data from a known structure, whose orders the selection must find among wrong ones;
// the same selection on one thread and on two (identical tables); each row the candidate scored alone;
// the held-out score recomputed from identify and simulate (from rest and after a window); a candidate
// that cannot be fitted reported in its row while the others are kept.

#include "test_support.hpp"

#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

using namespace bonl_test;

namespace {

/// The known system Model "small" driven by random levels held `hold` samples (seed), its output with
/// white noise (seed + 1): (u, y).
template <class Model>
std::pair<Eigen::VectorXd, Eigen::VectorXd> noisy_record(Eigen::Index samples, Eigen::Index hold, double noise,
                                                         std::uint64_t seed) {
  const Eigen::VectorXd u = bonl::signals::random_levels(samples, hold, 1.0, seed);
  return {u, known_system<Model>("small").simulate(u) + bonl::signals::white_noise(u.size(), noise, seed + 1)};
}

std::vector<bonl::Hammersteind> delay_grid() {
  std::vector<bonl::Hammersteind> grid;
  for (Eigen::Index nk : {1, 2, 3}) grid.emplace_back(2, 1, nk, 2);
  return grid;
}

}  // namespace

TEST_CASE("select finds the delay of a known system and ranks the others behind it", "[select]") {
  const bonl::Hammersteind truth = known_system<bonl::Hammersteind>("small");  // nk = 2
  const Eigen::VectorXd u = bonl::signals::random_levels(2000, 5, 1.0, 71);
  const Eigen::VectorXd y = truth.simulate(u) + bonl::signals::white_noise(u.size(), 0.01, 72);
  const bonl::Records<double> records{{u, y}};
  for (auto criterion : {bonl::SelectionCriterion::Validation, bonl::SelectionCriterion::AIC,
                         bonl::SelectionCriterion::BIC, bonl::SelectionCriterion::CrossValidation}) {
    bonl::SelectOptions options;
    options.criterion = criterion;
    const auto selection = bonl::select(delay_grid(), records, options);
    REQUIRE(selection.table.size() == 3);
    CHECK(selection.table[0].structure.nk() == 2);
    CHECK(selection.best.nk() == 2);
    CHECK(selection.table[0].score <= selection.table[1].score);
    CHECK(selection.table[1].score <= selection.table[2].score);
    // The refitted best is the identification on all the data.
    CHECK(selection.best.theta() == bonl::identify(truth, records).theta());
  }
}

TEST_CASE("select gives the same table on one thread and on two", "[select]") {
  const auto [u, y] = noisy_record<bonl::Hammersteind>(1500, 5, 0.02, 73);
  const bonl::Records<double> records{{u, y}};
  bonl::SelectOptions one, two;
  one.threads = 1;
  two.threads = 2;
  const auto a = bonl::select(delay_grid(), records, one);
  const auto b = bonl::select(delay_grid(), records, two);
  for (std::size_t i = 0; i < a.table.size(); ++i) {
    CHECK(a.table[i].structure.nk() == b.table[i].structure.nk());
    CHECK(a.table[i].score == b.table[i].score);
  }
}

TEST_CASE("select reports a candidate that cannot be fitted in its row and keeps the rest", "[select][bad_input]") {
  const bonl::ARXd truth = known_system<bonl::ARXd>("small");
  const Eigen::VectorXd u = bonl::signals::random_levels(40, 2, 1.0, 75);
  const Eigen::VectorXd y = truth.simulate(u);
  const bonl::Records<double> records{{u, y}};
  // 30 samples to fit on; ARX(20, 20, 0) has 41 parameters.
  const std::vector<bonl::ARXd> grid{bonl::ARXd(20, 20, 0), bonl::ARXd(2, 1, 2)};
  const auto selection = bonl::select(grid, records);
  CHECK(selection.table[0].structure.na() == 2);
  CHECK(selection.table[0].error.empty());
  CHECK(selection.table[1].structure.na() == 20);
  CHECK_THAT(selection.table[1].error, Catch::Matchers::Contains("41 parameters cannot be fitted on the 30 samples"));
  CHECK_FALSE(selection.table[1].model.has_value());

  CHECK_THROWS_WITH(bonl::select(std::vector<bonl::ARXd>{}, records), Catch::Matchers::Contains("candidates is empty"));
  bonl::SelectOptions options;
  options.validation_fraction = 1.0;
  CHECK_THROWS_WITH(bonl::select(grid, records, options),
                    Catch::Matchers::Contains("validation_fraction must be in (0, 1), got 1"));
  const Eigen::VectorXd short_y = y.head(30);
  CHECK_THROWS_WITH(bonl::select(grid, bonl::Records<double>{{u, short_y}}),
                    Catch::Matchers::Contains("records[0].u and records[0].y must have the same length"));
  CHECK_THROWS_AS(bonl::select(std::vector<bonl::ARXd>{bonl::ARXd(20, 20, 0)}, records), bonl::NumericalError);
}

TEST_CASE("each row of select's table is score_candidate's for that candidate", "[select]") {
  const auto [u, y] = noisy_record<bonl::Hammersteind>(1200, 5, 0.02, 76);
  const bonl::Records<double> records{{u, y}};
  bonl::SelectOptions options;
  options.window = 6;
  const bonl::SelectionData<double> data(records, options);
  const auto selection = bonl::select(delay_grid(), data);
  for (const auto& row : selection.table) {
    const auto alone = bonl::score_candidate(row.structure, data);
    CHECK(alone.score == row.score);
    CHECK(alone.fit_mse == row.fit_mse);
    CHECK(alone.validation_mse == row.validation_mse);
  }
}

TEST_CASE("the held-out part is the fraction of the record rounded half away from zero", "[select]") {
  CHECK(bonl::held_out_samples(10, 0.25) == 3);  // 2.5: Python's round() would give 2
  CHECK(bonl::held_out_samples(250, 0.25) == 63);
  CHECK(bonl::held_out_samples(6, 0.25) == 2);
  CHECK(bonl::held_out_samples(3, 0.1) == 1);  // at least one sample
  const auto [u, y] = noisy_record<bonl::ARXd>(10, 1, 0.01, 78);
  const bonl::Records<double> records{{u, y}};
  const bonl::SelectionData<double> data(records, {});
  CHECK(data.split() == std::vector<Eigen::Index>{7});
  // Fitted on the first 7 samples, scored on the last 3 of the record simulated whole.
  const auto row = bonl::score_candidate(bonl::ARXd(1, 1, 0), data);
  const bonl::ARXd fitted = bonl::identify(bonl::ARXd(1, 1, 0), bonl::Records<double>{records[0].head(7)});
  const Eigen::VectorXd error = (y - fitted.simulate(u)).tail(3);
  CHECK(near(row.validation_mse, error.squaredNorm() / 3.0, 1e-12));
  // Seven parameters on seven samples: failed, with why.
  const auto large = bonl::score_candidate(bonl::ARXd(3, 3, 0), data);
  CHECK(large.score == std::numeric_limits<double>::infinity());
  CHECK_FALSE(large.model.has_value());
  CHECK(large.error == "bonl: select: 7 parameters cannot be fitted on the 7 samples of the fit part");
}

TEST_CASE("with a window the held-out part is scored after its first samples", "[select]") {
  const auto [u, y] = noisy_record<bonl::Hammersteind>(800, 5, 0.02, 80);
  const bonl::Records<double> records{{u, y}};
  bonl::SelectOptions options;
  options.window = 7;
  const auto row = bonl::score_candidate(bonl::Hammersteind(2, 1, 2, 2), bonl::SelectionData<double>(records, options));
  const bonl::Hammersteind fitted =
      bonl::identify(bonl::Hammersteind(2, 1, 2, 2), bonl::Records<double>{records[0].head(600)});
  const Eigen::VectorXd after = fitted.simulate(u.tail(193), u.segment(600, 7), y.segment(600, 7));
  CHECK(near(row.validation_mse, (y.tail(193) - after).squaredNorm() / 193.0, 1e-12));

  options.window = 200;  // the held-out part is 200 samples
  CHECK_THROWS_WITH(
      bonl::SelectionData<double>(records, options),
      Catch::Matchers::Contains("records[0]'s held-out part (200 samples) must be longer than the window (200)"));
  options.window = -1;
  CHECK_THROWS_WITH(bonl::SelectionData<double>(records, options),
                    Catch::Matchers::Contains("window must be an integer >= 0, got -1"));
  options.window = 5;
  options.criterion = bonl::SelectionCriterion::AIC;
  CHECK_THROWS_WITH(bonl::SelectionData<double>(records, options),
                    Catch::Matchers::Contains(
                        "window applies to criteria 'validation' and 'cross_validation' only, got criterion 'aic'"));
}

namespace {

/// y(k) = 0.5 y(k-1) + 0.17 u(k-1) + 0.5 y(k-1)^3: stable for |u| <= 1 (0.5 y - 0.5 y^3 reaches 0.17 at
/// y = 0.405, below its maximum 0.192 at y = 0.577), and with no rest point, diverging, where
/// 0.17 |u| > 0.192: for inputs 1.25 times larger.
bonl::NonlinearFeedbackd softening_feedback() {
  bonl::NonlinearFeedbackd model(1, 0, 1, 3, 0, 1, 0);
  model.set_b(Eigen::VectorXd::Constant(1, 0.17));
  model.set_a(Eigen::VectorXd::Constant(1, -0.5));
  model.set_f(Eigen::Vector2d(0.0, 0.5));
  return model;
}

}  // namespace

TEST_CASE("select does not choose a model whose free run diverges on inputs somewhat beyond the measured", "[select]") {
  const bonl::NonlinearFeedbackd truth = softening_feedback();
  const Eigen::VectorXd u = bonl::signals::random_levels(1200, 40, 1.0, 77);  // long holds: time to diverge
  const Eigen::VectorXd y = truth.simulate(u);
  // The oracle: the truth's own free run, bounded on u and diverging on 1.25 u.
  Eigen::VectorXd simulated;
  REQUIRE(truth.try_simulate(u, simulated));
  REQUIRE_FALSE(truth.try_simulate((bonl::kFreeRunStretch * u).eval(), simulated));

  // The true structure fits the held-out data exactly, and is refused; the linear one (r = 1) is chosen.
  const bonl::Records<double> records{{u, y}};
  const std::vector<bonl::NonlinearFeedbackd> grid{bonl::NonlinearFeedbackd(1, 0, 1, 3, 0, 1, 0),
                                                   bonl::NonlinearFeedbackd(1, 0, 1, 1, 0, 1, 0)};
  const auto selection = bonl::select(grid, records);
  REQUIRE(selection.table.size() == 2);
  CHECK(selection.table[0].structure.r() == 1);
  CHECK(selection.table[0].error.empty());
  CHECK(std::isfinite(selection.table[0].score));
  CHECK(selection.table[1].structure.r() == 3);
  CHECK_THAT(selection.table[1].error,
             Catch::Matchers::Contains("its free run diverges on records[0]'s input stretched 1.25 times about u0"));
  CHECK(selection.table[1].score == std::numeric_limits<double>::infinity());
  REQUIRE(selection.table[1].model.has_value());  // kept, for the user to look at
  CHECK_FALSE(selection.table[1].model->try_simulate((bonl::kFreeRunStretch * u).eval(), simulated));
  CHECK(selection.best.r() == 1);
  CHECK(selection.best.try_simulate((bonl::kFreeRunStretch * u).eval(), simulated));

  // refit(), select()'s last step, refuses the true structure on all the data with the same reason.
  const bonl::SelectionData<double> data(records, {});
  std::string why;
  CHECK_FALSE(bonl::refit(grid[0], data, why).has_value());
  CHECK_THAT(why, Catch::Matchers::Contains("diverges"));
  // With only it to choose from, select says so rather than return it.
  CHECK_THROWS_WITH(
      bonl::select(std::vector<bonl::NonlinearFeedbackd>{grid[0]}, records),
      Catch::Matchers::Contains("every candidate failed: none has a finite score and a bounded free run"));
}

TEST_CASE("select does not choose a model whose free run leaves ten half-ranges of the measured output", "[select]") {
  // Data from an ARX gain of 1, and a model of gain 100 judged on them: its run goes about 100 half-ranges
  // from the middle (oracle: computed here from the simulation).
  bonl::ARXd model(1, 0, 1);
  model.set_b(Eigen::VectorXd::Constant(1, 50.0));
  model.set_a(Eigen::VectorXd::Constant(1, -0.5));
  const Eigen::VectorXd u = bonl::signals::random_levels(600, 5, 1.0, 78);
  Eigen::VectorXd y = (model.simulate(u) / 100.0).eval();
  const bonl::Records<double> records{{u, y}};
  const double middle = 0.5 * (y.maxCoeff() + y.minCoeff()), half = 0.5 * (y.maxCoeff() - y.minCoeff());
  const Eigen::VectorXd run = model.simulate((bonl::kFreeRunStretch * u).eval());
  const double furthest = (run.array() - middle).abs().maxCoeff() / half;
  REQUIRE(furthest > 100.0);
  const std::string why = bonl::detail::unbounded_free_run(model, records);
  CHECK_THAT(why, Catch::Matchers::Contains("its free run on records[0]'s input goes"));
  CHECK_THAT(why, Catch::Matchers::Contains("half-ranges of the measured output from its middle (at most 10)"));
  // The same model scaled to the data is bounded.
  model.set_b(Eigen::VectorXd::Constant(1, 0.5));
  CHECK(bonl::detail::unbounded_free_run(model, records).empty());
}

TEST_CASE("cross-validation holds each block out once and scores it by the fold's own fit", "[select]") {
  const auto [u, y] = noisy_record<bonl::Hammersteind>(900, 5, 0.02, 82);
  const auto [u2, y2] = noisy_record<bonl::Hammersteind>(500, 5, 0.02, 84);
  const bonl::Records<double> records{{u, y}, {u2, y2}};
  const bonl::Hammersteind structure(2, 1, 2, 2);
  for (const auto& [window, state] : {std::pair{Eigen::Index(0), bonl::InitialState::Measured},
                                      std::pair{Eigen::Index(6), bonl::InitialState::Measured},
                                      std::pair{Eigen::Index(0), bonl::InitialState::Estimated},
                                      std::pair{Eigen::Index(6), bonl::InitialState::Estimated}}) {
    CAPTURE(window, bonl::to_string(state));
    bonl::SelectOptions options;
    options.criterion = bonl::SelectionCriterion::CrossValidation;
    options.folds = 3;
    options.window = window;
    options.fold_initial_state = state;
    const auto row = bonl::score_candidate(structure, bonl::SelectionData<double>(records, options));
    REQUIRE(row.error.empty());
    REQUIRE(row.fold_mse.size() == 3);
    // The oracle: each fold fitted with identify on the parts around its blocks (after a window of
    // kFoldFitWindow samples, its state from there as fold_initial_state says), each block simulated
    // with the public simulate().
    bonl::IdentifyOptions fit;
    fit.initialisation_window = std::max(window, bonl::kFoldFitWindow);
    fit.initial_state = state;
    double squared = 0.0, count = 0.0;
    for (int f = 0; f < 3; ++f) {
      bonl::Records<double> parts;
      std::vector<std::pair<Eigen::Index, Eigen::Index>> blocks;
      for (const auto& record : records) {
        const Eigen::Index n = record.u.size();
        const Eigen::Index begin = (n * f + 1) / 3, end = (n * (f + 1) + 1) / 3;  // round(f n / 3)
        blocks.emplace_back(begin, end);
        if (begin > fit.initialisation_window) parts.push_back(record.head(begin));
        if (n - end > fit.initialisation_window) parts.push_back(record.segment(end, n - end));
      }
      const bonl::Hammersteind model = bonl::identify(structure, parts, fit);
      double fold_squared = 0.0, fold_count = 0.0;
      for (std::size_t i = 0; i < records.size(); ++i) {
        const auto [begin, end] = blocks[i];
        const auto& record = records[i];
        Eigen::VectorXd error;
        if (window == 0) {
          error = (record.y.head(end) - model.simulate(record.u.head(end))).tail(end - begin);
        } else {
          const Eigen::Index first = begin + window;
          error = record.y.segment(first, end - first) - model.simulate(record.u.segment(first, end - first),
                                                                        record.u.segment(begin, window),
                                                                        record.y.segment(begin, window));
        }
        fold_squared += error.squaredNorm();
        fold_count += static_cast<double>(error.size());
      }
      CHECK(near(row.fold_mse[static_cast<std::size_t>(f)], fold_squared / fold_count, 1e-12));
      squared += fold_squared;
      count += fold_count;
    }
    CHECK(near(row.score, squared / count, 1e-12));
    CHECK(row.validation_mse == row.score);
    // The estimated state is a fit of its own: the folds' models, and so the score, differ.
    options.fold_initial_state = bonl::InitialState::Measured;
    if (state == bonl::InitialState::Estimated) {
      CHECK(row.score != bonl::score_candidate(structure, bonl::SelectionData<double>(records, options)).score);
    }
    // The refit on all the records: after the window, as the folds were fitted and as it is scored,
    // with identify's own (measured) state whatever the folds'.
    options.fold_initial_state = state;
    bonl::IdentifyOptions refit;
    refit.initialisation_window = window;
    const auto selection = bonl::select(std::vector<bonl::Hammersteind>{structure}, records, options);
    CHECK(selection.best.theta() == bonl::identify(structure, records, refit).theta());
  }
}

TEST_CASE("cross-validation's folds and blocks are checked", "[select][bad_input]") {
  const auto [u, y] = noisy_record<bonl::ARXd>(100, 2, 0.01, 86);
  const bonl::Records<double> records{{u, y}};
  bonl::SelectOptions options;
  options.criterion = bonl::SelectionCriterion::CrossValidation;
  options.folds = 1;
  CHECK_THROWS_WITH(bonl::SelectionData<double>(records, options),
                    Catch::Matchers::Contains("folds must be >= 2, got 1"));
  options.folds = 5;
  // The folds' initial state is cross-validation's alone.
  options.criterion = bonl::SelectionCriterion::Validation;
  options.fold_initial_state = bonl::InitialState::Estimated;
  CHECK_THROWS_WITH(bonl::SelectionData<double>(records, options),
                    Catch::Matchers::Contains("fold_initial_state 'estimated' applies to criterion "
                                              "'cross_validation' only, got criterion 'validation'"));
  options.criterion = bonl::SelectionCriterion::CrossValidation;
  options.fold_initial_state = bonl::InitialState::Measured;
  options.window = 20;  // blocks of 20 samples
  CHECK_THROWS_WITH(
      bonl::SelectionData<double>(records, options),
      Catch::Matchers::Contains("records[0]'s 5 cross-validation blocks (20 samples the shortest) must be "
                                "longer than the window (20)"));
  // Folds without enough samples fail the candidate, not the selection.
  options.window = 0;
  options.folds = 50;  // blocks of 2 samples: every fold keeps a part
  const auto row = bonl::score_candidate(bonl::ARXd(1, 0, 0), bonl::SelectionData<double>(records, options));
  CHECK(row.error.empty());
  CHECK(row.fold_mse.size() == 50);
}
