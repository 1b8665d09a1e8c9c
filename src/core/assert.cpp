// The failure handler of POINSOT_ASSERT (assert.hpp).
#include "poinsot/core/assert.hpp"

#include <cstdio>
#include <cstdlib>

namespace poinsot::detail {

void assertion_failed(const char* condition, const char* message, const char* file, int line) noexcept {
  std::fprintf(stderr, "poinsot: internal error: %s:%d: %s (%s)\n", file, line, condition, message);
  std::fflush(stderr);
  std::abort();
}

}  // namespace poinsot::detail
