// Whole-record identification cost: bonl::identify of a Hammerstein-Wiener model of orders
// (na, nb, nk, r, r1) = (6, 5, 1, 3, 3), run-time sizes, double, on 100 000 samples of a known
// H-W system of those orders driven by random levels, with white output noise. One iteration is one
// identify() with the default options (output-error method, then Levenberg-Marquardt refinement of
// the free-run simulation error from two starts). The counter `per_sample` is the time per sample.
//
// Names: identify/HammersteinWiener/<samples>.

#include <benchmark/benchmark.h>

#include <bonl/bonl.hpp>

namespace {

struct IdentifyRecord {
  Eigen::VectorXd u, y;
};

/// A stable sixth-order denominator, three damped resonances: (1 - 1.6 z^-1 + 0.8 z^-2)
/// (1 - 1.2 z^-1 + 0.6 z^-2)(1 - 0.5 z^-1 + 0.3 z^-2).
Eigen::VectorXd sixth_order_a() {
  const Eigen::Vector3d first(1.0, -1.6, 0.8), second(1.0, -1.2, 0.6), third(1.0, -0.5, 0.3);
  Eigen::VectorXd product = Eigen::VectorXd::Zero(7), pair = Eigen::VectorXd::Zero(5);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) pair[i + j] += first[i] * second[j];
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 3; ++j) product[i + j] += pair[i] * third[j];
  return product.tail(6);
}

const IdentifyRecord& record(Eigen::Index samples) {
  static const IdentifyRecord data = [samples] {
    bonl::HammersteinWiener<> truth(6, 5, 1, 3, 3);
    truth.set_b((Eigen::VectorXd(6) << 1.0, 0.6, 0.3, 0.1, -0.05, 0.02).finished());
    truth.set_a(sixth_order_a());
    truth.set_f((Eigen::VectorXd(4) << 0.0, 0.05, 0.01, -0.005).finished());
    truth.set_p((Eigen::VectorXd(4) << 0.0, -0.01, -0.02, 0.008).finished());
    truth.set_q((Eigen::VectorXd(3) << 1.0, 0.2, -0.05).finished());
    IdentifyRecord r;
    r.u = bonl::signals::random_levels(samples, 5, 1.0, 11);
    r.y = truth.simulate(r.u) + bonl::signals::white_noise(samples, 0.005, 12);
    return r;
  }();
  return data;
}

void identify_hammerstein_wiener(benchmark::State& state) {
  const Eigen::Index samples = state.range(0);
  const IdentifyRecord& data = record(samples);
  const bonl::HammersteinWiener<> structure(6, 5, 1, 3, 3);
  double rms = 0.0;
  for (auto _ : state) {
    const auto model = bonl::identify(structure, data.u, data.y);
    rms = std::sqrt((model.simulate(data.u) - data.y).squaredNorm() / static_cast<double>(samples));
    benchmark::DoNotOptimize(rms);
  }
  state.counters["per_sample"] = benchmark::Counter(
      static_cast<double>(samples), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["simulation_rms"] = rms;
}

BENCHMARK(identify_hammerstein_wiener)
    ->Name("identify/HammersteinWiener")
    ->Arg(100000)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

}  // namespace
