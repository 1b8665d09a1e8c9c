// RigidBody: the lecture's square plate (eigenvalues 1/12, 7/12, 2/3 m a²), the Poinsot tensor against
// ∫ρ X⊗X for point masses, the parallel-axis theorem for a pivot, and the one-line errors.
#include "poinsot/dynamics/rigid_body.hpp"

#include <gtest/gtest.h>

#include "poinsot/core/error.hpp"
#include "poinsot_test.hpp"
#include "point_masses.hpp"

namespace poinsot::test {
namespace {

using dynamics::RigidBody;

TEST(RigidBody, SquarePlateOfTheLecture) {
  // [LEC]: a square plate of side a, mass m, about a corner: I = m a² [[1/3, −1/4, 0], [−1/4, 1/3, 0],
  // [0, 0, 2/3]], principal moments 1/12, 7/12, 2/3 (× m a²), the 1/12 axis along the diagonal (1, 1, 0)/√2.
  Mat3 I;
  I << 1.0 / 3, -0.25, 0, -0.25, 1.0 / 3, 0, 0, 0, 2.0 / 3;
  const RigidBody plate = RigidBody::from_inertia(I);
  EXPECT_NEAR(plate.principal_moments()[0], 1.0 / 12, 1e-15);
  EXPECT_NEAR(plate.principal_moments()[1], 7.0 / 12, 1e-15);
  EXPECT_NEAR(plate.principal_moments()[2], 2.0 / 3, 1e-15);
  EXPECT_NEAR(std::abs(plate.principal_axes().col(0).dot(Vec3(1, 1, 0).normalized())), 1.0, 1e-15);
  EXPECT_NEAR(plate.principal_axes().determinant(), 1.0, 1e-15);
  EXPECT_FALSE(plate.is_diagonal());
  // A lamina: K = tr(J)/2 − J has K_zz = 0 (the plate lies in z = 0).
  EXPECT_NEAR(plate.poinsot()(2, 2), 0.0, 1e-15);
}

TEST(RigidBody, PoinsotTensorIsTheSecondMoment) {
  std::vector<PointMass> pts;
  for (int i = 0; i < 7; ++i)
    pts.push_back({uniform(0.5, 2.0), random_vector(1.0)});
  Vec3 com = Vec3::Zero();
  double mass = 0.0;
  for (const auto& p : pts) {
    com += p.m * p.x;
    mass += p.m;
  }
  com /= mass;
  Mat3 K = Mat3::Zero();
  for (auto& p : pts) {
    p.x -= com;
    K += p.m * p.x * p.x.transpose();
  }
  const RigidBody body = RigidBody::from_inertia(inertia_about_origin(pts));
  EXPECT_LT(max_abs_diff(body.poinsot(), K), 1e-13);
  EXPECT_LT(max_abs_diff(body.inertia() * body.inertia_inverse(), Mat3::Identity()), 1e-12);
  // The principal decomposition reproduces J.
  const Mat3& P = body.principal_axes();
  EXPECT_LT(max_abs_diff(P * body.principal_moments().asDiagonal() * P.transpose(), body.inertia()), 1e-13);
}

TEST(RigidBody, PivotMovesTheRotationPointByTheParallelAxisTheorem) {
  // Point masses about their centre of mass, then about a pivot at −d: J_pivot = Σ m (x + d)… directly.
  std::vector<PointMass> pts = {{1.0, Vec3(0.1, 0, 0)},
                                {1.0, Vec3(-0.1, 0, 0)},
                                {2.0, Vec3(0, 0.05, 0.02)},
                                {2.0, Vec3(0, -0.05, -0.02)}};
  const Vec3 d(0.03, -0.02, 0.3);  // pivot → centre of mass, body frame
  std::vector<PointMass> about_pivot = pts;
  for (auto& p : about_pivot)
    p.x += d;
  const RigidBody top = RigidBody::from_inertia(inertia_about_origin(pts)).with_pivot(6.0, d);
  EXPECT_LT(max_abs_diff(top.inertia(), inertia_about_origin(about_pivot)), 1e-15);
  EXPECT_LT(max_abs_diff(top.inertia_com(), inertia_about_origin(pts)), 1e-15);
  EXPECT_TRUE(top.has_pivot());
  EXPECT_EQ(top.mass(), 6.0);
  EXPECT_EQ(top.pivot_to_com(), d);
}

TEST(RigidBody, DiagonalMomentsAreSortedIntoAProperFrame) {
  const RigidBody b = RigidBody::from_principal_moments(Vec3(3.0, 1.0, 2.5));
  EXPECT_EQ(b.principal_moments(), Vec3(1.0, 2.5, 3.0));
  EXPECT_NEAR(b.principal_axes().determinant(), 1.0, 1e-15);
  const Mat3& P = b.principal_axes();
  EXPECT_LT(max_abs_diff(P * b.principal_moments().asDiagonal() * P.transpose(), b.inertia()), 1e-15);
  EXPECT_TRUE(b.is_diagonal());
}

TEST(RigidBody, RejectsUnphysicalInertia) {
  EXPECT_THROW(RigidBody::from_principal_moments(Vec3(1, 1, 5)), InvalidInput);  // triangle inequality
  EXPECT_THROW(RigidBody::from_principal_moments(Vec3(0, 1, 1)), InvalidInput);
  EXPECT_THROW(RigidBody::from_principal_moments(Vec3(1, std::nan(""), 1)), InvalidInput);
  Mat3 asym = Mat3::Identity();
  asym(0, 1) = 0.1;
  EXPECT_THROW(RigidBody::from_inertia(asym), InvalidInput);
  EXPECT_THROW(RigidBody::from_principal_moments(Vec3(1, 2, 2)).with_pivot(0.0, Vec3(0, 0, 1)), InvalidInput);
  POINSOT_EXPECT_THROWS_MESSAGE(RigidBody::from_principal_moments(Vec3(1, 1, 5)), InvalidInput,
                                "triangle inequality");
}

}  // namespace
}  // namespace poinsot::test
