// bonl_model_tool: the C++ side of the cross-language JSON tests (tests/python/test_json.py).
//   bonl_model_tool simulate MODEL.json INPUT.txt   -> the model's free-run output, one value a line
//   bonl_model_tool identify OUT.json               -> identifies a P-H-W from a known system's
//                                                      response in C++ and writes it as JSON
// Values are printed with 17 significant digits, so doubles survive the trip exactly.

#include <bonl/bonl.hpp>
#include <bonl/io/model_json.hpp>

#include "known_systems.hpp"

#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

namespace {

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

int simulate(const std::string& model_path, const std::string& input_path) {
  std::vector<double> values;
  std::ifstream in(input_path);
  for (double v; in >> v;) values.push_back(v);
  const Eigen::VectorXd u = Eigen::Map<const Eigen::VectorXd>(values.data(), static_cast<Eigen::Index>(values.size()));
  const auto model = bonl::io::load_model(read_file(model_path));
  const Eigen::VectorXd y = std::visit([&](const auto& m) { return Eigen::VectorXd(m.simulate(u)); }, model);
  for (Eigen::Index k = 0; k < y.size(); ++k) std::printf("%.17g\n", y[k]);
  return 0;
}

int identify(const std::string& out_path) {
  const auto truth = bonl_test::known_phw();
  const Eigen::VectorXd u = bonl::signals::random_levels(2000, 5, 1.0, 3);
  const Eigen::VectorXd y = truth.simulate(u) + bonl::signals::white_noise(u.size(), 0.01, 4);
  std::ofstream(out_path) << bonl::io::to_json(bonl::identify(truth, u, y));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::vector<std::string> args(argv + 1, argv + argc);
    if (args.size() == 3 && args[0] == "simulate") return simulate(args[1], args[2]);
    if (args.size() == 2 && args[0] == "identify") return identify(args[1]);
    std::cerr << "usage: bonl_model_tool simulate MODEL.json INPUT.txt | identify OUT.json\n";
    return 2;
  } catch (const std::exception& error) {
    std::cerr << "bonl_model_tool: " << error.what() << "\n";
    return 1;
  }
}
