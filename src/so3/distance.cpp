#include "poinsot/so3/distance.hpp"

#include <cmath>

#include "poinsot/so3/quaternion.hpp"
#include "rotation_check.hpp"

namespace poinsot::so3 {

double angle_between(const Mat3& R1, const Mat3& R2) {
  require_rotation("angle_between: first rotation", R1, kRotationInputTolerance);
  require_rotation("angle_between: second rotation", R2, kRotationInputTolerance);
  const Quat q = detail::quaternion_of_rotation_unchecked(R1.transpose() * R2);
  return 2.0 * std::atan2(q.vec().norm(), std::abs(q.w()));
}

double angle_between(const Quat& q1, const Quat& q2) {
  const Quat a = canonical_unit_quaternion(q1);  // validates: finite, non-zero
  const Quat b = canonical_unit_quaternion(q2);
  const Quat rel = a.conjugate() * b;
  return 2.0 * std::atan2(rel.vec().norm(), std::abs(rel.w()));
}

}  // namespace poinsot::so3
