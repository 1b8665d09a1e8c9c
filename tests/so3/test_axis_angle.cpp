#include "poinsot/so3/axis_angle.hpp"

#include <numbers>

#include "poinsot/core/error.hpp"
#include "poinsot_test.hpp"

namespace poinsot::so3 {
namespace {
using test::kEps;

TEST(AxisAngle, RightHandRuleAboutZ) {
  // A quarter turn about +z takes +x to +y.
  const Mat3 R = rotation_from_axis_angle(Vec3::UnitZ(), std::numbers::pi / 2);
  EXPECT_LE((R * Vec3::UnitX() - Vec3::UnitY()).norm(), 2 * kEps);
}

TEST(AxisAngle, NonUnitAxisIsNormalisedAndNegativeAngleFlipsTheAxis) {
  const AxisAngle back = axis_angle_from_rotation(rotation_from_axis_angle(Vec3(0, 0, 5), -0.3));
  EXPECT_NEAR(back.angle, 0.3, 4 * kEps);
  EXPECT_LE((back.axis - Vec3(0, 0, -1)).norm(), 4 * kEps);
}

TEST(AxisAngle, IdentityHasAngleZero) {
  const AxisAngle a = axis_angle_from_rotation(Mat3::Identity());
  EXPECT_EQ(a.angle, 0.0);
  EXPECT_EQ(a.axis, Vec3::UnitZ());
}

TEST(AxisAngle, ZeroAxisIsAnError) {
  EXPECT_THROW(rotation_from_axis_angle(Vec3::Zero(), 1.0), InvalidInput);
  EXPECT_THROW(rotation_from_axis_angle(Vec3::UnitX(), INFINITY), InvalidInput);
}

}  // namespace
}  // namespace poinsot::so3
