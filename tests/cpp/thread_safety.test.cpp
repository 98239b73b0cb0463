// Independent estimators share nothing: N of them in N threads give bit-identical results to the
// same work done serially (no hidden global or static state in the estimator, models or RLS).

#include "test_support.hpp"

#include <thread>
#include <vector>

using namespace bonl_test;

namespace {

/// One record per worker: its own input, the known P-H-W's response and its own noise.
struct Work {
  Eigen::VectorXd u, y;
};

Work make_work(std::uint64_t seed) {
  const bonl::PaperPseudoHammersteinWiener truth = known_phw();
  Work work{bonl::signals::random_levels(3000, 5, 1.0, seed), Eigen::VectorXd()};
  work.y = truth.simulate(work.u) + bonl::signals::white_noise(work.u.size(), 0.01, seed + 50);
  return work;
}

/// Online estimation over the record, then a whole-record identification.
Eigen::VectorXd run(const Work& work) {
  bonl::Estimator<bonl::PaperPseudoHammersteinWiener> estimator(known_phw());
  for (Eigen::Index k = 0; k < work.u.size(); ++k) estimator.update(work.u[k], work.y[k]);
  bonl::IdentifyOptions options;
  options.refine_iterations = 5;
  const auto identified = bonl::identify(known_phw(), work.u, work.y, options);
  Eigen::VectorXd result(2 * estimator.theta().size());
  result << estimator.theta(), identified.theta();
  return result;
}

}  // namespace

TEST_CASE("N estimators in N threads equal the same work done serially, bit for bit", "[threads]") {
  constexpr int kWorkers = 4;
  std::vector<Work> works;
  for (int i = 0; i < kWorkers; ++i) works.push_back(make_work(100 + static_cast<std::uint64_t>(i)));
  std::vector<Eigen::VectorXd> serial, parallel(kWorkers);
  for (const Work& work : works) serial.push_back(run(work));
  std::vector<std::thread> threads;
  for (int i = 0; i < kWorkers; ++i) threads.emplace_back([&, i] { parallel[i] = run(works[i]); });
  for (std::thread& thread : threads) thread.join();
  for (int i = 0; i < kWorkers; ++i) {
    INFO("worker " << i);
    CHECK(parallel[i] == serial[i]);
    CHECK(parallel[i].allFinite());
  }
  CHECK(serial[0] != serial[1]);  // the workers did different work
}
