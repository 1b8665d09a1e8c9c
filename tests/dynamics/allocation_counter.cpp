// Test support (not a test file): replaces the global operator new/delete of the dynamics test executable
// by counting wrappers around malloc/free. Kept in its own translation unit so that no caller sees the
// replacement inlined.
#include "allocation_counter.hpp"

#include <atomic>
#include <cstdlib>
#include <new>

namespace {
std::atomic<long long> g_allocations{0};
}  // namespace

void* operator new(std::size_t n) {
  ++g_allocations;
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}

namespace poinsot::test {
long long allocation_count() {
  return g_allocations.load();
}
}  // namespace poinsot::test
