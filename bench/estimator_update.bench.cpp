// Cost of one online estimator update (Estimator<Model>::update) per model at the paper's orders
// (na = 3, nb = 2, nk = 8, r = r1 = 3), on a recorded noisy response of the known P-H-W system:
// fixed (paper-order template) sizes and run-time (Eigen::Dynamic) sizes, double and float (the
// float ones in estimator_update_float.bench.cpp), each method: output_error (the default),
// equation_error, paper. One benchmark iteration is one sample.
//
// Names: update/<Model::kName>/<fixed|dynamic>/<double|float>[/equation_error|/paper] (no suffix:
// the output-error method). The counter `updated` is the fraction of samples that ran the RLS step
// (measured in an untimed pass over the record): the P-H-W equation-error method skips the samples
// inside the backlash gap (about a quarter here), so its average is below the cost of a full update;
// the output-error method updates on every sample. Float runs of the equation-error and paper
// methods use P(0) = 1e4 I (see update()); a numerical failure would show here as a small `updated`.
//
// The cost depends on the data: where the structure does not fit them, the output-error update's
// safeguards work on most samples. update/PseudoHammersteinWiener/<fixed|dynamic>/double/<data>
// (data: delayed_fir, integrator; bench_data.hpp) time the default estimator there; the counters
// `limited` and `projected` are the fractions of samples whose forgetting the trace ceiling limited
// and whose step the stability projection shortened.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <limits>
#include <vector>

#include "bench_data.hpp"
#include "estimator_update.hpp"

namespace {

using bonl_bench::record;
using bonl_bench::register_sizes;
using bonl_bench::update;

/// The default (output-error) P-H-W update on the records it does not fit.
template <bool Fixed>
void register_mismatches(const std::string& suffix) {
  using Model = std::conditional_t<Fixed, bonl::PaperPseudoHammersteinWiener, bonl::PseudoHammersteinWienerd>;
  for (const bonl_bench::Mismatch data : bonl_bench::kMismatches) {
    benchmark::RegisterBenchmark(
        (std::string("update/") + Model::kName + "/" + suffix + "/" + bonl_bench::name(data)).c_str(),
        [data](benchmark::State& s) {
          update<Model>(s, bonl::Method::OutputError, bonl_bench::mismatched_record<double>(data));
        });
  }
}

/// The worst single update over 1e6 updates of the output-error estimator at the paper's P-H-W
/// orders, with its defaults (the window refinement from two starts) or its recursion alone. Each update is timed on
/// its own, and the 1e6 updates are run kRuns times from the same start: an update's own work is the same in every run
/// (the estimator is deterministic), while the machine's interrupts and preemptions fall on other
/// updates each time, so the least of an update's kRuns times is its own cost. "worst_ns" is the
/// largest such cost, "raw_worst_ns" the largest single timing of all (the machine's pauses in it:
/// compare the estimator without the window), "mean_ns" the mean of the least times.
void update_worst(benchmark::State& state, bool window) {
  using Model = bonl::PaperPseudoHammersteinWiener;
  const Model structure = bonl_bench::make_structure<Model>();
  const bonl_bench::Record<double>& data = record<double>();
  bonl::EstimatorOptions options;
  options.window.enabled = window;
  constexpr long kUpdates = 1000000;
  constexpr int kRuns = 3;
  std::vector<float> least(kUpdates);
  for (auto _ : state) {
    std::fill(least.begin(), least.end(), std::numeric_limits<float>::infinity());
    double raw_worst = 0.0;
    Eigen::Index swaps = 0;
    for (int run = 0; run < kRuns; ++run) {
      bonl::Estimator<Model> estimator(structure, options);
      for (long i = 0; i < kUpdates; ++i) {
        const Eigen::Index k = static_cast<Eigen::Index>(i % data.u.size());
        const auto start = std::chrono::steady_clock::now();
        benchmark::DoNotOptimize(estimator.update(data.u[k], data.y[k]));
        const double ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count();
        least[static_cast<std::size_t>(i)] = std::min(least[static_cast<std::size_t>(i)], static_cast<float>(ns));
        raw_worst = std::max(raw_worst, ns);
      }
      swaps = estimator.health().window.swaps;
    }
    double total = 0.0;
    for (const float ns : least) total += ns;
    state.counters["worst_ns"] = *std::max_element(least.begin(), least.end());
    state.counters["raw_worst_ns"] = raw_worst;
    state.counters["mean_ns"] = total / kUpdates;
    state.counters["swaps"] = static_cast<double>(swaps);
  }
}

/// The output-error update with its defaults (the window refinement from two starts) at the paper's
/// P-H-W orders: the mean (as the other updates, which time the recursions alone), and the worst
/// single update (update_worst), beside the recursion's alone.
void register_window() {
  using Model = bonl::PaperPseudoHammersteinWiener;
  benchmark::RegisterBenchmark("update/PseudoHammersteinWiener/fixed/double/window", [](benchmark::State& s) {
    update<Model>(s, bonl::Method::OutputError, record<double>(), true);
  });
  for (const bool window : {true, false}) {
    benchmark::RegisterBenchmark(window ? "update_worst/PseudoHammersteinWiener/fixed/double/window"
                                        : "update_worst/PseudoHammersteinWiener/fixed/double",
                                 [window](benchmark::State& state) { update_worst(state, window); })
        ->Iterations(1)
        ->Unit(benchmark::kMillisecond);
  }
}

const int registered = [] {
  register_window();
  register_sizes<double, true>("fixed/double");
  register_sizes<double, false>("dynamic/double");
  register_mismatches<true>("fixed/double");
  register_mismatches<false>("dynamic/double");
  return 0;
}();

}  // namespace
