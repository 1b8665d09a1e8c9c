#include "poinsot/so3/exp_log.hpp"

#include <cmath>

#include "poinsot/core/check.hpp"
#include "rotation_check.hpp"

namespace poinsot::so3 {

Mat3 exp_checked(const Vec3& v) {
  require_finite("so3::exp: rotation vector", v);
  return exp(v);
}

Vec3 log(const Mat3& R) {
  require_rotation("so3::log", R, kRotationInputTolerance);
  const Quat q = detail::quaternion_of_rotation_unchecked(R);  // w >= 0
  const Vec3 qv = q.vec();
  const double s = qv.norm();  // sin(θ/2)
  if (s == 0.0) return Vec3::Zero();
  const double theta = 2.0 * std::atan2(s, q.w());  // θ ∈ [0, π], accurate at both ends
  return (theta / s) * qv;
}

}  // namespace poinsot::so3
