#include "poinsot/inertia/mesh_io.hpp"

#include <array>
#include <bit>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <unordered_map>
#include <vector>

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <fmt/format.h>
#include <assimp/Importer.hpp>

#include "ply_check.hpp"
#include "poinsot/core/error.hpp"

namespace poinsot::inertia {
namespace {

/// Exact position of a vertex as the key of the welding map.
struct Key {
  std::array<std::uint64_t, 3> bits;
  bool operator==(const Key& o) const { return bits == o.bits; }
};
struct KeyHash {
  std::size_t operator()(const Key& k) const {
    std::uint64_t h = 1469598103934665603ull;
    for (std::uint64_t b : k.bits)
      h = (h ^ b) * 1099511628211ull + (h >> 29);
    return static_cast<std::size_t>(h);
  }
};

Key key_of(const Vec3& v) {
  // +0.0 and −0.0 are the same point.
  const Vec3 w = v + Vec3::Zero();
  return Key{{std::bit_cast<std::uint64_t>(w.x() == 0.0 ? 0.0 : w.x()),
              std::bit_cast<std::uint64_t>(w.y() == 0.0 ? 0.0 : w.y()),
              std::bit_cast<std::uint64_t>(w.z() == 0.0 ? 0.0 : w.z())}};
}

struct Builder {
  TriangleMesh mesh;
  std::unordered_map<Key, std::int32_t, KeyHash> index;
  std::size_t dropped = 0;  // points and lines

  std::int32_t vertex(const Vec3& p) {
    const auto [it, inserted] = index.try_emplace(key_of(p), static_cast<std::int32_t>(mesh.vertices.size()));
    if (inserted) mesh.vertices.push_back(p);
    return it->second;
  }

  void add_node(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent) {
    const aiMatrix4x4 m = parent * node.mTransformation;
    Mat3 linear;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        linear(r, c) = static_cast<double>(m[static_cast<unsigned>(r)][c]);
    const bool mirrored = linear.determinant() < 0.0;  // a reflection reverses the winding
    for (unsigned i = 0; i < node.mNumMeshes; ++i) {
      const aiMesh& am = *scene.mMeshes[node.mMeshes[i]];
      std::vector<std::int32_t> local(am.mNumVertices);
      for (unsigned v = 0; v < am.mNumVertices; ++v) {
        const aiVector3D p = m * am.mVertices[v];
        local[v] = vertex(Vec3(static_cast<double>(p.x), static_cast<double>(p.y), static_cast<double>(p.z)));
      }
      for (unsigned f = 0; f < am.mNumFaces; ++f) {
        const aiFace& face = am.mFaces[f];
        if (face.mNumIndices < 3) {
          ++dropped;
          continue;
        }
        // A polygon as a fan from its first corner: the signed triangles sum to the polygon exactly (convex
        // or not), so the mass-property integrals are those of the polygon.
        for (unsigned k = 1; k + 1 < face.mNumIndices; ++k) {
          std::array<std::int32_t, 3> t{local[face.mIndices[0]], local[face.mIndices[k]],
                                        local[face.mIndices[k + 1]]};
          if (mirrored) std::swap(t[1], t[2]);
          mesh.triangles.push_back(t);
        }
      }
    }
    for (unsigned c = 0; c < node.mNumChildren; ++c)
      add_node(scene, *node.mChildren[c], m);
  }
};

/// The vertex and face counts of an OFF file (the first two numbers after the keyword and comments) must not
/// exceed the file's size in bytes, each vertex and face taking at least one: assimp allocates for the counts
/// first (found by fuzzing: 4·10^24 vertices declared in a 100-byte file).
void check_off_counts(const std::string& path) {
  std::error_code ec;
  const auto file_bytes = static_cast<double>(std::filesystem::file_size(path, ec));
  std::ifstream in(path, std::ios::binary);
  std::string token;
  int counted = 0;
  while (counted < 2 && in >> token) {
    if (token.starts_with("#")) {
      std::getline(in, token);
      continue;
    }
    if (token.find("OFF") != std::string::npos) continue;
    const double count = std::strtod(token.c_str(), nullptr);
    if (!(count <= file_bytes)) {
      throw InvalidInput(
          fmt::format("mesh: \"{}\": OFF declares {} vertices or faces in a file of {} bytes; "
                      "expected counts that the file can hold",
                      path, token.substr(0, 30), static_cast<unsigned long long>(file_bytes)));
    }
    ++counted;
  }
}

}  // namespace

TriangleMesh load_mesh(const std::string& path, const MeshLimits& limits) {
  if (std::filesystem::is_directory(path)) {
    throw InvalidInput(
        fmt::format("mesh: \"{}\" is a folder; expected a mesh file (STL, OBJ, PLY, OFF)", path));
  }
  if (std::error_code ec; std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec)) {
    // A device or a pipe (/dev/zero, a FIFO) would be read without end.
    throw InvalidInput(fmt::format("mesh: \"{}\" is not a regular file; expected a mesh file", path));
  }
  {
    std::ifstream probe(path, std::ios::binary);
    if (!probe)
      throw InvalidInput(fmt::format("mesh: cannot open \"{}\"; expected a readable mesh file", path));
    if (probe.peek() == std::ifstream::traits_type::eof()) {
      throw InvalidInput(
          fmt::format("mesh: \"{}\" is empty; expected a mesh file (STL, OBJ, PLY, OFF)", path));
    }
  }
  std::error_code ec;
  if (const auto bytes = std::filesystem::file_size(path, ec); !ec && bytes > limits.max_file_bytes) {
    throw InvalidInput(
        fmt::format("mesh: \"{}\" is {} bytes; the limit is {} bytes (raise it with --max-mesh-bytes)", path,
                    bytes, limits.max_file_bytes));
  }
  if (std::filesystem::path(path).extension() == ".ply" || std::filesystem::path(path).extension() == ".PLY")
    detail::check_ply_file(path);
  if (std::filesystem::path(path).extension() == ".off" || std::filesystem::path(path).extension() == ".OFF")
    check_off_counts(path);
  Assimp::Importer importer;
  // Only validation, no post-processing: assimp's triangulation asserted on malformed OFF and PLY faces
  // (found by fuzzing); a malformed scene is now an error, and polygons are triangulated below. The file's
  // winding and vertices are kept (welding is done below, across meshes).
  const aiScene* scene = importer.ReadFile(path, aiProcess_ValidateDataStructure);
  if (scene == nullptr || scene->mRootNode == nullptr) {
    std::string reason = importer.GetErrorString();
    for (char& ch : reason)
      if (ch == '\n' || ch == '\r') ch = ' ';
    throw InvalidInput(fmt::format("mesh: cannot read \"{}\" ({}); expected a mesh file (STL, OBJ, PLY, OFF)",
                                   path, reason.empty() ? "unknown format" : reason));
  }
  std::size_t faces = 0;
  for (unsigned i = 0; i < scene->mNumMeshes; ++i)
    faces += scene->mMeshes[i]->mNumFaces;
  if (faces > limits.max_triangles) {
    throw InvalidInput(fmt::format(
        "mesh: \"{}\" has {} faces; the limit is {} triangles (raise it with --max-mesh-triangles)", path,
        faces, limits.max_triangles));
  }
  Builder b;
  b.add_node(*scene, *scene->mRootNode, aiMatrix4x4());
  if (b.mesh.triangles.empty()) {
    throw InvalidInput(fmt::format("mesh: \"{}\" contains no triangles; expected a triangle mesh", path));
  }
  return std::move(b.mesh);
}

void write_binary_stl(const TriangleMesh& mesh, const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw InvalidInput(fmt::format("mesh: cannot write \"{}\"", path));
  char header[80] = "poinsot binary STL";
  out.write(header, sizeof header);
  const auto n = static_cast<std::uint32_t>(mesh.triangles.size());
  out.write(reinterpret_cast<const char*>(&n), sizeof n);  // NOLINT: byte view of a little-endian int
  for (const auto& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[static_cast<std::size_t>(t[0])];
    const Vec3& b = mesh.vertices[static_cast<std::size_t>(t[1])];
    const Vec3& c = mesh.vertices[static_cast<std::size_t>(t[2])];
    const Vec3 normal = (b - a).cross(c - a).normalized();
    std::array<float, 12> f{};
    for (int k = 0; k < 3; ++k) {
      f[static_cast<std::size_t>(k)] = static_cast<float>(normal[k]);
      f[static_cast<std::size_t>(3 + k)] = static_cast<float>(a[k]);
      f[static_cast<std::size_t>(6 + k)] = static_cast<float>(b[k]);
      f[static_cast<std::size_t>(9 + k)] = static_cast<float>(c[k]);
    }
    out.write(reinterpret_cast<const char*>(f.data()), sizeof(float) * 12);  // NOLINT
    const std::uint16_t attr = 0;
    out.write(reinterpret_cast<const char*>(&attr), sizeof attr);  // NOLINT
  }
  if (!out) throw InvalidInput(fmt::format("mesh: writing \"{}\" failed", path));
}

}  // namespace poinsot::inertia
