// Tests of validity.hpp. Oracles: the worked message of docs/inertia.md, laminae (I1 + I2 = I3 exactly in
// theory), random point clouds (always physical), and Dykstra's alternating projections as an independent
// computation of the nearest valid moments.
#include "poinsot/inertia/validity.hpp"

#include <array>

#include <gtest/gtest.h>

#include "poinsot/core/error.hpp"
#include "poinsot/inertia/principal_axes.hpp"
#include "poinsot/inertia/shapes.hpp"
#include "poinsot_test.hpp"

namespace poinsot::inertia {
namespace {

using test::kEps;

TEST(Validity, TriangleInequalityMessageFromTheIssue) {
  const InertiaCheck c = check_inertia(Vec3(1, 1, 5).asDiagonal());
  EXPECT_FALSE(c.valid);
  EXPECT_EQ(c.condition, "triangle inequality");
  EXPECT_DOUBLE_EQ(c.amount, 3.0);
  EXPECT_EQ(c.message,
            "inertia: principal moments (1, 1, 5) kg·m² violate the triangle inequality I1 + I2 >= I3 (short "
            "by 3)");
  EXPECT_THROW(require_valid_inertia(Vec3(1, 1, 5).asDiagonal()), InvalidInput);
}

TEST(Validity, EachConditionIsNamedWithItsAmount) {
  const InertiaCheck neg = check_inertia(Vec3(-0.5, 2, 2).asDiagonal());
  EXPECT_EQ(neg.condition, "negative moment");
  EXPECT_DOUBLE_EQ(neg.amount, 0.5);
  EXPECT_NE(neg.message.find("below 0 by 0.5"), std::string::npos) << neg.message;
  Mat3 J = Mat3::Identity();
  J(0, 1) = 0.25;
  const InertiaCheck asym = check_inertia(J);
  EXPECT_EQ(asym.condition, "not symmetric");
  EXPECT_DOUBLE_EQ(asym.amount, 0.25);
  J(0, 1) = INFINITY;
  EXPECT_EQ(check_inertia(J).condition, "non-finite");
  EXPECT_THROW(check_inertia(Mat3::Identity(), -1.0), InvalidInput);
  // The name given by the caller leads the message.
  EXPECT_EQ(check_inertia(Vec3(1, 1, 5).asDiagonal(), kDefaultValidityTolerance, "body: inertia")
                .message.rfind("body: inertia: ", 0),
            0u);
}

TEST(Validity, PhysicalBodiesAreValid) {
  // Random point clouds: J = Σ m (|x|² I − x xᵀ) is physical by construction.
  for (int i = 0; i < 200; ++i) {
    Mat3 J = Mat3::Zero();
    for (int k = 0; k < 5; ++k) {
      const Vec3 x = test::random_vector();
      J += test::uniform(0.1, 1) * (x.squaredNorm() * Mat3::Identity() - x * x.transpose());
    }
    EXPECT_TRUE(check_inertia(J).valid) << check_inertia(J).message;
  }
  // Laminae sit on the boundary I1 + I2 = I3 and must pass despite round-off, also rotated.
  const Mat3 R = test::random_rotation();
  EXPECT_TRUE(check_inertia(R * plate(1.0, 0.3, 0.7).inertia_com * R.transpose()).valid);
  EXPECT_TRUE(check_inertia(Mat3::Zero()).valid);               // a point mass
  EXPECT_TRUE(check_inertia(rod(1.0, 2.0).inertia_com).valid);  // a rod: I1 = 0
}

/// Dykstra's algorithm: projection onto the intersection of the three half-spaces n_k·μ >= 0.
Vec3 dykstra(const Vec3& x) {
  const std::array<Vec3, 3> n{Vec3(-1, 1, 1), Vec3(1, -1, 1), Vec3(1, 1, -1)};
  Vec3 y = x;
  std::array<Vec3, 3> p{Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  for (int it = 0; it < 20000; ++it) {
    const Vec3 before = y;
    for (int k = 0; k < 3; ++k) {
      const Vec3 z = y + p[static_cast<std::size_t>(k)];
      const Vec3& nk = n[static_cast<std::size_t>(k)];
      const double s = nk.dot(z);
      const Vec3 proj = s >= 0 ? z : Vec3(z - s / nk.squaredNorm() * nk);
      p[static_cast<std::size_t>(k)] = z - proj;
      y = proj;
    }
    if (it > 10 && (y - before).norm() < 1e-17) break;  // converged to round-off
  }
  return y;
}

TEST(Validity, RepairIsTheNearestValidTensorWithTheSameAxes) {
  for (int i = 0; i < 40; ++i) {
    const Vec3 lambda(test::uniform(-1, 1), test::uniform(-1, 1), test::uniform(-1, 3));
    const Mat3 R = test::random_rotation();
    const Mat3 J = R * lambda.asDiagonal() * R.transpose();
    const InertiaRepair r = repair_inertia(J);
    EXPECT_TRUE(check_inertia(r.inertia).valid) << check_inertia(r.inertia).message;
    // Independent projection of the moments (Dykstra converges linearly; 1e-9 is far above its error at
    // convergence and far above the direct method's round-off, far below any wrong face).
    const Vec3 mu = dykstra(lambda);
    Vec3 mu_sorted = mu;
    std::sort(mu_sorted.data(), mu_sorted.data() + 3);
    EXPECT_LE((r.moments_after - mu_sorted).cwiseAbs().maxCoeff(), 1e-9);
    EXPECT_NEAR(r.distance, (mu - lambda).norm(), 1e-9);
    // Same axes: the repaired tensor is diagonal in the frame R.
    const Mat3 D = R.transpose() * r.inertia * R;
    EXPECT_LE((D - Mat3(D.diagonal().asDiagonal())).cwiseAbs().maxCoeff(), 1e-12);
  }
}

TEST(Validity, RepairLeavesValidTensorsAloneAndRemovesAsymmetry) {
  const Mat3 J = box(1.0, Vec3(0.1, 0.2, 0.3)).inertia_com;
  const InertiaRepair same = repair_inertia(J);
  EXPECT_EQ(same.inertia, J);
  EXPECT_EQ(same.distance, 0.0);
  Mat3 A = J;
  A(0, 1) += 1e-3;  // an antisymmetric part of Frobenius norm 1e-3/√2 plus a symmetric change
  const InertiaRepair r = repair_inertia(A);
  EXPECT_TRUE(check_inertia(r.inertia).valid);
  EXPECT_EQ(r.inertia, r.inertia.transpose().eval());
  EXPECT_GE(r.distance, 1e-3 / std::sqrt(2.0) * (1 - 1e-12));
  EXPECT_THROW(repair_inertia(Mat3::Constant(NAN)), InvalidInput);
}

}  // namespace
}  // namespace poinsot::inertia
