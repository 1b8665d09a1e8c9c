# Dependencies of individual layers, linked PRIVATE to poinsot so that public headers need nothing more than
# Eigen. poinsot is a static library, so poinsotConfig.cmake.in finds them again for consumers at link time.
# Included at the end of src/CMakeLists.txt. One commented block per layer.

# --- inertia (issue 3): assimp reads the mesh files (STL, OBJ, PLY, OFF) of inertia/mesh_io.cpp; toml++ reads
# the composite-body files of inertia/body_file.cpp. Debian 12: libassimp-dev (target assimp::assimp),
# libtomlplusplus-dev (target tomlplusplus::tomlplusplus).
find_package(assimp REQUIRED)
find_package(tomlplusplus REQUIRED)
target_link_libraries(poinsot PRIVATE assimp::assimp tomlplusplus::tomlplusplus)
# --- end inertia

# --- dynamics (issue 4): Boost.Math (header-only) for the Jacobi elliptic functions and the elliptic integrals
# of the exact free rigid body and of the heavy-top theory.
find_package(Boost 1.74 REQUIRED)
target_link_libraries(poinsot PRIVATE Boost::headers)
# --- end dynamics

# --- io: tinyxml2 reads the robot description files (URDF, MJCF, SDF) of io/robot_model.cpp. Debian 12:
# libtinyxml2-dev (target tinyxml2::tinyxml2).
find_package(tinyxml2 REQUIRED)
target_link_libraries(poinsot PRIVATE tinyxml2::tinyxml2)
# --- end io
