// The paper's experiment (experiment/paper_experiment.hpp): the paper's orders and labels, the
// records of the default experiment, and the end-to-end result: the paper's ranking of the models.

#include "test_support.hpp"

#include <cstdio>
#include <set>
#include <string>

#include <bonl/experiment/paper_experiment.hpp>

using namespace bonl_test;
namespace experiment = bonl::experiment;
using bonl::Method;

namespace {

/// " ARX 7.9977e-04, Hammerstein ...": every model's validation MSE, for messages.
std::string validation_mse(const experiment::MethodResult& m) {
  std::string text;
  m.for_each([&](const auto& r) {
    char number[32];
    std::snprintf(number, sizeof number, " %.4e", r.mse);
    text += (text.empty() ? " " : ", ") + std::string(r.kName) + number;
  });
  return text;
}

}  // namespace

TEST_CASE("the paper's models, orders and labels come from the models' descriptions", "[experiment]") {
  const auto proposed = experiment::paper_model<bonl::PaperPseudoHammersteinWiener>();
  CHECK(proposed.orders() == std::array<Eigen::Index, 5>{3, 2, 8, 3, 0});
  const auto with_q = experiment::paper_model<bonl::HammersteinWienerd>();  // run-time orders: the same values
  CHECK(with_q.orders() == std::array<Eigen::Index, 6>{3, 2, 8, 3, 3, 0});
  CHECK_THROWS_WITH(experiment::paper_order("nx"),
                    Catch::Matchers::StartsWith("bonl: ") && Catch::Matchers::Contains("no order 'nx'"));
  // The model beside P-H-W: np as the polynomial's r, the thresholds its default until the data place them.
  const auto plays = experiment::paper_model<bonl::PrandtlIshlinskiiHammersteind>();
  CHECK(plays.orders() == std::array<Eigen::Index, 6>{3, 2, 8, 3, experiment::paper_order("r"), 0});
  CHECK(plays.thresholds() == bonl::PrandtlIshlinskiiHammersteind(3, 2, 8, 3, 3).thresholds());
  CHECK(experiment::paper_label("PrandtlIshlinskiiHammerstein") == "P-I-H");
  CHECK_FALSE(experiment::published_score("PrandtlIshlinskiiHammerstein"));
  CHECK(experiment::paper_label("PseudoHammersteinWiener") == "P-H-W");
  CHECK(experiment::paper_label("HammersteinWiener") == "H-W");
  CHECK(experiment::paper_label("Hammerstein") == "Hammerstein");
  CHECK(experiment::paper_label("ARX") == "ARX");
  // Table 1's rows: a and q are numbered from 1, b, f and p from 0, c is one number.
  std::set<std::string> labels;
  for (const auto& [label, value] : experiment::labelled_parameters(proposed)) labels.insert(label);
  CHECK(labels ==
        std::set<std::string>{"b0", "b1", "b2", "a1", "a2", "a3", "f0", "f1", "f2", "f3", "p0", "p1", "p2", "p3", "c"});
  const auto with_q_rows = experiment::labelled_parameters(with_q);
  CHECK(with_q_rows.back().first == "q3");
  CHECK(with_q_rows.back().second == with_q.q()[2]);
  CHECK(experiment::published_score("PseudoHammersteinWiener")->mse == 0.0289);
  CHECK_FALSE(experiment::published_score("Wiener"));
}

TEST_CASE("the default experiment: records, end stops, and the paper's ranking", "[experiment][slow]") {
  const bonl::plant::Parameters parameters;
  const experiment::PaperExperimentResult result = experiment::run_paper_experiment(parameters);
  for (const auto* record : {&result.records.identification, &result.records.validation}) {
    CHECK(record->velocity.size() == 5001);
    CHECK_FALSE(record->trajectory.reached_end_stop);
    CHECK(record->trajectory.min_position > 0.0);
    CHECK(record->trajectory.max_position < parameters.stroke);
    // The processed velocity follows the plant's joint rate: the 10 Hz filter and the noise leave
    // a small part of its spread.
    CHECK(bonl::metrics::nrmse(record->true_velocity, record->velocity) < 0.2);
  }
  // Both methods, every model, the robustness check on its eight trajectories.
  REQUIRE(result.methods.size() == 2);
  CHECK(result.robustness_trajectories == 8);
  for (const experiment::MethodResult& m : result.methods) {
    m.for_each([&](const auto& r) {
      INFO(bonl::to_string(m.method) << " " << r.kName);
      CHECK(r.simulated.size() == 5001);
      CHECK(r.mse == Approx(bonl::metrics::mse(result.records.validation.velocity, r.simulated)).epsilon(1e-12));
      CHECK(std::isfinite(r.online_mse));
      CHECK(r.robustness_mse.size() == 8);
    });
  }
  CHECK_THROWS_WITH(result.method(Method::EquationError), Catch::Matchers::Contains("equation_error was not run"));
  // The Prandtl-Ishlinskii Hammerstein model's thresholds are the data rule's on the identification
  // input, for both methods and the online estimate alike (the paper method's recursion and the
  // online one never see identify's extra start).
  const double half_range =
      (result.records.identification.input.maxCoeff() - result.records.identification.input.minCoeff()) / 2.0;
  const Eigen::VectorXd ruled =
      bonl::PlayOperators<double>::spread_thresholds(experiment::paper_order("np"), half_range);
  // The smallest is wider than the plant's pilot play, in volts beyond the dead band (README).
  CHECK(ruled[0] >
        parameters.dead_band + parameters.pilot_hysteresis * (parameters.neutral_voltage - parameters.dead_band));
  for (const experiment::MethodResult& m : result.methods) {
    INFO(bonl::to_string(m.method));
    CHECK(m.get<bonl::PrandtlIshlinskiiHammersteind>().model.thresholds() == ruled);
    CHECK(m.get<bonl::PrandtlIshlinskiiHammersteind>().online_model.thresholds() == ruled);
  }
  // The paper's ranking P-H-W < Hammerstein < ARX holds for the default method. With the paper's
  // own estimator, Hammerstein < ARX holds but its P-H-W does not beat its Hammerstein on this
  // validation record (docs/explanation/paper_experiment.md: eq. (27) feeds the gap samples the output's
  // increments), so only what holds is asserted for it, and the shortfall is printed.
  using bonl::PaperARX;
  using bonl::PaperHammerstein;
  using bonl::PaperPseudoHammersteinWiener;
  const experiment::MethodResult& ours = result.method(Method::OutputError);
  INFO("default: MSE" << validation_mse(ours));
  CHECK(ours.get<PaperPseudoHammersteinWiener>().mse < ours.get<PaperHammerstein>().mse);
  CHECK(ours.get<PaperHammerstein>().mse < ours.get<PaperARX>().mse);
  // The plays before the linear block take part of the hysteresis P-H-W's backlash models: below
  // Hammerstein, above P-H-W (README, "The experiment").
  using bonl::PrandtlIshlinskiiHammersteind;
  CHECK(ours.get<PrandtlIshlinskiiHammersteind>().mse < ours.get<PaperHammerstein>().mse);
  CHECK(ours.get<PrandtlIshlinskiiHammersteind>().mse > ours.get<PaperPseudoHammersteinWiener>().mse);
  const experiment::MethodResult& paper = result.method(Method::Paper);
  std::printf("paper method: MSE%s\n", validation_mse(paper).c_str());
  CHECK(paper.get<PaperHammerstein>().mse < paper.get<PaperARX>().mse);
}

TEST_CASE("without pilot hysteresis and pin backlash the identified c is near zero", "[experiment][slow]") {
  // Bound: 1% of the validation velocity's standard deviation (0.117 rad/s); measured 2e-6 rad/s
  // with the default method. The paper method ends at 0.013 and is not held to it.
  bonl::plant::Parameters parameters;
  parameters.pilot_hysteresis = 0.0;
  parameters.joint_backlash = 0.0;
  const auto records = experiment::acquire(parameters);
  const auto ours = experiment::identify_paper_models(records, Method::OutputError);
  CHECK(ours.get<bonl::PaperPseudoHammersteinWiener>().model.c() <=
        0.01 * standard_deviation(records.validation.velocity));
}

TEST_CASE("P-H-W's advantage grows with the pilot hysteresis, and P-I-H's less", "[experiment][slow]") {
  // The valve backlash is what P-H-W models: with none, P-H-W and Hammerstein are equal; at 8% of
  // full opening P-H-W's error is clearly below Hammerstein's (measured: 3.8e-4 against 8.4e-4).
  double ratio[2], plays[2];
  for (int i = 0; i < 2; ++i) {
    bonl::plant::Parameters parameters;
    parameters.pilot_hysteresis = i == 0 ? 0.0 : 0.08;
    const auto models = experiment::identify_paper_models(experiment::acquire(parameters), Method::OutputError);
    ratio[i] = models.get<bonl::PaperPseudoHammersteinWiener>().mse / models.get<bonl::PaperHammerstein>().mse;
    plays[i] = models.get<bonl::PrandtlIshlinskiiHammersteind>().mse / models.get<bonl::PaperHammerstein>().mse;
  }
  CHECK(ratio[0] == Approx(1.0).epsilon(0.05));
  CHECK(ratio[1] < 0.6);
  // The Prandtl-Ishlinskii Hammerstein model gains on Hammerstein too, as its plays take the
  // hysteresis (measured: 1.09 at none, 0.57 at 8%), but less than P-H-W.
  CHECK(plays[1] < plays[0]);
  CHECK(plays[1] < 1.0);
  CHECK(ratio[1] < plays[1]);
}
