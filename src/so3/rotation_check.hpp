#pragma once
// Internal to the so3 layer: the test that a matrix is a rotation, shared by the functions that require one.
#include <string_view>

#include "poinsot/core/types.hpp"

namespace poinsot::so3::detail {

/// Throws InvalidInput unless R is finite, ‖RᵀR − I‖_F ≤ tolerance and det R > 0. `what` names the caller.
void require_rotation(std::string_view what, const Mat3& R, double tolerance);

/// The canonical (w ≥ 0) unit quaternion of a matrix already known to be a rotation (Shepperd's method).
Quat quaternion_of_rotation_unchecked(const Mat3& R);

}  // namespace poinsot::so3::detail
