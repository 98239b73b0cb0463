// The RLS core alone, bonl::Rls<double, N>, for N = 4..32 parameters at compile time, and the same
// sizes at run time (bonl::Rls<double>), on the shared random regressors (bench_data.hpp) with
// forgetting factor kLambda: how the cost of one update grows with the parameter count (the
// symmetric rank-1 update is O(N^2)). One iteration is one sample.
//
// Names: rls/fixed/N, rls/dynamic/N (N: the parameter count).

#include <benchmark/benchmark.h>

#include "bench_data.hpp"

namespace {

template <int N>
void rls(benchmark::State& state, Eigen::Index n) {
  const bonl_bench::Regressors data = bonl_bench::regressors(n);
  bonl::Rls<double, N> estimator(n, bonl_bench::kP0);
  // Regressors as fixed-size vectors, so that the fixed-size core sees what an estimator passes it.
  std::vector<Eigen::Matrix<double, N, 1>> phi(static_cast<std::size_t>(data.phi.cols()));
  for (std::size_t k = 0; k < phi.size(); ++k) phi[k] = data.phi.col(static_cast<Eigen::Index>(k));
  std::size_t k = 0;
  std::int64_t refused = 0;
  for (auto _ : state) {
    const bool ok = estimator.update(phi[k], data.y[static_cast<Eigen::Index>(k)], bonl_bench::kLambda);
    benchmark::DoNotOptimize(ok);
    refused += ok ? 0 : 1;
    if (++k == phi.size()) k = 0;
  }
  benchmark::DoNotOptimize(estimator.theta().data());
  benchmark::ClobberMemory();
  state.SetItemsProcessed(state.iterations());
  state.counters["params"] = static_cast<double>(n);
  state.counters["refused"] = static_cast<double>(refused);
}

template <int... Ns>
void register_fixed(std::integer_sequence<int, Ns...>) {
  (benchmark::RegisterBenchmark(("rls/fixed/" + std::to_string(Ns)).c_str(),
                                [](benchmark::State& s) { rls<Ns>(s, Ns); }),
   ...);
}

using Sizes = std::integer_sequence<int, 4, 6, 8, 10, 12, 13, 14, 15, 16, 20, 24, 28, 32>;

template <int... Ns>
void register_dynamic(std::integer_sequence<int, Ns...>) {
  (benchmark::RegisterBenchmark(("rls/dynamic/" + std::to_string(Ns)).c_str(),
                                [](benchmark::State& s) { rls<Eigen::Dynamic>(s, Ns); }),
   ...);
}

const int registered = [] {
  register_fixed(Sizes{});
  register_dynamic(Sizes{});
  return 0;
}();

}  // namespace
