#pragma once
// BONL_FLATTEN: inline every call inside the marked function, recursively (GCC and Clang; nothing
// elsewhere). For per-sample kernels written in Eigen expressions: past a certain function size GCC 12
// stops inlining Eigen's small helpers and calls them out of line (in the RLS update, the copy of the
// 14-entry theta), which costs time on every sample (docs/performance.md).

// BONL_COLD: keeps a rarely taken path (the RLS scale fold, a pass over the whole matrix) out of
// line, also inside a flattened function: inlined, it made GCC spill registers across the whole
// update (docs/performance.md).

#if defined(__GNUC__) || defined(__clang__)
#define BONL_FLATTEN __attribute__((flatten))
#define BONL_COLD __attribute__((noinline, cold))
#else
#define BONL_FLATTEN
#define BONL_COLD
#endif
