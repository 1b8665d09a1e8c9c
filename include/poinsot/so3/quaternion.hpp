#pragma once
/// @file quaternion.hpp
/// Unit quaternions ↔ rotation matrices. Hamilton convention, `q = w + x i + y j + z k`, and the rotation of
/// a vector is `q v q*`; for the rotation by θ about the unit axis n, `q = (cos θ/2, sin θ/2 n)`. The matrix
/// is the body-to-space R of the seeds when q is the body's attitude. Printed and stored in the order (w, x,
/// y, z).
///
/// q and −q are the same rotation. quaternion_from_rotation returns the canonical one, w ≥ 0 (and at w = 0
/// the first non-zero of x, y, z positive), so that results are deterministic.

#include "poinsot/core/types.hpp"
#include "poinsot/so3/rotation_check.hpp"

namespace poinsot::so3 {

/// The rotation matrix of the quaternion `q`, which is normalised first: any finite non-zero q is accepted
/// (its norm is not a rotation, only its direction). Throws InvalidInput for a zero or non-finite q.
Mat3 rotation_from_quaternion(const Quat& q);

/// The canonical unit quaternion (w ≥ 0) of the rotation R, by Shepperd's method (largest of w², x², y², z²
/// first; no loss of accuracy at any angle). R must be a rotation to within `tolerance` in ‖RᵀR − I‖_F
/// (so3::is_rotation) and have det R > 0; the result is normalised. Throws InvalidInput otherwise.
Quat quaternion_from_rotation(const Mat3& R, double tolerance = kRotationInputTolerance);

/// q normalised to unit length and to the canonical sign (w ≥ 0). Throws InvalidInput for a zero or
/// non-finite q.
Quat canonical_unit_quaternion(const Quat& q);

/// The quaternion `(w, x, y, z)` from its four components in that order.
inline Quat quaternion_wxyz(double w, double x, double y, double z) {
  return Quat(w, x, y, z);
}

}  // namespace poinsot::so3
