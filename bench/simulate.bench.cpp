// Free-run simulation cost per sample (Model::try_simulate into a preallocated output) for each
// model at the paper's orders with known, stable parameters, over the 4096-sample record's input.
// Fixed (paper-order) and run-time sizes, double. One iteration simulates the whole record; the
// counter `per_sample` is the time per sample.
//
// Names: simulate/<Model::kName>/<fixed|dynamic>/double.

#include <benchmark/benchmark.h>

#include "bench_data.hpp"

namespace {

template <class Model>
void simulate(benchmark::State& state) {
  const auto& data = bonl_bench::record<double>();
  const Model model = bonl_bench::make_known_model<Model>();
  typename Model::VectorX y(data.u.size());
  bool ok = true;
  for (auto _ : state) {
    ok = model.try_simulate(data.u, y) && ok;
    benchmark::DoNotOptimize(y.data());
    benchmark::ClobberMemory();
  }
  if (!ok) state.SkipWithError("free run failed (non-finite output)");
  const auto samples = static_cast<double>(data.u.size());
  state.SetItemsProcessed(state.iterations() * data.u.size());
  state.counters["per_sample"] =
      benchmark::Counter(samples, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["params"] = static_cast<double>(model.num_params());
}

template <bool Fixed>
void register_sizes(const std::string& suffix) {
  bonl::for_each_model(bonl_bench::PaperOrderModels<double, Fixed>{}, [&](auto tag) {
    using Model = typename decltype(tag)::type;
    benchmark::RegisterBenchmark((std::string("simulate/") + Model::kName + "/" + suffix).c_str(), simulate<Model>);
  });
}

const int registered = [] {
  register_sizes<true>("fixed/double");
  register_sizes<false>("dynamic/double");
  return 0;
}();

}  // namespace
