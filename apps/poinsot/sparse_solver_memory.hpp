#pragma once
// How the process's allocator serves the sparse factorisations of `poinsot optimize`.
//
// Ipopt factorises its KKT matrix with MUMPS once or more per iteration, and MUMPS allocates its work arrays
// afresh for each factorisation. glibc hands allocations above its mmap threshold (128 KiB, rising to at
// most 32 MiB) to mmap and returns them to the system when they are freed, so every factorisation of a large
// KKT matrix (the phase-per-arc re-solve has about 8000 variables) touches new pages and takes a page fault
// for each. Keeping the freed memory in the process's heap lets the next factorisation reuse it: on the
// benchmark's per-axis slews, four times fewer page faults and a third less CPU time. The results do not
// change (the same arithmetic on other addresses); the resident memory stays at its peak until the command
// ends. docs/measurements/optimal_control.md, "Speed", has the figures.

namespace poinsot::cli {

/// Serves every allocation up to 1 GiB from the heap and never trims the heap: freed work arrays are kept
/// for the next factorisation (glibc's mallopt M_MMAP_THRESHOLD and M_TRIM_THRESHOLD). A no-op where the
/// allocator is not glibc's (the sanitizer builds replace malloc).
void keep_freed_memory_for_factorisations();

}  // namespace poinsot::cli
