// Tests of principal_axes.hpp. Oracles: the lecture's square plate about its corner (LEC: 1/12, 7/12, 2/3 m
// a², axes along the diagonals and the normal), tensors built as R diag(λ) Rᵀ from known λ and R, and Eigen's
// iterative QL solver as a second formulation.
#include "poinsot/inertia/principal_axes.hpp"

#include <cmath>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

#include "poinsot/core/error.hpp"
#include "poinsot/inertia/shapes.hpp"
#include "poinsot_test.hpp"

namespace poinsot::inertia {
namespace {

using test::kEps;
using test::max_abs_diff;

void expect_proper_rotation(const Mat3& A) {
  EXPECT_LE(max_abs_diff(A.transpose() * A, Mat3::Identity()), 16 * kEps);  // ~ one rounding per rotation
  EXPECT_NEAR(A.determinant(), 1.0, 8 * kEps);
}

void expect_sign_rule(const Mat3& A) {
  for (int c = 0; c < 2; ++c) {
    int k = 0;
    for (int i = 1; i < 3; ++i)
      if (std::abs(A(i, c)) > std::abs(A(k, c)) * (1 + 1e-12)) k = i;
    EXPECT_GT(A(k, c), 0.0) << "axis " << c + 1 << " = " << A.col(c).transpose();
  }
  EXPECT_LE(max_abs_diff(A.col(2), A.col(0).cross(A.col(1))), 4 * kEps);
}

TEST(PrincipalAxes, LecturePlateAboutItsCornerTo1e15) {
  // The lecture's worked example, built from its parts: the plate about its corner (shapes + parallel
  // axis), m = a = 1 and also m = 3, a = 0.2 (relative accuracy must not depend on the scale).
  for (const auto& [m, a] : {std::pair{1.0, 1.0}, std::pair{3.0, 0.2}}) {
    const Mat3 J = plate(m, a, a).inertia_about(Vec3(-a / 2, -a / 2, 0));
    const PrincipalAxes p = principal_axes(J);
    const double ma2 = m * a * a;
    const Vec3 expected(1.0 / 12.0, 7.0 / 12.0, 2.0 / 3.0);
    for (int k = 0; k < 3; ++k) {
      EXPECT_LE(std::abs(p.moments[k] / ma2 - expected[k]), 1e-15 * expected[k]) << k;
    }
    const double h = 1.0 / std::sqrt(2.0);
    EXPECT_LE(max_abs_diff(p.axes.col(0), Vec3(h, h, 0)), 1e-15);
    EXPECT_LE(max_abs_diff(p.axes.col(1), Vec3(h, -h, 0)), 1e-15);
    // (1,1,0)/√2, (1,−1,0)/√2, z is left-handed; the sign rule makes a3 = a1 × a2 = −z.
    EXPECT_LE(max_abs_diff(p.axes.col(2), Vec3(0, 0, -1)), 1e-15);
    EXPECT_EQ(p.symmetry, Symmetry::asymmetric);
    expect_proper_rotation(p.axes);
  }
}

TEST(PrincipalAxes, RecoversKnownEigenpairsOfRandomTensors) {
  for (int i = 0; i < 200; ++i) {
    Vec3 lambda(test::uniform(0.1, 1), test::uniform(0.1, 1), 0);
    lambda[2] = lambda[0] + lambda[1] * test::uniform(0.2, 1.0);
    std::sort(lambda.data(), lambda.data() + 3);
    const Mat3 R = test::random_rotation();
    const Mat3 J = R * lambda.asDiagonal() * R.transpose();
    const PrincipalAxes p = principal_axes(J);
    // Backward stable: eigenvalue errors are a few ulps of the trace (forming J costs a few more).
    EXPECT_LE((p.moments - lambda).cwiseAbs().maxCoeff(), 8 * kEps * lambda.sum());
    EXPECT_LE(max_abs_diff(p.axes * p.moments.asDiagonal() * p.axes.transpose(), J),
              16 * kEps * lambda.sum());
    expect_proper_rotation(p.axes);
    expect_sign_rule(p.axes);
    // Second formulation: Eigen's iterative QL.
    const Vec3 ql = Eigen::SelfAdjointEigenSolver<Mat3>(J).eigenvalues();
    EXPECT_LE((p.moments - ql).cwiseAbs().maxCoeff(), 16 * kEps * lambda.sum());
  }
}

TEST(PrincipalAxes, NearlyEqualMomentsStayAccurate) {
  // Moments 1, 1 + δ, 2 with δ from 1e-6 down to 1e-14: the closed-form cubic loses about half the digits
  // here; Jacobi keeps the error at a few ulps of the trace, so δ itself is resolved once δ >> eps.
  for (double delta : {1e-6, 1e-9, 1e-12, 1e-14}) {
    for (int i = 0; i < 20; ++i) {
      const Vec3 lambda(1.0, 1.0 + delta, 2.0);
      const Mat3 R = test::random_rotation();
      const Mat3 J = R * lambda.asDiagonal() * R.transpose();
      const PrincipalAxes p = principal_axes(J, 0.0);  // tolerance 0: no degenerate-axis rule
      EXPECT_LE((p.moments - lambda).cwiseAbs().maxCoeff(), 8 * kEps * 4.0) << delta;
      // The isolated axis (moment 2) is well conditioned: gap 1.
      EXPECT_LE(std::min((p.axes.col(2) - R.col(2)).norm(), (p.axes.col(2) + R.col(2)).norm()), 32 * kEps);
    }
  }
}

TEST(PrincipalAxes, DegenerateBodiesKeepTheUniqueAxisAndAStatedFrame) {
  for (int i = 0; i < 50; ++i) {
    const Vec3 u = test::random_unit_vector();
    // Oblate: J = A I + (C − A) u⊗u with C > A (a disc); prolate with C < A (a rod-like cylinder).
    for (const double C : {3.0, 0.5}) {
      const double A = 1.0;
      const Mat3 J = A * Mat3::Identity() + (C - A) * u * u.transpose();
      const PrincipalAxes p = principal_axes(J);
      const int unique = C > A ? 2 : 0;
      EXPECT_EQ(p.symmetry, C > A ? Symmetry::oblate : Symmetry::prolate);
      const Vec3 a = p.axes.col(unique);
      EXPECT_LE(std::min((a - u).norm(), (a + u).norm()), 16 * kEps);
      expect_proper_rotation(p.axes);
      expect_sign_rule(p.axes);
      // Deterministic: the same tensor gives bit-identical axes.
      EXPECT_EQ(principal_axes(J).axes, p.axes);
    }
  }
  // Spherical: identity axes.
  const PrincipalAxes s = principal_axes(solid_sphere(2.0, 0.3).inertia_com);
  EXPECT_EQ(s.symmetry, Symmetry::spherical);
  EXPECT_EQ(s.axes, Mat3::Identity());
  // A point mass (zero tensor).
  EXPECT_EQ(principal_axes(Mat3::Zero()).symmetry, Symmetry::spherical);
}

TEST(PrincipalAxes, ClassificationToleranceIsSettable) {
  const Vec3 m(1.0, 1.0 + 1e-6, 2.0);
  EXPECT_EQ(classify(m), Symmetry::asymmetric);
  EXPECT_EQ(classify(m, 1e-5), Symmetry::oblate);
  EXPECT_EQ(classify(Vec3(1.0, 2.0, 2.0 + 1e-6), 1e-5), Symmetry::prolate);
  EXPECT_EQ(classify(Vec3(1.0, 1.0 + 1e-7, 1.0 + 2e-7), 1e-6), Symmetry::spherical);
  EXPECT_EQ(to_string(Symmetry::prolate), "prolate");
  EXPECT_EQ(principal_axes(cylinder(1.0, 0.1, 2.0).inertia_com).symmetry, Symmetry::prolate);  // long
  EXPECT_EQ(principal_axes(cylinder(1.0, 1.0, 0.1).inertia_com).symmetry, Symmetry::oblate);   // flat
  EXPECT_THROW(classify(m, -1.0), InvalidInput);
}

TEST(PrincipalAxes, RejectsNonSymmetricAndNonFinite) {
  Mat3 J = Mat3::Identity();
  J(0, 1) = 0.1;
  EXPECT_THROW(principal_axes(J), InvalidInput);
  J(0, 1) = NAN;
  EXPECT_THROW(principal_axes(J), InvalidInput);
}

}  // namespace
}  // namespace poinsot::inertia
