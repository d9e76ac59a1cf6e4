#pragma once
// The global operator new/delete of an allocation test whose count must see only some threads (a cyclic
// thread beside Fast DDS's, which allocate freely): every operator new calls count_allocation(), which the
// test defines (e.g. "if this thread is the cyclic one, add 1"). Include it in exactly one file of a test
// executable that does not link tomc_counting_allocator.
#include <cstddef>
#include <cstdlib>
#include <new>

namespace tomc::testing {
void count_allocation() noexcept;  // defined by the including test
}  // namespace tomc::testing

void* operator new(std::size_t size) {
  tomc::testing::count_allocation();
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) {
  tomc::testing::count_allocation();
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  tomc::testing::count_allocation();
  return std::malloc(size == 0 ? 1 : size);
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
  tomc::testing::count_allocation();
  return std::malloc(size == 0 ? 1 : size);
}
// GCC 12 inlines these into call sites whose operator new it does not see and warns about a mismatch that is
// not there (both sides are the malloc/free pair above): not inlined, nothing to misread.
[[gnu::noinline]] void operator delete(void* p) noexcept {
  std::free(p);
}
[[gnu::noinline]] void operator delete[](void* p) noexcept {
  std::free(p);
}
[[gnu::noinline]] void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}
[[gnu::noinline]] void operator delete[](void* p, std::size_t) noexcept {
  std::free(p);
}
