#pragma once
/// @file mesh_io.hpp
/// Reading triangle meshes with assimp (Open Asset Import Library): STL (ascii and binary), OBJ, PLY, OFF and
/// every other format assimp knows. Polygons are triangulated by assimp; points and lines are dropped (and
/// counted); node transforms of the scene are applied; vertices at exactly the same position are merged
/// (across all meshes of the file), so that edges can be matched for the diagnostics of mesh.hpp. Winding is
/// never changed. Coordinates are taken as metres.

#include <string>

#include "poinsot/inertia/mesh.hpp"

namespace poinsot::inertia {

/// Reads `path`. Throws InvalidInput when the file cannot be read, is empty, is not a mesh that assimp can
/// parse, or contains no triangle (the message names the file and assimp's reason).
TriangleMesh load_mesh(const std::string& path);

/// Writes `mesh` as a binary STL file (for tests and benchmarks; normals computed from the winding). Throws
/// InvalidInput when the file cannot be written.
void write_binary_stl(const TriangleMesh& mesh, const std::string& path);

}  // namespace poinsot::inertia
