// Tests of shapes.hpp against independent computations: the mesh method (mesh.hpp, divergence theorem) on
// tessellations at N and 2N segments, Richardson-extrapolated (the inscribed polyhedron's error is
// C/N² + O(1/N⁴), so (4 Q(2N) − Q(N))/3 has error O(1/N⁴)); Gauss-Legendre quadrature for the rod and
// the plate; the shell mode of the mesh method for thin shells.
#include "poinsot/inertia/shapes.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "poinsot/core/error.hpp"
#include "poinsot/inertia/mesh.hpp"
#include "poinsot/inertia/tessellation.hpp"
#include "poinsot_test.hpp"

namespace poinsot::inertia {
namespace {

using test::kEps;
using test::max_abs_diff;

struct Extrapolated {
  double volume;
  Vec3 com;
  Mat3 J;  // about the centre of mass, unit density
};

Extrapolated richardson(const ShapeSpec& s, int n) {
  const MassProperties a = mesh_mass_properties(tessellate(s, n), 1.0);
  const MassProperties b = mesh_mass_properties(tessellate(s, 2 * n), 1.0);
  return {(4 * b.mass - a.mass) / 3, (4 * b.com - a.com) / 3, (4 * b.inertia_com - a.inertia_com) / 3};
}

/// Shape (closed form, from the density) against the extrapolated mesh method, relative to the largest
/// moment.
void expect_matches_mesh(const ShapeSpec& s, double rel_tol) {
  SCOPED_TRACE(s.kind);
  const Extrapolated e = richardson(s, 64);
  const MassProperties f = shape_with_density(s, 1.0);
  EXPECT_NEAR(f.mass, e.volume, rel_tol * f.mass);
  EXPECT_NEAR(shape_measure(s), e.volume, rel_tol * f.mass);
  EXPECT_LE(e.com.norm(), rel_tol * std::cbrt(f.mass));
  const double scale = f.inertia_com.cwiseAbs().maxCoeff();
  EXPECT_LE(max_abs_diff(f.inertia_com, e.J), rel_tol * scale) << "closed form\n"
                                                               << f.inertia_com << "\nmesh\n"
                                                               << e.J;
}

ShapeSpec spec(const char* kind) {
  ShapeSpec s;
  s.kind = kind;
  return s;
}

// Tolerance 2e-5: the extrapolated error at N = 64, 128 is about (2π/64)⁴ ≈ 1e-4 times a constant below 1
// (measured at N = 128, 256: 4e-8 to 4e-7, so about 16 times that here); a wrong coefficient in a formula
// changes the result by percents. N is kept small so that the sanitizer build runs this in seconds.
constexpr double kMeshTol = 2e-5;

TEST(Shapes, BoxIsExactOnItsMesh) {
  ShapeSpec s = spec("box");
  s.size = Vec3(0.3, 0.1, 0.02);
  const MassProperties mesh = mesh_mass_properties(tessellate(s, 3), 2.0);
  const MassProperties f = shape_with_density(s, 2.0);
  EXPECT_NEAR(mesh.mass, f.mass, 8 * kEps * f.mass);
  EXPECT_LE(max_abs_diff(mesh.inertia_com, f.inertia_com), 16 * kEps * f.inertia_com.norm());
}

TEST(Shapes, SolidsMatchTheMeshMethod) {
  ShapeSpec s = spec("sphere");
  s.radius = 0.7;
  expect_matches_mesh(s, kMeshTol);
  s.inner_radius = 0.4;  // thick shell: two shells, the inner one inward
  expect_matches_mesh(s, kMeshTol);

  ShapeSpec c = spec("cylinder");
  c.radius = 0.3;
  c.length = 1.1;
  expect_matches_mesh(c, kMeshTol);
  c.inner_radius = 0.2;
  expect_matches_mesh(c, kMeshTol);

  ShapeSpec k = spec("cone");
  k.radius = 0.4;
  k.height = 0.9;
  expect_matches_mesh(k, kMeshTol);

  ShapeSpec e = spec("ellipsoid");
  e.size = Vec3(0.5, 0.3, 0.2);
  expect_matches_mesh(e, kMeshTol);

  ShapeSpec p = spec("capsule");
  p.radius = 0.2;
  p.length = 0.6;
  expect_matches_mesh(p, kMeshTol);

  ShapeSpec t = spec("torus");
  t.major_radius = 0.5;
  t.minor_radius = 0.15;
  expect_matches_mesh(t, kMeshTol);
}

/// Gauss-Legendre nodes and weights on [−1, 1], 5 points (exact for polynomials of degree <= 9).
constexpr std::array<double, 5> kGLx{-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                                     0.9061798459386640};
constexpr std::array<double, 5> kGLw{0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                     0.4786286704993665, 0.2369268850561891};

TEST(Shapes, RodAndPlateMatchQuadrature) {
  // Rod along z of length L, linear density λ: ∫ x⊗x dm by quadrature, J = tr(K) I − K.
  const double L = 1.3, lambda = 0.7;
  Mat3 K = Mat3::Zero();
  for (std::size_t i = 0; i < 5; ++i) {
    const Vec3 x(0, 0, 0.5 * L * kGLx[i]);
    K += lambda * 0.5 * L * kGLw[i] * x * x.transpose();
  }
  ShapeSpec r = spec("rod");
  r.length = L;
  const MassProperties rod_f = shape_with_density(r, lambda);
  EXPECT_NEAR(rod_f.mass, lambda * L, 4 * kEps);
  EXPECT_LE(max_abs_diff(rod_f.inertia_com, Mat3(K.trace() * Mat3::Identity() - K)), 16 * kEps);

  // Plate a × b, areal density σ: tensor-product quadrature.
  const double a = 0.4, b = 0.9, sigma = 3.0;
  K.setZero();
  for (std::size_t i = 0; i < 5; ++i)
    for (std::size_t j = 0; j < 5; ++j) {
      const Vec3 x(0.5 * a * kGLx[i], 0.5 * b * kGLx[j], 0);
      K += sigma * 0.25 * a * b * kGLw[i] * kGLw[j] * x * x.transpose();
    }
  ShapeSpec p = spec("plate");
  p.size = Vec3(a, b, 0);
  const MassProperties plate_f = shape_with_density(p, sigma);
  EXPECT_NEAR(plate_f.mass, sigma * a * b, 4 * kEps);
  EXPECT_LE(max_abs_diff(plate_f.inertia_com, Mat3(K.trace() * Mat3::Identity() - K)), 16 * kEps);
  EXPECT_EQ(point_mass(2.0).inertia_com, Mat3::Zero());
}

TEST(Shapes, ThinShellsMatchTheShellMethod) {
  // Spherical shell: shell mode on the tessellated sphere surface, extrapolated.
  ShapeSpec s = spec("sphere");
  s.radius = 0.6;
  auto shell = [&](int n) { return mesh_shell_mass_properties(tessellate(s, n), 1.0); };
  const MassProperties a = shell(64), b = shell(128);
  const double area = (4 * b.mass - a.mass) / 3;
  const Mat3 J = (4 * b.inertia_com - a.inertia_com) / 3;
  s.hollow = true;
  const MassProperties f = shape_with_density(s, 1.0);
  EXPECT_NEAR(f.mass, area, kMeshTol * f.mass);
  EXPECT_LE(max_abs_diff(f.inertia_com, J), kMeshTol * f.inertia_com.norm());

  // Thin-walled tube without end caps: an open surface of revolution.
  const double R = 0.25, L = 0.8;
  auto tube = [&](int n) { return mesh_shell_mass_properties(revolve({{R, -L / 2}, {R, L / 2}}, n), 1.0); };
  const MassProperties ta = tube(64), tb = tube(128);
  ShapeSpec c = spec("cylinder");
  c.radius = R;
  c.length = L;
  c.hollow = true;
  const MassProperties tf = shape_with_density(c, 1.0);
  EXPECT_NEAR(tf.mass, (4 * tb.mass - ta.mass) / 3, kMeshTol * tf.mass);
  EXPECT_LE(max_abs_diff(tf.inertia_com, Mat3((4 * tb.inertia_com - ta.inertia_com) / 3)),
            kMeshTol * tf.inertia_com.norm());
}

TEST(Shapes, MassAndDensityAgree) {
  ShapeSpec t = spec("torus");
  t.major_radius = 1.0;
  t.minor_radius = 0.2;
  const double V = 2 * std::numbers::pi * std::numbers::pi * 1.0 * 0.04;
  const MassProperties by_density = shape_with_density(t, 5.0);
  const MassProperties by_mass = shape_with_mass(t, 5.0 * V);
  EXPECT_NEAR(by_density.mass, 5.0 * V, 4 * kEps * by_density.mass);
  EXPECT_LE(max_abs_diff(by_density.inertia_com, by_mass.inertia_com), 8 * kEps * by_mass.inertia_com.norm());
  EXPECT_EQ(density_unit(t), "kg/m³");
  EXPECT_EQ(density_unit(spec("rod")), "kg/m");
  EXPECT_EQ(density_unit(spec("plate")), "kg/m²");
}

TEST(Shapes, BadSizesAreRejectedWithTheirName) {
  auto message = [](auto f) { return test::message_of(f); };
  EXPECT_NE(message([] { box(1.0, Vec3(1, -2, 1)); }).find("box: size y"), std::string::npos);
  EXPECT_NE(message([] { solid_sphere(0.0, 1.0); }).find("sphere: mass"), std::string::npos);
  EXPECT_NE(message([] { cylinder(1.0, 1.0, 1.0, 1.0); }).find("inner radius 1 m"), std::string::npos);
  EXPECT_NE(message([] { torus(1.0, 0.1, 0.2); }).find("minor radius"), std::string::npos);
  EXPECT_NE(message([] { rod(1.0, NAN); }).find("rod: length"), std::string::npos);
  EXPECT_NE(message([] { shape_with_mass(spec("blob"), 1.0); }).find("\"blob\""), std::string::npos);
  EXPECT_THROW(shape_with_density(spec("point"), 1.0), InvalidInput);
  EXPECT_THROW(capsule(1.0, 0.1, INFINITY), InvalidInput);
  EXPECT_THROW(cone(1.0, 0.1, 0.0), InvalidInput);
  EXPECT_THROW(ellipsoid(1.0, Vec3(1, 1, 0)), InvalidInput);
}

}  // namespace
}  // namespace poinsot::inertia
