#pragma once
/// @file axis_angle.hpp
/// Axis–angle form of a rotation: the rotation by `angle` radians about the unit vector `axis`,
/// counter-clockwise seen from the tip of the axis (right-hand rule). `rotation vector = angle · axis` is the
/// form of exp_log.hpp.

#include "poinsot/core/types.hpp"

namespace poinsot::so3 {

/// A rotation as a unit axis and an angle in radians.
struct AxisAngle {
  Vec3 axis = Vec3::UnitZ();  ///< unit vector (dimensionless)
  double angle = 0.0;         ///< rad
};

/// The rotation matrix of `angle` about `axis`. The axis is normalised; throws InvalidInput for a zero or
/// non-finite axis or a non-finite angle.
Mat3 rotation_from_axis_angle(const Vec3& axis, double angle);

/// Axis and angle θ ∈ [0, π] of the rotation R (the principal logarithm, see so3::log). At θ = 0 the axis
/// is undefined and returned as +z.
AxisAngle axis_angle_from_rotation(const Mat3& R);

}  // namespace poinsot::so3
