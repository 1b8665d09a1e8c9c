#pragma once
/// @file distance.hpp
/// The angle between two rotations: the angle θ ∈ [0, π] of the relative rotation `R1ᵀ R2` (the geodesic
/// distance on SO(3) with the bi-invariant metric), computed as `2 atan2(|q_v|, |q_w|)` of the relative
/// quaternion, so that angles of 1e-15 rad are resolved.

#include "poinsot/core/types.hpp"

namespace poinsot::so3 {

/// Angle in radians of the rotation that takes R1 to R2 (θ of R1ᵀR2). Both must be rotations.
double angle_between(const Mat3& R1, const Mat3& R2);

/// The same for unit quaternions (either sign of each).
double angle_between(const Quat& q1, const Quat& q2);

}  // namespace poinsot::so3
