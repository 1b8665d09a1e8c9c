#pragma once
/// @file exp_log.hpp
/// The exponential map of SO(3) (Rodrigues' formula) and its inverse, the principal logarithm.
///
/// For a rotation vector `v = θ n` (angle θ in radians, unit axis n):
///
///     exp(v) = I + (sin θ / θ) j(v) + ((1 − cos θ) / θ²) j(v)²,
///
/// the rotation by θ about n, counter-clockwise seen from the tip of n (right-hand rule). Both coefficients
/// are evaluated without cancellation: `(1 − cos θ)/θ² = 2 sin²(θ/2)/θ²`, and below θ = 1e-4 by their Taylor
/// series, so exp is accurate to a few ulps at every angle, 1e-12 and 0 included.
///
/// log returns the rotation vector of angle θ ∈ [0, π]. The angle comes from `2 atan2(|q_v|, |q_w|)` of the
/// rotation's quaternion (obtained by Shepperd's method), which keeps full relative accuracy near 0 and
/// near π, where the classical `acos((tr R − 1)/2)` loses half of the digits. At exactly θ = π both ±θn are
/// valid; the one with a non-negative first non-zero component of n is returned.

#include "poinsot/core/types.hpp"
#include "poinsot/so3/hat.hpp"

#include <cmath>

namespace poinsot::so3 {

/// Rodrigues' formula: the rotation matrix `exp(j(v))` of the rotation vector `v` (rad). No validation:
/// non-finite input gives a non-finite result (use exp_checked for input from users).
inline Mat3 exp(const Vec3& v) {
  const double theta2 = v.squaredNorm();
  double a;             // sin θ / θ
  double b;             // (1 − cos θ) / θ²
  if (theta2 < 1e-8) {  // θ < 1e-4: Taylor series, truncation error below θ⁶/5040 < 1e-27
    a = 1.0 - theta2 / 6.0 * (1.0 - theta2 / 20.0);
    b = 0.5 - theta2 / 24.0 * (1.0 - theta2 / 30.0);
  } else {
    // One sincos of the half angle: sin θ = 2 s c and 1 − cos θ = 2 s², both free of cancellation.
    const double theta = std::sqrt(theta2);
    const double s = std::sin(0.5 * theta);
    const double c = std::cos(0.5 * theta);
    a = 2.0 * s * c / theta;
    b = 2.0 * s * s / theta2;
  }
  const Mat3 k = hat(v);
  return Mat3::Identity() + a * k + b * (k * k);
}

/// exp with validation: throws InvalidInput for a non-finite rotation vector.
Mat3 exp_checked(const Vec3& v);

/// The principal logarithm: the rotation vector `θ n`, θ ∈ [0, π], with `exp(log(R)) == R`. R must be a
/// rotation (‖RᵀR − I‖_F ≤ 1e-6 and det R > 0); otherwise InvalidInput, which suggests project_to_so3.
Vec3 log(const Mat3& R);

}  // namespace poinsot::so3
