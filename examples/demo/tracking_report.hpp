#pragma once
// bonl_demo --control: the tracking experiment's result (bonl/experiment/tracking_experiment.hpp) as
// a table on stdout, and as --json, --markdown (docs/results/tracking_summary.md) and --csv.

#include <bonl/experiment.hpp>

#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>

namespace bonl_demo {

inline void print_tracking(const bonl::experiment::TrackingResult& result) {
  const auto& o = result.options;
  std::printf(
      "Tracking a reference joint velocity (smooth random, %.2g Hz, RMS %.3g rad/s, period %.0f s) for %.0f s\n",
      o.reference_bandwidth_hz, o.reference_rms, o.period, o.duration);
  std::printf(
      "PI by SIMC from the ARX model: Kc = %.4g V/(rad/s), tau_I = %.4g s; feedforward: the inverses of the "
      "%s method's models\n\n",
      result.proportional_gain, result.integral_time, bonl::to_string(o.method));
  const double pi = result.run("PI").rms;
  std::printf("%-28s %14s %14s\n", "controller", "RMS [rad/s]", "vs PI alone");
  for (const auto& run : result.runs) {
    if (run.plant_changes) continue;
    std::printf("%-28s %14.5f %13.1f%%\n", run.label.c_str(), run.rms, 100.0 * (run.rms / pi - 1.0));
  }
  std::printf(
      "\nThe plant changes at %.0f s (pilot hysteresis x%.3g, bulk modulus x%.3g): RMS over the period before "
      "it, and over %.0f-%.0f s after it\n",
      o.change_time, o.pilot_hysteresis_factor, o.bulk_modulus_factor, o.period, 2.0 * o.period);
  std::printf("%-28s %14s %14s %10s\n", "controller", "before", "after", "ratio");
  for (const auto& run : result.runs) {
    if (!run.plant_changes) continue;
    std::printf("%-28s %14.5f %14.5f %10.2f\n", run.label.c_str(), run.rms_before_change, run.rms_after_change,
                run.rms_after_change / run.rms_before_change);
  }
  const auto& adaptive = result.runs.back();
  std::printf("adaptive: %ld inverses derived from the estimate, %ld estimates refused by the guard\n",
              static_cast<long>(adaptive.rederivations), static_cast<long>(adaptive.refused));
}

/// {"tracking_rms": {"PI": ..., "ARX": ..., ...}, "plant_change": {controller: {"before": ..., "after": ...}},
///  "pi": {"proportional_gain": ..., "integral_time": ...}, "adaptive": {"rederivations": ..., "refused": ...}}
inline void write_tracking_json(const std::string& path, const bonl::experiment::TrackingResult& result) {
  std::ofstream out(path);
  char number[64];
  const auto num = [&](double v) {
    std::snprintf(number, sizeof number, "%.17g", v);
    return std::string(number);
  };
  std::string rms, change;
  for (const auto& run : result.runs) {
    if (!run.plant_changes) {
      rms += (rms.empty() ? "\"" : ", \"") + run.controller + "\": " + num(run.rms);
    } else {
      change += (change.empty() ? "\"" : ",\n  \"") + run.controller +
                "\": {\"before\": " + num(run.rms_before_change) + ", \"after\": " + num(run.rms_after_change) + "}";
    }
  }
  const auto& adaptive = result.runs.back();
  out << "{\"tracking_rms\": {" << rms << "},\n \"plant_change\": {" << change
      << "},\n \"pi\": {\"proportional_gain\": " << num(result.proportional_gain)
      << ", \"integral_time\": " << num(result.integral_time)
      << "},\n \"adaptive\": {\"rederivations\": " << adaptive.rederivations << ", \"refused\": " << adaptive.refused
      << "},\n \"method\": \"" << bonl::to_string(result.options.method) << "\"}\n";
  if (!out) throw std::runtime_error("bonl_demo: cannot write " + path);
}

/// docs/results/tracking_summary.md: the two tables of print_tracking.
inline void write_tracking_markdown(const std::string& path, const bonl::experiment::TrackingResult& result) {
  std::ofstream out(path);
  char line[256];
  const double pi = result.run("PI").rms;
  out << "| controller | tracking RMS [rad/s] | vs PI alone |\n|---|---:|---:|\n";
  for (const auto& run : result.runs) {
    if (run.plant_changes) continue;
    std::snprintf(line, sizeof line, "| %s | %.5f | %+.1f%% |\n", run.label.c_str(), run.rms,
                  100.0 * (run.rms / pi - 1.0));
    out << line;
  }
  std::snprintf(line, sizeof line,
                "\n| under the plant change at %g s | RMS before [rad/s] | RMS %g-%g s after | ratio |\n",
                result.options.change_time, result.options.period, 2.0 * result.options.period);
  out << line << "|---|---:|---:|---:|\n";
  for (const auto& run : result.runs) {
    if (!run.plant_changes) continue;
    std::snprintf(line, sizeof line, "| %s | %.5f | %.5f | %.2f |\n", run.label.c_str(), run.rms_before_change,
                  run.rms_after_change, run.rms_after_change / run.rms_before_change);
    out << line;
  }
  if (!out) throw std::runtime_error("bonl_demo: cannot write " + path);
}

/// time, reference, then each run's joint rate and command.
inline void write_tracking_csv(const std::string& path, const bonl::experiment::TrackingResult& result) {
  std::ofstream out(path);
  out << "time,reference";
  for (const auto& run : result.runs) {
    const std::string name = run.controller + (run.plant_changes ? " changing" : "");
    out << ",joint_rate " << name << ",command " << name;
  }
  out << '\n';
  for (Eigen::Index k = 0; k < result.time.size(); ++k) {
    out << result.time[k] << ',' << result.reference[k];
    for (const auto& run : result.runs) out << ',' << run.joint_rate[k] << ',' << run.command[k];
    out << '\n';
  }
  if (!out) throw std::runtime_error("bonl_demo: cannot write " + path);
}

}  // namespace bonl_demo
