#pragma once
// Counts heap allocations at their source, the C allocator: operator new (libstdc++'s calls malloc)
// and Eigen (its aligned_malloc calls std::malloc) alike, and whatever else allocates. Include it in
// exactly one source file of a test executable (it defines the counting functions), then compare
// bonl_test::allocations() before and after the code under test.
//
// Counting malloc itself, rather than replacing operator new and forbidding Eigen's malloc through
// EIGEN_RUNTIME_NO_MALLOC and a counting eigen_assert, leaves Eigen's configuration as every other
// suite has it: the suites that count link the estimators the others share (compiled_once.hpp)
// instead of compiling their own, which made allocation.test.cpp the test build's longest compile.
//
// With glibc (the main build), this executable defines malloc and its siblings, which glibc lets a
// program replace, and forwards them to glibc's own (__libc_malloc, ...). Under AddressSanitizer
// (scripts/sanitize.sh), whose runtime defines malloc itself, its allocation hook counts instead: it
// is called for every allocation the runtime makes, operator new's included.

#include <atomic>
#include <cerrno>
#include <cstddef>
#include <cstdio>
#include <cstdlib>

namespace bonl_test {
inline std::atomic<long> g_allocation_count{0};
inline bool allocations_counted();
/// The heap allocations so far. Aborts where they are not being counted, so that a count of 0
/// cannot pass for an allocation-free run.
inline long allocations() {
  if (!allocations_counted()) {
    std::fputs("counting_allocator.hpp: the allocation hook is not installed\n", stderr);
    std::abort();
  }
  return g_allocation_count.load();
}
}  // namespace bonl_test

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define BONL_TEST_ASAN 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define BONL_TEST_ASAN 1
#endif

#ifdef BONL_TEST_ASAN
#include <sanitizer/allocator_interface.h>

namespace bonl_test {
inline void count_allocation(const volatile void*, std::size_t) { ++g_allocation_count; }
inline void ignore_free(const volatile void*) {}
// Installed when the executable starts, before any test runs; the runtime refuses a fifth hook (0).
inline const int g_hook_installed = __sanitizer_install_malloc_and_free_hooks(count_allocation, ignore_free);
inline bool allocations_counted() { return g_hook_installed != 0; }
}  // namespace bonl_test
#else
namespace bonl_test {
inline bool allocations_counted() { return true; }
}  // namespace bonl_test

extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* pointer, std::size_t size);
void* __libc_memalign(std::size_t alignment, std::size_t size);
void __libc_free(void* pointer);

void* malloc(std::size_t size) noexcept {
  ++bonl_test::g_allocation_count;
  return __libc_malloc(size);
}
void* calloc(std::size_t count, std::size_t size) noexcept {
  ++bonl_test::g_allocation_count;
  return __libc_calloc(count, size);
}
void* realloc(void* pointer, std::size_t size) noexcept {
  ++bonl_test::g_allocation_count;
  return __libc_realloc(pointer, size);
}
void free(void* pointer) noexcept { __libc_free(pointer); }
void* memalign(std::size_t alignment, std::size_t size) noexcept {
  ++bonl_test::g_allocation_count;
  return __libc_memalign(alignment, size);
}
void* aligned_alloc(std::size_t alignment, std::size_t size) noexcept {
  ++bonl_test::g_allocation_count;
  return __libc_memalign(alignment, size);
}
int posix_memalign(void** pointer, std::size_t alignment, std::size_t size) noexcept {
  // The alignment must be a power of two and a multiple of sizeof(void*) (POSIX).
  if (alignment % sizeof(void*) != 0 || (alignment & (alignment - 1)) != 0) return EINVAL;
  ++bonl_test::g_allocation_count;
  void* allocated = __libc_memalign(alignment, size);
  if (allocated == nullptr) return ENOMEM;
  *pointer = allocated;
  return 0;
}
}
#endif
