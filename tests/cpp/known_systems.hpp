#pragma once
// The known systems the C++ tests, the soak test and the model tool identify: one per model of
// bonl::Models, read from tests/data/known_systems.json, the file the Python tests read too. No test
// framework here, so that programs outside Catch2 can use them.

#include <bonl/bonl.hpp>
#include <bonl/io.hpp>

#include <nlohmann/json.hpp>

#include <fstream>
#include <initializer_list>
#include <sstream>
#include <stdexcept>
#include <string>

#include "test_data_dir.hpp"

namespace bonl_test {

inline Eigen::VectorXd vec(std::initializer_list<double> values) {
  Eigen::VectorXd v(static_cast<Eigen::Index>(values.size()));
  Eigen::Index i = 0;
  for (double value : values) v[i++] = value;
  return v;
}

/// The paper_orders set is at the paper's orders (na = 3, nb = 2, nk = 8, r = r1 = 3), so the fixed-order
/// Paper* types read it; the small set (na = 2, nb = 1, nk = 2, r = 2) is for the bad-input tests.
inline constexpr Eigen::Index kNk = 8;

inline const nlohmann::json& known_systems_file() {
  static const nlohmann::json file = [] {
    const std::string path = std::string(data_dir()) + "/known_systems.json";
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot read " + path);
    std::stringstream text;
    text << in.rdbuf();
    return nlohmann::json::parse(text.str());
  }();
  return file;
}

/// The known system of Model's kind from `set` ("paper_orders" or "small"), as a Model.
template <class Model>
Model known_system(const char* set = "paper_orders") {
  return bonl::io::model_from_json<Model>(known_systems_file().at(set).at(Model::kName).dump());
}

/// Every model's name, quoted and in bonl::Models' order: "ARX", "Hammerstein", ... (the list the
/// model file reader's messages give).
inline std::string quoted_model_names() {
  std::string names;
  bonl::for_each_model(bonl::Models{}, [&names](auto tag) {
    names += (names.empty() ? "\"" : ", \"") + std::string(decltype(tag)::type::kName) + "\"";
  });
  return names;
}

/// Models with a backlash: a parameter block called c.
template <class Model>
constexpr bool has_backlash() {
  for (const auto& block : Model::kDescription.parameters) {
    if (block.name[0] == 'c' && block.name[1] == '\0') return true;
  }
  return false;
}

/// The Wiener-Hammerstein known system's blocks (x1 within about +-0.8 on random levels of amplitude 1)
/// with a saturating piecewise-linear nonlinearity, two hinges: slope 1 between the knots -0.3 and
/// 0.4, 0.3 left of -0.3 and 0.4 right of 0.4; `r` > 1 adds the square term 0.2 x1^2.
inline bonl::WienerHammersteind saturating_wiener_hammerstein(Eigen::Index r = 1) {
  const auto known = known_system<bonl::WienerHammersteind>();
  bonl::WienerHammersteind model(3, 2, kNk, r, 2, 3, 2);
  model.set_b1(known.b1());
  model.set_a1(known.a1());
  if (r > 1) {
    Eigen::VectorXd f = Eigen::VectorXd::Zero(r);
    f[0] = 1.0;
    f[1] = 0.2;
    model.set_f(f);
  }
  model.set_knots(vec({-0.3, 0.4}));
  model.set_g(vec({-0.7, -0.6}));
  model.set_b2(known.b2());
  model.set_a2(known.a2());
  return model;
}

/// A nonlinear-feedback system with friction on the velocity: a second-order linear block (poles
/// 0.7 and 0.8), and fed back through D = q^-1 + 0.3 q^-2 the output's first difference s through
/// f(s) = -0.5 s^3 plus a Coulomb-like damping, hinges at s = -+0.05 of slope -0.4 each (outputs
/// within about +-4.5 and |s| < 0.6 on random levels of amplitude 1 held 10 samples).
inline bonl::NonlinearFeedbackd friction_feedback() {
  bonl::NonlinearFeedbackd model(2, 1, 1, 3, 2, 2, 1);
  model.set_b(vec({0.2, 0.1}));
  model.set_a(vec({-1.5, 0.56}));
  model.set_f(vec({0.0, -0.5}));
  model.set_knots(vec({-0.05, 0.05}));
  model.set_g(vec({-0.4, -0.4}));
  model.set_d(vec({1.0, 0.3}));
  return model;
}

/// friction_feedback() with an integrator (ni = 1): a drive whose position integrates a velocity that
/// the friction acts on (s is then the velocity, the output the position).
inline bonl::NonlinearFeedbackd friction_drive_position() {
  const bonl::NonlinearFeedbackd velocity = friction_feedback();
  bonl::NonlinearFeedbackd model(2, 1, 1, 3, 2, 2, 1, 0, 1);
  model.set_theta(velocity.theta());
  model.set_knots(velocity.knots());
  return model;
}

/// A nonlinear-feedback system with hysteresis in the loop, a restoring force with memory as in the
/// Bouc-Wen benchmark: a second-order linear block (poles of radius 0.84), fed back through
/// D = q^-1 + 0.4 q^-2 a Prandtl-Ishlinskii operator of the output, three plays of thresholds 1, 2
/// and 3 (the spread rule's for the outputs' half-range of about 4 on random levels of amplitude 1
/// held 5 samples) with weights -0.06, -0.05 and -0.04, and a cubic -0.002 y^3.
inline bonl::NonlinearFeedbackd hysteretic_feedback() {
  bonl::NonlinearFeedbackd model(2, 1, 1, 3, 0, 2, 0, 3);
  model.set_b(vec({0.2, 0.1}));
  model.set_a(vec({-1.6, 0.7}));
  model.set_f(vec({0.0, -0.002}));
  model.set_thresholds(vec({0.2, 0.5, 1.0}));
  model.set_w(vec({-0.06, -0.05, -0.04}));
  model.set_d(vec({1.0, 0.4}));
  return model;
}

inline bonl::PaperARX known_arx() { return known_system<bonl::PaperARX>(); }
inline bonl::PaperHammerstein known_hammerstein() { return known_system<bonl::PaperHammerstein>(); }
inline bonl::PaperHammersteinWiener known_hammerstein_wiener() { return known_system<bonl::PaperHammersteinWiener>(); }
inline bonl::PaperPseudoHammersteinWiener known_phw() { return known_system<bonl::PaperPseudoHammersteinWiener>(); }

}  // namespace bonl_test
