#include "poinsot/so3/projection.hpp"

#include "poinsot/core/error.hpp"
#include "poinsot_test.hpp"

namespace poinsot::so3 {
namespace {
using test::kEps;

/// A random symmetric positive-definite matrix I + δ·(random symmetric).
Mat3 random_spd_near_identity(double delta) {
  Mat3 a = Mat3::Zero();
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j)
      a(i, j) = a(j, i) = test::uniform(-1, 1);
  return Mat3::Identity() + delta * a;
}

TEST(Projection, RecoversTheOrthogonalPolarFactor) {
  // Oracle: M = R S with S symmetric positive definite has polar factor R, which is the nearest rotation.
  for (int i = 0; i < 3000; ++i) {
    const Mat3 R = test::random_rotation();
    const Mat3 S = random_spd_near_identity(0.02);
    EXPECT_LE(test::max_abs_diff(project_to_so3(R * S, 1.0), R), 64 * kEps);
  }
}

TEST(Projection, ResultIsARotationToRoundOff) {
  for (int i = 0; i < 2000; ++i) {
    Mat3 M = test::random_rotation();
    M += 1e-6 * Mat3::Random();
    const Mat3 Q = project_to_so3(M);
    // Frobenius norm over nine entries, each a few ulps off.
    EXPECT_LE(orthogonality_error(Q), 16 * kEps);
    EXPECT_NEAR(Q.determinant(), 1.0, 16 * kEps);
    // Nearest: no other rotation we try is closer.
    const Mat3 other =
        project_to_so3(Q * Eigen::AngleAxisd(1e-4, test::random_unit_vector()).toRotationMatrix());
    EXPECT_LT((Q - M).norm(), (other - M).norm());
  }
}

TEST(Projection, OrthogonalityErrorOfKnownMatrices) {
  EXPECT_EQ(orthogonality_error(Mat3::Identity()), 0.0);
  // (2I)ᵀ(2I) − I = 3I: Frobenius norm 3√3.
  EXPECT_NEAR(orthogonality_error(2.0 * Mat3::Identity()), 3.0 * std::sqrt(3.0), 8 * kEps);
}

TEST(Projection, RejectsReflectionsFarMatricesAndNonFinite) {
  EXPECT_THROW(project_to_so3(-Mat3::Identity()), InvalidInput);
  EXPECT_THROW(project_to_so3(Mat3::Zero()), InvalidInput);
  EXPECT_THROW(project_to_so3(3.0 * Mat3::Identity()), InvalidInput);
  Mat3 m = Mat3::Identity();
  m(0, 0) = INFINITY;
  EXPECT_THROW(project_to_so3(m), InvalidInput);
  EXPECT_NO_THROW(project_to_so3(3.0 * Mat3::Identity(), 100.0));  // the caller may widen the tolerance
}

}  // namespace
}  // namespace poinsot::so3
