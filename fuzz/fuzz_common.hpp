#pragma once
// Shared by the libFuzzer targets: a check that stops the run, and doubles decoded from the input
// with a bias toward the values that break numerical code.

#include <fuzzer/FuzzedDataProvider.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>

/// A violated invariant is a finding: say which, then trap (libFuzzer saves the input as crash-*).
#define FUZZ_CHECK(condition)                                                                  \
  do {                                                                                         \
    if (!(condition)) {                                                                        \
      std::fprintf(stderr, "FUZZ_CHECK failed: %s (%s:%d)\n", #condition, __FILE__, __LINE__); \
      __builtin_trap();                                                                        \
    }                                                                                          \
  } while (false)

namespace bonl_fuzz {

/// Bitwise equality of two arrays of numbers (so that -0 != 0 and NaN == the same NaN).
template <typename Scalar>
bool same_bits(const Scalar* a, const Scalar* b, long n) {
  return n == 0 || std::memcmp(a, b, static_cast<std::size_t>(n) * sizeof(Scalar)) == 0;
}

/// NaN, +-inf, +-1e300, +-max, denormals, 0, -0, 1e-300, the smallest normal, ...
inline double special_value(int index) {
  using L = std::numeric_limits<double>;
  static constexpr int kCount = 20;
  switch (index % kCount) {
    case 0: return L::quiet_NaN();
    case 1: return -L::quiet_NaN();
    case 2: return L::infinity();
    case 3: return -L::infinity();
    case 4: return 1e300;
    case 5: return -1e300;
    case 6: return L::max();
    case 7: return -L::max();
    case 8: return L::denorm_min();
    case 9: return -L::denorm_min();
    case 10: return 0.0;
    case 11: return -0.0;
    case 12: return 1e-300;
    case 13: return -1e-300;
    case 14: return L::min();
    case 15: return L::epsilon();
    case 16: return 1.0;
    case 17: return -1.0;
    case 18: return 1e150;
    default: return L::signaling_NaN();
  }
}

/// One double: half ordinary values (in [-2, 2], so that estimators reach interesting states),
/// a quarter of arbitrary magnitude (mantissa times 10^e, e in [-330, 310]), a quarter special
/// values or raw bit patterns.
inline double any_double(FuzzedDataProvider& in) {
  const auto selector = in.ConsumeIntegral<std::uint8_t>();
  if (selector < 128) return static_cast<double>(in.ConsumeIntegral<std::int16_t>()) / 16384.0;
  if (selector < 192) {
    const double mantissa = static_cast<double>(in.ConsumeIntegral<std::int16_t>()) / 4096.0;
    const int exponent = in.ConsumeIntegralInRange<int>(-330, 310);
    char text[64];
    std::snprintf(text, sizeof text, "%.6ge%d", mantissa, exponent);
    return std::strtod(text, nullptr);  // mantissa * 10^exponent, overflowing to inf, underflowing to 0
  }
  if (selector < 240) return special_value(selector - 192);
  const auto bits = in.ConsumeIntegral<std::uint64_t>();
  double value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

}  // namespace bonl_fuzz
