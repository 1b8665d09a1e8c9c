# Dependencies of individual layers, linked PRIVATE to poinsot so that public headers need nothing more than
# Eigen. poinsot is a static library, so poinsotConfig.cmake.in finds them again for consumers at link time.
# Included at the end of src/CMakeLists.txt. One commented block per layer.

# --- inertia: assimp reads the mesh files (STL, OBJ, PLY, OFF) of inertia/mesh_io.cpp; toml++ reads
# the composite-body files of inertia/body_file.cpp. Debian 12: libassimp-dev (target assimp::assimp),
# libtomlplusplus-dev (target tomlplusplus::tomlplusplus).
find_package(assimp REQUIRED)
find_package(tomlplusplus REQUIRED)
target_link_libraries(poinsot PRIVATE assimp::assimp tomlplusplus::tomlplusplus)
# --- end inertia

# --- dynamics: Boost.Math (header-only) for the Jacobi elliptic functions and the elliptic integrals
# of the exact free rigid body and of the heavy-top theory.
find_package(Boost 1.74 REQUIRED)
target_link_libraries(poinsot PRIVATE Boost::headers)
# --- end dynamics

# --- optimal: Ipopt (Debian coinor-libipopt-dev, found with pkg-config `ipopt`) solves the collocation NLP of
# optimal/direct_collocation.cpp. Private: the public headers of optimal/ do not include Ipopt.
find_package(PkgConfig REQUIRED)
pkg_check_modules(IPOPT REQUIRED IMPORTED_TARGET ipopt)
target_link_libraries(poinsot PRIVATE PkgConfig::IPOPT)
# --- end optimal
# --- ensemble: Random123's Philox (header-only; Debian 12 librandom123-dev) for the counter-based draws of
# ensemble/counter_rng.cpp. The batched kernels are compiled without floating-point contraction, so that their
# SIMD and scalar paths and the scalar rk4 and dlm of dynamics/ round identically also where FMA is available
# (-march=native): GCC contracts a*b + c into an FMA by default in C++ (docs/ensemble.md).
find_path(POINSOT_RANDOM123_INCLUDE_DIR Random123/philox.h REQUIRED)
target_include_directories(poinsot SYSTEM PRIVATE ${POINSOT_RANDOM123_INCLUDE_DIR})
file(GLOB _poinsot_ensemble_kernels ${CMAKE_CURRENT_SOURCE_DIR}/ensemble/batch_*.cpp
     ${CMAKE_CURRENT_SOURCE_DIR}/dynamics/rk4.cpp ${CMAKE_CURRENT_SOURCE_DIR}/dynamics/dlm.cpp)
set_source_files_properties(${_poinsot_ensemble_kernels} PROPERTIES COMPILE_OPTIONS "-ffp-contract=off")
# The batched rk4 takes √|q|² per lane under a torque in space: without errno (sqrt is correctly rounded either
# way, so the bits do not change) the loop over the lanes vectorises.
set_source_files_properties(${CMAKE_CURRENT_SOURCE_DIR}/ensemble/batch_rk4.cpp
                            PROPERTIES COMPILE_OPTIONS "-ffp-contract=off;-fno-math-errno")
# --- end ensemble
# --- io/robot: tinyxml2 reads the robot description files (URDF, MJCF, SDF) of io/robot/robot_model.cpp. Debian 12:
# libtinyxml2-dev (target tinyxml2::tinyxml2).
find_package(tinyxml2 REQUIRED)
target_link_libraries(poinsot PRIVATE tinyxml2::tinyxml2)
# --- end io/robot
