// bonl_soak: the estimator as it would run for months inside a controller. P-H-W online
// identification (paper orders, output-error method by default, constant forgetting factor 0.98) of a known P-H-W
// plant through a repeating cycle of phases:
//   rich      random input levels, 1% output noise, occasional outliers (|y| spikes of 20 std(y));
//   constant  the input held at one value (only the output noise excites);
//   rich      again;
//   zero      machine and sensors off: u = y = 0, a zero regressor (covariance wind-up's worst case).
// Checked every sample: theta finite. Every --check-every samples: P finite, exactly symmetric,
// positive definite (smallest eigenvalue > 0), trace within the ceiling. Measured: the largest |P|
// entry, the smallest eigenvalue, and for each rich phase after a poor one the recovery time: the
// samples until the median |innovation| over a 100-sample window first comes within 1.5x the median
// over the second half of the same phase. Exit status 1 if any check fails, a rich phase does not
// recover within its first half, or a rich phase passes without a single accepted update (the
// estimator has stopped learning: the recovery time cannot see that, since a stalled estimator's
// innovation is as large in the second half of a phase as in the first). Figures are in
// docs/lab/reliability.md.
//
//   bonl_soak [--samples N] [--phase-length L] [--check-every C] [--no-ceiling | --trace-ceiling X] [--seed S]
//             [--method output_error|equation_error|paper] [--no-window] [--json FILE]
//   --no-window  the output-error method's recursion alone, without its window refinement (on by
//                default: EstimatorOptions::window)

#include <bonl/bonl.hpp>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "known_systems.hpp"

namespace {

using Model = bonl::PaperPseudoHammersteinWiener;

struct Settings {
  long long samples = 100'000'000;
  long long phase_length = 50'000;
  long long check_every = 10'000;
  std::optional<double> trace_ceiling;  // unset: the method's default
  bonl::Method method = bonl::Method::OutputError;
  unsigned seed = 2026;
  std::string json;
  bool window = true;  // the output-error method's window refinement, as the estimator's default
};

[[noreturn]] void usage(const std::string& problem) {
  std::cerr
      << "bonl_soak: " << problem
      << "\nusage: bonl_soak [--samples N] [--phase-length L] [--check-every C] [--no-ceiling | --trace-ceiling X]"
         " [--seed S] [--method output_error|equation_error|paper] [--no-window] [--json FILE]\n";
  std::exit(2);
}

long long parse_count(const std::string& text, const char* name) {
  try {
    std::size_t used = 0;
    const long long value = std::stoll(text, &used);
    if (used != text.size() || value < 1) throw std::invalid_argument(name);
    return value;
  } catch (const std::exception&) {
    usage(std::string(name) + " must be a positive integer, got '" + text + "'");
  }
}

Settings parse(int argc, char** argv) {
  Settings s;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) usage(arg + " needs a value");
      return argv[++i];
    };
    if (arg == "--samples")
      s.samples = parse_count(value(), "--samples");
    else if (arg == "--phase-length")
      s.phase_length = parse_count(value(), "--phase-length");
    else if (arg == "--check-every")
      s.check_every = parse_count(value(), "--check-every");
    else if (arg == "--seed")
      s.seed = static_cast<unsigned>(parse_count(value(), "--seed"));
    else if (arg == "--json")
      s.json = value();
    else if (arg == "--no-window")
      s.window = false;
    else if (arg == "--no-ceiling")
      s.trace_ceiling = std::numeric_limits<double>::infinity();
    else if (arg == "--trace-ceiling") {
      const std::string text = value();
      try {
        s.trace_ceiling = std::stod(text);
      } catch (const std::exception&) {
        usage("--trace-ceiling must be a number, got '" + text + "'");
      }
    } else if (arg == "--method") {
      try {
        s.method = bonl::method_from_string(value());
      } catch (const std::invalid_argument& error) {
        usage(std::string("--method: ") + error.what());
      }
    } else
      usage("unknown argument '" + arg + "'");
  }
  if (s.phase_length < 4000) usage("--phase-length must be >= 4000 (recovery is measured within the first half)");
  return s;
}

/// The known P-H-W plant one sample at a time (Model::simulate works on whole records; the soak
/// needs an endless one). Checked against Model::simulate at start-up.
class Plant {
 public:
  explicit Plant(const Model& model)
      : m_f(model.f()), m_p(model.p()), m_b(model.b()), m_a(model.a()), m_c(model.c()), m_nk(model.nk()),
        m_w(static_cast<std::size_t>(model.nk() + model.nb() + 1), 0.0),
        m_x(static_cast<std::size_t>(model.na()), 0.0) {}

  double step(double u) {
    m_w.insert(m_w.begin(), bonl::TwoSegmentPolynomial<double>::evaluate(m_f, m_p, u));
    m_w.pop_back();
    double x = 0.0;
    for (Eigen::Index i = 0; i < m_b.size(); ++i) x += m_b[i] * m_w[static_cast<std::size_t>(m_nk + i)];
    for (Eigen::Index j = 0; j < m_a.size(); ++j) x -= m_a[j] * m_x[static_cast<std::size_t>(j)];
    m_x.insert(m_x.begin(), x);
    m_x.pop_back();
    m_y = bonl::Backlash<double>::map(x, m_y, m_c);
    return m_y;
  }

 private:
  Eigen::VectorXd m_f, m_p, m_b, m_a;
  double m_c;
  Eigen::Index m_nk;
  std::vector<double> m_w, m_x;
  double m_y = 0.0;
};

enum class Phase { Rich, Constant, Zero };
Phase phase_of(long long cycle_index) {
  switch (cycle_index % 4) {
    case 1: return Phase::Constant;
    case 3: return Phase::Zero;
    default: return Phase::Rich;
  }
}

double median(std::vector<double> values) {
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

struct Recovery {
  Phase after;
  long long samples;  // -1: did not recover in the first half of the phase
};

/// Recovery time of one rich phase from its |innovation| record (see the top of the file).
long long recovery_time(const std::vector<double>& abs_innovation) {
  constexpr std::size_t kWindow = 100;
  const std::size_t n = abs_innovation.size();
  const std::vector<double> late(abs_innovation.begin() + static_cast<std::ptrdiff_t>(n / 2), abs_innovation.end());
  const double level = median(late);
  for (std::size_t start = 0; start + kWindow <= n / 2; start += 10) {
    const std::vector<double> window(abs_innovation.begin() + static_cast<std::ptrdiff_t>(start),
                                     abs_innovation.begin() + static_cast<std::ptrdiff_t>(start + kWindow));
    if (median(window) <= 1.5 * level) return static_cast<long long>(start + kWindow);
  }
  return -1;
}

}  // namespace

int main(int argc, char** argv) {
  const Settings settings = parse(argc, argv);
  const Model truth = bonl_test::known_phw();

  // Self-check of the per-sample plant against the library's own simulation.
  {
    const Eigen::VectorXd u = bonl::signals::random_levels(5000, 5, 1.0, 1);
    const Eigen::VectorXd y = truth.simulate(u);
    Plant plant(truth);
    double worst = 0.0;
    for (Eigen::Index k = 0; k < u.size(); ++k) worst = std::max(worst, std::abs(plant.step(u[k]) - y[k]));
    if (worst > 1e-12) {
      std::cerr << "bonl_soak: the per-sample plant differs from Model::simulate by " << worst << "\n";
      return 1;
    }
  }

  bonl::EstimatorOptions options;
  options.forgetting = bonl::ForgettingSchedule::constant(0.98);
  options.method = settings.method;
  options.trace_ceiling = settings.trace_ceiling;
  options.window.enabled = settings.window;
  try {
    options.validate();
  } catch (const std::invalid_argument& error) {
    usage(error.what());
  }
  const bool ceiling = std::isfinite(options.resolved_trace_ceiling());
  bonl::Estimator<Model> estimator(truth, options);
  const double trace_limit = options.resolved_trace_ceiling() * options.resolved_p0() * double(truth.num_params());

  std::mt19937_64 rng(settings.seed);
  std::uniform_real_distribution<double> level(-1.0, 1.0);
  std::uniform_int_distribution<int> hold(1, 10);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double output_std = 0.12;  // std of the plant's output under the rich input (measured: ~0.12)
  const double noise = 0.01 * output_std;
  const double outlier_probability = 2e-4;
  const double outlier_size = 20.0 * output_std;

  Plant plant(truth);
  double u = 0.0;
  int held = 0;
  double constant_level = 0.0;
  long long outliers = 0;
  double largest_p = 0.0, smallest_eigenvalue = std::numeric_limits<double>::infinity();
  double largest_theta = 0.0, largest_trace = 0.0;
  long long checks = 0, failures = 0;
  std::vector<std::string> problems;
  std::vector<Recovery> recoveries;
  std::vector<double> abs_innovation;
  abs_innovation.reserve(static_cast<std::size_t>(settings.phase_length));
  Phase previous_poor = Phase::Zero;
  long long status_counts[4] = {0, 0, 0, 0};
  long long updates_in_phase = 0, stalled_phases = 0, first_stall_end = -1;

  const auto report_problem = [&](long long k, const std::string& what) {
    if (problems.size() < 20) problems.push_back("sample " + std::to_string(k) + ": " + what);
    ++failures;
  };

  const auto started = std::chrono::steady_clock::now();
  for (long long k = 0; k < settings.samples; ++k) {
    const long long phase_index = k / settings.phase_length;
    const long long in_phase = k % settings.phase_length;
    const Phase phase = phase_of(phase_index);
    if (in_phase == 0) {
      constant_level = level(rng);
      held = 0;
    }
    if (phase == Phase::Rich) {
      if (held-- <= 0) {
        u = level(rng);
        held = hold(rng) - 1;
      }
    } else if (phase == Phase::Constant) {
      u = constant_level;
    } else {
      u = 0.0;
    }
    const double y_true = plant.step(u);
    double y = 0.0;
    if (phase != Phase::Zero) {
      y = y_true + noise * gauss(rng);
      if (phase == Phase::Rich && unit(rng) < outlier_probability) {
        y += unit(rng) < 0.5 ? -outlier_size : outlier_size;
        ++outliers;
      }
    }

    const bonl::UpdateStatus status = estimator.update(u, y);
    ++status_counts[static_cast<int>(status)];
    if (status == bonl::UpdateStatus::Updated) ++updates_in_phase;
    if (!estimator.theta().allFinite()) report_problem(k, "theta is not finite");
    if (phase == Phase::Rich) abs_innovation.push_back(std::abs(y - estimator.last_prediction()));

    if (in_phase == settings.phase_length - 1) {
      if (phase == Phase::Rich) {
        if (updates_in_phase == 0) {  // stalled: the estimator learned nothing in a whole rich phase
          if (stalled_phases == 0) first_stall_end = k;
          ++stalled_phases;
        }
        if (phase_index > 0) recoveries.push_back({previous_poor, recovery_time(abs_innovation)});
        abs_innovation.clear();
      } else {
        previous_poor = phase;
      }
      updates_in_phase = 0;
    }

    if ((k + 1) % settings.check_every == 0) {
      ++checks;
      const auto p = estimator.normalised_covariance();  // the coordinates the ceiling bounds
      if (!p.allFinite()) {
        report_problem(k, "P is not finite");
        continue;
      }
      if (p != p.transpose()) report_problem(k, "P is not exactly symmetric");
      const double min_eigenvalue =
          Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(p, Eigen::EigenvaluesOnly).eigenvalues().minCoeff();
      if (!(min_eigenvalue > 0.0)) report_problem(k, "P is not positive definite: " + std::to_string(min_eigenvalue));
      if (ceiling && p.trace() > trace_limit * (1.0 + 1e-12)) report_problem(k, "trace(P) above the ceiling");
      largest_p = std::max(largest_p, p.cwiseAbs().maxCoeff());
      largest_trace = std::max(largest_trace, p.trace());
      smallest_eigenvalue = std::min(smallest_eigenvalue, min_eigenvalue);
      largest_theta = std::max(largest_theta, estimator.theta().cwiseAbs().maxCoeff());
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();

  long long not_recovered = 0;
  std::vector<double> after_constant, after_zero;
  for (const Recovery& r : recoveries) {
    if (r.samples < 0) {
      ++not_recovered;
      continue;
    }
    (r.after == Phase::Constant ? after_constant : after_zero).push_back(double(r.samples));
  }
  if (not_recovered > 0) {
    ++failures;
    problems.push_back(std::to_string(not_recovered) + " rich phases did not recover within their first half");
  }
  if (stalled_phases > 0) {
    ++failures;
    problems.push_back(std::to_string(stalled_phases) +
                       " rich phases without a single accepted update (the first ended at sample " +
                       std::to_string(first_stall_end) + "): the estimator stopped learning");
  }
  // The recovery times' spread: median, 90th percentile and largest, over `phases` phases.
  struct Spread {
    double median, p90, max;
    std::size_t phases;
  };
  const auto spread = [](std::vector<double> v) -> std::optional<Spread> {
    if (v.empty()) return std::nullopt;
    std::sort(v.begin(), v.end());
    return Spread{v[v.size() / 2], v[v.size() * 9 / 10], v.back(), v.size()};
  };
  const auto stats = [&](const std::vector<double>& v) {
    const auto s = spread(v);
    if (!s) return std::string("none");
    char text[160];
    std::snprintf(text, sizeof text, "median %.0f, 90%% %.0f, max %.0f samples (%zu phases)", s->median, s->p90, s->max,
                  s->phases);
    return std::string(text);
  };
  const bonl::EstimatorHealth& health = estimator.health();

  std::printf("bonl_soak: %lld samples of P-H-W online identification, %s method%s, lambda = 0.98, trace ceiling %g\n",
              settings.samples, bonl::to_string(settings.method),
              settings.window && settings.method == bonl::Method::OutputError ? " with the window refinement" : "",
              options.resolved_trace_ceiling());
  std::printf("  phases of %lld samples: rich, constant, rich, zero; %lld outliers of +-%.2f\n", settings.phase_length,
              outliers, outlier_size);
  std::printf("  wall time %.1f s (%.0f ns per sample, data generation and checks included)\n", seconds,
              1e9 * seconds / double(settings.samples));
  std::printf("  statuses: updated %lld, no information %lld, rejected non-finite %lld, numerical failure %lld\n",
              status_counts[0], status_counts[1], status_counts[2], status_counts[3]);
  std::printf("  health: forgetting limited on %lld updates, %lld failures, %lld internal restarts\n",
              static_cast<long long>(health.forgetting_limited), static_cast<long long>(health.failures),
              static_cast<long long>(health.internal_restarts));
  std::printf("  checkpoint: %lld returns\n", static_cast<long long>(health.checkpoint_returns));
  if (settings.window) {
    const bonl::WindowRefinementCounts& w = health.window;
    std::printf(
        "  window: %lld iterations, %lld refused steps, %lld swaps, %lld refusals, %lld undetermined, %lld restarts, "
        "%lld overruns\n",
        static_cast<long long>(w.iterations), static_cast<long long>(w.refused_steps), static_cast<long long>(w.swaps),
        static_cast<long long>(w.refusals), static_cast<long long>(w.undetermined), static_cast<long long>(w.reseeds),
        static_cast<long long>(w.overruns));
  }
  std::printf(
      "  %lld covariance checks: largest |P| %.3e, largest trace %.3e (ceiling %.3e), smallest eigenvalue %.3e\n",
      checks, largest_p, largest_trace, trace_limit, smallest_eigenvalue);
  std::printf("  largest |theta| %.3e\n", largest_theta);
  std::printf("  recovery after constant input: %s\n", stats(after_constant).c_str());
  std::printf("  recovery after zero input:     %s\n", stats(after_zero).c_str());
  std::printf("  rich phases without an accepted update: %lld\n", stalled_phases);
  for (const std::string& problem : problems) std::printf("  PROBLEM %s\n", problem.c_str());
  std::printf("  result: %s\n", failures == 0 ? "pass" : "FAIL");

  if (!settings.json.empty()) {
    // One run's figures, for tests/soak/report.py (scripts/soak.sh gathers them into
    // docs/results/soak.json).
    const auto numbers = [&](const std::vector<double>& v) {
      const auto s = spread(v);
      if (!s) return std::string("null");
      return "{\"median\": " + std::to_string(s->median) + ", \"p90\": " + std::to_string(s->p90) +
             ", \"max\": " + std::to_string(s->max) + ", \"phases\": " + std::to_string(s->phases) + "}";
    };
    std::ofstream out(settings.json);
    out.precision(6);
    out << "{\"samples\": " << settings.samples << ", \"seed\": " << settings.seed << ", \"method\": \""
        << bonl::to_string(settings.method) << "\", \"window\": " << (settings.window ? "true" : "false")
        << ", \"phase_length\": " << settings.phase_length
        << ", \"trace_ceiling\": " << (ceiling ? std::to_string(options.resolved_trace_ceiling()) : std::string("null"))
        << ", \"seconds\": " << seconds << ", \"outliers\": " << outliers << ", \"updated\": " << status_counts[0]
        << ", \"largest_abs_p\": " << largest_p << ", \"largest_trace\": " << largest_trace
        << ", \"smallest_eigenvalue\": " << smallest_eigenvalue << ", \"largest_abs_theta\": " << largest_theta
        << ", \"plant_largest_abs_theta\": " << truth.theta().cwiseAbs().maxCoeff() << ", \"failures\": " << failures
        << ", \"forgetting_limited\": " << health.forgetting_limited << ", \"numerical_failures\": " << health.failures
        << ", \"checkpoint_returns\": " << health.checkpoint_returns
        << ", \"rich_phases_after_poor\": " << recoveries.size() << ", \"not_recovered\": " << not_recovered
        << ", \"recovery_after_constant\": " << numbers(after_constant)
        << ", \"recovery_after_zero\": " << numbers(after_zero) << ", \"stalled_rich_phases\": " << stalled_phases;
    if (settings.window) {
      const bonl::WindowRefinementCounts& w = health.window;
      out << ", \"window_counts\": {\"iterations\": " << w.iterations << ", \"refused_steps\": " << w.refused_steps
          << ", \"swaps\": " << w.swaps << ", \"refusals\": " << w.refusals << ", \"undetermined\": " << w.undetermined
          << ", \"reseeds\": " << w.reseeds << ", \"overruns\": " << w.overruns << "}";
    }
    out << ", \"pass\": " << (failures == 0 ? "true" : "false") << "}\n";
  }
  return failures == 0 ? 0 : 1;
}
