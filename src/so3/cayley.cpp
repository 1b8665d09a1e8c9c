#include "poinsot/so3/cayley.hpp"

#include <fmt/format.h>

#include "poinsot/core/check.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/so3/hat.hpp"

namespace poinsot::so3 {

Mat3 cayley(const Vec3& c) {
  const Mat3 k = hat(c);
  return Mat3::Identity() + (2.0 / (1.0 + c.squaredNorm())) * (k + k * k);
}

Vec3 cayley_inverse(const Mat3& R) {
  require_finite("cayley_inverse: matrix", R);
  const double denom = 1.0 + R.trace();
  if (!(denom > 1e-12)) {
    throw InvalidInput(
        fmt::format("cayley_inverse: rotation has 1 + tr R = {:.3g}; a half-turn (angle pi) has no "
                    "Cayley vector, expected an angle < pi",
                    denom));
  }
  return 2.0 * vee(R) / denom;  // vee(R) is half of vee(R − Rᵀ)
}

}  // namespace poinsot::so3
