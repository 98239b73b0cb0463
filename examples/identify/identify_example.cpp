// The paper's identification experiment on a known system: a P-H-W "machine" (two-segment input
// nonlinearity, third-order linear block with delay 8, backlash) is excited with the paper's
// multi-sine, measured with 2% output noise, and the models of `Models` are identified with the
// paper's orders and settings by both methods, then validated by free-run simulation on a different
// trajectory. Prints the parameters (like the paper's Table 1) and the validation MSE (like Table 2).
// bonl's main job is the paper's experiment on the CVODE plant (bonl_demo); this one needs no plant.

#include <bonl/bonl.hpp>

#include <algorithm>
#include <array>
#include <cstdio>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace {

bonl::PaperPseudoHammersteinWiener machine() {
  bonl::PaperPseudoHammersteinWiener m(3, 2, 8, 3);
  m.set_f((Eigen::VectorXd(4) << 0.002, 0.06, 0.02, -0.01).finished());
  m.set_p((Eigen::VectorXd(4) << -0.003, -0.02, -0.03, 0.015).finished());
  m.set_b((Eigen::VectorXd(3) << 1.0, 0.5, 0.2).finished());
  m.set_a((Eigen::VectorXd(3) << -1.7, 1.04, -0.238).finished());
  m.set_c(0.1);
  return m;
}

/// The models identified, in the order of the paper's tables; a new one is one entry.
using Models = bonl::ModelList<bonl::PaperPseudoHammersteinWiener, bonl::PaperHammersteinWiener, bonl::PaperHammerstein,
                               bonl::PaperARX>;

template <class Model>
Model structure() {
  std::array<Eigen::Index, Model::kDescription.orders.size()> orders{};
  for (std::size_t i = 0; i < orders.size(); ++i) {
    const std::string name = Model::kDescription.orders[i].name;
    orders[i] = name == "na" ? 3 : name == "nb" ? 2 : name == "nk" ? 8 : 3;  // the paper's orders; r = r1 = 3
  }
  return bonl::make_model<Model>(orders);
}

/// A model's parameters by row label: "b0", "a1", ..., "c".
template <class Model>
std::map<std::string, double> labelled(const Model& model) {
  std::map<std::string, double> out;
  for (std::size_t i = 0; i < Model::kDescription.parameters.size(); ++i) {
    const bonl::ParameterDescription& block = Model::kDescription.parameters[i];
    const Eigen::VectorXd values = model.parameter(i);
    for (Eigen::Index k = 0; k < values.size(); ++k) {
      const std::string label = block.shape == bonl::ParameterShape::Number
                                    ? std::string(block.name)
                                    : block.name + std::to_string(block.first_index + k);
      out[label] = values[k];
    }
  }
  return out;
}

template <class Model>
double validate(const Model& model, const Eigen::VectorXd& u, const Eigen::VectorXd& y) {
  Eigen::VectorXd simulated;
  if (!model.try_simulate(u, simulated)) return std::numeric_limits<double>::infinity();
  return bonl::metrics::mse(y, simulated);
}

void run(bonl::Method method, const Eigen::VectorXd& u, const Eigen::VectorXd& y, const Eigen::VectorXd& u_val,
         const Eigen::VectorXd& y_val) {
  bonl::IdentifyOptions options;  // the paper's: lambda 0.98 then 1, P(0) = 1e6 I, c(0) = 0.01
  options.method = method;
  std::vector<std::string> names{};
  std::vector<std::map<std::string, double>> parameters;
  std::vector<double> mse;
  bonl::for_each_model(Models{}, [&](auto tag) {
    using Model = typename decltype(tag)::type;
    const Model model = bonl::identify(structure<Model>(), u, y, options);
    names.push_back(Model::kName);
    parameters.push_back(labelled(model));
    mse.push_back(validate(model, u_val, y_val));
  });
  names.push_back("(truth)");
  parameters.push_back(labelled(machine()));

  // Rows in the order they first appear (the P-H-W's blocks first, then q).
  std::vector<std::string> rows;
  for (const char* block : {"b", "a", "f", "p", "q", "c"}) {
    for (const auto& model : parameters) {
      for (const auto& entry : model) {
        if (entry.first.rfind(block, 0) == 0 && std::find(rows.begin(), rows.end(), entry.first) == rows.end()) {
          rows.push_back(entry.first);
        }
      }
    }
  }
  std::printf("\n=== method: %s ===\nTable 1. Identified parameters\n%-6s", bonl::to_string(method), "");
  for (const std::string& name : names) std::printf(" %24s", name.c_str());
  std::printf("\n");
  for (const std::string& row : rows) {
    std::printf("%-6s", row.c_str());
    for (const auto& model : parameters) {
      const auto found = model.find(row);
      if (found == model.end())
        std::printf(" %24s", "");
      else
        std::printf(" %24.4f", found->second);
    }
    std::printf("\n");
  }
  std::printf("Table 2. Validation MSE (free-run simulation on another trajectory)\n%-6s", "MSE");
  for (double value : mse) std::printf(" %24.3e", value);
  std::printf("\n%s's error is", names[0].c_str());
  for (std::size_t i = 1; i < mse.size(); ++i) {
    std::printf(" %.0f%% lower than %s's%s", 100 * (1 - mse[0] / mse[i]), names[i].c_str(),
                i + 1 < mse.size() ? "," : "");
  }
  std::printf(" (the paper: 14%%, 30%%, 75%%)\n");
}

}  // namespace

int main() {
  const bonl::PaperPseudoHammersteinWiener truth = machine();
  const Eigen::VectorXd u = bonl::signals::paper_multisine(5000, 0.01, 0.4);
  const Eigen::VectorXd y_clean = truth.simulate(u);
  const double sigma = 0.02 * std::sqrt((y_clean.array() - y_clean.mean()).square().mean());
  const Eigen::VectorXd y = y_clean + bonl::signals::white_noise(u.size(), sigma, 1);
  // Validation: a different trajectory (smooth random levels), measured with the same noise.
  const Eigen::VectorXd u_val = bonl::signals::random_levels(5000, 50, 1.0, 2);
  const Eigen::VectorXd y_val = truth.simulate(u_val) + bonl::signals::white_noise(u_val.size(), sigma, 3);
  std::printf("Known P-H-W machine (c = 0.1), paper's multi-sine, 5000 samples, output noise 2%% of std(y).\n");
  run(bonl::Method::Paper, u, y, u_val, y_val);
  run(bonl::Method::OutputError, u, y, u_val, y_val);
  return 0;
}
