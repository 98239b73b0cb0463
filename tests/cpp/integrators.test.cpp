// Integrators in the linear blocks (detail/integrators.hpp): the order ni of every model of bonl::Models.
// The oracle is the same model without integrators whose denominator is A (1 - q^-1)^ni multiplied out
// here (na + ni estimated poles, no integrator code on its path):
// - the free run equals the oracle's; at the truth predict() and simulate() after a measured past give
//   the output;
// - the output-error sensitivities equal central finite differences of the free run;
// - the estimated A alone is what pole_radius() and the stability test see;
// - a model file keeps ni, a file without it reads as 0, and ni outside 0..2 is refused;
// - the control inverse runs on the whole denominator: an integrating model follows its reference;
// - identify() recovers the models with an integrator from noise-free data (to NRMSE 1e-6 but two,
//   whose figures are below).

#include "test_support.hpp"

#include <bonl/control.hpp>
#include <bonl/io.hpp>

#include <cctype>
#include <cstring>
#include <string>

using namespace bonl_test;

namespace {

/// The index of the last order named `prefix` or `prefix` and a block's number (the block with the
/// integrators: na, or the Wiener-Hammerstein model's na2), or of the block of parameters named so
/// (a, a2; not alpha).
template <class Entries>
std::size_t last_starting_with(const Entries& entries, const char* prefix) {
  const std::size_t length = std::strlen(prefix);
  std::size_t found = entries.size();
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const char* name = entries[i].name;
    if (std::strncmp(name, prefix, length) != 0) continue;
    if (name[length] == '\0' || std::isdigit(static_cast<unsigned char>(name[length]))) found = i;
  }
  REQUIRE(found < entries.size());
  return found;
}

/// `model` with its orders changed by `change` and its parameters copied, the denominator given.
template <class Model, class Change>
Model rebuilt(const Model& model, Change&& change, const Eigen::VectorXd& denominator) {
  constexpr auto& description = Model::kDescription;
  auto orders = model.orders();
  change(orders);
  Model out = bonl::make_model<Model>(orders);
  const std::size_t a = last_starting_with(description.parameters, "a");
  for (std::size_t i = 0; i < description.parameters.size(); ++i) {
    out.set_parameter(i, i == a ? denominator : model.parameter(i));
  }
  return out;
}

/// The model with ni integrators and the same estimated parameters.
template <class Model>
Model with_integrators(const Model& model, Eigen::Index ni) {
  const std::size_t a = last_starting_with(Model::kDescription.parameters, "a");
  return rebuilt(
      model, [ni](auto& orders) { orders.back() = ni; }, model.parameter(a));
}

/// The oracle: no integrators, the denominator A (1 - q^-1)^ni multiplied out by convolution.
template <class Model>
Model multiplied_out(const Model& model) {
  constexpr auto& description = Model::kDescription;
  const Eigen::Index ni = model.orders().back();
  const Eigen::VectorXd a = model.parameter(last_starting_with(description.parameters, "a"));
  Eigen::VectorXd poly(a.size() + 1);
  poly << 1.0, a;
  for (Eigen::Index n = 0; n < ni; ++n) {
    Eigen::VectorXd next = Eigen::VectorXd::Zero(poly.size() + 1);
    next.head(poly.size()) += poly;
    next.tail(poly.size()) -= poly;
    poly = next;
  }
  const std::size_t na = last_starting_with(description.orders, "na");
  return rebuilt(
      model,
      [ni, na](auto& orders) {
        orders.back() = 0;
        orders[na] += ni;
      },
      poly.tail(poly.size() - 1));
}

/// The known system of Model's kind, with ni integrators. The nonlinear-feedback one feeds back the
/// velocity (friction_feedback()): a position fed back through a cubic would run away once integrated.
/// With two integrators its A acts on the acceleration and only the friction damps the velocity,
/// amplified by 1 / A(1): its A is made faster (poles 0.1 and 0.2), so that the loop stays stable.
template <class Model>
Model integrating_system(Eigen::Index ni) {
  if constexpr (std::is_same_v<Model, bonl::NonlinearFeedbackd>) {
    Model model = with_integrators(friction_feedback(), ni);
    if (ni == 2) model.set_a(vec({-0.3, 0.02}));
    return model;
  } else if constexpr (std::is_same_v<Model, bonl::BoucWenFeedbackd>) {
    // Its A is the linearisation at rest, which the integrators make integrate; the known system's
    // alpha > 0 takes stiffness away at large amplitude, and with an integrator that runs off (the
    // free run leaves the finite numbers). alpha < 0 adds it: free near rest, held at large amplitude.
    // With two integrators D also damps (d_2 = -0.9) and A is faster (poles 0.1, 0.2 and 0.3): with
    // the known system's the sensitivities grow until central differences no longer resolve them.
    Model model = with_integrators(known_system<Model>(), ni);
    model.set_alpha(-0.05);
    if (ni == 2) {
      model.set_a(vec({-0.6, 0.11, -0.006}));
      model.set_d(vec({1.0, -0.9}));
    }
    return model;
  } else {
    return with_integrators(known_system<Model>(), ni);
  }
}

/// A zero-mean input, so that an integrating output wanders without running off: random levels of
/// amplitude 0.5 less their running mean.
Eigen::VectorXd wandering_input(Eigen::Index n, std::uint64_t seed) {
  Eigen::VectorXd u = bonl::signals::random_levels(n, 5, 0.5, seed);
  return (u.array() - u.mean()).matrix();
}

double relative_difference(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return (a - b).cwiseAbs().maxCoeff() / (1.0 + b.cwiseAbs().maxCoeff());
}

}  // namespace

TEMPLATE_LIST_TEST_CASE("a model with integrators runs as its denominator multiplied out", "[integrators]",
                        bonl::Models) {
  using Model = TestType;
  for (Eigen::Index ni : {1, 2}) {
    INFO(Model::kName << ", ni = " << ni);
    const Model model = integrating_system<Model>(ni);
    const Model oracle = multiplied_out(model);
    const Eigen::VectorXd u = wandering_input(ni == 1 ? 1500 : 300, 5);
    const Eigen::VectorXd y = oracle.simulate(u);
    INFO("output range " << y.minCoeff() << " .. " << y.maxCoeff());
    CHECK(relative_difference(model.simulate(u), y) <= 1e-9);

    // One step ahead from the measured output, and the free run after a measured past: at the truth the
    // key terms, whose lags are differenced, give the output itself (the multiplied-out model's
    // predictor is no oracle here: inside a backlash's gap it runs free on a pole at 1, where rounding
    // differences grow).
    // P-H-W is left out: its predictor stores x clipped to the measured y +- c, and with an integrator
    // each clip enters the differenced lags as a step that 1 / A(1) (about 10 for its known system)
    // amplifies, so a rounding error of 1e-12 grows to 0.4 over 1500 samples (measured; without
    // integrators A is stable and it decays). docs/explanation/algorithm.md says so.
    if constexpr (!has_backlash<Model>()) {
      CHECK(relative_difference(model.predict(u, y), y) <= 1e-9);
      const Eigen::Index past = u.size() / 3;
      const Eigen::VectorXd continued = model.simulate(u.tail(u.size() - past), u.head(past), y.head(past));
      CHECK(relative_difference(continued, y.tail(u.size() - past)) <= 1e-9);
    }

    // The integrators are structure: the stability radius is the estimated A's, below 1.
    CHECK(bonl::pole_radius(model) < 1.0);
    CHECK(bonl::pole_radius(oracle) >= 1.0 - 1e-6);
  }
}

TEMPLATE_LIST_TEST_CASE("the output-error sensitivities with integrators are the free run's derivatives",
                        "[integrators]", bonl::Models) {
  using Model = TestType;
  for (Eigen::Index ni : {1, 2}) {
    INFO(Model::kName << ", ni = " << ni);
    const Model model = integrating_system<Model>(ni);
    const Eigen::VectorXd u = wandering_input(400, 7);
    const typename Model::Params theta = model.theta();
    typename Model::OutputErrorTerms terms(model);
    Eigen::MatrixXd psi(u.size(), theta.size());
    Eigen::VectorXd y(u.size());
    for (Eigen::Index k = 0; k < u.size(); ++k) {
      const auto step = terms.step(theta, u[k]);
      y[k] = step.output;
      psi.row(k) = step.sensitivity.transpose();
      terms.accept();
    }
    CHECK(relative_difference(y, model.simulate(u)) <= 1e-10);
    // A backlash output is piecewise smooth: a sample whose regime the step flips differs (as in the
    // suite without integrators, recursive_output_error.test.cpp), so samples are counted.
    const Eigen::Index matching = matching_samples(psi, simulation_differences(model, u));
    INFO(matching << " of " << u.size() << " samples match");
    CHECK(matching >= u.size() * 98 / 100);
  }
}

TEMPLATE_LIST_TEST_CASE("a model file keeps the integrators, and a file without them reads as none", "[integrators]",
                        bonl::Models) {
  using Model = TestType;
  const Model model = integrating_system<Model>(1);
  const std::string text = bonl::io::to_json(model);
  CHECK(text.find("\"ni\":1") != std::string::npos);
  const Model loaded = bonl::io::model_from_json<Model>(text);
  CHECK(loaded.orders() == model.orders());
  CHECK(loaded.theta() == model.theta());
  const Model none = with_integrators(model, 0);
  CHECK(bonl::io::to_json(none).find("\"ni\"") == std::string::npos);  // written as before integrators existed
  CHECK(bonl::io::model_from_json<Model>(bonl::io::to_json(none)).orders().back() == 0);

  auto orders = model.orders();
  orders.back() = 3;
  CHECK_THROWS_WITH(bonl::make_model<Model>(orders),
                    Catch::Matchers::Contains("ni (integrators, poles fixed at 1) must be 0, 1 or 2, got 3"));
  std::string bad = text;
  bad.replace(bad.find("\"ni\":1"), 6, "\"ni\":3");
  CHECK_THROWS_WITH(bonl::io::model_from_json<Model>(bad),
                    Catch::Matchers::Contains("orders.ni must be between 0 and 2"));
}

TEST_CASE("an integrating model follows its reference through the control inverse", "[integrators][control]") {
  const auto check = [](const auto& model, const bonl::control::InverseOptions& options) {
    INFO(model.kName);
    const Eigen::VectorXd u = wandering_input(1500, 13);
    const Eigen::VectorXd reference = model.simulate(u);  // reachable
    const auto run = bonl::control::InverseModel<std::decay_t<decltype(model)>>(model, options).commands(reference);
    const Eigen::VectorXd followed = model.simulate(run.command);
    const Eigen::Index from = model.nk();
    CHECK((followed - reference).tail(reference.size() - from).cwiseAbs().maxCoeff() <=
          1e-9 * (1.0 + reference.cwiseAbs().maxCoeff()));
  };
  bonl::control::InverseOptions wide;
  wide.command_min = -2.0;
  wide.command_max = 2.0;
  check(integrating_system<bonl::ARXd>(1), {});
  check(integrating_system<bonl::Hammersteind>(1), wide);
  check(integrating_system<bonl::Wienerd>(1), {});
}

TEMPLATE_LIST_TEST_CASE("identify recovers the models with an integrator from noise-free data",
                        "[integrators][identify]", bonl::Models) {
  using Model = TestType;
  const Model truth = integrating_system<Model>(1);
  INFO(Model::kName);
  const Eigen::VectorXd u = wandering_input(4000, 21);
  const Eigen::VectorXd fresh = wandering_input(4000, 22);
  Model structure = truth;
  structure.set_theta(Model::Params::Zero(truth.num_params()));
  // The known systems' constant and even terms integrate to a ramp that dominates the output, and
  // the refinement converges more slowly than without the integrator (measured on the Hammerstein
  // system: NRMSE 4.5e-5 after the default 100 iterations, 4e-14 after 400).
  bonl::IdentifyOptions options;
  options.refine_iterations = 400;
  const Model model = bonl::identify(structure, u, truth.simulate(u), options);
  // Where the fresh input leaves the identification input's range an input polynomial continues
  // linearly: the truth, given the same range, does the same.
  Model continued = truth;
  continued.set_input_range(u.minCoeff(), u.maxCoeff());
  const double nrmse = bonl::metrics::nrmse(continued.simulate(fresh), model.simulate(fresh));
  INFO("NRMSE on the fresh input " << nrmse);
  // Not recovered to 1e-6 (measured 0.0175 and 5.6e-4): the Hammerstein-Wiener system, whose ramp
  // takes x to 200 where its cubic output polynomial reaches 1e7, and the Wiener-Hammerstein one,
  // whose square term ramps through the second block. Their bounds catch a change for the worse.
  if constexpr (std::is_same_v<Model, bonl::HammersteinWienerd>) {
    CHECK(nrmse <= 0.03);
  } else if constexpr (std::is_same_v<Model, bonl::WienerHammersteind>) {
    CHECK(nrmse <= 1e-3);
  } else {
    CHECK(nrmse <= 1e-6);
  }
}
