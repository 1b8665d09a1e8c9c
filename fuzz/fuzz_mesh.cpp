// Fuzz harness: the mesh reader (inertia/mesh_io.hpp) and what follows it for `poinsot inertia mesh` —
// diagnostics, solid and shell mass properties. Compiled once and linked once per format with the definition
// of poinsot_fuzz_mesh_extension() below (fuzz/CMakeLists.txt generates it).
#include "fuzz_support.hpp"
#include "poinsot/inertia/mesh.hpp"
#include "poinsot/inertia/mesh_io.hpp"

/// The file extension of the format this harness reads (".stl", ".obj", ".ply" or ".off"), which selects
/// assimp's importer.
extern "C" const char* poinsot_fuzz_mesh_extension();

// assimp allocates a few objects once, on its first import (its importer registry): done here, before the
// leak checks of the inputs.
extern "C" int LLVMFuzzerInitialize(int* /*argc*/, char*** /*argv*/) {
  static const char tetra[] =
      "solid t\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 0 1 0\nvertex 1 0 0\nendloop\nendfacet\n"
      "endsolid t\n";
  const std::string path = poinsot::fuzz::input_file(reinterpret_cast<const std::uint8_t*>(tetra),
                                                     sizeof tetra - 1, ".stl");  // NOLINT
  poinsot::fuzz::expect_clean([&] { poinsot::inertia::load_mesh(path); });
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = poinsot::fuzz::input_file(data, size, poinsot_fuzz_mesh_extension());
  poinsot::fuzz::expect_clean([&] {
    using namespace poinsot::inertia;  // NOLINT: harness
    MeshLimits limits;
    limits.max_file_bytes = 1 << 20;  // the fuzzer's inputs are small; keep each run fast
    limits.max_triangles = 100000;
    const TriangleMesh mesh = load_mesh(path, limits);
    poinsot::fuzz::expect_clean([&] { diagnose(mesh); });
    poinsot::fuzz::expect_clean([&] { mesh_mass_properties(mesh, 1000.0, MeshOptions{true}); });
    poinsot::fuzz::expect_clean([&] { mesh_shell_mass_properties(mesh, 1.0); });
  });
  return 0;
}
