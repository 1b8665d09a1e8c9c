#include "poinsot/so3/distance.hpp"

#include <numbers>

#include "poinsot/core/error.hpp"
#include "poinsot/so3/exp_log.hpp"
#include "poinsot_test.hpp"

namespace poinsot::so3 {
namespace {
using test::kEps;

TEST(Distance, AngleFromIdentityIsTheRotationAngle) {
  for (int i = 0; i < 3000; ++i) {
    const double theta = test::uniform(0.0, std::numbers::pi);
    const Vec3 n = test::random_unit_vector();
    EXPECT_NEAR(angle_between(Mat3::Identity(), exp(theta * n)), theta, 16 * kEps);
  }
}

TEST(Distance, IsBiInvariantAndSymmetric) {
  for (int i = 0; i < 2000; ++i) {
    const Mat3 A = test::random_rotation(), B = test::random_rotation(), C = test::random_rotation();
    const double d = angle_between(A, B);
    EXPECT_NEAR(angle_between(C * A, C * B), d, 64 * kEps);
    EXPECT_NEAR(angle_between(A * C, B * C), d, 64 * kEps);
    EXPECT_NEAR(angle_between(B, A), d, 16 * kEps);
  }
}

TEST(Distance, TinyAnglesAreResolved) {
  const Mat3 A = test::random_rotation();
  for (double theta : {1e-6, 1e-10, 1e-13}) {
    const Mat3 B = A * exp(theta * Vec3(0.6, 0.0, 0.8));
    // The entries of A·exp(...) carry ~1 ulp of absolute error, so the angle is known to a few ulps absolute.
    EXPECT_NEAR(angle_between(A, B), theta, 16 * kEps);
  }
}

TEST(Distance, QuaternionFormIgnoresSign) {
  const Quat q1 = test::random_quaternion();
  const Quat q2 = test::random_quaternion();
  const Quat minus_q2(-q2.w(), -q2.x(), -q2.y(), -q2.z());
  EXPECT_NEAR(angle_between(q1, q2), angle_between(q1, minus_q2), 8 * kEps);
  EXPECT_NEAR(angle_between(q1, q2), angle_between(q1.toRotationMatrix(), q2.toRotationMatrix()), 64 * kEps);
  EXPECT_THROW(angle_between(Quat(0, 0, 0, 0), q2), InvalidInput);
}

}  // namespace
}  // namespace poinsot::so3
