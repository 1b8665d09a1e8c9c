#include "poinsot/so3/axis_angle.hpp"

#include <fmt/format.h>

#include "poinsot/core/check.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/so3/exp_log.hpp"

namespace poinsot::so3 {

Mat3 rotation_from_axis_angle(const Vec3& axis, double angle) {
  require_finite("axis_angle: axis", axis);
  require_finite("axis_angle: angle (rad)", angle);
  const double n = axis.norm();
  if (!(n > 0.0)) {
    throw InvalidInput(
        fmt::format("axis_angle: axis {} has zero length; expected a non-zero vector", format_vector(axis)));
  }
  return exp((angle / n) * axis);
}

AxisAngle axis_angle_from_rotation(const Mat3& R) {
  const Vec3 v = log(R);
  const double theta = v.norm();
  if (theta == 0.0) return AxisAngle{Vec3::UnitZ(), 0.0};
  return AxisAngle{v / theta, theta};
}

}  // namespace poinsot::so3
