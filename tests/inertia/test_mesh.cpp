// Tests of mesh.hpp. Oracles: closed forms of the box (exact polyhedron) and of a cube's surface, the same
// mesh moved far from the origin and rotated, and meshes broken on purpose for each diagnostic.
#include "poinsot/inertia/mesh.hpp"

#include <gtest/gtest.h>

#include "poinsot/core/error.hpp"
#include "poinsot/inertia/shapes.hpp"
#include "poinsot/inertia/tessellation.hpp"
#include "poinsot_test.hpp"

namespace poinsot::inertia {
namespace {

using test::kEps;
using test::max_abs_diff;

using test::message_of;

TEST(Mesh, BoxIsExact) {
  const Vec3 size(0.3, 0.1, 0.02);
  const MassProperties m = mesh_mass_properties(box_mesh(size), 2700.0);
  const MassProperties f = box(2700.0 * size.prod(), size);
  EXPECT_NEAR(m.mass, f.mass, 4 * kEps * f.mass);
  EXPECT_LE(m.com.norm(), 4 * kEps * size.norm());
  EXPECT_LE(max_abs_diff(m.inertia_com, f.inertia_com), 8 * kEps * f.inertia_com.norm());
}

TEST(Mesh, FarFromTheOriginAndRotated) {
  // A tessellated capsule moved 1e6 m away and rotated: relative to its own size (0.5 m) the result must keep
  // the accuracy of the mesh near the origin. Without the interior reference point the second moments about
  // the origin (~m·1e12) would cancel to leave ~1e-4 relative error; with it, ~1e-10 (the vertices themselves
  // are rounded to ulp(1e6) ≈ 1.2e-10 m, i.e. 2e-10 relative to the size).
  ShapeSpec s;
  s.kind = "capsule";
  s.radius = 0.2;
  s.length = 0.5;
  const TriangleMesh near = tessellate(s, 64);
  const MassProperties ref = mesh_mass_properties(near, 1000.0);
  const Mat3 R = test::random_rotation();
  const Vec3 t(1e6, -2e6, 3e5);
  TriangleMesh far = near;
  for (auto& v : far.vertices)
    v = R * v + t;
  const MassProperties m = mesh_mass_properties(far, 1000.0);
  EXPECT_NEAR(m.mass, ref.mass, 1e-8 * ref.mass);
  EXPECT_LE((m.com - (R * ref.com + t)).norm(), 1e-9);
  const Mat3 expected = R * ref.inertia_com * R.transpose();
  EXPECT_LE(max_abs_diff(m.inertia_com, expected), 1e-8 * expected.norm());
}

TEST(Mesh, ShellOfACube) {
  // The surface of a cube of side a and mass m: J = 5/18 m a² (six faces, each a plate, parallel axes).
  const double a = 0.4, m = 1.5;
  const MassProperties s = mesh_shell_mass_properties_with_mass(box_mesh(Vec3(a, a, a)), m);
  EXPECT_LE(max_abs_diff(s.inertia_com, Mat3(5.0 / 18.0 * m * a * a * Mat3::Identity())),
            8 * kEps * m * a * a);
  const MassProperties by_density = mesh_shell_mass_properties(box_mesh(Vec3(a, a, a)), 2.0);
  EXPECT_NEAR(by_density.mass, 2.0 * 6 * a * a, 8 * kEps);
}

TEST(Mesh, CleanMeshHasNoFindings) {
  const MeshDiagnostics d = diagnose(box_mesh(Vec3(1, 2, 3)));
  EXPECT_TRUE(d.messages().empty());
  EXPECT_EQ(d.shells, 1u);
  EXPECT_NEAR(d.signed_volume, 6.0, 8 * kEps * 6);
  EXPECT_NEAR(d.area, 22.0, 8 * kEps * 22);
}

TEST(Mesh, OpenEdgesAreAnError) {
  TriangleMesh m = box_mesh(Vec3(1, 1, 1));
  m.triangles.pop_back();  // a hole: the three edges of the missing triangle are used once
  const MeshDiagnostics d = diagnose(m);
  EXPECT_EQ(d.open_edges, 3u);
  const std::string msg = message_of([&] { mesh_mass_properties(m, 1.0); });
  EXPECT_NE(msg.find("open edges: 3 (not watertight)"), std::string::npos) << msg;
  // Shell mode accepts open surfaces.
  EXPECT_NO_THROW(mesh_shell_mass_properties(m, 1.0));
}

TEST(Mesh, InconsistentWindingIsAnError) {
  TriangleMesh m = box_mesh(Vec3(1, 1, 1));
  std::swap(m.triangles[0][1], m.triangles[0][2]);
  const MeshDiagnostics d = diagnose(m);
  EXPECT_EQ(d.inconsistent_edges, 3u);
  EXPECT_EQ(d.open_edges, 0u);
  EXPECT_NE(message_of([&] { mesh_mass_properties(m, 1.0); }).find("inconsistent winding: 3 edges"),
            std::string::npos);
}

TEST(Mesh, InwardMeshIsReportedAndFlippedOnlyWhenAsked) {
  TriangleMesh m = box_mesh(Vec3(1, 2, 3));
  flip_orientation(m);
  EXPECT_TRUE(diagnose(m).inward());
  const std::string msg = message_of([&] { mesh_mass_properties(m, 1.0); });
  EXPECT_NE(msg.find("inward orientation (signed volume -6 m³)"), std::string::npos) << msg;
  MeshOptions flip;
  flip.flip_inward = true;
  MeshDiagnostics d;
  const MassProperties p = mesh_mass_properties(m, 1.0, flip, &d);
  EXPECT_NEAR(p.mass, 6.0, 8 * kEps * 6);
  EXPECT_LE(max_abs_diff(p.inertia_com, box(6.0, Vec3(1, 2, 3)).inertia_com), 64 * kEps);
  EXPECT_EQ(d.messages().back(), "inward orientation: signed volume -6 m³");
}

TEST(Mesh, DegenerateTrianglesAndShellsAreCounted) {
  TriangleMesh m = box_mesh(Vec3(1, 1, 1));
  TriangleMesh second = box_mesh(Vec3(1, 1, 1));
  const auto offset = static_cast<std::int32_t>(m.vertices.size());
  for (const auto& v : second.vertices)
    m.vertices.push_back(v + Vec3(5, 0, 0));
  for (auto t : second.triangles) {
    for (auto& i : t)
      i += offset;
    m.triangles.push_back(t);
  }
  m.triangles.push_back({0, 0, 1});  // collapsed
  const MeshDiagnostics d = diagnose(m);
  EXPECT_EQ(d.shells, 2u);
  EXPECT_EQ(d.degenerate_triangles, 1u);
  const auto msgs = d.messages();
  EXPECT_NE(std::find(msgs.begin(), msgs.end(), "shells: 2 (disconnected parts)"), msgs.end());
  // Still a valid solid: two unit cubes, centre of mass between them.
  const MassProperties p = mesh_mass_properties(m, 1.0);
  EXPECT_NEAR(p.mass, 2.0, 16 * kEps);
  EXPECT_LE((p.com - Vec3(2.5, 0, 0)).norm(), 16 * kEps * 5);
}

TEST(Mesh, RejectsBadMeshesAndDensities) {
  EXPECT_THROW(diagnose(TriangleMesh{}), InvalidInput);
  TriangleMesh m = box_mesh(Vec3(1, 1, 1));
  EXPECT_THROW(mesh_mass_properties(m, 0.0), InvalidInput);
  EXPECT_THROW(mesh_mass_properties_with_mass(m, -1.0), InvalidInput);
  EXPECT_THROW(mesh_shell_mass_properties(m, NAN), InvalidInput);
  m.triangles[0][0] = 99;
  EXPECT_NE(message_of([&] { diagnose(m); }).find("vertex index 99"), std::string::npos);
  // A flat, closed "solid" with no volume: two triangles back to back.
  TriangleMesh flat;
  flat.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  flat.triangles = {{0, 1, 2}, {0, 2, 1}};
  EXPECT_NE(message_of([&] { mesh_mass_properties(flat, 1.0); }).find("encloses a volume of 0"),
            std::string::npos);
}

}  // namespace
}  // namespace poinsot::inertia
