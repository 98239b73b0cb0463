// ARX, Hammerstein, HammersteinWiener and PseudoHammersteinWiener on measured data (the hydraulic
// actuator and the cascaded tanks), each model of MeasuredModels named by its kName:
// the same procedure as measured_data.py, which documents it (selection by a grid search scored on
// the last 25 % of the estimation data only, refit on the whole estimation part, free-run
// simulation from rest, RMS on the validation part), and the same table.
//
//   bonl_measured_data [--data DIR] [--out DIR] [--json FILE] [--selection FILE] [--markdown FILE]
//                      [--small-grid] [--jobs N]
//
// DIR defaults to the repository's data/ (BONL_MEASURED_DATA_DIR, set by CMake). Writes the model
// files (bonl JSON) and the simulated outputs (CSV) into --out, the table into --json, the chosen
// structures with their scores into --selection (docs/results/measured_data.json, which a test
// re-identifies) and the tables with the published figures beside them into --markdown
// (docs/results/measured_data_summary.md, quoted by docs/lab/measured_data.md).

#include <bonl/bonl.hpp>
#include <bonl/io.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#ifndef BONL_MEASURED_DATA_DIR
#define BONL_MEASURED_DATA_DIR "data"
#endif

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kFitFraction = 0.75;

// ------------------------------------------------------------------------------------------- data

/// A CSV file with a header line: column name -> values. Empty lines and empty cells are skipped.
std::map<std::string, std::vector<double>> read_csv(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw std::runtime_error("cannot open " + path);
  const auto split = [](const std::string& line) {
    std::vector<std::string> cells;
    std::stringstream stream(line);
    std::string cell;
    while (std::getline(stream, cell, ',')) {
      cell.erase(std::remove(cell.begin(), cell.end(), '"'), cell.end());
      cell.erase(std::remove(cell.begin(), cell.end(), '\r'), cell.end());
      cells.push_back(cell);
    }
    return cells;
  };
  std::string line;
  std::getline(file, line);
  const std::vector<std::string> names = split(line);
  std::map<std::string, std::vector<double>> columns;
  while (std::getline(file, line)) {
    const std::vector<std::string> cells = split(line);
    for (std::size_t i = 0; i < cells.size() && i < names.size(); ++i) {
      if (!cells[i].empty() && !names[i].empty()) columns[names[i]].push_back(std::stod(cells[i]));
    }
  }
  return columns;
}

Eigen::VectorXd column(const std::map<std::string, std::vector<double>>& csv, const std::string& name,
                       std::size_t rows) {
  const auto found = csv.find(name);
  if (found == csv.end() || found->second.size() < rows) throw std::runtime_error("missing column " + name);
  return Eigen::Map<const Eigen::VectorXd>(found->second.data(), static_cast<Eigen::Index>(rows));
}

// ------------------------------------------------------------------------------------- candidates

/// The models, each named by its kName; their orders come from their descriptions.
using MeasuredModels =
    bonl::ModelList<bonl::ARXd, bonl::Hammersteind, bonl::HammersteinWienerd, bonl::PseudoHammersteinWienerd>;

/// Values of each order, by the order's name (a model takes those its description names).
using Grid = std::map<std::string, std::vector<Eigen::Index>>;
const Grid kGrid{{"na", {1, 2, 3, 4}}, {"nb", {0, 1, 2, 3}}, {"nk", {0, 1, 2}}, {"r", {1, 2, 3}}, {"r1", {2, 3}}};
const Grid kSmallGrid{{"na", {2, 3}}, {"nb", {1, 2}}, {"nk", {0, 1}}, {"r", {2, 3}}, {"r1", {3}}};

enum class Offset { None, Mean, First };
const char* to_string(Offset offset) {
  switch (offset) {
    case Offset::None: return "none";
    case Offset::Mean: return "mean";
    case Offset::First: return "first";
  }
  return "?";
}

struct Candidate {
  std::vector<Eigen::Index> orders;  // in the order the model's description lists them
  Offset offset = Offset::None;
};

/// Is the i-th order of Model an optional one (ni) at its default? Such an order is left out of the
/// candidates' names and the selection's JSON, as the Python example and model files leave it out.
template <class Model>
bool at_default(std::size_t i, Eigen::Index value) {
  const auto& order = Model::kDescription.orders[i];
  return order.default_value != bonl::OrderDescription::kRequired && value == order.default_value;
}

template <class Model>
std::string describe(const Candidate& c) {
  std::string text;
  for (std::size_t i = 0; i < c.orders.size(); ++i) {
    if (at_default<Model>(i, c.orders[i])) continue;
    text +=
        std::string(text.empty() ? "" : " ") + Model::kDescription.orders[i].name + "=" + std::to_string(c.orders[i]);
  }
  if (c.offset != Offset::None) text += std::string(", offset ") + to_string(c.offset);
  return text;
}

/// Every candidate of Model, in the Python example's grid order (the orders as the description lists
/// them, the last fastest, then the offset).
template <class Model>
std::vector<Candidate> candidates(const Grid& grid, const std::vector<Offset>& offsets) {
  // An order the grid does not search (the integrators ni) takes the model's default, as in the
  // Python example; one without a default must be in the grid.
  std::vector<std::vector<Eigen::Index>> defaults;
  defaults.reserve(Model::kDescription.orders.size());  // the pointers below stay valid
  std::vector<const std::vector<Eigen::Index>*> values;
  for (const auto& order : Model::kDescription.orders) {
    const auto searched = grid.find(order.name);
    if (searched != grid.end()) {
      values.push_back(&searched->second);
    } else if (order.default_value != bonl::OrderDescription::kRequired) {
      values.push_back(&defaults.emplace_back(1, order.default_value));
    } else {
      throw std::invalid_argument(std::string("measured_data: the grid has no values for the order ") + order.name);
    }
  }
  std::vector<Candidate> result;
  std::vector<std::size_t> index(values.size(), 0);
  while (true) {
    Candidate c;
    for (std::size_t i = 0; i < values.size(); ++i) c.orders.push_back((*values[i])[index[i]]);
    for (Offset offset : offsets) {
      c.offset = offset;
      result.push_back(c);
    }
    std::size_t i = values.size();
    while (i > 0 && ++index[i - 1] == values[i - 1]->size()) index[--i] = 0;
    if (i == 0) return result;
  }
}

/// The estimator settings: a model without internal variables (ARX) is a linear regression, by least
/// squares (forgetting 1, P(0) = 1e6 I in the data's units); the block models by the equation-error method with the
/// paper's settings, then refinement (the settings the published figures in docs/lab/measured_data.md
/// were produced with; issue 18 redoes this example).
template <class Model>
bonl::IdentifyOptions settings() {
  bonl::IdentifyOptions options;
  options.method = bonl::Method::EquationError;
  if (!Model::kHasInternalVariables) {
    options.forgetting = bonl::ForgettingSchedule::constant(1.0);
    options.normalise = false;  // P(0) = 1e6 I in the data's units: the batch solution's regulariser
  }
  return options;
}

std::pair<double, double> offset_constants(Offset offset, const Eigen::VectorXd& u, const Eigen::VectorXd& y) {
  switch (offset) {
    case Offset::None: return {0.0, 0.0};
    case Offset::Mean: {  // a plain left-to-right sum, as the Python example does, so both agree bit for bit
      const auto mean = [](const Eigen::VectorXd& v) {
        double sum = 0.0;
        for (Eigen::Index k = 0; k < v.size(); ++k) sum += v[k];
        return sum / static_cast<double>(v.size());
      };
      return {mean(u), mean(y)};
    }
    case Offset::First: return {u[0], y[0]};
  }
  return {0.0, 0.0};
}

/// A fitted model: its file text and its free run (from rest).
struct Fitted {
  std::string json;
  std::function<bool(const Eigen::VectorXd&, Eigen::VectorXd&)> simulate;
};

/// Identifies Model at candidate `c` on (u, y) (already shifted). Throws NumericalError.
template <class Model>
Fitted fit(const Candidate& c, const Eigen::VectorXd& u, const Eigen::VectorXd& y) {
  std::array<Eigen::Index, Model::kDescription.orders.size()> orders{};
  std::copy(c.orders.begin(), c.orders.end(), orders.begin());
  const Model model = bonl::identify(bonl::make_model<Model>(orders), u, y, settings<Model>());
  return {bonl::io::to_json(model, 2),
          [model](const Eigen::VectorXd& input, Eigen::VectorXd& output) { return model.try_simulate(input, output); }};
}

double rms(const Eigen::VectorXd& error) { return std::sqrt(error.squaredNorm() / static_cast<double>(error.size())); }

/// Free run on u - u0, shifted back by y0; false if it diverges.
bool simulate(const Fitted& model, const Eigen::VectorXd& u, double u0, double y0, Eigen::VectorXd& out) {
  const Eigen::VectorXd shifted = u.array() - u0;
  if (!model.simulate(shifted, out)) return false;
  out.array() += y0;
  return out.allFinite();
}

/// Fit on the first 75 % of the estimation record, simulate all of it from rest, RMS on the last 25 %.
template <class Model>
double check_score(const Candidate& c, const Eigen::VectorXd& u, const Eigen::VectorXd& y) {
  const auto [u0, y0] = offset_constants(c.offset, u, y);
  const Eigen::Index n_fit = static_cast<Eigen::Index>(std::lround(kFitFraction * static_cast<double>(u.size())));
  try {
    const Eigen::VectorXd u_fit = u.head(n_fit).array() - u0;
    const Eigen::VectorXd y_fit = y.head(n_fit).array() - y0;
    const Fitted model = fit<Model>(c, u_fit, y_fit);
    Eigen::VectorXd simulated;
    if (!simulate(model, u, u0, y0, simulated)) return kInf;
    const double score = rms(simulated.tail(u.size() - n_fit) - y.tail(u.size() - n_fit));
    return std::isfinite(score) ? score : kInf;
  } catch (const bonl::NumericalError&) {
    return kInf;
  }
}

struct Result {
  Candidate chosen;
  std::string description;  // the chosen orders and offset, by name
  double check_rms = kInf;
  double validation_rms = kInf;
  double u0 = 0.0, y0 = 0.0;
  Fitted model;
  Eigen::VectorXd simulated;
};

template <class Model>
Result run_case(const Eigen::VectorXd& u_est, const Eigen::VectorXd& y_est, const Eigen::VectorXd& u_sim,
                const Eigen::VectorXd& y_sim, Eigen::Index score_from, const Grid& grid,
                const std::vector<Offset>& offsets, unsigned jobs) {
  const std::vector<Candidate> cands = candidates<Model>(grid, offsets);
  std::vector<double> scores(cands.size(), kInf);
  std::atomic<std::size_t> next{0};
  const auto worker = [&] {
    for (std::size_t i = next++; i < cands.size(); i = next++) scores[i] = check_score<Model>(cands[i], u_est, y_est);
  };
  std::vector<std::thread> threads;
  for (unsigned t = 1; t < jobs; ++t) threads.emplace_back(worker);
  worker();
  for (std::thread& thread : threads) thread.join();

  std::size_t best = 0;  // lowest score, first in grid order on ties
  for (std::size_t i = 1; i < cands.size(); ++i)
    if (scores[i] < scores[best]) best = i;
  if (!std::isfinite(scores[best]))
    throw std::runtime_error(std::string(Model::kName) + ": every candidate broke down");

  Result result;
  result.chosen = cands[best];
  result.check_rms = scores[best];
  std::tie(result.u0, result.y0) = offset_constants(result.chosen.offset, u_est, y_est);
  const Eigen::VectorXd u_shift = u_est.array() - result.u0;
  const Eigen::VectorXd y_shift = y_est.array() - result.y0;
  result.model = fit<Model>(result.chosen, u_shift, y_shift);
  result.description = describe<Model>(result.chosen);
  if (simulate(result.model, u_sim, result.u0, result.y0, result.simulated)) {
    const Eigen::Index n = u_sim.size() - score_from;
    result.validation_rms = rms(result.simulated.tail(n) - y_sim.tail(n));
  }
  return result;
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream file(path);
  if (!file) throw std::runtime_error("cannot write " + path);
  file << text;
}

/// The published figures beside each model's row (from data/*/SOURCE.md), by case and model.
const std::map<std::string, std::map<std::string, std::string>> kPublished = {
    {"actuator",
     {{"ARX", "linear ARX(3,2,1) about 0.99"}, {"HammersteinWiener", "1995 sigmoid neural network about 0.47"}}},
    {"cascaded_tanks",
     {{"ARX", "best linear 0.75"},
      {"Hammerstein", "Volterra 0.54"},
      {"HammersteinWiener", "best black-box about 0.34"},
      {"PseudoHammersteinWiener", "physical grey-box 0.18"}}}};

std::string number(double value) {
  if (!std::isfinite(value)) return "null";
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

}  // namespace

int main(int argc, char** argv) {
  std::string data = BONL_MEASURED_DATA_DIR, out = "measured_data_out", json, selection_file, markdown_file;
  bool small = false;
  unsigned jobs = std::max(1u, std::min(2u, std::thread::hardware_concurrency()));
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(arg + " needs a value");
      return argv[++i];
    };
    if (arg == "--data")
      data = value();
    else if (arg == "--out")
      out = value();
    else if (arg == "--json")
      json = value();
    else if (arg == "--selection")
      selection_file = value();
    else if (arg == "--markdown")
      markdown_file = value();
    else if (arg == "--small-grid")
      small = true;
    else if (arg == "--jobs")
      jobs = static_cast<unsigned>(std::max(1, std::stoi(value())));
    else {
      std::fprintf(stderr,
                   "usage: %s [--data DIR] [--out DIR] [--json FILE] [--selection FILE] [--markdown FILE] "
                   "[--small-grid] [--jobs N]\n",
                   argv[0]);
      return 2;
    }
  }
  const Grid& grid = small ? kSmallGrid : kGrid;

  const auto actuator = read_csv(data + "/hydraulic-actuator/actuator.csv");
  const Eigen::VectorXd u_act = column(actuator, "u", 1024), y_act = column(actuator, "p", 1024);
  const auto tanks = read_csv(data + "/cascaded-tanks/dataBenchmark.csv");
  const Eigen::VectorXd u_est = column(tanks, "uEst", 1024), y_est = column(tanks, "yEst", 1024);
  const Eigen::VectorXd u_val = column(tanks, "uVal", 1024), y_val = column(tanks, "yVal", 1024);
  const Eigen::Index n_est = 512;

  std::map<std::string, std::map<std::string, Result>> results;
  std::vector<std::string> names;  // in MeasuredModels' order
  bonl::for_each_model(MeasuredModels{}, [&](auto tag) {
    using Model = typename decltype(tag)::type;
    names.push_back(Model::kName);
    results["actuator"][Model::kName] =
        run_case<Model>(u_act.head(n_est), y_act.head(n_est), u_act, y_act, n_est, grid, {Offset::None}, jobs);
    results["cascaded_tanks"][Model::kName] =
        run_case<Model>(u_est, y_est, u_val, y_val, 0, grid, {Offset::Mean, Offset::First}, jobs);
  });

  const std::pair<const char*, const char*> titles[] = {
      {"actuator", "Hydraulic actuator: simulation RMS on samples 513-1024"},
      {"cascaded_tanks", "Cascaded tanks: simulation RMS on the validation record (V)"}};
  std::string table = "{\n";
  for (const auto& [key, title] : titles) {
    std::printf("%s\n  %-24s %10s %8s  chosen (from estimation data only)\n", title, "model", "validation", "check");
    table += std::string("  \"") + key + "\": {";
    bool first = true;
    for (const std::string& name : names) {
      const Result& r = results[key][name];
      std::printf("  %-24s %10.4f %8.4f  %s\n", name.c_str(), r.validation_rms, r.check_rms, r.description.c_str());
      table += std::string(first ? "" : ", ") + "\"" + name + "\": " + number(r.validation_rms);
      first = false;
    }
    table += std::string("}") + (std::string(key) == "actuator" ? ",\n" : "\n");
  }
  table += "}\n";

  if (!out.empty()) {
    std::filesystem::create_directories(out);
    for (const auto& [key, title] : titles) {
      std::string simulated = "measured";
      for (const std::string& name : names) {
        write_text(out + "/" + key + "_" + name + ".json", results[key][name].model.json + "\n");
        simulated += "," + name;
      }
      simulated += "\n";
      const Eigen::VectorXd& measured = std::string(key) == "actuator" ? y_act : y_val;
      for (Eigen::Index k = 0; k < measured.size(); ++k) {
        simulated += number(measured[k]);
        for (const std::string& name : names) {
          const Eigen::VectorXd& s = results[key][name].simulated;
          simulated += "," + (k < s.size() ? number(s[k]) : std::string("nan"));
        }
        simulated += "\n";
      }
      write_text(out + "/" + key + "_simulated.csv", simulated);
    }
  }
  if (!json.empty()) write_text(json, table);

  // The chosen structures and their scores, and the tables for the docs.
  std::string selection = "{\n";
  std::string markdown;
  std::map<std::string, std::vector<std::string>> order_names;
  std::map<std::string, std::vector<Eigen::Index>> order_defaults;  // kRequired, or an optional order's default
  bonl::for_each_model(MeasuredModels{}, [&](auto tag) {
    using Model = typename decltype(tag)::type;
    for (const auto& order : Model::kDescription.orders) order_names[Model::kName].push_back(order.name);
    for (std::size_t i = 0; i < Model::kDescription.orders.size(); ++i) {
      order_defaults[Model::kName].push_back(Model::kDescription.orders[i].default_value);
    }
  });
  const std::pair<const char*, const char*> headers[] = {{"actuator", "actuator, samples 513-1024"},
                                                         {"cascaded_tanks", "cascaded tanks, validation record [V]"}};
  for (const auto& [key, header] : headers) {
    selection += std::string("  \"") + key + "\": {\n";
    markdown += std::string(markdown.empty() ? "" : "\n") + "| " + header + " | orders chosen | ours | published |\n" +
                "|---|---|---|---|\n";
    for (std::size_t m = 0; m < names.size(); ++m) {
      const Result& r = results[key][names[m]];
      std::string orders;
      for (std::size_t i = 0; i < r.chosen.orders.size(); ++i) {
        const Eigen::Index fallback = order_defaults[names[m]][i];
        if (fallback != bonl::OrderDescription::kRequired && r.chosen.orders[i] == fallback) continue;  // as at_default
        orders += std::string(orders.empty() ? "" : ", ") + "\"" + order_names[names[m]][i] +
                  "\": " + std::to_string(r.chosen.orders[i]);
      }
      selection += "    \"" + names[m] + "\": {\"orders\": {" + orders + "}, \"offset\": \"" +
                   to_string(r.chosen.offset) + "\", \"check_rms\": " + number(r.check_rms) +
                   ", \"validation_rms\": " + number(r.validation_rms) + "}" + (m + 1 < names.size() ? ",\n" : "\n");
      char rms_text[32];
      std::snprintf(rms_text, sizeof rms_text, "%.3f", r.validation_rms);
      const auto published = kPublished.at(key).find(names[m]);
      markdown += "| " + names[m] + " | " + r.description + " | " + rms_text + " | " +
                  (published == kPublished.at(key).end() ? std::string() : published->second) + " |\n";
    }
    selection += std::string("  }") + (std::string(key) == "actuator" ? ",\n" : "\n");
  }
  selection += "}\n";
  if (!selection_file.empty()) write_text(selection_file, selection);
  if (!markdown_file.empty()) write_text(markdown_file, markdown);
  return 0;
}
