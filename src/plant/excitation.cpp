// Command signals V(t) for the plant (excitation.hpp). Each generator validates its arguments,
// precomputes what a call needs and returns a closure that captures it by value: a call only
// evaluates sines (or indexes a vector) and never allocates.

#include <bonl/plant/excitation.hpp>

#include <bonl/detail/validate.hpp>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>

namespace bonl::plant::excitation {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2.0 * kPi;
constexpr double kMaxSmoothRandomTones = 1e6;

/// Throws std::invalid_argument("bonl: excitation::<function>: <message>") unless `condition`.
void require(bool condition, const char* function, const std::string& message) {
  bonl::detail::require(condition, std::string("excitation::") + function + ": " + message);
}

void require_finite(double value, const char* function, const char* name) {
  require(std::isfinite(value), function,
          std::string(name) + " must be finite, got " + bonl::detail::format_number(value));
}

void require_positive(double value, const char* function, const char* name) {
  require(std::isfinite(value) && value > 0.0, function,
          std::string(name) + " must be finite and > 0, got " + bonl::detail::format_number(value));
}

/// Schroeder phases phi_k = -pi k (k + 1) / n, k = 1..n.
std::vector<double> schroeder_phases(std::size_t n) {
  std::vector<double> phases(n);
  for (std::size_t k = 1; k <= n; ++k) {
    phases[k - 1] = -kPi * static_cast<double>(k * (k + 1)) / static_cast<double>(n);
  }
  return phases;
}

/// The multisine after validation; `function` names the public entry point in messages.
Command make_multisine(const char* function, const std::vector<double>& frequencies_hz, double amplitude, double offset,
                       std::vector<double> phases) {
  require(!frequencies_hz.empty(), function, "frequencies_hz must not be empty");
  for (std::size_t i = 0; i < frequencies_hz.size(); ++i) {
    require(std::isfinite(frequencies_hz[i]) && frequencies_hz[i] >= 0.0, function,
            "frequencies_hz must be finite and >= 0, got " + bonl::detail::format_number(frequencies_hz[i]) +
                " at index " + std::to_string(i));
  }
  require_finite(amplitude, function, "amplitude");
  require_finite(offset, function, "offset");
  if (phases.empty()) {
    phases = schroeder_phases(frequencies_hz.size());
  } else {
    require(phases.size() == frequencies_hz.size(), function,
            "phases must be empty or have as many entries as frequencies_hz (" + std::to_string(frequencies_hz.size()) +
                "), got " + std::to_string(phases.size()));
    for (std::size_t i = 0; i < phases.size(); ++i) {
      require(std::isfinite(phases[i]), function, "phases has a non-finite value at index " + std::to_string(i));
    }
  }
  std::vector<double> omegas(frequencies_hz.size());
  for (std::size_t i = 0; i < omegas.size(); ++i) omegas[i] = kTwoPi * frequencies_hz[i];
  return [omegas = std::move(omegas), phases = std::move(phases), amplitude, offset](double t) {
    double sum = 0.0;
    for (std::size_t i = 0; i < omegas.size(); ++i) sum += std::sin(omegas[i] * t + phases[i]);
    return offset + amplitude * sum;
  };
}

/// floor(x), except that an x short of the next integer by no more than `tolerance` counts as it.
double floor_with_snap(double x, double tolerance) {
  const double below = std::floor(x);
  return (below + 1.0) - x <= tolerance ? below + 1.0 : below;
}

}  // namespace

Command step(double level, double t_step, double before) {
  require_finite(level, "step", "level");
  require_finite(t_step, "step", "t_step");
  require_finite(before, "step", "before");
  return [level, t_step, before](double t) { return t < t_step ? before : level; };
}

Command multisine(const std::vector<double>& frequencies_hz, double amplitude, double offset,
                  std::vector<double> phases) {
  return make_multisine("multisine", frequencies_hz, amplitude, offset, std::move(phases));
}

Command paper_multisine(double amplitude, double offset) {
  return make_multisine("paper_multisine", {0.1, 0.2, 0.4, 0.5, 1.0}, amplitude, offset, {});
}

Command smooth_random(double bandwidth_hz, double rms, double duration, std::uint64_t seed, double offset) {
  const char* function = "smooth_random";
  require_positive(bandwidth_hz, function, "bandwidth_hz");
  require(std::isfinite(rms) && rms >= 0.0, function,
          "rms must be finite and >= 0, got " + bonl::detail::format_number(rms));
  require_positive(duration, function, "duration");
  require_finite(offset, function, "offset");
  // Tones k / duration, k = 1..floor(bandwidth * duration); a product that rounding left just short
  // of an integer still admits the tone at the bandwidth itself.
  const double product = bandwidth_hz * duration;
  require(std::isfinite(product), function, "bandwidth_hz * duration must be finite");
  const double tones = floor_with_snap(product, 1e-9 * std::max(1.0, product));
  require(tones >= 1.0, function,
          "bandwidth_hz * duration must be >= 1 so that at least one tone k / duration fits under the "
          "bandwidth, got bandwidth_hz = " +
              bonl::detail::format_number(bandwidth_hz) + " and duration = " + bonl::detail::format_number(duration));
  // Each call of the command costs one sine per tone: a limit far above any use (10 Hz over 10^5 s
  // is 10^6 tones) that turns an absurd product into an error rather than std::bad_alloc or a
  // simulation that never ends.
  require(tones <= kMaxSmoothRandomTones, function,
          "bandwidth_hz * duration must be <= " + std::to_string(static_cast<long>(kMaxSmoothRandomTones)) +
              " (one sine per tone and call), got bandwidth_hz = " + bonl::detail::format_number(bandwidth_hz) +
              " and duration = " + bonl::detail::format_number(duration));
  const auto n = static_cast<std::size_t>(tones);
  std::mt19937_64 generator(seed);
  std::uniform_real_distribution<double> uniform_phase(0.0, kTwoPi);
  std::vector<double> omegas(n);
  std::vector<double> phases(n);
  for (std::size_t k = 1; k <= n; ++k) {
    omegas[k - 1] = kTwoPi * static_cast<double>(k) / duration;
    phases[k - 1] = uniform_phase(generator);
  }
  // Over [0, duration] the tones are orthogonal, each with mean square amplitude^2 / 2.
  const double amplitude = rms * std::sqrt(2.0 / static_cast<double>(n));
  return [omegas = std::move(omegas), phases = std::move(phases), amplitude, offset](double t) {
    double sum = 0.0;
    for (std::size_t i = 0; i < omegas.size(); ++i) sum += std::sin(omegas[i] * t + phases[i]);
    return offset + amplitude * sum;
  };
}

Command chirp(double f0_hz, double f1_hz, double duration, double amplitude, double offset) {
  const char* function = "chirp";
  require(std::isfinite(f0_hz) && f0_hz >= 0.0, function,
          "f0_hz must be finite and >= 0, got " + bonl::detail::format_number(f0_hz));
  require(std::isfinite(f1_hz) && f1_hz >= 0.0, function,
          "f1_hz must be finite and >= 0, got " + bonl::detail::format_number(f1_hz));
  require_positive(duration, function, "duration");
  require_finite(amplitude, function, "amplitude");
  require_finite(offset, function, "offset");
  // phase(t) = 2 pi (f0 t + (f1 - f0) t^2 / (2 duration)) on [0, duration]; before 0 it continues at
  // f0 and after duration at f1, both with a continuous phase.
  const double omega0 = kTwoPi * f0_hz;
  const double omega1 = kTwoPi * f1_hz;
  const double sweep = kPi * (f1_hz - f0_hz) / duration;  // 2 pi (f1 - f0) / (2 duration)
  const double end_phase = kPi * (f0_hz + f1_hz) * duration;
  return [omega0, omega1, sweep, end_phase, duration, amplitude, offset](double t) {
    double phase;
    if (t <= 0.0) {
      phase = omega0 * t;
    } else if (t <= duration) {
      phase = (omega0 + sweep * t) * t;
    } else {
      phase = end_phase + omega1 * (t - duration);
    }
    return offset + amplitude * std::sin(phase);
  };
}

Command sampled(const Eigen::VectorXd& values, double ts, double t0) {
  const char* function = "sampled";
  require(values.size() > 0, function, "values must not be empty");
  for (Eigen::Index i = 0; i < values.size(); ++i) {
    require(std::isfinite(values[i]), function, "values has a non-finite value at index " + std::to_string(i));
  }
  require_positive(ts, function, "ts");
  require_finite(t0, function, "t0");
  const double last = static_cast<double>(values.size() - 1);
  return [values = Eigen::VectorXd(values), ts, t0, last](double t) {
    if (std::isnan(t)) return t;
    // Sample k covers [t0 + k ts, t0 + (k + 1) ts). A time that rounding left within a few ulps below
    // an edge (t = t0 + k ts computed in floating point) counts as on the edge.
    const double x = (t - t0) / ts;
    const double tolerance = 8.0 * DBL_EPSILON * (1.0 + (std::abs(t) + std::abs(t0)) / ts);
    const double k = std::min(std::max(floor_with_snap(x, tolerance), 0.0), last);
    return values[static_cast<Eigen::Index>(k)];
  };
}

}  // namespace bonl::plant::excitation
