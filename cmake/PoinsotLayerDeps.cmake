# Optional dependencies of individual layers, included at the end of src/CMakeLists.txt. Keep each block small
# and say which layer needs it.

# dynamics (issue 4): Boost.Math (header-only) for the Jacobi elliptic functions and the elliptic integrals
# of the exact free rigid body and of the heavy-top theory. Kept out of public headers, hence PRIVATE.
find_package(Boost 1.74 REQUIRED)
target_link_libraries(poinsot PRIVATE Boost::headers)
