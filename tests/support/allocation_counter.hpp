#pragma once
// Test support: the number of calls of the global operator new so far in this test executable (replaced in
// allocation_counter.cpp), to show that stepping loops allocate nothing.
namespace poinsot::test {
long long allocation_count();
}  // namespace poinsot::test
