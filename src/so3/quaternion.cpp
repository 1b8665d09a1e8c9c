#include "poinsot/so3/quaternion.hpp"

#include <fmt/format.h>

#include "poinsot/core/check.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"
#include "rotation_check.hpp"

namespace poinsot::so3 {

Quat canonical_unit_quaternion(const Quat& q) {
  require_finite("quaternion", q);
  const double n = q.norm();
  if (!(n > 0.0)) {
    throw InvalidInput(
        fmt::format("quaternion: got {}, expected a non-zero quaternion (w, x, y, z)", format_quaternion(q)));
  }
  Quat u(q.coeffs() / n);
  if (u.w() < 0.0 ||
      (u.w() == 0.0 && (u.x() < 0.0 || (u.x() == 0.0 && (u.y() < 0.0 || (u.y() == 0.0 && u.z() < 0.0)))))) {
    u.coeffs() = -u.coeffs();
  }
  return u;
}

Mat3 rotation_from_quaternion(const Quat& q) {
  return canonical_unit_quaternion(q).toRotationMatrix();
}

Quat quaternion_from_rotation(const Mat3& R, double tolerance) {
  require_rotation("quaternion_from_rotation", R, tolerance);
  return detail::quaternion_of_rotation_unchecked(R);
}

}  // namespace poinsot::so3
