// A plain loop over Estimator<Model>::update for profilers (callgrind, perf), which the timing loop
// of Google Benchmark would blur: `passes` passes over the benchmark record (4096 samples), each from
// the initial estimate, at the paper's orders with fixed sizes in double.
//   bonl_profile_update MODEL[-METHOD] [PASSES [DATA]]
//     MODEL: a model's name (ARX, Hammerstein, HammersteinWiener, PseudoHammersteinWiener, Wiener);
//     METHOD: output_error (the default), equation_error, paper;
//     DATA: known (the default: the known P-H-W system's record), delayed_fir or integrator (records
//     the structure does not fit, where the update's safeguards work: bench_data.hpp)
// Instructions per sample: run it under callgrind with 1 and 3 passes and divide the difference by
// 2 * 4096 (docs/lab/performance.md has the recipe and the latest profile).

#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "bench_data.hpp"

namespace {

template <class Model>
long run(bonl::Method method, long passes, const std::string& data) {
  bonl::EstimatorOptions options;
  options.method = method;
  using Scalar = typename Model::Scalar;
  const bonl_bench::Record<Scalar>* record = data == "known" ? &bonl_bench::record<Scalar>() : nullptr;
  for (const bonl_bench::Mismatch mismatch : bonl_bench::kMismatches) {
    if (data == bonl_bench::name(mismatch)) record = &bonl_bench::mismatched_record<Scalar>(mismatch);
  }
  if (record == nullptr) return -1;
  return bonl_bench::count_updates(bonl_bench::make_structure<Model>(), options, *record, passes).updated;
}

int usage() {
  std::fprintf(stderr,
               "usage: bonl_profile_update MODEL[-METHOD] [PASSES [DATA]]  (MODEL: a model's name, e.g. "
               "PseudoHammersteinWiener; METHOD: output_error, equation_error, paper; PASSES >= 1, default 1; "
               "DATA: known (default), delayed_fir, integrator)\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || argc > 4) return usage();
  const std::string name = argv[1];
  const std::size_t dash = name.find('-');
  const std::string model = name.substr(0, dash);
  bonl::Method method = bonl::Method::OutputError;
  if (dash != std::string::npos) {
    try {
      method = bonl::method_from_string(name.substr(dash + 1));
    } catch (const std::invalid_argument&) {
      return usage();
    }
  }
  char* end = nullptr;
  const long passes = argc >= 3 ? std::strtol(argv[2], &end, 10) : 1;
  if (argc >= 3 && (end == argv[2] || *end != '\0' || passes < 1)) return usage();
  const std::string data = argc == 4 ? argv[3] : "known";

  long updated = -1;
  bonl::for_each_model(bonl::PaperOrderModels{}, [&](auto tag) {
    using Model = typename decltype(tag)::type;
    if (model == Model::kName) updated = run<Model>(method, passes, data);
  });
  if (updated < 0) return usage();
  // Printed, so that the loop cannot be optimised away; also a check that the estimator updated.
  std::printf("%s: %ld passes, %ld updates\n", name.c_str(), passes, updated);
  return 0;
}
