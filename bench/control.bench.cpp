// Per-sample cost of the inverse models (bonl/control/): InverseModel<Model>::step for each model at
// the paper's orders with the known parameters (bench_data.hpp), fixed and run-time orders, over the
// reference the model gives on the record's input (random levels in [-1, 1]); and each block inverse
// alone. One iteration runs the whole 4096-sample reference; `per_sample` is the time per sample.
//
// The adaptive inverse (AdaptiveInverse) per sample: step, then update with the model's own output
// on the command, the inverse derived again every 100 samples (its cost spread over them).
//
// Names: inverse/<Model::kName>/<fixed|dynamic>/double, inverse/blocks/<block>,
// inverse/adaptive/PseudoHammersteinWiener/fixed/double.

#include <benchmark/benchmark.h>

#include <bonl/control.hpp>

#include "bench_data.hpp"

namespace {

void per_sample(benchmark::State& state, Eigen::Index samples) {
  state.SetItemsProcessed(state.iterations() * samples);
  state.counters["per_sample"] = benchmark::Counter(
      static_cast<double>(samples), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

bonl::control::InverseOptions command_range() {
  bonl::control::InverseOptions options;
  options.command_min = -1.5;
  options.command_max = 1.5;
  return options;
}

template <class Model>
void inverse_model(benchmark::State& state) {
  const Model model = bonl_bench::make_known_model<Model>();
  const Eigen::VectorXd reference = model.simulate(bonl_bench::record<double>().u);
  bonl::control::InverseModel<Model> inverse(model, command_range());
  const Eigen::Index n = reference.size() - model.nk();
  double sum = 0.0;
  for (auto _ : state) {
    inverse.reset();
    for (Eigen::Index k = 0; k < n; ++k) sum += inverse.step(reference[k + model.nk()]).value;
    benchmark::DoNotOptimize(sum);
  }
  per_sample(state, n);
}

template <bool Fixed>
void register_sizes(const std::string& suffix) {
  bonl::for_each_model(bonl_bench::PaperOrderModels<double, Fixed>{}, [&](auto tag) {
    using Model = typename decltype(tag)::type;
    if constexpr (bonl::control::has_inverse<Model>::value) {  // not the Wiener-Hammerstein model (yet)
      benchmark::RegisterBenchmark((std::string("inverse/") + Model::kName + "/" + suffix).c_str(),
                                   inverse_model<Model>);
    }
  });
}

/// The blocks' inverses alone, on the reference of the known P-H-W model (x_d and w made up from it).
const Eigen::VectorXd& block_reference() {
  static const Eigen::VectorXd r =
      bonl_bench::make_known_model<bonl::PseudoHammersteinWienerd>().simulate(bonl_bench::record<double>().u);
  return r;
}

void linear(benchmark::State& state, const Eigen::VectorXd& b) {
  const Eigen::VectorXd& r = block_reference();
  bonl::control::LinearInverse<double> inverse(bonl_bench::true_a(), b, 8);
  const Eigen::Index window = inverse.window_size();
  const Eigen::Index n = r.size() - window;
  double sum = 0.0;
  for (auto _ : state) {
    inverse.reset();
    for (Eigen::Index k = 0; k < n; ++k) {
      const double w = inverse.input(r.segment(k, window));
      inverse.commit(r[k], w);
      sum += w;
    }
    benchmark::DoNotOptimize(sum);
  }
  per_sample(state, n);
}

template <class Inverse>
void static_block(benchmark::State& state, const Inverse& inverse, double scale) {
  const Eigen::VectorXd& r = block_reference();
  double sum = 0.0;
  for (auto _ : state) {
    for (Eigen::Index k = 0; k < r.size(); ++k) sum += inverse(scale * r[k]).value;
    benchmark::DoNotOptimize(sum);
  }
  per_sample(state, r.size());
}

void backlash(benchmark::State& state, double band) {
  const Eigen::VectorXd& r = block_reference();
  bonl::control::BacklashInverse<double> inverse(bonl_bench::kTrueC, band);
  double sum = 0.0;
  for (auto _ : state) {
    inverse.reset();
    for (Eigen::Index k = 0; k < r.size(); ++k) sum += inverse.step(r[k]);
    benchmark::DoNotOptimize(sum);
  }
  per_sample(state, r.size());
}

void adaptive_inverse(benchmark::State& state) {
  using Model = bonl::PaperPseudoHammersteinWiener;
  const Model model = bonl_bench::make_known_model<Model>();
  const Eigen::VectorXd reference = model.simulate(bonl_bench::record<double>().u);
  bonl::control::AdaptiveInverseOptions options;
  options.inverse = command_range();
  options.inverse.backlash_band_per_c = 1.0;
  options.estimator.forgetting = bonl::ForgettingSchedule::constant(0.999);
  options.estimator.p0 = 0.01;
  const Eigen::Index n = reference.size() - model.nk();
  // The measured output: the model's response to the commands the inverse gives (computed once).
  const auto commands = bonl::control::InverseModel<Model>(model, options.inverse).commands(reference);
  const Eigen::VectorXd y = model.simulate(commands.command);
  double sum = 0.0;
  for (auto _ : state) {
    state.PauseTiming();
    bonl::control::AdaptiveInverse<Model> adaptive(model, options);
    state.ResumeTiming();
    for (Eigen::Index k = 0; k < n; ++k) {
      const double u = adaptive.step(reference[k + model.nk()]).value;
      adaptive.update(u, y[k]);
      sum += u;
    }
    benchmark::DoNotOptimize(sum);
  }
  per_sample(state, n);
}

const int registered = [] {
  register_sizes<true>("fixed/double");
  register_sizes<false>("dynamic/double");
  benchmark::RegisterBenchmark("inverse/blocks/linear_exact",
                               [](benchmark::State& s) { linear(s, bonl_bench::true_b()); });
  benchmark::RegisterBenchmark("inverse/blocks/linear_zpetc", [](benchmark::State& s) {
    linear(s, (Eigen::VectorXd(3) << 1.0, 1.5, 0.2).finished());  // zeros at -1.35 and -0.15
  });
  benchmark::RegisterBenchmark("inverse/blocks/input_polynomial", [](benchmark::State& s) {
    static const bonl::control::InputPolynomialInverse<double> inverse(bonl_bench::true_f(), bonl_bench::true_p(), -1.5,
                                                                       1.5);
    static_block(s, inverse, 0.05);  // w of the order of the model's (x / 16.7)
  });
  benchmark::RegisterBenchmark("inverse/blocks/output_polynomial", [](benchmark::State& s) {
    static const bonl::control::OutputPolynomialInverse<double> inverse(bonl_bench::true_q());
    static_block(s, inverse, 1.0);
  });
  benchmark::RegisterBenchmark("inverse/blocks/backlash", [](benchmark::State& s) { backlash(s, 0.0); });
  benchmark::RegisterBenchmark("inverse/blocks/backlash_band", [](benchmark::State& s) { backlash(s, 0.02); });
  benchmark::RegisterBenchmark("inverse/adaptive/PseudoHammersteinWiener/fixed/double", adaptive_inverse);
  return 0;
}();

}  // namespace
