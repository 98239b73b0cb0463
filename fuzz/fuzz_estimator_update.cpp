// libFuzzer target: bytes -> bonl::Estimator<Model> fed a stream of (u, y) with NaN, inf, huge,
// tiny and denormal values among ordinary ones (bonl/estimator/recursive_estimator.hpp).
//
// The input picks a model (every model of bonl::Models at small run-time orders, or at the paper's
// fixed orders in double and in float), its orders (some invalid), the method, the
// forgetting schedule, p0, c0, internal_refresh, trace_ceiling and recover_after (some invalid),
// then a stream of operations: mostly update(u, y), sometimes reset(), reset(theta0), start_pass(),
// recover(), start_recording(), model().
//
// Contract checked after every operation (besides ASan/UBSan/LSan and no hang):
// - Orders and options that the documentation calls invalid throw std::invalid_argument from the
//   constructors; valid ones do not throw.
// - theta is finite; the recursion's covariance P (normalised_covariance()) is finite, exactly
//   symmetric (P(i,j) and P(j,i) bit for bit), has a positive diagonal, and trace(P) <=
//   trace_ceiling * n * p0 (up to rounding).
// - update(u, y) with a non-finite u or y returns RejectedNonFinite and leaves theta, P, samples(),
//   diverged() and the health counters unchanged; with finite u and y it never returns
//   RejectedNonFinite, and samples() counts the samples it took: one, none while the data's scale is
//   measured (NoInformation), two while the recursion catches up on them (then the checks below are
//   the second sample's, and only the invariants are checked).
// - NoInformation and NumericalFailure leave theta unchanged, and P too unless recover_after made
//   this update an automatic recovery (P = p0 I); NumericalFailure sets diverged() and counts a
//   failure; diverged() changes only by a failure, recover() or reset(). Updated clears
//   consecutive_failures.
// - reset() gives theta = the model's initial estimate, P = p0 I, samples() = 0, diverged() false,
//   health cleared; reset(theta0) throws std::invalid_argument for a wrong size or a non-finite
//   entry and otherwise gives theta = theta0, P = p0 I; start_pass() keeps theta and P and sets
//   samples() to 0 (after catch_up(), which it calls first); recover() keeps theta, sets P = p0 I and
//   clears diverged(); model() is theta
//   with a P-H-W c < 0 projected to 0.
// - While recording, the newest entry of trajectory() is the last sample's status and theta.

#include <cstdint>
#include <cstdio>
#include <exception>

#include "estimator_harness.hpp"

using namespace bonl_fuzz;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  constexpr int kRunTimeKinds = static_cast<int>(bonl::Models::size);
  const int kind = in.ConsumeIntegralInRange<int>(0, kRunTimeKinds + kFixedKinds - 1);
  try {
    if (kind < kRunTimeKinds) {  // every model of bonl::Models at small run-time orders, a few invalid
      fuzz_model_at(bonl::Models{}, kind, in);
    } else {
      fuzz_fixed_kind(kind - kRunTimeKinds, in);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "unexpected exception: %s\n", e.what());
    FUZZ_CHECK(false);
  }
  return 0;
}
