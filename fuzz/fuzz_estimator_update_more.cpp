// Second translation unit of fuzz_estimator_update: the fixed-order kinds in double (see
// estimator_harness.hpp; fuzz_estimator_update_float.cpp has those in float).

#include "estimator_harness.hpp"

namespace bonl_fuzz {

void fuzz_fixed_kind(int kind, FuzzedDataProvider& in) {
  constexpr int kModels = static_cast<int>(bonl::Models::size);
  if (kind < kModels) {
    fuzz_model_at(bonl::PaperOrderModels{}, kind, in);
  } else {
    fuzz_fixed_float_kind(kind - kModels, in);
  }
}

}  // namespace bonl_fuzz
