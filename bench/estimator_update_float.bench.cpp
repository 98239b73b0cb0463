// The float updates of estimator_update.bench.cpp (update/<Model>/<fixed|dynamic>/float[/method]),
// in a file of their own so that they compile beside the double ones.

#include "estimator_update.hpp"

namespace {

const int registered = [] {
  bonl_bench::register_sizes<float, true>("fixed/float");
  bonl_bench::register_sizes<float, false>("dynamic/float");
  return 0;
}();

}  // namespace
