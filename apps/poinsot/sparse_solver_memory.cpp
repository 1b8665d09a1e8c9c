// The allocator settings of sparse_solver_memory.hpp.
#include "sparse_solver_memory.hpp"

#include <malloc.h>

namespace poinsot::cli {

void keep_freed_memory_for_factorisations() {
  constexpr int kLargestHeapAllocation = 1 << 30;  // bytes
  mallopt(M_MMAP_THRESHOLD, kLargestHeapAllocation);
  mallopt(M_TRIM_THRESHOLD, kLargestHeapAllocation);
}

}  // namespace poinsot::cli
