// Links bonl's components from its installed CMake package:
// find_package(bonl CONFIG REQUIRED COMPONENTS io plant experiment) + bonl::io, bonl::plant and
// bonl::experiment.
#include <bonl/bonl.hpp>
#include <bonl/experiment.hpp>
#include <bonl/io.hpp>
#include <bonl/plant/excitation.hpp>
#include <bonl/plant/simulator.hpp>
#include <iostream>
int main() {
  // bonl::plant: one second of the plant after a step of the command (compiled, CVODE).
  bonl::plant::SimulationOptions options;
  options.duration = 1.0;
  const bonl::plant::Trajectory run =
      bonl::plant::simulate(bonl::plant::Parameters{}, bonl::plant::excitation::step(3.0), options);
  // bonl::io: a model through its JSON file and back (header-only, nlohmann_json).
  bonl::Hammersteind model(2, 1, 1, 2);
  model.set_a((Eigen::Vector2d() << -1.2, 0.5).finished());
  const bonl::Hammersteind back = bonl::io::model_from_json<bonl::Hammersteind>(bonl::io::to_json(model));
  // bonl::experiment: the records' processing, and the paper's orders (compiled).
  const Eigen::VectorXd rate = bonl::experiment::differentiate(run.pin_angle, options.sample_time);
  const auto phw = bonl::experiment::paper_model<bonl::PaperPseudoHammersteinWiener>();
  std::cout << "plant samples " << run.time.size() << ", json round trip " << (back.a() == model.a())
            << ", experiment: rate samples " << rate.size() << ", paper nk " << phw.nk() << '\n';
  return run.time.size() > 50 && back.a() == model.a() && rate.size() == run.time.size() && phw.nk() == 8 ? 0 : 1;
}
