// Third translation unit of fuzz_estimator_update: the fixed-order kinds in float (see
// estimator_harness.hpp).

#include "estimator_harness.hpp"

namespace bonl_fuzz {

void fuzz_fixed_float_kind(int index, FuzzedDataProvider& in) {
  fuzz_model_at(bonl::ModelsWithScalar<bonl::PaperOrderModels, float>::type{}, index, in);
}

}  // namespace bonl_fuzz
