#pragma once
/// @file mesh_io.hpp
/// Reading triangle meshes with assimp (Open Asset Import Library): STL (ascii and binary), OBJ, PLY, OFF and
/// every other format assimp knows. Polygons are triangulated as fans from their first corner (exact for the
/// mass properties of a planar polygon, convex or not; assimp's own triangulation asserted on malformed
/// faces); points and lines are dropped (and counted); node transforms of the scene are applied; vertices at
/// exactly the same position are merged (across all meshes of the file), so that edges can be matched for the
/// diagnostics of mesh.hpp. Winding is never changed. Coordinates are taken as metres.

#include <cstddef>
#include <string>

#include "poinsot/inertia/mesh.hpp"

namespace poinsot::inertia {

/// Resource limits of load_mesh, checked before the work they bound: the file size before the file is
/// parsed, the triangle count (summed over the file's meshes) before the mesh is assembled and examined.
struct MeshLimits {
  std::size_t max_file_bytes = std::size_t{256} << 20;  ///< 256 MiB
  std::size_t max_triangles = 5'000'000;
};

/// Reads `path`. Throws InvalidInput when the file cannot be read, is empty, is larger than
/// limits.max_file_bytes or has more than limits.max_triangles triangles (the message names the limit and
/// the option that raises it: --max-mesh-bytes, --max-mesh-triangles), is not a mesh that assimp can parse,
/// or contains no triangle (the message names the file and assimp's reason).
TriangleMesh load_mesh(const std::string& path, const MeshLimits& limits = {});

/// Writes `mesh` as a binary STL file (for tests and benchmarks; normals computed from the winding). Throws
/// InvalidInput when the file cannot be written.
void write_binary_stl(const TriangleMesh& mesh, const std::string& path);

}  // namespace poinsot::inertia
