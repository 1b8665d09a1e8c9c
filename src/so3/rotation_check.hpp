#pragma once
// Internal to the so3 layer: the quaternion of a matrix already checked by so3::require_rotation.
#include "poinsot/core/types.hpp"
#include "poinsot/so3/rotation_check.hpp"

namespace poinsot::so3::detail {

/// The canonical (w ≥ 0) unit quaternion of a matrix already known to be a rotation (Shepperd's method).
Quat quaternion_of_rotation_unchecked(const Mat3& R);

}  // namespace poinsot::so3::detail
