// Fuzz harness: the mesh reader (inertia/mesh_io.hpp) and what follows it for `poinsot inertia mesh` —
// diagnostics, solid and shell mass properties. Built once per format: POINSOT_FUZZ_MESH_EXT is the file
// extension (".stl", ".obj", ".ply", ".off") that selects assimp's importer.
#include "fuzz_support.hpp"
#include "poinsot/inertia/mesh.hpp"
#include "poinsot/inertia/mesh_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = poinsot::fuzz::input_file(data, size, POINSOT_FUZZ_MESH_EXT);
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
