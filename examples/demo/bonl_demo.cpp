// bonl_demo: the paper's experiment on the simulated excavator dipper joint (docs/explanation/plant.md).
// Runs bonl::experiment::run_paper_experiment (every model of PaperModels identified with the
// paper's orders and settings on the multi-sine record by the output-error method, bonl's default,
// and the paper's, validated by free-run simulation on another trajectory; the online estimates
// alone; the robustness check) and formats its result: Table 1 (parameters) and Table 2
// (validation MSE of the velocity) in the paper's layout, the online table, the robustness table,
// and --json, --csv, --markdown. --sweep varies the pilot hysteresis and the pin backlash to show
// where the proposed model's advantage comes from.

#include <bonl/bonl.hpp>
#include <bonl/experiment.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "svg_plot.hpp"
#include "tracking_report.hpp"

namespace {

namespace experiment = bonl::experiment;
using experiment::MethodResult;
using experiment::PaperExperimentResult;

const char* kUsage =
    "usage: bonl_demo [--method output_error|paper] [--json FILE] [--csv FILE] [--markdown FILE] [--sweep DIR]\n"
    "       bonl_demo --control [--json FILE] [--csv FILE] [--markdown FILE]\n"
    "  Runs the paper's identification experiment on the default (20 t) plant and prints\n"
    "  Table 1 (identified parameters) and Table 2 (validation MSE of the velocity) for the\n"
    "  output-error and the paper's estimator, and the online estimates' validation MSE.\n"
    "  --method M   which method's results --json and --csv write at the top level (default: output_error)\n"
    "  --json FILE  {\"mse\": {model name: mse}, \"params\": {...}, \"methods\": {...},\n"
    "               \"online\": {\"output_error\": {model name: mse}, \"paper\": {...}}}\n"
    "  --csv FILE   time, input, measured and predicted validation velocities\n"
    "  --markdown FILE  the validation MSE table of the README (docs/results/plant_experiment_summary.md);\n"
    "               with --sweep, the sweep's table (docs/results/sweep_summary.md)\n"
    "  --sweep DIR  vary the pilot hysteresis (0-8%) and the pin backlash (0-20 mrad); writes\n"
    "               DIR/sweep.csv and DIR/sweep.svg (validation MSE of every model against each)\n"
    "  --control    instead: the tracking experiment (docs/how-to/control.md): a reference joint velocity tracked\n"
    "               by a PI loop alone, with each identified model's inverse as feedforward, and with the\n"
    "               adaptive P-H-W feedforward while the plant changes; --json writes\n"
    "               {\"tracking_rms\": {\"PI\": ..., model name: ...}, \"plant_change\": {...}, ...},\n"
    "               --markdown docs/results/tracking_summary.md, --csv the time series\n";

/// Line colours of the sweep chart, in the paper's column order.
const char* const kPalette[] = {"#d62728", "#ff7f0e", "#2ca02c", "#1f77b4", "#9467bd", "#8c564b", "#e377c2"};

/// One model of a method's result, as the tables show it.
struct Column {
  std::string name;   ///< Model::kName
  std::string label;  ///< the paper's label
  const experiment::ModelScores* scores;
  std::vector<std::pair<std::string, double>> parameters;  ///< Table 1's rows
};

/// The models of `m` in the paper's column order: the proposed model (the last of PaperModels) first.
std::vector<Column> columns(const MethodResult& m) {
  std::vector<Column> out;
  m.for_each([&](const auto& r) {
    out.push_back({r.kName, experiment::paper_label(r.kName), &r, experiment::labelled_parameters(r.model)});
  });
  std::reverse(out.begin(), out.end());
  return out;
}

/// "a, b and c".
std::string join_words(const std::vector<std::string>& words) {
  std::string out;
  for (std::size_t i = 0; i < words.size(); ++i) {
    out += (i == 0 ? "" : i + 1 == words.size() ? " and " : ", ") + words[i];
  }
  return out;
}

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

/// How much lower `mse` is than `other`'s, in whole percent ("25%"; "0%", never "-0%").
std::string percent_lower(double mse, double other) {
  const double percent = std::round(100.0 * (1.0 - mse / other));
  return format("%.0f%%", percent == 0.0 ? 0.0 : percent);
}

void print_header(const char* first, const std::vector<Column>& cols, const char* pattern) {
  std::printf("%-10s", first);
  for (const Column& c : cols) std::printf(pattern, c.label.c_str());
  std::printf("\n");
}

void print_tables(const MethodResult& m) {
  const std::vector<Column> cols = columns(m);
  std::printf("\nTable 1. Identification results (method: %s)\n", bonl::to_string(m.method));
  print_header("Parameter", cols, " %12s");
  // The rows: every parameter label, in the order the models of PaperModels first name them.
  std::vector<std::string> rows;
  for (auto c = cols.rbegin(); c != cols.rend(); ++c) {
    for (const auto& [label, value] : c->parameters) {
      if (std::find(rows.begin(), rows.end(), label) == rows.end()) rows.push_back(label);
    }
  }
  for (const std::string& row : rows) {
    std::printf("%-10s", row.c_str());
    for (const Column& c : cols) {
      const auto cell =
          std::find_if(c.parameters.begin(), c.parameters.end(), [&](const auto& entry) { return entry.first == row; });
      if (cell == c.parameters.end())
        std::printf(" %12s", "");
      else
        std::printf(" %12.4g", cell->second);
    }
    std::printf("\n");
  }

  std::printf("\nTable 2. MSE of the identified models (validation velocity, free-run simulation)\n");
  print_header("Error", cols, " %12s");
  std::printf("%-10s", "MSE");
  for (const Column& c : cols) std::printf(" %12.4e", c.scores->mse);
  std::printf("   (rad/s)^2\n");
  std::vector<std::string> lower, others, published;
  for (std::size_t i = 1; i < cols.size(); ++i) {
    lower.push_back(percent_lower(cols[0].scores->mse, cols[i].scores->mse));
    others.push_back(cols[i].label + "'s");
    if (const auto score = experiment::published_score(cols[i].name)) {
      published.push_back(std::to_string(score->proposed_lower_percent) + "%");
    }
  }
  std::string line = cols[0].label + "'s MSE is " + join_words(lower) + " lower than " + join_words(others);
  if (!published.empty()) {
    line += " (paper: ";
    for (std::size_t i = 0; i < published.size(); ++i) line += (i ? ", " : "") + published[i];
    line += ")";
  }
  std::printf("%s\n", line.c_str());
}

void print_online(const PaperExperimentResult& result) {
  const std::vector<Column> identified = columns(result.method(bonl::Method::OutputError));
  std::printf("\nOnline: the recursive estimator alone after one pass (no refinement), validation MSE\n");
  std::printf("%-13s", "method");
  for (const Column& c : identified) std::printf(" %12s", c.label.c_str());
  std::printf("\n");
  for (const MethodResult& m : result.methods) {
    std::printf("%-13s", bonl::to_string(m.method));
    for (const Column& c : columns(m)) std::printf(" %12.4e", c.scores->online_mse);
    std::printf("   (rad/s)^2\n");
  }
  std::printf("%-13s", "identify()");
  for (const Column& c : identified) std::printf(" %12.4e", c.scores->mse);
  std::printf("   (identify(): recursive estimate refined)\n");
}

/// The same identified models on the robustness trajectories; the counts check the paper's ranking
/// (the proposed model below Hammerstein, Hammerstein below ARX).
void print_robustness(const PaperExperimentResult& result) {
  const std::size_t n = result.robustness_trajectories;
  std::printf("\nRobustness: validation MSE on %zu further trajectories (smooth random x4, other multi-sines x4)\n", n);
  std::printf("%-4s %-9s", "", "method");
  for (const Column& c : columns(result.methods.front())) std::printf(" %11s", c.label.c_str());
  std::printf("\n");
  for (std::size_t i = 0; i < n; ++i) {
    for (const MethodResult& m : result.methods) {
      std::printf("%-4zu %-12s", i + 1, bonl::to_string(m.method));
      for (const Column& c : columns(m)) std::printf(" %11.3e", c.scores->robustness_mse[i]);
      std::printf("\n");
    }
  }
  for (const MethodResult& m : result.methods) {
    const auto& proposed = m.get<bonl::PaperPseudoHammersteinWiener>().robustness_mse;
    const auto& hammerstein = m.get<bonl::PaperHammerstein>().robustness_mse;
    const auto& arx = m.get<bonl::PaperARX>().robustness_mse;
    int counts[3] = {0, 0, 0};
    for (std::size_t i = 0; i < n; ++i) {
      const bool proposed_best = proposed[i] < hammerstein[i], h_over_arx = hammerstein[i] < arx[i];
      counts[0] += proposed_best;
      counts[1] += h_over_arx;
      counts[2] += proposed_best && h_over_arx;
    }
    std::printf("%s method: %s < Hammerstein on %d/%zu, Hammerstein < ARX on %d/%zu, both on %d/%zu\n",
                bonl::to_string(m.method), experiment::paper_label(bonl::PaperPseudoHammersteinWiener::kName).c_str(),
                counts[0], n, counts[1], n, counts[2], n);
    // A model the paper does not report, against the proposed model and Hammerstein.
    for (const Column& c : columns(m)) {
      if (experiment::published_score(c.name)) continue;
      int below[2] = {0, 0};
      for (std::size_t i = 0; i < n; ++i) {
        below[0] += c.scores->robustness_mse[i] < proposed[i];
        below[1] += c.scores->robustness_mse[i] < hammerstein[i];
      }
      std::printf("%s method: %s < %s on %d/%zu, %s < Hammerstein on %d/%zu\n", bonl::to_string(m.method),
                  c.label.c_str(), experiment::paper_label(bonl::PaperPseudoHammersteinWiener::kName).c_str(), below[0],
                  n, c.label.c_str(), below[1], n);
    }
  }
}

std::string json_number(double v) {
  if (!std::isfinite(v)) return "null";
  std::ostringstream out;
  out.precision(17);
  out << v;
  return out.str();
}

std::string json_array(const Eigen::VectorXd& v) {
  std::string out = "[";
  for (Eigen::Index i = 0; i < v.size(); ++i) out += (i ? ", " : "") + json_number(v[i]);
  return out + "]";
}

/// {model name: MSE}, identified or online.
std::string json_mse(const MethodResult& m, bool online) {
  std::string out = "{";
  m.for_each([&](const auto& r) {
    out +=
        (out.size() > 1 ? ", \"" : "\"") + std::string(r.kName) + "\": " + json_number(online ? r.online_mse : r.mse);
  });
  return out + "}";
}

/// {"mse": {...}, "params": {model name: {parameter name: value}}}: every parameter block by its
/// description's name.
std::string json_results(const MethodResult& m) {
  std::string out = "{\"mse\": " + json_mse(m, false) + ",\n \"params\": {";
  bool first = true;
  m.for_each([&](const auto& r) {
    using Model = typename std::decay_t<decltype(r)>::Model;
    out += std::string(first ? "\n" : ",\n") + "  \"" + r.kName + "\": {";
    first = false;
    for (std::size_t i = 0; i < Model::kDescription.parameters.size(); ++i) {
      const bonl::ParameterDescription& parameter = Model::kDescription.parameters[i];
      const Eigen::VectorXd value = r.model.parameter(i);
      out += (i ? ", \"" : "\"") + std::string(parameter.name) +
             "\": " + (parameter.shape == bonl::ParameterShape::Number ? json_number(value[0]) : json_array(value));
    }
    out += "}";
  });
  return out + "}}";
}

void write_json(const std::string& path, const PaperExperimentResult& result, bonl::Method chosen) {
  std::string top = json_results(result.method(chosen));
  top.pop_back();  // reopen the object to add the per-method results
  std::string methods, online;
  for (const MethodResult& m : result.methods) {
    const std::string name = bonl::to_string(m.method);
    methods += (methods.empty() ? "\"" : ",\n \"") + name + "\": " + json_results(m);
    online += (online.empty() ? "\"" : ", \"") + name + "\": " + json_mse(m, true);
  }
  std::ofstream out(path);
  out << top << ",\n \"method\": \"" << bonl::to_string(chosen) << "\",\n \"methods\": {" << methods
      << "},\n \"online\": {" << online << "}}\n";
  if (!out) throw std::runtime_error("bonl_demo: cannot write " + path);
}

/// "1st", "2nd", "3rd", "4th", ...
std::string ordinal(std::size_t n) {
  const char* suffix = n % 100 / 10 == 1 ? "th" : n % 10 == 1 ? "st" : n % 10 == 2 ? "nd" : n % 10 == 3 ? "rd" : "th";
  return std::to_string(n) + suffix;
}

/// The README's table: validation MSE of each method, and how much lower the proposed model's is;
/// then, for each model the paper does not report, where it ranks in each row and after which models.
void write_markdown(const std::string& path, const PaperExperimentResult& result) {
  const MethodResult& ours = result.method(bonl::Method::OutputError);
  const std::vector<Column> header = columns(ours);
  std::ofstream out(path);
  std::string others;
  for (std::size_t i = 1; i < header.size(); ++i) others += (i > 1 ? " / " : "") + header[i].label;
  out << "| method |";
  for (const Column& c : header) out << ' ' << c.label << " |";
  out << ' ' << header[0].label << " lower than " << others << " |\n|---|";
  for (std::size_t i = 0; i <= header.size(); ++i) out << "---|";
  out << '\n';
  // The paper's row as it publishes it (its percentages are from unrounded values; "-" for a model
  // it does not report).
  std::string percentages;
  out << "| paper (Table 2 of the paper, real excavator) |";
  for (std::size_t i = 0; i < header.size(); ++i) {
    const auto score = experiment::published_score(header[i].name);
    out << ' ' << (score ? format("%g", score->mse) : std::string()) << " |";
    if (i > 0) {
      percentages +=
          (percentages.empty() ? "" : " / ") + (score ? std::to_string(score->proposed_lower_percent) + "%" : "-");
    }
  }
  out << ' ' << percentages << " |\n";
  struct Row {
    std::string name;        ///< the table's
    std::string short_name;  ///< the sentence's
    std::vector<Column> cols;
    bool online;
  };
  const std::vector<Row> rows = {
      {"bonl output_error, identify()", "with bonl's output_error identify()", header, false},
      {"bonl output_error, online (one pass, the estimator's defaults)", "online", header, true},
      {"bonl paper (eqs. 21-31, with the default trace ceiling)", "with the paper's method",
       columns(result.method(bonl::Method::Paper)), false}};
  const auto mse = [](const Column& c, bool online) { return online ? c.scores->online_mse : c.scores->mse; };
  for (const Row& row : rows) {
    out << "| " << row.name << " |";
    for (const Column& c : row.cols) out << ' ' << format("%.3g", mse(c, row.online)) << " |";
    out << ' ';
    for (std::size_t i = 1; i < row.cols.size(); ++i) {
      out << (i > 1 ? " / " : "") << percent_lower(mse(row.cols[0], row.online), mse(row.cols[i], row.online));
    }
    out << " |\n";
  }
  for (std::size_t i = 0; i < header.size(); ++i) {
    if (experiment::published_score(header[i].name)) continue;
    std::vector<std::string> places;
    for (const Row& row : rows) {
      std::vector<std::string> better;
      for (const Column& c : row.cols) {
        if (mse(c, row.online) < mse(row.cols[i], row.online)) better.push_back(c.label);
      }
      places.push_back(ordinal(better.size() + 1) + " " + row.short_name +
                       (better.empty() ? "" : " (after " + join_words(better) + ")"));
    }
    out << '\n'
        << header[i].label << " (" << header[i].name << ", not in the paper) ranks, of " << header.size() << ", "
        << join_words(places) << ".\n";
  }
  if (!out) throw std::runtime_error("bonl_demo: cannot write " + path);
}

void write_csv(const std::string& path, const experiment::Record& validation, const MethodResult& m) {
  std::ofstream out(path);
  out.precision(10);
  out << "time_s,input_V,measured_velocity_rad_s";
  m.for_each([&](const auto& r) { out << ',' << r.kName << "_rad_s"; });
  out << '\n';
  for (Eigen::Index k = 0; k < validation.time.size(); ++k) {
    out << validation.time[k] << "," << validation.input[k] << "," << validation.velocity[k];
    m.for_each([&](const auto& r) { out << ',' << r.simulated[k]; });
    out << '\n';
  }
  if (!out) throw std::runtime_error("bonl_demo: cannot write " + path);
}

/// The README's sweep table (output-error method, every second point of each sweep and both at
/// zero): each model's validation MSE, how much lower P-H-W's is than each model that sees the
/// valve's hysteresis differently (P-I-H, the plays before the linear block) or not at all
/// (Hammerstein), and P-H-W's c; then c with both at zero for each method.
template <class Point>
void write_sweep_markdown(const std::string& path, const std::vector<Point>& points) {
  using Proposed = bonl::PaperPseudoHammersteinWiener;
  const std::vector<Column> header = columns(points.front().result.method(bonl::Method::OutputError));
  std::ofstream out(path);
  out << "| output_error: plant |";
  for (const Column& c : header) out << ' ' << c.label << " |";
  std::vector<std::size_t> compared;  // the columns P-H-W is compared with: unpublished ones and Hammerstein
  for (std::size_t i = 1; i < header.size(); ++i) {
    if (!experiment::published_score(header[i].name) || header[i].name == bonl::PaperHammerstein::kName) {
      compared.push_back(i);
    }
  }
  out << ' ' << header[0].label << " lower than ";
  for (std::size_t j = 0; j < compared.size(); ++j) out << (j ? " / " : "") << header[compared[j]].label;
  out << " | " << header[0].label << "'s c [rad/s] |\n|---|";
  for (std::size_t i = 0; i < header.size() + 2; ++i) out << "---:|";
  out << '\n';
  std::string parameter;
  std::size_t index = 0;
  for (const Point& p : points) {
    index = p.parameter == parameter ? index + 1 : 0;
    parameter = p.parameter;
    if (index % 2 != 0) continue;
    const std::string plant = p.parameter == "pilot_hysteresis" ? "pilot hysteresis " + format("%g%%", 100 * p.value)
                              : p.parameter == "joint_backlash" ? "pin backlash " + format("%g mrad", 1000 * p.value)
                                                                : std::string("both zero");
    const std::vector<Column> cols = columns(p.result.method(bonl::Method::OutputError));
    out << "| " << plant << " |";
    for (const Column& c : cols) out << ' ' << format("%.3g", c.scores->mse) << " |";
    out << ' ';
    for (std::size_t j = 0; j < compared.size(); ++j) {
      out << (j ? " / " : "") << percent_lower(cols[0].scores->mse, cols[compared[j]].scores->mse);
    }
    out << " | " << format("%.2g", p.result.method(bonl::Method::OutputError).template get<Proposed>().model.c())
        << " |\n";
  }
  const PaperExperimentResult& zero = points.back().result;
  out << "\nWith both at zero the identified c is "
      << format("%.2g", zero.method(bonl::Method::OutputError).get<Proposed>().model.c())
      << " rad/s with the output-error method and "
      << format("%.2g", zero.method(bonl::Method::Paper).get<Proposed>().model.c()) << " rad/s with the paper's.\n";
  if (!out) throw std::runtime_error("bonl_demo: cannot write " + path);
}

int sweep(const std::string& dir, const std::string& markdown) {
  struct Point {
    std::string parameter;
    double value;
    PaperExperimentResult result;
  };
  using Proposed = bonl::PaperPseudoHammersteinWiener;
  experiment::PaperExperimentOptions options;
  options.robustness = false;
  std::vector<Point> points;
  const auto run = [&](const std::string& name, double value,
                       const std::function<void(bonl::plant::Parameters&)>& set) {
    bonl::plant::Parameters parameters;
    set(parameters);
    points.push_back({name, value, experiment::run_paper_experiment(parameters, options)});
    std::printf("%-16s %7.4g", name.c_str(), value);
    for (const MethodResult& m : points.back().result.methods) {
      std::printf(" %s %s:", m.method == bonl::Method::OutputError ? "" : "|", bonl::to_string(m.method));
      for (const Column& c : columns(m)) std::printf(" %s %.3e", c.label.c_str(), c.scores->mse);
      std::printf(" c %.4f", m.get<Proposed>().model.c());
    }
    std::printf("\n");
    std::fflush(stdout);
  };
  std::vector<double> hv, delta;
  for (int i = 0; i <= 8; ++i) hv.push_back(0.01 * i);
  for (int i = 0; i <= 8; ++i) delta.push_back(2.5e-3 * i);
  for (double v : hv) run("pilot_hysteresis", v, [v](bonl::plant::Parameters& p) { p.pilot_hysteresis = v; });
  for (double v : delta) run("joint_backlash", v, [v](bonl::plant::Parameters& p) { p.joint_backlash = v; });
  run("both_zero", 0.0, [](bonl::plant::Parameters& p) {
    p.pilot_hysteresis = 0.0;
    p.joint_backlash = 0.0;
  });

  std::ofstream csv(dir + "/sweep.csv");
  csv.precision(10);
  csv << "parameter,value,method";
  for (const Column& c : columns(points.front().result.methods.front())) csv << ",mse_" << c.name;
  csv << ',' << Proposed::kName << "_c\n";
  for (const Point& p : points) {
    for (const MethodResult& m : p.result.methods) {
      csv << p.parameter << "," << p.value << "," << bonl::to_string(m.method);
      for (const Column& c : columns(m)) csv << ',' << c.scores->mse;
      csv << ',' << m.get<Proposed>().model.c() << "\n";
    }
  }
  const auto chart = [&](const std::string& parameter, double scale, const std::string& x_label, bonl::Method method) {
    bonl_demo::Chart c;
    c.title =
        std::string(method == bonl::Method::OutputError ? "output-error method" : "paper method") + ": validation MSE";
    c.x_label = x_label;
    c.y_label = "validation MSE of the velocity [(rad/s)^2]";
    for (const Point& p : points) {
      if (p.parameter != parameter) continue;
      const std::vector<Column> cols = columns(p.result.method(method));
      if (c.series.empty()) {
        for (std::size_t i = 0; i < cols.size(); ++i) {
          c.series.push_back({cols[i].label, kPalette[i % (sizeof kPalette / sizeof kPalette[0])], {}});
        }
      }
      c.x.push_back(p.value * scale);
      for (std::size_t i = 0; i < cols.size(); ++i) c.series[i].y.push_back(cols[i].scores->mse);
    }
    // Off scale: an error 10 times ARX's largest, i.e. a model that went unstable on validation.
    double arx_max = 0.0;
    for (const Point& p : points) {
      if (p.parameter == parameter) arx_max = std::max(arx_max, p.result.method(method).get<bonl::PaperARX>().mse);
    }
    c.y_cap = 10.0 * arx_max;
    return c;
  };
  const std::string hv_label = "pilot hysteresis hv [% of full opening]", delta_label = "pin backlash delta [mrad]";
  bonl_demo::write_svg(dir + "/sweep.svg", {chart("pilot_hysteresis", 100.0, hv_label, bonl::Method::OutputError),
                                            chart("joint_backlash", 1000.0, delta_label, bonl::Method::OutputError),
                                            chart("pilot_hysteresis", 100.0, hv_label, bonl::Method::Paper),
                                            chart("joint_backlash", 1000.0, delta_label, bonl::Method::Paper)});
  const PaperExperimentResult& zero = points.back().result;
  const Eigen::VectorXd y = experiment::acquire(bonl::plant::Parameters{}).validation.velocity;
  std::printf(
      "\nWith no pilot hysteresis and no pin backlash, the identified c is %.4g (output_error) and %.4g (paper) "
      "rad/s; the default plant's validation velocity has a standard deviation of %.4g rad/s.\n",
      zero.method(bonl::Method::OutputError).get<Proposed>().model.c(),
      zero.method(bonl::Method::Paper).get<Proposed>().model.c(), std::sqrt((y.array() - y.mean()).square().mean()));
  std::printf("wrote %s/sweep.csv and %s/sweep.svg\n", dir.c_str(), dir.c_str());
  if (!markdown.empty()) {
    write_sweep_markdown(markdown, points);
    std::printf("wrote %s\n", markdown.c_str());
  }
  return 0;
}

void print_report(const PaperExperimentResult& result) {
  const bonl::plant::Parameters& parameters = result.parameters;
  std::printf(
      "Plant: 20 t excavator dipper joint (docs/explanation/plant.md), pilot hysteresis %.0f%%, pin backlash %.1f "
      "mrad.\n",
      100 * parameters.pilot_hysteresis, 1000 * parameters.joint_backlash);
  std::printf(
      "Records: 50 s at 100 Hz, 10 repeats averaged, 10 Hz low-pass, differentiated. Identification: "
      "paper's multi-sine; validation: smooth random signal (1 Hz band).\n");
  for (const auto* record : {&result.records.identification, &result.records.validation}) {
    const auto& run = record->trajectory;
    std::printf("  %s: piston %.3f-%.3f m of %.2f m%s, CVODE %ld steps\n",
                record == &result.records.identification ? "identification" : "validation   ", run.min_position,
                run.max_position, parameters.stroke, run.reached_end_stop ? " (REACHED AN END STOP)" : "", run.steps);
  }
  std::printf("  plant simulation and processing: %.2f s\n", result.seconds.plant);
  // The paper's method first, then bonl's.
  print_tables(result.method(bonl::Method::Paper));
  print_tables(result.method(bonl::Method::OutputError));
  print_online(result);
  std::printf("\nidentification and validation: %.2f s\n", result.seconds.identification);
  print_robustness(result);
}

}  // namespace

int main(int argc, char** argv) {
  std::string json, csv, sweep_dir, markdown;
  bool control = false;
  bonl::Method chosen = bonl::Method::OutputError;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "bonl_demo: %s needs a value\n%s", arg.c_str(), kUsage);
        std::exit(2);
      }
      return argv[++i];
    };
    if (arg == "--help" || arg == "-h") {
      std::printf("%s", kUsage);
      return 0;
    } else if (arg == "--json") {
      json = value();
    } else if (arg == "--csv") {
      csv = value();
    } else if (arg == "--markdown") {
      markdown = value();
    } else if (arg == "--control") {
      control = true;
    } else if (arg == "--sweep") {
      sweep_dir = value();
    } else if (arg == "--method") {
      const std::string m = value();
      if (m != "output_error" && m != "paper") {
        std::fprintf(stderr, "bonl_demo: --method must be output_error or paper, got %s\n", m.c_str());
        return 2;
      }
      chosen = bonl::method_from_string(m);
    } else {
      std::fprintf(stderr, "bonl_demo: unknown argument %s\n%s", arg.c_str(), kUsage);
      return 2;
    }
  }
  try {
    if (!sweep_dir.empty()) return sweep(sweep_dir, markdown);
    if (control) {
      const experiment::TrackingResult result = experiment::run_tracking_experiment();
      bonl_demo::print_tracking(result);
      if (!json.empty()) bonl_demo::write_tracking_json(json, result);
      if (!markdown.empty()) bonl_demo::write_tracking_markdown(markdown, result);
      if (!csv.empty()) bonl_demo::write_tracking_csv(csv, result);
      return 0;
    }
    // The 20 t machine, with pilot hysteresis and pin backlash.
    const PaperExperimentResult result = experiment::run_paper_experiment(bonl::plant::Parameters{});
    print_report(result);
    if (!json.empty()) write_json(json, result, chosen);
    if (!csv.empty()) write_csv(csv, result.records.validation, result.method(chosen));
    if (!markdown.empty()) write_markdown(markdown, result);
    return 0;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "bonl_demo: %s\n", error.what());
    return 1;
  }
}
