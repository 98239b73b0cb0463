#pragma once
// BONL_FLATTEN: inline every call inside the marked function, recursively (GCC and Clang; nothing
// elsewhere). For per-sample kernels written in Eigen expressions: past a certain function size GCC 12
// stops inlining Eigen's small helpers and calls them out of line (in the RLS update, the copy of the
// 14-entry theta), which costs time on every sample (docs/lab/performance.md).

// BONL_COLD: keeps a rarely taken path (the RLS scale fold, a pass over the whole matrix) out of
// line, also inside a flattened function: inlined, it made GCC spill registers across the whole
// update (docs/lab/performance.md).

// Under AddressSanitizer BONL_FLATTEN is empty: the inlining buys speed only, and inlining the
// instrumented Eigen helpers everywhere made the sanitized build several times slower to compile
// (docs/lab/performance.md).
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define BONL_SANITIZED_BUILD 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define BONL_SANITIZED_BUILD 1
#endif

#if (defined(__GNUC__) || defined(__clang__)) && !defined(BONL_SANITIZED_BUILD)
#define BONL_FLATTEN __attribute__((flatten))
#else
#define BONL_FLATTEN
#endif

#if defined(__GNUC__) || defined(__clang__)
#define BONL_COLD __attribute__((noinline, cold))
#else
#define BONL_COLD
#endif
