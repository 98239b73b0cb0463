// Cost of one online estimator update per model at the paper's orders (na = 3, nb = 2, nk = 8,
// r = r1 = 3), fixed sizes, both methods, on a recorded noisy response of the known P-H-W system.
// The P-H-W default method skips the RLS step for samples inside the backlash gap (about a quarter
// here), so its average is below the cost of a full update.

#include <benchmark/benchmark.h>
#include <bonl/bonl.hpp>

namespace {

struct Record {
  Eigen::VectorXd u, y;
};

const Record& record() {
  static const Record data = [] {
    bonl::PaperPseudoHammersteinWiener truth(3, 2, 8, 3);
    truth.set_f((Eigen::VectorXd(4) << 0.002, 0.06, 0.02, -0.01).finished());
    truth.set_p((Eigen::VectorXd(4) << -0.003, -0.02, -0.03, 0.015).finished());
    truth.set_b((Eigen::VectorXd(3) << 1.0, 0.5, 0.2).finished());
    truth.set_a((Eigen::VectorXd(3) << -1.7, 1.04, -0.238).finished());
    truth.set_c(0.1);
    Record r;
    r.u = bonl::signals::random_levels(4096, 5, 1.0, 1);
    r.y = truth.simulate(r.u) + bonl::signals::white_noise(r.u.size(), 0.01, 2);
    return r;
  }();
  return data;
}

template <class Model>
void update(benchmark::State& state, const Model& structure, bonl::Method method) {
  const Record& data = record();
  bonl::EstimatorOptions options;
  options.method = method;
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
  state.SetItemsProcessed(state.iterations());
}

void arx(benchmark::State& s) { update(s, bonl::PaperARX(3, 2, 8), bonl::Method::Default); }
void hammerstein(benchmark::State& s) { update(s, bonl::PaperHammerstein(3, 2, 8, 3), bonl::Method::Default); }
void hammerstein_wiener(benchmark::State& s) {
  update(s, bonl::PaperHammersteinWiener(3, 2, 8, 3, 3), bonl::Method::Default);
}
void phw_default(benchmark::State& s) {
  update(s, bonl::PaperPseudoHammersteinWiener(3, 2, 8, 3), bonl::Method::Default);
}
void phw_paper(benchmark::State& s) { update(s, bonl::PaperPseudoHammersteinWiener(3, 2, 8, 3), bonl::Method::Paper); }
void phw_dynamic(benchmark::State& s) { update(s, bonl::PseudoHammersteinWienerd(3, 2, 8, 3), bonl::Method::Default); }

}  // namespace

BENCHMARK(arx);
BENCHMARK(hammerstein);
BENCHMARK(hammerstein_wiener);
BENCHMARK(phw_default);
BENCHMARK(phw_paper);
BENCHMARK(phw_dynamic);
