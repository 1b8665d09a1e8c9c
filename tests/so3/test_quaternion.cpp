#include "poinsot/so3/quaternion.hpp"

#include <numbers>

#include "poinsot/core/error.hpp"
#include "poinsot/so3/exp_log.hpp"
#include "poinsot/so3/projection.hpp"
#include "poinsot_test.hpp"

namespace poinsot::so3 {
namespace {
using test::kEps;

TEST(Quaternion, MatrixOfTheHalfAngleQuaternionIsExp) {
  for (int i = 0; i < 3000; ++i) {
    const Vec3 n = test::random_unit_vector();
    const double theta = test::uniform(-7.0, 7.0);
    const Quat q(std::cos(theta / 2), std::sin(theta / 2) * n.x(), std::sin(theta / 2) * n.y(),
                 std::sin(theta / 2) * n.z());
    // The argument θn of exp is rounded to ε|θ| relative, which moves the matrix by as much.
    EXPECT_LE(test::max_abs_diff(rotation_from_quaternion(q), exp(theta * n)),
              8 * kEps * std::max(1.0, std::abs(theta)));
  }
}

TEST(Quaternion, HalfTurnsAreConvertedAccurately) {
  // The naive w = sqrt(1 + tr R)/2 formula fails here (tr R = −1); Shepperd's branch does not.
  for (const Vec3& n :
       {Vec3(Vec3::UnitX()), Vec3(Vec3::UnitY()), Vec3(Vec3::UnitZ()), Vec3(1, -1, 1).normalized()}) {
    const Mat3 R = exp(std::numbers::pi * n);
    const Quat q = quaternion_from_rotation(R);
    EXPECT_NEAR(std::abs(q.w()), 0.0, 4 * kEps);
    EXPECT_NEAR(std::abs(q.vec().dot(n)), 1.0, 4 * kEps);
    EXPECT_GE(q.w(), 0.0);  // canonical sign
  }
}

TEST(Quaternion, NonUnitInputIsNormalised) {
  const Quat q(2.0, 0.0, 0.0, 2.0);  // 90° about z, scaled
  const Mat3 R = rotation_from_quaternion(q);
  EXPECT_LE(test::max_abs_diff(R, exp(Vec3(0, 0, std::numbers::pi / 2))), 4 * kEps);
  EXPECT_LE(orthogonality_error(R), 4 * kEps);
}

TEST(Quaternion, CanonicalSignIsWNonNegative) {
  const Quat q = canonical_unit_quaternion(Quat(-0.5, 0.5, -0.5, 0.5));
  EXPECT_EQ(q.w(), 0.5);
  EXPECT_EQ(q.x(), -0.5);
}

TEST(Quaternion, BadInputIsRejectedWithAClearMessage) {
  EXPECT_THROW(rotation_from_quaternion(Quat(0, 0, 0, 0)), InvalidInput);
  EXPECT_THROW(rotation_from_quaternion(Quat(1, std::nan(""), 0, 0)), InvalidInput);
  EXPECT_THROW(quaternion_from_rotation(Mat3::Constant(1.0)), InvalidInput);
  EXPECT_EQ(test::message_of([] { rotation_from_quaternion(Quat(0, 0, 0, 0)); }),
            "quaternion: got (0, 0, 0, 0), expected a non-zero quaternion (w, x, y, z)");
}

}  // namespace
}  // namespace poinsot::so3
