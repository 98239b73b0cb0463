#pragma once
// The timed loop of one online estimator update and its registration per model (fixed or run-time
// sizes, one scalar type, each method), shared by estimator_update.bench.cpp (double) and
// estimator_update_float.bench.cpp (float): the two instantiate as much code each and compile side
// by side. The names and counters are described in estimator_update.bench.cpp.

#include <benchmark/benchmark.h>

#include <string>
#include <type_traits>

#include "bench_data.hpp"

namespace bonl_bench {

template <class Model>
void update(benchmark::State& state, bonl::Method method, const bonl_bench::Record<typename Model::Scalar>& data,
            bool window = false) {
  using Scalar = typename Model::Scalar;
  const Model structure = bonl_bench::make_structure<Model>();
  bonl::EstimatorOptions options;
  options.method = method;
  options.window.enabled = window;
  // In float the paper's P(0) = 1e6 I breaks down within 60 samples of this record (the covariance
  // loses positiveness and every later update is refused, which would time a cheap rejection, not an
  // update); 1e4 keeps every model's float estimator updating.
  if constexpr (std::is_same_v<Scalar, float>) {
    if (method != bonl::Method::OutputError) options.p0 = 1e4;  // the output-error default, 10, is fine
  }
  const bonl_bench::PassCounts counts = bonl_bench::count_updates(structure, options, data);
  const auto fraction = [&](long count) { return static_cast<double>(count) / static_cast<double>(data.u.size()); };
  bonl::Estimator<Model> estimator(structure, options);
  Eigen::Index k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(estimator.update(data.u[k], data.y[k]));
    if (++k == data.u.size()) {
      // Start over from zero, so the timing is that of a first pass from the paper's initial values
      // (repeated passes over a short record are not what an online estimator sees).
      state.PauseTiming();
      k = 0;
      estimator.reset();
      state.ResumeTiming();
    }
  }
  benchmark::DoNotOptimize(estimator.theta().data());
  benchmark::ClobberMemory();
  state.SetItemsProcessed(state.iterations());
  state.counters["updated"] = fraction(counts.updated);
  state.counters["limited"] = fraction(counts.forgetting_limited);
  state.counters["projected"] = fraction(counts.projections);
  state.counters["params"] = static_cast<double>(structure.num_params());
}

template <typename S, bool Fixed>
void register_sizes(const std::string& suffix) {
  bonl::for_each_model(bonl_bench::PaperOrderModels<S, Fixed>{}, [&](auto tag) {
    using Model = typename decltype(tag)::type;
    for (const bonl::Method method : {bonl::Method::OutputError, bonl::Method::EquationError, bonl::Method::Paper}) {
      const std::string extra = method == bonl::Method::OutputError ? "" : std::string("/") + bonl::to_string(method);
      benchmark::RegisterBenchmark((std::string("update/") + Model::kName + "/" + suffix + extra).c_str(),
                                   [method](benchmark::State& s) { update<Model>(s, method, record<S>()); });
    }
  });
}

}  // namespace bonl_bench
