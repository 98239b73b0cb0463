// bonl_online_accuracy: how close the online estimate comes to offline identification.
//
// For each known system of tests/data/online_systems.json, one pass of the recursive estimator
// (Estimator::update, default settings unless stated) and bonl::identify (offline: the recursive
// estimate refined by Levenberg-Marquardt on the simulation error), each judged by free-run
// simulation on a fresh input against the noise-free output (NRMSE = ||y - y_sim|| / ||y - mean y||):
// - noise-free, 4000 samples, random levels held 5 samples and the paper's multi-sine: NRMSE of the
//   online output-error (its recursion alone, and with its defaults: the window refinement from two
//   starts), equation-error and paper methods
//   and of identify(); P-H-W: |c - c_true| / c_true;
// - white output noise of 2% and 10% of std(y), and AR(1) noise (pole 0.9) of 10%, random levels,
//   10 seeds: the same five NRMSEs per seed;
// - on every record also the window's kept Levenberg-Marquardt iterations and the NRMSE of
//   identify() limited to that many iterations (whether the window lacks iterations);
// - tracking: constant forgetting 0.995, noise-free, 8000 samples, the input gain +30% (and c doubled)
//   at sample 4000: samples after the change until the online model's NRMSE against the new system
//   is below 1% (checked every 50 samples), without and with the window refinement;
// - units: the same systems recorded with u and y multiplied independently by factors from 1e-3 to
//   1e4 (the structure rescaled with them): noise-free, the default estimator's NRMSE against
//   identify()'s on every pair of factors; under each noise at the four extreme pairs, the online
//   over offline ratio of the median NRMSE over the seeds, against the ratio in the original units.
//
//   bonl_online_accuracy [--systems FILE] [--json FILE] [--markdown FILE] [--quick] [--check FILE]
//     --quick       noise-free and tracking figures, the noisy figures of seed 1 only, and of the units
//                   the four extreme pairs noise-free and the first one's seed 1 under each noise
//     --check FILE  compare what was computed with a results file written by --json (relative 2%,
//                   values below 1e-9 count as equal); exit status 1 when one differs
//
// The committed results are docs/results/online_accuracy.json, .md and _summary.md (docs/explanation/algorithm.md's
// table; scripts/online_accuracy.sh writes all three); ctest runs --quick --check against the JSON.

#include <bonl/bonl.hpp>
#include <bonl/io.hpp>

#include <nlohmann/json.hpp>

#include "parameter_step.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <thread>
#include <variant>
#include <vector>

namespace {

using Json = nlohmann::ordered_json;
using Eigen::VectorXd;

constexpr Eigen::Index kSamples = 4000;
constexpr int kSeeds = 10;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct Noise {
  const char* key;
  const char* label;
  double level;  // standard deviation as a fraction of std(y)
  double pole;   // AR(1) pole; 0: white
};
constexpr Noise kNoises[] = {{"white_2", "2% white", 0.02, 0.0},
                             {"white_10", "10% white", 0.10, 0.0},
                             {"ar1_10", "10% AR(1), pole 0.9", 0.10, 0.9}};
constexpr bonl::Method kMethods[] = {bonl::Method::OutputError, bonl::Method::EquationError, bonl::Method::Paper};

double standard_deviation(const VectorXd& y) { return std::sqrt((y.array() - y.mean()).square().mean()); }

/// NRMSE of `model` simulating `u` against `y`; infinity when the simulation diverges.
template <class Model>
double nrmse(const Model& model, const VectorXd& u, const VectorXd& y) {
  VectorXd simulated;
  if (!model.try_simulate(u, simulated)) return kInfinity;
  const double value = bonl::metrics::nrmse(y, simulated);
  return std::isfinite(value) ? value : kInfinity;
}

/// One pass of the estimator over (u, y): its model; `health`, where given, gets its health.
template <class Model>
Model online(const Model& structure, const VectorXd& u, const VectorXd& y, bonl::EstimatorOptions options,
             bonl::EstimatorHealth* health = nullptr) {
  bonl::Estimator<Model> estimator(structure, options);
  for (Eigen::Index k = 0; k < u.size(); ++k) estimator.update(u[k], y[k]);
  if (health) *health = estimator.health();
  return estimator.model();
}

/// Output noise of standard deviation `level * std(y)`: white, or AR(1) with pole `pole`.
VectorXd output_noise(const VectorXd& y, const Noise& noise, std::uint64_t seed) {
  VectorXd e = bonl::signals::white_noise(y.size(), 1.0, seed);
  for (Eigen::Index k = 1; k < e.size(); ++k) e[k] += noise.pole * e[k - 1];
  return e * (noise.level * standard_deviation(y) / standard_deviation(e));
}

/// The plant of the tracking test: `before` up to `change`, then `after`, one free run (the
/// output-error terms with fixed parameters are the model's simulation, sample by sample).
template <class Model>
VectorXd switched_response(const Model& before, const Model& after, const VectorXd& u, Eigen::Index change) {
  typename Model::OutputErrorTerms simulation(before);
  VectorXd y(u.size());
  for (Eigen::Index k = 0; k < u.size(); ++k) {
    y[k] = simulation.step(k < change ? before.theta() : after.theta(), u[k]).output;
    simulation.accept();
  }
  return y;
}

Json number(double value) { return std::isfinite(value) ? Json(value) : Json(nullptr); }

struct Inputs {
  VectorXd u, u_validation;
};
Inputs random_levels(std::uint64_t seed, std::uint64_t validation_seed) {
  return {bonl::signals::random_levels(kSamples, 5, 1.0, seed),
          bonl::signals::random_levels(kSamples, 5, 1.0, validation_seed)};
}
Inputs multisine() {
  const VectorXd phases = bonl::signals::random_levels(5, 1, 3.14159, 303);
  return {bonl::signals::paper_multisine(kSamples, 0.01, 0.4),
          bonl::signals::multisine(kSamples, 0.01, bonl::signals::paper_tones(), 0.4, phases)};
}

/// The four NRMSEs of one record (online by each method, identify()) and, for P-H-W, the online
/// output-error estimate's relative c error.
template <class Model>
Json measure(const Model& truth, const Inputs& inputs, const VectorXd& y) {
  const VectorXd y_validation = truth.simulate(inputs.u_validation);
  Json out = Json::object();
  for (bonl::Method method : kMethods) {
    bonl::EstimatorOptions options;
    options.method = method;
    options.window.enabled = false;  // output_error: the recursion alone
    try {
      const Model estimate = online(truth, inputs.u, y, options);
      out[bonl::to_string(method)] = number(nrmse(estimate, inputs.u_validation, y_validation));
      if constexpr (std::is_same_v<Model, bonl::PseudoHammersteinWienerd>) {
        if (method == bonl::Method::OutputError) {
          out["c_relative_error"] = number(std::abs(estimate.c() - truth.c()) / truth.c());
        }
      }
    } catch (const std::exception&) {
      out[bonl::to_string(method)] = nullptr;
    }
  }
  bonl::EstimatorHealth health;
  {  // the output-error method as it comes: with its window refinement
    bonl::EstimatorOptions options;
    out["output_error_window"] =
        number(nrmse(online(truth, inputs.u, y, options, &health), inputs.u_validation, y_validation));
    out["window_iterations"] = health.window.iterations;
  }
  // identify() as it is, and with as many Levenberg-Marquardt iterations as the window kept: whether
  // the window's iterations are what it lacks (most of them are over fewer samples than the record).
  for (const bool limited : {false, true}) {
    bonl::IdentifyOptions options;
    if (limited) options.refine_iterations = static_cast<int>(health.window.iterations);
    const char* key = limited ? "identify_at_window_iterations" : "identify";
    try {
      out[key] = number(nrmse(bonl::identify(truth, inputs.u, y, options), inputs.u_validation, y_validation));
    } catch (const bonl::NumericalError&) {
      out[key] = nullptr;
    }
  }
  return out;
}

template <class Model>
Json tracking(const Model& truth, bool window) {
  const Eigen::Index samples = 2 * kSamples, change = kSamples;
  const VectorXd u = bonl::signals::random_levels(samples, 5, 1.0, 404);
  const VectorXd u_validation = bonl::signals::random_levels(kSamples, 5, 1.0, 405);
  const Model after = bonl_test::with_parameter_step(truth);
  const VectorXd y = switched_response(truth, after, u, change);
  const VectorXd y_validation = after.simulate(u_validation);
  bonl::EstimatorOptions options;
  options.forgetting = bonl::ForgettingSchedule::constant(0.995);
  options.window.enabled = window;
  bonl::Estimator<Model> estimator(truth, options);
  Json recovered = nullptr;
  for (Eigen::Index k = 0; k < samples; ++k) {
    estimator.update(u[k], y[k]);
    const Eigen::Index since = k + 1 - change;
    if (since > 0 && since % 50 == 0 && recovered.is_null() &&
        nrmse(estimator.model(), u_validation, y_validation) < 0.01) {
      recovered = since;
    }
  }
  Json out;
  out["samples_to_1_percent"] = recovered;
  out["final"] = number(nrmse(estimator.model(), u_validation, y_validation));
  return out;
}

/// The factors u and y are multiplied by: the four extreme pairs first (the quick run's), then the
/// rest of the grid of {1e-3, 1e-1, 1, 1e2, 1e4} for each.
std::vector<std::pair<double, double>> unit_factors() {
  std::vector<std::pair<double, double>> pairs = {{1e-3, 1e-3}, {1e4, 1e4}, {1e-3, 1e4}, {1e4, 1e-3}};
  for (double fu : {1e-3, 1e-1, 1.0, 1e2, 1e4}) {
    for (double fy : {1e-3, 1e-1, 1.0, 1e2, 1e4}) {
      if (std::find(pairs.begin(), pairs.end(), std::make_pair(fu, fy)) == pairs.end()) pairs.emplace_back(fu, fy);
    }
  }
  return pairs;
}
constexpr std::size_t kExtremePairs = 4;

/// The default online estimator and identify() on a record in other units: u times fu, y times fy,
/// the structure rescaled with them; NRMSE on the validation record in the same units.
template <class Model>
Json in_units(const Model& truth, const Inputs& inputs, const VectorXd& y, const VectorXd& y_validation, double fu,
              double fy) {
  const Model structure = bonl::rescaled(truth, fu, fy);
  const VectorXd u = inputs.u * fu, u_validation = inputs.u_validation * fu;
  const VectorXd y_scaled = y * fy, validation = y_validation * fy;
  Json out;
  out["online"] = number(nrmse(online(structure, u, y_scaled, bonl::EstimatorOptions{}), u_validation, validation));
  try {
    out["identify"] = number(nrmse(bonl::identify(structure, u, y_scaled), u_validation, validation));
  } catch (const bonl::NumericalError&) {
    out["identify"] = nullptr;
  }
  return out;
}

template <class Model>
Json units(const Model& truth, bool quick) {
  const auto factors = unit_factors();
  Json result;
  result["noise_free"] = Json::array();
  {
    const Inputs levels = random_levels(101, 202);
    const VectorXd y = truth.simulate(levels.u), y_validation = truth.simulate(levels.u_validation);
    for (std::size_t i = 0; i < (quick ? kExtremePairs : factors.size()); ++i) {
      Json entry = in_units(truth, levels, y, y_validation, factors[i].first, factors[i].second);
      entry["u_factor"] = factors[i].first;
      entry["y_factor"] = factors[i].second;
      result["noise_free"].push_back(entry);
    }
  }
  result["noisy"] = Json::array();
  for (std::size_t i = 0; i < (quick ? 1 : kExtremePairs); ++i) {
    Json entry;
    entry["u_factor"] = factors[i].first;
    entry["y_factor"] = factors[i].second;
    for (const Noise& noise : kNoises) {
      Json seeds = Json::array();
      for (int seed = 1; seed <= (quick ? 1 : kSeeds); ++seed) {
        const Inputs levels = random_levels(1000 + seed, 2000 + seed);
        const VectorXd clean = truth.simulate(levels.u);
        seeds.push_back(in_units(truth, levels, clean + output_noise(clean, noise, 3000 + seed),
                                 truth.simulate(levels.u_validation), factors[i].first, factors[i].second));
      }
      entry[noise.key] = seeds;
    }
    result["noisy"].push_back(entry);
  }
  return result;
}

template <class Model>
Json evaluate(const Model& truth, bool quick) {
  Json result;
  {
    const Inputs levels = random_levels(101, 202);
    const Inputs sines = multisine();
    result["noise_free"]["random_levels"] = measure(truth, levels, truth.simulate(levels.u));
    result["noise_free"]["multisine"] = measure(truth, sines, truth.simulate(sines.u));
  }
  for (const Noise& noise : kNoises) {
    Json seeds = Json::array();
    for (int seed = 1; seed <= (quick ? 1 : kSeeds); ++seed) {
      const Inputs levels = random_levels(1000 + seed, 2000 + seed);
      const VectorXd clean = truth.simulate(levels.u);
      seeds.push_back(measure(truth, levels, clean + output_noise(clean, noise, 3000 + seed)));
    }
    result["noisy"][noise.key] = seeds;
  }
  result["tracking"] = tracking(truth, false);
  result["tracking_window"] = tracking(truth, true);
  result["units"] = units(truth, quick);
  return result;
}

struct System {
  std::string name, set;
  bonl::io::AnyModel model;
};

std::vector<System> load_systems(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  const Json document = Json::parse(in);
  std::vector<System> systems;
  for (const Json& entry : document.at("systems")) {
    systems.push_back({entry.at("name").get<std::string>(), entry.at("set").get<std::string>(),
                       bonl::io::load_model(entry.at("model").dump())});
  }
  return systems;
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

double as_number(const Json& value) { return value.is_null() ? kInfinity : value.get<double>(); }

/// Median over seeds of one estimator's NRMSE.
double median_of(const Json& seeds, const char* key) {
  std::vector<double> values;
  for (const Json& seed : seeds) values.push_back(as_number(seed.at(key)));
  return median(values);
}

/// The units figures of one system: noise-free pairs of factors where the default estimator is at
/// or below max(1e-6, identify()'s NRMSE) and how many there are; the largest relative difference of
/// the online over offline ratio (median over the seeds) from the ratio in the original units, over
/// the extreme pairs and the noises; the worst noise-free online NRMSE over the pairs.
struct UnitsFigures {
  int met = 0, pairs = 0;
  double largest_ratio_change = 0.0;
  double worst_online = 0.0, worst_identify = 0.0;
};
UnitsFigures units_figures(const Json& system) {
  UnitsFigures out;
  const Json& units = system.at("units");
  for (const Json& entry : units.at("noise_free")) {
    const double online = as_number(entry.at("online")), offline = as_number(entry.at("identify"));
    ++out.pairs;
    if (online <= std::max(1e-6, offline)) ++out.met;
    out.worst_online = std::max(out.worst_online, online);
    out.worst_identify = std::max(out.worst_identify, offline);
  }
  for (const Json& entry : units.at("noisy")) {
    for (const Noise& noise : kNoises) {
      const Json& original = system.at("noisy").at(noise.key);
      const double reference = median_of(original, "output_error_window") / median_of(original, "identify");
      const Json& seeds = entry.at(noise.key);
      const double ratio = median_of(seeds, "online") / median_of(seeds, "identify");
      const double change =
          std::isfinite(ratio) && std::isfinite(reference) ? std::abs(ratio / reference - 1.0) : kInfinity;
      out.largest_ratio_change = std::max(out.largest_ratio_change, change);
    }
  }
  return out;
}

std::string format(double value, const char* spec = "%.2g") {
  if (!std::isfinite(value)) return "diverged";
  char text[32];
  std::snprintf(text, sizeof text, spec, value);
  return text;
}

/// A relative change as a percentage, or "diverged" where a ratio was not finite.
std::string percent(double change) { return std::isfinite(change) ? format(100.0 * change, "%.2g") + "%" : "diverged"; }

/// Against the online targets, the recursion alone and with the window refinement: the online over
/// offline ratio of the median NRMSE under noise over every system-noise pair; the noise-free
/// systems at max(1e-6, identify()'s NRMSE) or below; the systems back under 1% within 1000 samples
/// after the step change.
std::string targets(const Json& results) {
  struct Column {
    const char* label;
    const char* key;
    const char* tracking;
  };
  const Column columns[] = {
      {"recursion alone (window off)", "output_error", "tracking"},
      {"the default (the window refinement from two starts)", "output_error_window", "tracking_window"},
      {"offline: identify() with the window's iteration count", "identify_at_window_iterations", nullptr}};
  std::ostringstream out;
  const std::size_t systems = results.at("systems").size();
  out << "| online output_error | median ratio to identify() under noise | worst ratio | pairs within 1.2 |"
         " pairs within 1.5 | noise-free at or below max(1e-6, identify()), random levels | multi-sine |"
         " tracking: back under 1% within 1000 samples |\n"
      << "|---|---|---|---|---|---|---|---|\n";
  for (const Column& column : columns) {
    std::vector<double> ratios;
    int noise_free[2] = {0, 0};
    int tracked = 0;
    for (const Json& system : results.at("systems")) {
      for (const Noise& noise : kNoises) {
        const Json& seeds = system.at("noisy").at(noise.key);
        ratios.push_back(median_of(seeds, column.key) / median_of(seeds, "identify"));
      }
      int i = 0;
      for (const char* input : {"random_levels", "multisine"}) {
        const Json& r = system.at("noise_free").at(input);
        if (as_number(r.at(column.key)) <= std::max(1e-6, as_number(r.at("identify")))) ++noise_free[i];
        ++i;
      }
      if (!column.tracking) continue;
      const Json& recovered = system.at(column.tracking).at("samples_to_1_percent");
      if (!recovered.is_null() && recovered.get<long>() <= 1000) ++tracked;
    }
    const auto within = [&](double bound) {
      return std::count_if(ratios.begin(), ratios.end(), [&](double r) { return r <= bound; });
    };
    out << "| " << column.label << " | " << format(median(ratios), "%.2f") << " | "
        << format(*std::max_element(ratios.begin(), ratios.end()), "%.2f") << " | " << within(1.2) << " of "
        << ratios.size() << " | " << within(1.5) << " of " << ratios.size() << " | " << noise_free[0] << " of "
        << systems << " | " << noise_free[1] << " of " << systems << " | "
        << (column.tracking ? std::to_string(tracked) + " of " + std::to_string(systems) : std::string("-")) << " |\n";
  }
  out << "\nThe last row is offline identification limited to as many Levenberg-Marquardt iterations as the\n"
         "window kept on the same record (each record's own count), over the whole record.\n";
  return out.str();
}

/// The summary: for each condition and estimator, the range over
/// the block-model systems (ARX apart) of the NRMSE (noise-free) or of its median over the seeds.
std::string summary(const Json& results) {
  const auto range = [&](bool arx, const std::function<double(const Json&)>& value) {
    double low = kInfinity, high = 0.0;
    for (const Json& system : results.at("systems")) {
      const bool is_arx = system.at("name").get<std::string>().rfind("ARX", 0) == 0;
      if (is_arx != arx) continue;
      const double v = value(system);
      low = std::min(low, v);
      high = std::max(high, v);
    }
    return format(low) + " to " + format(high);
  };
  const char* estimators[] = {"output_error", "output_error_window", "equation_error", "paper", "identify"};
  std::ostringstream out;
  out << "| models | condition | output_error, recursion alone | output_error, default | online equation_error | "
         "online paper | "
         "identify() |\n"
      << "|---|---|---|---|---|---|---|\n";
  for (bool arx : {false, true}) {
    const char* models = arx ? "ARX" : "other models";
    for (const char* input : {"random_levels", "multisine"}) {
      out << "| " << models << " | noise-free, "
          << (std::string(input) == "multisine" ? "multi-sine" : "random levels");
      for (const char* key : estimators) {
        out << " | " << range(arx, [&](const Json& s) { return as_number(s.at("noise_free").at(input).at(key)); });
      }
      out << " |\n";
    }
    for (const Noise& noise : kNoises) {
      out << "| " << models << " | " << noise.label;
      for (const char* key : estimators) {
        out << " | " << range(arx, [&](const Json& s) { return median_of(s.at("noisy").at(noise.key), key); });
      }
      out << " |\n";
    }
  }
  out << "\n" << targets(results);
  int met = 0, pairs = 0, within = 0, systems = 0;
  double largest_change = 0.0;  // over the systems whose ratios stayed finite in every unit
  int diverged = 0;
  for (const Json& system : results.at("systems")) {
    const UnitsFigures figures = units_figures(system);
    met += figures.met;
    pairs += figures.pairs;
    within += figures.largest_ratio_change <= 0.05 ? 1 : 0;
    if (std::isfinite(figures.largest_ratio_change)) {
      largest_change = std::max(largest_change, figures.largest_ratio_change);
    } else {
      ++diverged;
    }
    ++systems;
  }
  out << "\n| units: u and y times 1e-3 to 1e4 | noise-free pairs at or below max(1e-6, identify()) | systems whose "
         "noisy ratios stay within 5% of the original units' | largest change of a ratio where finite | "
         "systems with a diverged run in some units |\n"
      << "|---|---|---|---|---|\n"
      << "| the default estimator | " << met << " of " << pairs << " | " << within << " of " << systems << " | "
      << percent(largest_change) << " | " << diverged << " |\n";
  return out.str();
}

/// The markdown tables of docs/results/online_accuracy.md.
std::string markdown(const Json& results) {
  std::ostringstream out;
  out << "# Online against offline: measured figures\n\n"
      << "Written by `bonl_online_accuracy` (examples/online_accuracy, `bash scripts/online_accuracy.sh`) from the\n"
      << "known systems of `tests/data/online_systems.json`; the numbers are in `online_accuracy.json` beside this\n"
      << "file, and ctest re-runs part of them (`examples/online_accuracy_quick`). NRMSE of free-run simulation on a\n"
      << "fresh input against the noise-free output. \"online\": one pass of `Estimator::update`, \"default\" with\n"
      << "its default settings (the window refinement from two starts), \"recursion alone\" with the window off;\n"
      << "`identify()`: offline, the recursive estimates refined by Levenberg-Marquardt.\n\n";
  out << "## Summary\n\n"
      << "Ranges over the systems of each kind (ARX, and the other models: block, feedback and hysteresis ones) of "
         "the\n"
      << "NRMSE, for noisy records of its median over the seeds. This table is also in docs/explanation/algorithm.md\n"
      << "(`online_accuracy_summary.md`).\n\n"
      << summary(results) << "\n";
  out << "## Noise-free, 4000 samples\n\n"
      << "| system | random levels: recursion alone | default | equation_error | paper | identify() | P-H-W c error |"
         " multi-sine: recursion alone | default | equation_error | paper | identify() | P-H-W c error |\n"
      << "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Json& system : results.at("systems")) {
    out << "| " << system.at("name").get<std::string>();
    for (const char* input : {"random_levels", "multisine"}) {
      const Json& r = system.at("noise_free").at(input);
      for (const char* key : {"output_error", "output_error_window", "equation_error", "paper", "identify"}) {
        out << " | " << format(as_number(r.at(key)));
      }
      out << " | " << (r.contains("c_relative_error") ? format(as_number(r.at("c_relative_error"))) : "");
    }
    out << " |\n";
  }
  out << "\n## Output noise, random levels, 4000 samples, " << kSeeds << " seeds: median NRMSE\n\n"
      << "The ratio is the online output-error median (the recursion alone, the default) over identify()'s.\n\n"
      << "| system | noise | recursion alone | default | online equation_error | online paper | "
         "identify() | ratio, recursion alone | ratio, default |\n"
      << "|---|---|---|---|---|---|---|---|---|\n";
  for (const Json& system : results.at("systems")) {
    for (const Noise& noise : kNoises) {
      const Json& seeds = system.at("noisy").at(noise.key);
      const double ours = median_of(seeds, "output_error"), offline = median_of(seeds, "identify");
      const double window = median_of(seeds, "output_error_window");
      out << "| " << system.at("name").get<std::string>() << " | " << noise.label << " | " << format(ours) << " | "
          << format(window) << " | " << format(median_of(seeds, "equation_error")) << " | "
          << format(median_of(seeds, "paper")) << " | " << format(offline) << " | " << format(ours / offline, "%.2f")
          << " | " << format(window / offline, "%.2f") << " |\n";
    }
  }
  out << "\n## The window's iterations against identify()'s\n\n"
      << "The window keeps a Levenberg-Marquardt step per pass over its samples; \"identify() at the window's\n"
      << "iterations\" is identify() on the same record with that many iterations (its default: 100), over the whole\n"
      << "record.\n\n"
      << "| system | multi-sine, noise-free: window iterations | window | identify() at the window's iterations | "
         "identify() |";
  for (const Noise& noise : kNoises)
    out << " " << noise.label << ": window iterations (median) | ratio, window | ratio, identify() at them |";
  out << "\n|---|---|---|---|---|";
  for (std::size_t i = 0; i < std::size(kNoises); ++i) out << "---|---|---|";
  out << "\n";
  for (const Json& system : results.at("systems")) {
    const Json& sines = system.at("noise_free").at("multisine");
    out << "| " << system.at("name").get<std::string>() << " | " << sines.at("window_iterations").get<long>() << " | "
        << format(as_number(sines.at("output_error_window"))) << " | "
        << format(as_number(sines.at("identify_at_window_iterations"))) << " | "
        << format(as_number(sines.at("identify")));
    for (const Noise& noise : kNoises) {
      const Json& seeds = system.at("noisy").at(noise.key);
      const double offline = median_of(seeds, "identify");
      out << " | " << format(median_of(seeds, "window_iterations"), "%.0f") << " | "
          << format(median_of(seeds, "output_error_window") / offline, "%.2f") << " | "
          << format(median_of(seeds, "identify_at_window_iterations") / offline, "%.2f");
    }
    out << " |\n";
  }
  out << "\n## Units\n\n"
      << "The noise-free random-level record and the noisy ones with u and y multiplied independently by 1e-3,\n"
      << "1e-1, 1, 1e2 and 1e4 (25 pairs; under noise the four extreme pairs, " << kSeeds << " seeds), the structure\n"
      << "rescaled with them, the default estimator and identify() judged in those units. \"ratio change\": the\n"
      << "largest relative difference of the online over offline ratio of median NRMSEs from the original units'.\n\n"
      << "| system | noise-free pairs met | worst online NRMSE | worst identify() NRMSE | ratio change under noise |\n"
      << "|---|---|---|---|---|\n";
  for (const Json& system : results.at("systems")) {
    const UnitsFigures figures = units_figures(system);
    out << "| " << system.at("name").get<std::string>() << " | " << figures.met << " of " << figures.pairs << " | "
        << format(figures.worst_online) << " | " << format(figures.worst_identify) << " | "
        << percent(figures.largest_ratio_change) << " |\n";
  }
  out << "\n## Tracking: constant forgetting 0.995, input gain +30% (P-H-W: and c doubled) at sample 4000\n\n"
      << "| system | samples until NRMSE < 1% | NRMSE at the end (4000 samples after) | window: samples | window: "
         "NRMSE |\n"
      << "|---|---|---|---|---|\n";
  const auto recovered = [](const Json& t) {
    return t.at("samples_to_1_percent").is_null() ? std::string("not within 4000")
                                                  : std::to_string(t.at("samples_to_1_percent").get<long>());
  };
  for (const Json& system : results.at("systems")) {
    const Json& t = system.at("tracking");
    const Json& r = system.at("tracking_window");
    out << "| " << system.at("name").get<std::string>() << " | " << recovered(t) << " | "
        << format(as_number(t.at("final"))) << " | " << recovered(r) << " | " << format(as_number(r.at("final")))
        << " |\n";
  }
  return out.str();
}

/// Every number in `computed` against the same place in `committed`. Returns the mismatches.
void compare(const Json& computed, const Json& committed, const std::string& where, std::vector<std::string>& out) {
  if (computed.is_object()) {
    for (const auto& [key, value] : computed.items()) {
      if (!committed.is_object() || !committed.contains(key)) {
        out.push_back(where + "/" + key + ": not in the committed results");
      } else {
        compare(value, committed.at(key), where + "/" + key, out);
      }
    }
  } else if (computed.is_array()) {
    for (std::size_t i = 0; i < computed.size(); ++i) {
      if (!committed.is_array() || i >= committed.size()) {
        out.push_back(where + "/" + std::to_string(i) + ": not in the committed results");
      } else {
        compare(computed[i], committed[i], where + "/" + std::to_string(i), out);
      }
    }
  } else if (computed.is_number() || committed.is_number() || computed.is_null() || committed.is_null()) {
    const double a = as_number(computed), b = as_number(committed);
    const bool same = (a == b) || (std::abs(a) <= 1e-9 && std::abs(b) <= 1e-9) ||
                      std::abs(a - b) <= 0.02 * std::max(std::abs(a), std::abs(b));
    if (!same) out.push_back(where + ": computed " + format(a, "%.6g") + ", committed " + format(b, "%.6g"));
  } else if (computed != committed) {
    out.push_back(where + ": computed " + computed.dump() + ", committed " + committed.dump());
  }
}

[[noreturn]] void usage(const std::string& problem) {
  std::cerr
      << "bonl_online_accuracy: " << problem
      << "\nusage: bonl_online_accuracy [--systems FILE] [--json FILE] [--markdown FILE] [--quick] [--check FILE]\n";
  std::exit(2);
}

}  // namespace

int main(int argc, char** argv) {
  std::string systems_path = BONL_ONLINE_SYSTEMS, json_path, markdown_path, check_path;
  bool quick = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) usage(arg + " needs a value");
      return argv[++i];
    };
    if (arg == "--systems")
      systems_path = value();
    else if (arg == "--json")
      json_path = value();
    else if (arg == "--markdown")
      markdown_path = value();
    else if (arg == "--check")
      check_path = value();
    else if (arg == "--quick")
      quick = true;
    else
      usage("unknown argument '" + arg + "'");
  }
  try {
    const std::vector<System> systems = load_systems(systems_path);
    std::vector<Json> evaluated(systems.size());
    // The systems are independent: spread them over the cores, each result in its own slot.
    std::atomic<std::size_t> next{0};
    const auto work = [&] {
      for (std::size_t i = next++; i < systems.size(); i = next++) {
        evaluated[i] = std::visit([&](const auto& model) { return evaluate(model, quick); }, systems[i].model);
        std::fprintf(stderr, "%s done\n", systems[i].name.c_str());
      }
    };
    std::vector<std::thread> threads(std::max(1u, std::thread::hardware_concurrency()));
    for (auto& thread : threads) thread = std::thread(work);
    for (auto& thread : threads) thread.join();

    Json results;
    results["generated_by"] = "bonl_online_accuracy";
    results["samples"] = kSamples;
    results["seeds"] = quick ? 1 : kSeeds;
    results["systems"] = Json::array();
    for (std::size_t i = 0; i < systems.size(); ++i) {
      Json entry;
      entry["name"] = systems[i].name;
      entry["set"] = systems[i].set;
      entry.update(evaluated[i]);
      results["systems"].push_back(entry);
    }
    if (!json_path.empty()) {
      std::ofstream out(json_path);
      out << results.dump(1) << "\n";
      if (!out) throw std::runtime_error("cannot write " + json_path);
    }
    if (!markdown_path.empty()) {
      std::ofstream out(markdown_path);
      out << markdown(results);
      if (!out) throw std::runtime_error("cannot write " + markdown_path);
      // The summary alone, beside it (docs/explanation/algorithm.md includes it verbatim).
      const std::string summary_path = markdown_path.substr(0, markdown_path.rfind(".md")) + "_summary.md";
      std::ofstream summary_out(summary_path);
      summary_out << summary(results);
      if (!summary_out) throw std::runtime_error("cannot write " + summary_path);
    }
    if (json_path.empty() && markdown_path.empty() && check_path.empty()) std::cout << markdown(results);
    if (!check_path.empty()) {
      std::ifstream in(check_path);
      if (!in) throw std::runtime_error("cannot read " + check_path);
      Json committed = Json::parse(in);
      Json computed = results;
      computed.erase("seeds");  // --quick computes seed 1 of each; compared position by position
      std::vector<std::string> mismatches;
      compare(computed, committed, "", mismatches);
      for (const std::string& m : mismatches) std::cerr << "mismatch " << m << "\n";
      std::cerr << "checked against " << check_path << ": " << mismatches.size() << " mismatches\n";
      return mismatches.empty() ? 0 : 1;
    }
    return 0;
  } catch (const std::exception& error) {
    std::cerr << "bonl_online_accuracy: " << error.what() << "\n";
    return 1;
  }
}
