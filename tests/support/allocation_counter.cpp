// Test support (not a test file): replaces the global operator new/delete of the test executables that link
// it (tests/CMakeLists.txt: dynamics, multibody) by counting wrappers around malloc/free. Kept in its own
// translation unit so that no caller sees the replacement inlined.
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
// Every allocating form is replaced, so that each deallocation below frees memory this file obtained from
// malloc (the sanitizers report a mismatch otherwise, e.g. for the nothrow form used by std::stable_sort).
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  ++g_allocations;
  return std::malloc(n == 0 ? 1 : n);
}
void* operator new[](std::size_t n) {
  return operator new(n);
}
void* operator new[](std::size_t n, const std::nothrow_t& tag) noexcept {
  return operator new(n, tag);
}
void operator delete[](void* p) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
  std::free(p);
}
void operator delete(void* p, const std::nothrow_t&) noexcept {
  std::free(p);
}
void operator delete[](void* p, const std::nothrow_t&) noexcept {
  std::free(p);
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
