#include "poinsot/so3/exp_log.hpp"

#include <numbers>

#include "poinsot/core/error.hpp"
#include "poinsot/so3/projection.hpp"
#include "poinsot_test.hpp"

namespace poinsot::so3 {
namespace {
using test::kEps;

/// Independent oracle: the rotation matrix of the quaternion (cos θ/2, sin θ/2 n), by Eigen.
Mat3 oracle_exp(const Vec3& v) {
  const double theta = v.norm();
  if (theta == 0.0) return Mat3::Identity();
  return Eigen::AngleAxisd(theta, v / theta).toRotationMatrix();
}

TEST(Exp, MatchesTheQuaternionFormulaOverThousandsOfRandomVectors) {
  for (int i = 0; i < 5000; ++i) {
    const Vec3 v = test::random_unit_vector() * test::uniform(0.0, 3.0 * std::numbers::pi);
    EXPECT_LE(test::max_abs_diff(exp(v), oracle_exp(v)), 8 * kEps) << v.transpose();
  }
}

TEST(Exp, IsARotation) {
  for (int i = 0; i < 2000; ++i) {
    const Mat3 R = exp(test::random_vector(10.0));
    // Frobenius norm over nine entries, each a few ulps off.
    EXPECT_LE(orthogonality_error(R), 16 * kEps);
    EXPECT_NEAR(R.determinant(), 1.0, 16 * kEps);
  }
}

TEST(Exp, SmallAnglesKeepFullRelativeAccuracy) {
  // For θ ≪ 1 the off-diagonal entries are ±v_i + O(θ²): they must carry v to a few ulps, relative.
  for (double theta : {1e-4, 1e-6, 1e-8, 1e-12, 1e-300}) {
    const Vec3 v = Vec3(0.3, -0.5, 0.81).normalized() * theta;
    const Mat3 R = exp(v);
    // R = I + a j(v) + b j(v)², a = sin θ/θ, b = (1 − cos θ)/θ², by their series (exact to O(θ⁶) here).
    const double t2 = theta * theta;
    const double a = 1.0 - t2 / 6.0 + t2 * t2 / 120.0;
    const double b = 0.5 - t2 / 24.0;
    EXPECT_NEAR(R(2, 1), a * v.x() + b * v.y() * v.z(), 4 * kEps * theta);
    EXPECT_NEAR(R(1, 0), a * v.z() + b * v.x() * v.y(), 4 * kEps * theta);
    EXPECT_NEAR(R(0, 2), a * v.y() + b * v.x() * v.z(), 4 * kEps * theta);
  }
  EXPECT_EQ(exp(Vec3::Zero()), Mat3::Identity());
}

TEST(Exp, CompositionAlongOneAxisAddsAngles) {
  for (int i = 0; i < 1000; ++i) {
    const Vec3 n = test::random_unit_vector();
    const double s = test::uniform(-4, 4);
    const double t = test::uniform(-4, 4);
    EXPECT_LE(test::max_abs_diff(exp(s * n) * exp(t * n), exp((s + t) * n)), 16 * kEps);
  }
}

TEST(Exp, CheckedVersionRejectsNonFiniteInput) {
  EXPECT_THROW(exp_checked(Vec3(0.0, std::nan(""), 1.0)), InvalidInput);
  EXPECT_THROW(exp_checked(Vec3(INFINITY, 0.0, 1.0)), InvalidInput);
  EXPECT_NO_THROW(exp_checked(Vec3(0.1, 0.2, 0.3)));
}

TEST(Log, NoLossOfAccuracyNearZero) {
  const Vec3 n = Vec3(1.0, -2.0, 0.5).normalized();
  for (double theta : {1e-4, 1e-8, 1e-12, 1e-15}) {
    const Vec3 back = log(exp(theta * n));
    EXPECT_LE((back - theta * n).norm(), 4 * kEps * theta) << "theta = " << theta;
  }
  EXPECT_EQ(log(Mat3::Identity()), Vec3::Zero());
}

TEST(Log, NoLossOfAccuracyNearPi) {
  const Vec3 n = Vec3(0.2, 0.7, -0.4).normalized();
  for (double delta : {1e-4, 1e-8, 1e-10, 1e-12}) {
    const double theta = std::numbers::pi - delta;
    const Vec3 back = log(exp(theta * n));
    // exp rounds its entries to ~1 ulp; log recovers θ and n with an error of the same order. The classical
    // acos((tr R − 1)/2) would be off by ~sqrt(ulp) ≈ 1e-8 here.
    EXPECT_LE((back - theta * n).norm(), 16 * kEps) << "delta = " << delta;
  }
}

TEST(Log, AtExactlyPiReturnsAValidHalfTurn) {
  for (const Vec3& n : {Vec3(Vec3::UnitX()), Vec3(Vec3::UnitY()), Vec3(Vec3::UnitZ()),
                        Vec3(1, 1, 0).normalized(), Vec3(-1, 2, 2).normalized()}) {
    const Mat3 R = oracle_exp(std::numbers::pi * n);
    const Vec3 v = log(R);
    EXPECT_NEAR(v.norm(), std::numbers::pi, 8 * kEps);
    EXPECT_LE(test::max_abs_diff(exp(v), R), 16 * kEps);
    EXPECT_NEAR(std::abs(v.normalized().dot(n)), 1.0, 8 * kEps);
  }
}

TEST(Log, RejectsMatricesThatAreNotRotations) {
  EXPECT_THROW(log(2.0 * Mat3::Identity()), InvalidInput);
  EXPECT_THROW(log(-Mat3::Identity()), InvalidInput);  // orthogonal, det −1
  Mat3 nan = Mat3::Identity();
  nan(1, 2) = std::nan("");
  EXPECT_THROW(log(nan), InvalidInput);
  POINSOT_EXPECT_THROWS_MESSAGE(log(2.0 * Mat3::Identity()), InvalidInput, "not a rotation");
}

}  // namespace
}  // namespace poinsot::so3
