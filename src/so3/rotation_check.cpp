// "Is R a rotation?" (rotation_check.hpp) and the canonical quaternion of a checked rotation.
#include "poinsot/so3/rotation_check.hpp"

#include <cmath>

#include <fmt/format.h>

#include "poinsot/core/check.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/so3/quaternion.hpp"
#include "rotation_check.hpp"

namespace poinsot::so3 {

bool is_rotation(const Mat3& R, double tolerance) {
  if (!R.allFinite()) return false;
  return orthogonality_error(R) <= tolerance && R.determinant() > 0.0;
}

void require_rotation(std::string_view what, const Mat3& R, double tolerance) {
  require_finite(what, R);
  const double err = orthogonality_error(R);
  if (!(err <= tolerance)) {
    throw InvalidInput(
        fmt::format("{}: matrix {} is not a rotation (|R^T R - I| = {:.3g} > {:.3g}); "
                    "expected an orthogonal matrix (use so3::project_to_so3 for a nearly "
                    "orthogonal one)",
                    what, format_matrix(R), err, tolerance));
  }
  const double det = R.determinant();
  if (!(det > 0.0)) {
    throw InvalidInput(
        fmt::format("{}: matrix {} has determinant {:.6g}; expected a proper rotation (det = +1)", what,
                    format_matrix(R), det));
  }
}

}  // namespace poinsot::so3

namespace poinsot::so3::detail {

Quat quaternion_of_rotation_unchecked(const Mat3& R) {
  Quat q(R);  // Eigen's conversion is Shepperd's method: branch on the largest of w², x², y², z².
  q.normalize();
  if (q.w() < 0.0 ||
      (q.w() == 0.0 && (q.x() < 0.0 || (q.x() == 0.0 && (q.y() < 0.0 || (q.y() == 0.0 && q.z() < 0.0)))))) {
    q.coeffs() = -q.coeffs();
  }
  return q;
}

}  // namespace poinsot::so3::detail
