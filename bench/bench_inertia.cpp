// Inertia layer, one core, double precision. Run: build/release/bench/bench_inertia
// Mesh mass properties on a tessellated torus of 1,002,528 triangles (708 × 708 quads), reported as triangles
// per second: the divergence-theorem integral alone (volume_integrals), the full solid computation with the
// topology diagnostics (edge sort, shells), the shell mode, and separately the time to read the same mesh
// from a binary STL file with assimp (load_mesh). Also the 3×3 Jacobi eigensolver.
#include <cstdio>
#include <filesystem>
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include "poinsot/inertia/mesh.hpp"
#include "poinsot/inertia/mesh_io.hpp"
#include "poinsot/inertia/principal_axes.hpp"
#include "poinsot/inertia/tessellation.hpp"

namespace {
using poinsot::Mat3;
using poinsot::Vec3;
namespace in = poinsot::inertia;

const in::TriangleMesh& big_mesh() {
  static const in::TriangleMesh mesh = [] {
    in::ShapeSpec s;
    s.kind = "torus";
    s.major_radius = 0.5;
    s.minor_radius = 0.2;
    in::TriangleMesh m = in::tessellate(s, 708);
    for (auto& v : m.vertices)
      v += Vec3(100.0, -50.0, 20.0);  // away from the origin, as real parts are
    return m;
  }();
  return mesh;
}

void BM_MeshVolumeIntegrals(benchmark::State& state) {
  const in::TriangleMesh& m = big_mesh();
  const Vec3 origin = in::bounding_box_center(m);
  for (auto _ : state)
    benchmark::DoNotOptimize(in::volume_integrals(m, origin));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(m.triangles.size()));
  state.counters["triangles"] = static_cast<double>(m.triangles.size());
}
BENCHMARK(BM_MeshVolumeIntegrals)->Unit(benchmark::kMillisecond);

void BM_MeshMassPropertiesWithDiagnostics(benchmark::State& state) {
  const in::TriangleMesh& m = big_mesh();
  for (auto _ : state)
    benchmark::DoNotOptimize(in::mesh_mass_properties(m, 7800.0));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(m.triangles.size()));
}
BENCHMARK(BM_MeshMassPropertiesWithDiagnostics)->Unit(benchmark::kMillisecond);

void BM_MeshShell(benchmark::State& state) {
  const in::TriangleMesh& m = big_mesh();
  for (auto _ : state)
    benchmark::DoNotOptimize(in::mesh_shell_mass_properties(m, 2.0));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(m.triangles.size()));
}
BENCHMARK(BM_MeshShell)->Unit(benchmark::kMillisecond);

void BM_LoadBinaryStl(benchmark::State& state) {
  const in::TriangleMesh& m = big_mesh();
  const std::string path =
      (std::filesystem::temp_directory_path() / "poinsot_bench_torus.stl").string();  // ~50 MB
  in::write_binary_stl(m, path);
  for (auto _ : state)
    benchmark::DoNotOptimize(in::load_mesh(path));
  std::filesystem::remove(path);
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(m.triangles.size()));
}
BENCHMARK(BM_LoadBinaryStl)->Unit(benchmark::kMillisecond);

void BM_PrincipalAxes(benchmark::State& state) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Mat3> tensors(1024);
  for (auto& J : tensors) {
    const Mat3 A = Mat3::NullaryExpr([&] { return u(rng); });
    J = A * A.transpose();
  }
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(in::principal_axes(tensors[i]));
    i = (i + 1) % tensors.size();
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_PrincipalAxes);

}  // namespace
