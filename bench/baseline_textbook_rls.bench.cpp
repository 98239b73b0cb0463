// Baseline: recursive least squares as a textbook writes it in Eigen, with run-time sizes and the
// explicit covariance update of the paper's eq. (23):
//   K = P phi / (lambda + phi' P phi),  theta += K (y - phi' theta),  P = (P - K phi' P) / lambda.
// The full P is updated (no symmetry kept), and temporaries are allocated as ordinary Eigen code does.
// Two variants:
// - textbook_rls/N: K (phi' P) as an outer product of K and the row phi' P, O(N^2) (the baseline the
//   report's ratios use, `naive_rls_ns` at the P-H-W parameter count, 14);
// - textbook_rls_literal/N: the expression typed literally, `P - K * phi.transpose() * P`, which
//   Eigen evaluates left to right as the N x N matrix K phi' times P, O(N^3).
// Same regressors (bench_data.hpp), forgetting factor and P(0) as the RLS core benchmark and the
// Python baselines. One iteration is one sample.

#include <benchmark/benchmark.h>

#include "bench_data.hpp"

namespace {

class TextbookRls {
 public:
  TextbookRls(Eigen::Index n, double p0)
      : m_theta(Eigen::VectorXd::Zero(n)), m_P(Eigen::MatrixXd::Identity(n, n) * p0) {}

  void update(const Eigen::VectorXd& phi, double y, double lambda) {
    const Eigen::VectorXd P_phi = m_P * phi;
    const Eigen::VectorXd K = P_phi / (lambda + phi.dot(P_phi));
    m_theta += K * (y - phi.dot(m_theta));
    m_P = (m_P - K * (phi.transpose() * m_P)) / lambda;
  }
  void update_literal(const Eigen::VectorXd& phi, double y, double lambda) {
    const Eigen::VectorXd K = m_P * phi / (lambda + (phi.transpose() * m_P * phi).value());
    m_theta = m_theta + K * (y - (phi.transpose() * m_theta).value());
    m_P = (m_P - K * phi.transpose() * m_P) / lambda;
  }
  const Eigen::VectorXd& theta() const { return m_theta; }
  const Eigen::MatrixXd& covariance() const { return m_P; }

 private:
  Eigen::VectorXd m_theta;
  Eigen::MatrixXd m_P;
};

template <bool Literal>
void textbook(benchmark::State& state, Eigen::Index n) {
  const bonl_bench::Regressors data = bonl_bench::regressors(n);
  std::vector<Eigen::VectorXd> phi(static_cast<std::size_t>(data.phi.cols()));
  for (std::size_t k = 0; k < phi.size(); ++k) phi[k] = data.phi.col(static_cast<Eigen::Index>(k));
  TextbookRls estimator(n, bonl_bench::kP0);
  std::size_t k = 0;
  for (auto _ : state) {
    if constexpr (Literal) {
      estimator.update_literal(phi[k], data.y[static_cast<Eigen::Index>(k)], bonl_bench::kLambda);
    } else {
      estimator.update(phi[k], data.y[static_cast<Eigen::Index>(k)], bonl_bench::kLambda);
    }
    benchmark::DoNotOptimize(estimator.theta().data());
    benchmark::ClobberMemory();
    if (++k == phi.size()) k = 0;
  }
  benchmark::DoNotOptimize(estimator.covariance().data());
  if (!estimator.theta().allFinite()) state.SkipWithError("textbook RLS diverged");
  state.SetItemsProcessed(state.iterations());
  state.counters["params"] = static_cast<double>(n);
}

const int registered = [] {
  for (int n : {4, 6, 8, 10, 12, 13, 14, 15, 16, 20, 24, 28, 32}) {
    benchmark::RegisterBenchmark(("textbook_rls/" + std::to_string(n)).c_str(),
                                 [n](benchmark::State& s) { textbook<false>(s, n); });
  }
  for (int n : {6, 13, 14, 15}) {
    benchmark::RegisterBenchmark(("textbook_rls_literal/" + std::to_string(n)).c_str(),
                                 [n](benchmark::State& s) { textbook<true>(s, n); });
  }
  return 0;
}();

}  // namespace
