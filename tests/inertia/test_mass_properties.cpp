// Tests of mass_properties.hpp: J <-> K, parallel-axis theorem both ways, re-expression, composites, voids.
// Oracles: the lecture's plate tensor about its corner (LEC, checked symbolically in docs/conventions.md A),
// closed forms of boxes, and the mesh method (mesh.hpp) on transformed meshes.
#include "poinsot/inertia/mass_properties.hpp"

#include <gtest/gtest.h>

#include "poinsot/core/error.hpp"
#include "poinsot/inertia/mesh.hpp"
#include "poinsot/inertia/shapes.hpp"
#include "poinsot/inertia/tessellation.hpp"
#include "poinsot_test.hpp"

namespace poinsot::inertia {
namespace {

using test::kEps;
using test::max_abs_diff;

TEST(MassProperties, PoinsotAndInertiaAreInverse) {
  for (int i = 0; i < 50; ++i) {
    const Mat3 A = Mat3::Random();
    const Mat3 J = A * A.transpose();
    EXPECT_LE(max_abs_diff(inertia_from_poinsot(poinsot_from_inertia(J)), J), 8 * kEps * J.norm());
  }
}

TEST(MassProperties, PoinsotTensorOfABoxIsItsSecondMoment) {
  // K = ∫ρ x xᵀ: for a box a × b × c of mass m, K = m/12 diag(a², b², c²) (direct integration).
  const Vec3 s(0.3, 0.1, 0.02);
  const MassProperties b = box(0.4, s);
  const Mat3 expected = (0.4 / 12.0 * s.cwiseAbs2()).asDiagonal();
  EXPECT_LE(max_abs_diff(b.poinsot_com(), expected), 4 * kEps * expected.norm());
}

TEST(MassProperties, LecturePlateAboutItsCorner) {
  // LEC: I = m a² [[1/3, −1/4, 0], [−1/4, 1/3, 0], [0, 0, 2/3]] about the corner.
  const double m = 2.5;
  const double a = 0.7;
  const MassProperties p = plate(m, a, a);
  const Mat3 J = p.inertia_about(Vec3(-a / 2, -a / 2, 0.0));
  Mat3 expected;
  expected << 1.0 / 3, -0.25, 0, -0.25, 1.0 / 3, 0, 0, 0, 2.0 / 3;
  expected *= m * a * a;
  EXPECT_LE(max_abs_diff(J, expected), 4 * kEps * m * a * a);
  // And back: the centre-of-mass tensor is recovered.
  const MassProperties back = from_inertia_about(m, p.com, J, Vec3(-a / 2, -a / 2, 0.0));
  EXPECT_LE(max_abs_diff(back.inertia_com, p.inertia_com), 8 * kEps * m * a * a);
}

TEST(MassProperties, ParallelAxisMatchesTheMeshMethodAboutTheOrigin) {
  // A box mesh displaced by t: its integrals about the origin give J about the origin directly.
  const Vec3 size(0.3, 0.2, 0.5);
  TriangleMesh mesh = box_mesh(size);
  const Vec3 t(1.0, -2.0, 0.5);
  for (auto& v : mesh.vertices)
    v += t;
  const VolumeIntegrals in = volume_integrals(mesh, Vec3::Zero());
  const double rho = 7.0;
  const Mat3 K0 = rho * in.second;
  const Mat3 J0 = inertia_from_poinsot(K0);
  const MassProperties b = [&] {
    MassProperties x = box(rho * size.prod(), size);
    x.com = t;
    return x;
  }();
  // Round-off: the mesh sums terms of size m|t|², so compare to eps times that scale.
  EXPECT_LE(max_abs_diff(b.inertia_about(Vec3::Zero()), J0), 64 * kEps * b.mass * t.squaredNorm());
  EXPECT_LE(max_abs_diff(shift_to_com(J0, b.mass, t, Vec3::Zero()), b.inertia_com),
            64 * kEps * b.mass * t.squaredNorm());
}

TEST(MassProperties, ReexpressionMatchesARotatedMesh) {
  const Vec3 size(0.3, 0.2, 0.5);
  const MassProperties b = box(3.0, size);
  for (int i = 0; i < 10; ++i) {
    const Mat3 R = test::random_rotation();
    TriangleMesh mesh = box_mesh(size);
    for (auto& v : mesh.vertices)
      v = R * v;
    const MassProperties m = mesh_mass_properties_with_mass(mesh, 3.0);
    EXPECT_LE(max_abs_diff(reexpress(b.inertia_com, R), m.inertia_com), 64 * kEps * b.inertia_com.norm());
  }
  EXPECT_THROW(reexpress(b.inertia_com, 2.0 * Mat3::Identity()), InvalidInput);
  EXPECT_THROW(reexpress(b.inertia_com, -Mat3::Identity()), InvalidInput);  // a reflection
}

TEST(MassProperties, TwoHalvesMakeTheWholeBox) {
  // Box 2a × b × c = two boxes a × b × c at x = ±a/2: the closed form of the whole is the oracle.
  const double a = 0.3, b = 0.2, c = 0.1, m = 2.0;
  MassProperties left = box(m / 2, Vec3(a, b, c));
  const MassProperties right = left.placed(Mat3::Identity(), Vec3(a / 2, 0, 0));
  left = left.placed(Mat3::Identity(), Vec3(-a / 2, 0, 0));
  const MassProperties whole = combine(left, right);
  const MassProperties expected = box(m, Vec3(2 * a, b, c));
  EXPECT_NEAR(whole.mass, m, 4 * kEps * m);
  EXPECT_LE(whole.com.norm(), 4 * kEps * a);
  EXPECT_LE(max_abs_diff(whole.inertia_com, expected.inertia_com), 8 * kEps * expected.inertia_com.norm());
  // And removing the right half gives the left half back.
  const MassProperties back = subtract(whole, right);
  EXPECT_NEAR(back.mass, m / 2, 4 * kEps * m);
  EXPECT_LE(max_abs_diff(back.com, left.com), 8 * kEps * a);
  EXPECT_LE(max_abs_diff(back.inertia_com, left.inertia_com), 16 * kEps * expected.inertia_com.norm());
}

TEST(MassProperties, CompositeWithPosesMatchesTheMeshOfTheAssembly) {
  // Three rotated and displaced boxes: combine() against the mesh method on the union of their meshes
  // (three disjoint shells; the divergence theorem adds their volumes).
  TriangleMesh all;
  MassProperties total;
  bool first = true;
  const double rho = 1000.0;
  for (int i = 0; i < 3; ++i) {
    const Vec3 size(0.1 + 0.1 * i, 0.2, 0.05 * (i + 1));
    const Mat3 R = test::random_rotation();
    const Vec3 t = test::random_vector(2.0);
    TriangleMesh m = box_mesh(size);
    const auto offset = static_cast<std::int32_t>(all.vertices.size());
    for (const auto& v : m.vertices)
      all.vertices.push_back(R * v + t);
    for (auto tri : m.triangles) {
      for (auto& k : tri)
        k += offset;
      all.triangles.push_back(tri);
    }
    const MassProperties part = box(rho * size.prod(), size).placed(R, t);
    total = first ? part : combine(total, part);
    first = false;
  }
  MeshDiagnostics d;
  const MassProperties mesh = mesh_mass_properties(all, rho, {}, &d);
  EXPECT_EQ(d.shells, 3u);
  EXPECT_NEAR(mesh.mass, total.mass, 1e-13 * total.mass);
  EXPECT_LE(max_abs_diff(mesh.com, total.com), 1e-13 * 4.0);
  EXPECT_LE(max_abs_diff(mesh.inertia_com, total.inertia_com), 1e-12 * total.inertia_com.norm());
}

TEST(MassProperties, RejectsBadInput) {
  const MassProperties b = box(1.0, Vec3(1, 1, 1));
  EXPECT_THROW(shift_from_com(Mat3::Identity(), -1.0, Vec3::Zero(), Vec3::Zero()), InvalidInput);
  EXPECT_THROW(b.inertia_about(Vec3(NAN, 0, 0)), InvalidInput);
  EXPECT_THROW(subtract(b, box(2.0, Vec3(1, 1, 1))), InvalidInput);
  MassProperties negative = b;
  negative.mass = -1.0;
  EXPECT_THROW(combine(negative, negative), InvalidInput);
  POINSOT_EXPECT_THROWS_MESSAGE(subtract(b, box(2.0, Vec3(1, 1, 1))), InvalidInput,
                                "removed from a body of mass 1 kg");
}

}  // namespace
}  // namespace poinsot::inertia
