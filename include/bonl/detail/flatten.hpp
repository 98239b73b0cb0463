#pragma once
// BONL_FLATTEN: inline every call inside the marked function, recursively (GCC and Clang; nothing
// elsewhere). For per-sample kernels written in Eigen expressions: past a certain function size GCC 12
// stops inlining Eigen's small helpers and calls them out of line (in the RLS update, the copy of the
// 14-entry theta), and the update cost up to a tenth more at the paper's sizes (H-W, AVX-512).

#if defined(__GNUC__) || defined(__clang__)
#define BONL_FLATTEN __attribute__((flatten))
#else
#define BONL_FLATTEN
#endif
