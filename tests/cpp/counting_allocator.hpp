#pragma once
// Replaces the global operator new/delete to count heap allocations. Include it in exactly one
// source file of a test executable (it defines the replacement functions), then compare
// bonl_test::allocations() before and after the code under test.

#include <atomic>
#include <cstdlib>
#include <new>

namespace bonl_test {
inline std::atomic<long> g_allocation_count{0};
inline long allocations() { return g_allocation_count.load(); }
}  // namespace bonl_test

void* operator new(std::size_t size) {
  ++bonl_test::g_allocation_count;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) { return operator new(size); }
void* operator new(std::size_t size, std::align_val_t align) {
  ++bonl_test::g_allocation_count;
  const std::size_t a = static_cast<std::size_t>(align);
  if (void* p = std::aligned_alloc(a, (size + a - 1) / a * a)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size, std::align_val_t align) { return operator new(size, align); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
